!> Collapse of a thick cylinder (plane strain, b/a = 2, Tresca = Mohr–Coulomb with
!> phi = psi = 0) under internal pressure: the limit pressure is 2 c ln(b/a) (the whole ring
!> plastic, sigma_theta - sigma_r = 2c, equilibrium d sigma_r / dr = 2c / r). Quarter ring
!> with symmetry rollers, through the whole program (deck -> results file).
!> - The recommended elements (Q8R, T6) are driven by an imposed radial displacement of the inner
!>   face; the pressure is the reaction over the face. It must reach 2 c ln 2 within 1 % and
!>   never exceed it by more than 1 % (plastic flow without locking gives a plateau).
!> - Q8 (3 x 3 points) locks after plastic flow: driven by pressure past the limit it must
!>   not end 'completed' silently, it either stops (limit load / diverged) or carries the
!>   large-displacement warning in its message and in the results file.
!> - Q4 (2 x 2 points) locks as well: driven by displacement it climbs well past the limit.
!> The values are reported for doc/theory.md 8.4 (test/doc_report.f90); with the environment
!> variable PECPLAS_REPORT_COLLAPSE set, `cylinder_locking` also runs the whole table of the
!> doc (T3, Q4, T6, Q8, Q8R on 2 x 1, 4 x 2, 6 x 3 cells, and 4 x 2 driven 15 times further),
!> for tools/pecplas_py/docs/theory_report.py.
module test_massif_collapse
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use doc_report, only: report
   use lame_mesh, only: write_ring_mesh, ring_node, ring_quadratic, A, B
   implicit none (type, external)
   private
   public :: collect_massif_collapse

   character(len=*), parameter :: DIR = 'build/test_out'
   real(wp), parameter :: C = 10.0_wp, E = 1.0e4_wp, NU = 0.3_wp
   real(wp), parameter :: PI = acos(-1.0_wp)
   !> Tresca limit pressure of the ring.
   real(wp), parameter :: P_LIMIT = 2.0_wp*C*log(B/A)
   !> Imposed inner displacement: 40 times c b^2 / (2 G a), the inner displacement at which
   !> an incompressible ring becomes fully plastic, so the plateau is long (a locking element
   !> climbs on it: Q8 2 x 1 cells reach 1.07 p_lim) yet below 0.1 times the model size.
   real(wp), parameter :: U_END = 40.0_wp*C*B**2*(1.0_wp + NU)/(E*A)

contains

   subroutine collect_massif_collapse(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('q8r_cylinder_plateau', test_q8r_plateau), &
               new_unittest('t6_cylinder_plateau', test_t6_plateau), &
               new_unittest('q8_cylinder_not_silent', test_q8_not_silent), &
               new_unittest('cylinder_locking', test_locking)]
   end subroutine collect_massif_collapse

   !> Deck of the Tresca ring of nr x nt cells; drive 'DISPLACEMENT' (inner face moved
   !> radially by U_END) or 'PRESSURE' (inner pressure `factor` P_LIMIT), over `incs`
   !> increments; `further` multiplies the imposed displacement.
   subroutine write_cylinder_deck(path, etype, nr, nt, drive, factor, incs, further)
      character(len=*), intent(in) :: path, etype, drive
      integer, intent(in) :: nr, nt, incs
      real(wp), intent(in) :: factor
      real(wp), intent(in), optional :: further
      integer :: u, j, mr, mt
      real(wp) :: t, u_far
      u_far = U_END
      if (present(further)) u_far = further*U_END
      mr = merge(2, 1, ring_quadratic(etype))*nr
      mt = merge(2, 1, ring_quadratic(etype))*nt
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'Tresca thick cylinder '//etype
      call write_ring_mesh(u, etype, .false., nr, nt)
      write (u, '(a)') '*MATERIAL, NAME=clay, TYPE=MOHR_COULOMB'
      write (u, '(3(a,es24.16))') 'E = ', E, ', NU = ', NU, ', C = ', C
      write (u, '(a)') 'PHI = 0, PSI = 0'
      write (u, '(a)') '*SECTION, SET=ring, MATERIAL=clay'
      if (drive == 'DISPLACEMENT') then
         write (u, '(a)') '*LOAD, NAME=drive, TYPE=DISPLACEMENT'
         do j = 0, mt
            t = 0.5_wp*PI*real(j, wp)/mt
            ! dofs held by the symmetry rollers are not imposed again
            if (j < mt) write (u, '(i0,a,es24.16)') ring_node(0, j, mr), ', 1, ', u_far*cos(t)
            if (j > 0) write (u, '(i0,a,es24.16)') ring_node(0, j, mr), ', 2, ', u_far*sin(t)
         end do
      else
         write (u, '(a)') '*LOAD, NAME=drive, TYPE=PRESSURE'
         write (u, '(a,es24.16)') 'inner, ', factor*P_LIMIT
      end if
      write (u, '(a,i0)') '*STEP, NAME=expand, INCREMENTS=', incs
      write (u, '(a)') 'drive, 1.0'
      write (u, '(a)') '*SOLVER, METHOD=NEWTON, TOLERANCE=1e-8, MAX_CUTS=3'
      write (u, '(a)') '*OUTPUT, STRESSES=NO, STRAINS=NO'
      close (u)
   end subroutine write_cylinder_deck

   !> Inner pressure of every increment of results file `h5`: the radial reactions of the
   !> inner face over its arc (a pi / 2, thickness 1).
   subroutine reaction_pressures(h5, nr, nt, quadratic, p, error)
      character(len=*), intent(in) :: h5
      integer, intent(in) :: nr, nt
      logical, intent(in) :: quadratic
      real(wp), allocatable, intent(out) :: p(:)
      type(error_t), allocatable, intent(out) :: error
      type(results_reader_t) :: rd
      real(wp), allocatable :: r(:, :)
      character(len=32) :: group
      integer :: n, k, j, mr, mt, node
      real(wp) :: t
      mr = merge(2, 1, quadratic)*nr
      mt = merge(2, 1, quadratic)*nt
      call rd%open(h5, error)
      if (allocated(error)) return
      call rd%history_length(n, error)
      if (allocated(error)) return
      allocate (p(n))
      do k = 1, n
         write (group, '(a,i6.6,a)') '/increments/', k, '/reaction'
         call rd%dataset(trim(group), r, error)
         if (allocated(error)) return
         p(k) = 0.0_wp
         do j = 0, mt
            t = 0.5_wp*PI*real(j, wp)/mt
            node = ring_node(0, j, mr)
            p(k) = p(k) + r(1, node)*cos(t) + r(2, node)*sin(t)
         end do
         p(k) = p(k)/(0.5_wp*PI*A)
      end do
      call rd%close()
   end subroutine reaction_pressures

   subroutine test_q8r_plateau(error)
      type(error_t), allocatable, intent(out) :: error
      call check_plateau('Q8R', 4, 2, 12, error)
   end subroutine test_q8r_plateau

   subroutine test_t6_plateau(error)
      type(error_t), allocatable, intent(out) :: error
      call check_plateau('T6', 4, 2, 12, error)
   end subroutine test_t6_plateau

   !> Displacement-driven run of `etype` on nr x nt cells (`further` times U_END, default 1):
   !> the inner pressure of every increment, `p`; the run must complete. Reported as
   !> collapse/ETYPE_NRxNT (or collapse/further/ETYPE_NRxNT): p_end / p_lim, p_max / p_lim.
   subroutine driven_pressures(etype, nr, nt, incs, p, error, further)
      character(len=*), intent(in) :: etype
      integer, intent(in) :: nr, nt, incs
      real(wp), allocatable, intent(out) :: p(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: further
      type(model_t) :: model
      type(problem_t) :: problem
      character(len=:), allocatable :: deck, h5, tag
      character(len=16) :: cells
      integer :: code
      call make_directories(DIR)
      write (cells, '(i0,a,i0)') nr, 'x', nt
      tag = etype//'_'//trim(cells)
      if (present(further)) tag = 'further/'//tag
      deck = DIR//'/collapse_'//etype//'_'//trim(cells)//merge('_far', '    ', present(further))
      deck = trim(deck)
      h5 = deck//'.h5'
      deck = deck//'.inp'
      call write_cylinder_deck(deck, etype, nr, nt, 'DISPLACEMENT', 1.0_wp, incs, further)
      code = run_deck(deck, h5, .true., model, problem)
      call check(error, code == 0, etype//' '//trim(cells)// &
         ' displacement-driven run must complete')
      if (allocated(error)) return
      call reaction_pressures(h5, nr, nt, ring_quadratic(etype), p, error)
      if (allocated(error)) return
      call check(error, size(p) > 0 .and. all(abs(p) < huge(1.0_wp)), etype//' '// &
         trim(cells)//': no finite pressures')
      if (allocated(error)) return
      call report('collapse/'//tag, [p(size(p))/P_LIMIT, maxval(p)/P_LIMIT])
   end subroutine driven_pressures

   !> Displacement-driven run of `etype` on nr x nt cells: the last pressure within 1 % of
   !> 2 c ln 2 (discretisation error of a coarse quadratic mesh) and none above 1.01 times it.
   subroutine check_plateau(etype, nr, nt, incs, error)
      character(len=*), intent(in) :: etype
      integer, intent(in) :: nr, nt, incs
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: p(:)
      character(len=:), allocatable :: status, message, warnings
      character(len=160) :: buf
      character(len=16) :: cells
      call driven_pressures(etype, nr, nt, incs, p, error)
      if (allocated(error)) return
      write (buf, '(a,i0,a,i0,a,f7.4,a,f7.4)') etype//' ', nr, 'x', nt, &
         ': p_end / p_lim =', p(size(p))/P_LIMIT, ', p_max / p_lim =', maxval(p)/P_LIMIT
      write (*, '(a)') '        '//trim(buf)
      call check(error, abs(p(size(p))/P_LIMIT - 1.0_wp) <= 0.01_wp .and. &
         maxval(p) <= 1.01_wp*P_LIMIT, 'collapse pressure off 2 c ln(b/a) by more than 1 %: '// &
         trim(buf))
      if (allocated(error)) return
      ! max |u| = U_END is 0.074 times the model size: no large-displacement warning
      write (cells, '(i0,a,i0)') nr, 'x', nt
      call read_ending(DIR//'/collapse_'//etype//'_'//trim(cells)//'.h5', status, message, &
         warnings, error)
      if (allocated(error)) return
      call check(error, len(warnings) == 0 .and. index(message, 'warning') == 0, &
         etype//' run below 0.1 x model size must not warn: '//warnings)
   end subroutine check_plateau

   !> Q4 (2 x 2 points: 4 isochoric constraints of 5 deformation modes) locks after plastic
   !> flow: on 4 x 2 cells the pressure climbs past 1.1 times the limit (measured 1.48), the
   !> curve rising to its end (p_max = p_end). With PECPLAS_REPORT_COLLAPSE set, the whole
   !> table of doc/theory.md 8.4 is run and reported (each run must complete with finite
   !> pressures, at least 0.8 times the limit: the ring is fully plastic at U_END).
   subroutine test_locking(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: TYPES(5) = ['T3 ', 'Q4 ', 'T6 ', 'Q8 ', 'Q8R']
      integer, parameter :: CELLS(2, 3) = reshape([2, 1, 4, 2, 6, 3], [2, 3])
      real(wp), allocatable :: p(:)
      character(len=64) :: flag
      integer :: i, j, n, stat
      call driven_pressures('Q4', 4, 2, 12, p, error)
      if (allocated(error)) return
      call check(error, p(size(p)) > 1.1_wp*P_LIMIT .and. maxval(p) <= p(size(p)), &
         'Q4 4 x 2 must lock (end pressure above 1.1 p_lim, reached at the end)')
      if (allocated(error)) return
      call get_environment_variable('PECPLAS_REPORT_COLLAPSE', flag, n, stat)
      if (stat /= 0 .or. n == 0) return
      do i = 1, size(TYPES)
         do j = 1, size(CELLS, 2)
            call driven_pressures(trim(TYPES(i)), CELLS(1, j), CELLS(2, j), 12, p, error)
            if (allocated(error)) return
            call check(error, p(size(p)) >= 0.8_wp*P_LIMIT, trim(TYPES(i))// &
               ' below 0.8 p_lim although the ring is fully plastic')
            if (allocated(error)) return
         end do
         ! 15 times further, the same increment size
         call driven_pressures(trim(TYPES(i)), 4, 2, 180, p, error, further=15.0_wp)
         if (allocated(error)) return
      end do
   end subroutine test_locking

   !> Q8 (3 x 3) pressure-driven to 1.1 times the limit: it may not end 'completed' without
   !> the large-displacement warning, in the results file's `warnings` attribute and in its
   !> status message; a warning keeps exit code 0. (Measured: completed at max |u| = 5.1,
   !> 1.8 times the model size: the locked mesh carries more than the limit pressure.)
   subroutine test_q8_not_silent(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      character(len=:), allocatable :: deck, h5, status, message, warnings
      integer :: code
      call make_directories(DIR)
      deck = DIR//'/collapse_q8_pressure.inp'
      h5 = DIR//'/collapse_q8_pressure.h5'
      call write_cylinder_deck(deck, 'Q8', 4, 2, 'PRESSURE', 1.1_wp, 11)
      code = run_deck(deck, h5, .true., model, problem)
      call read_ending(h5, status, message, warnings, error)
      if (allocated(error)) return
      write (*, '(a,i0,a)') '        Q8 past the limit: exit code ', code, ', status '// &
         status//', warnings "'//warnings//'"'
      call report('collapse/q8_pressure_completed', merge(1.0_wp, 0.0_wp, status == 'completed'))
      call report_displacement(h5, error)
      if (allocated(error)) return
      if (status /= 'completed') return ! stopped at the limit: not silent either
      call check(error, code == 0 .and. &
         index(warnings, 'small-strain theory no longer holds') > 0 .and. &
         index(message, 'warning: '//warnings) > 0, &
         'Q8 run past the collapse pressure completed without the large-displacement warning')
   end subroutine test_q8_not_silent

   !> Reports collapse/q8_pressure_umax: the largest nodal displacement of the last increment
   !> of `h5` and the model size (diagonal of the quarter ring's bounding box, b sqrt 2).
   subroutine report_displacement(h5, error)
      character(len=*), intent(in) :: h5
      type(error_t), allocatable, intent(out) :: error
      type(results_reader_t) :: rd
      real(wp), allocatable :: u(:, :)
      integer :: n
      call rd%open(h5, error)
      if (allocated(error)) return
      call rd%history_length(n, error)
      if (allocated(error)) return
      call rd%displacement(n, u, error)
      if (allocated(error)) return
      call rd%close()
      call report('collapse/q8_pressure_umax', [maxval(norm2(u, dim=1)), B*sqrt(2.0_wp)])
   end subroutine report_displacement

   !> Root attributes status, status_message and warnings ('' when absent) of `h5`.
   subroutine read_ending(h5, status, message, warnings, error)
      character(len=*), intent(in) :: h5
      character(len=:), allocatable, intent(out) :: status, message, warnings
      type(error_t), allocatable, intent(out) :: error
      type(results_reader_t) :: rd
      call rd%open(h5, error)
      if (allocated(error)) return
      call rd%attribute('/', 'status', status, error)
      if (allocated(error)) return
      call rd%attribute('/', 'status_message', message, error)
      if (allocated(error)) return
      ! the root attribute `warnings` is a list of strings (tested through h5py in
      ! test_results_file.py); the status message, also in the file, carries the same text
      warnings = ''
      if (index(message, 'warning: ') > 0) warnings = message(index(message, 'warning: ') + 9:)
      call rd%close()
   end subroutine read_ending

end module test_massif_collapse
