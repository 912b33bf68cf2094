!> Elastoplastic soils through the whole program (`run_deck`, decks in test/data/plasticity):
!> homogeneous biaxial and triaxial tests against the closed-form Mohr–Coulomb strength, and
!> a smooth strip footing on Tresca soil against Prandtl's q_u = (2 + pi) c.
module test_massif_plasticity_fe
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_stiffness, only: linear_solver_name
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_io_deck_reader, only: read_deck
   use fixtures_runs, only: read_text, write_text
   use pecplas_massif_materials_soil, only: RETURN_SMOOTH, RETURN_EDGE
   use doc_report, only: report
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_plasticity, only: mc_strength, PI
   implicit none (type, external)
   private
   public :: collect_massif_plasticity_fe

   character(len=*), parameter :: DIR = 'build/test_out/plasticity'
   character(len=*), parameter :: DATA = 'test/data/plasticity/'
   !> Closed-form strength of the sample decks: p = 100, c = 10, phi = 30 deg.
   real(wp), parameter :: P = 100.0_wp, COH = 10.0_wp, PHI = 30.0_wp

contains

   subroutine collect_massif_plasticity_fe(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('biaxial_mohr_coulomb', test_biaxial_mc), &
               new_unittest('biaxial_drucker_prager', test_biaxial_dp), &
               new_unittest('triaxial_axisymmetric_edge', test_triaxial), &
               new_unittest('strip_footing_prandtl', test_footing), &
               new_unittest('spare_material_no_solver_choice', test_spare_material)]
   end subroutine collect_massif_plasticity_fe

   !> Runs `deck` (exit code 0 expected) and returns the sum of the reactions in direction 2
   !> over node set `nset` at every increment.
   subroutine run(deck, nset, model, problem, load, error)
      character(len=*), intent(in) :: deck, nset
      type(model_t), intent(out) :: model
      type(problem_t), intent(out) :: problem
      real(wp), allocatable, intent(out) :: load(:)
      type(error_t), allocatable, intent(out) :: error
      type(results_reader_t) :: rd
      real(wp), allocatable :: reac(:, :)
      character(len=:), allocatable :: out
      character(len=40) :: path
      integer :: code, n, i, k
      call make_directories(DIR)
      out = DIR//'/'//deck//'.h5'
      code = run_deck(DATA//deck//'.inp', out, .true., model, problem)
      if (code /= 0) then
         call fatal_error(error, deck//': run did not complete')
         return
      end if
      k = model%mesh%find_nset(nset)
      call rd%open(out, error)
      if (allocated(error)) return
      call rd%history_length(n, error)
      if (allocated(error)) return
      allocate (load(n))
      do i = 1, n
         write (path, '(a,i6.6,a)') '/increments/', i, '/reaction'
         call rd%dataset(trim(path), reac, error)
         if (allocated(error)) return
         load(i) = sum(reac(2, model%mesh%nsets(k)%nodes))
      end do
      call rd%close()
   end subroutine run

   !> Plane strain, Mohr–Coulomb psi = 10: top reactions -334.641 (to 1e-8), every point
   !> on the main plane with sigma_yy = -334.641 and sigma_xx = -p; UMFPACK chosen for the
   !> non-symmetric tangent.
   subroutine test_biaxial_mc(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), allocatable :: load(:)
      real(wp) :: s1
      call run('biaxial_mc', 'top', model, problem, load, error)
      if (allocated(error)) return
      s1 = mc_strength(P, COH, PHI)
      call check_close(error, -load(size(load)), s1, 1.0e-8_wp, 'top reactions = -sigma_1 B')
      if (allocated(error)) return
      associate (st => problem%state%sets(1))
         call check(error, all(abs(st%stress(2, :, :) + s1) <= 1.0e-8_wp*s1) .and. &
            all(abs(st%stress(1, :, :) + P) <= 1.0e-8_wp*s1) .and. &
            all(nint(st%hist(6, :, :)) == RETURN_SMOOTH), &
            'homogeneous failure on the main plane at every point')
      end associate
      if (allocated(error)) return
      call check(error, linear_solver_name(model) == 'UMFPACK', 'non-symmetric tangent: UMFPACK')
   end subroutine test_biaxial_mc

   !> A material no element set has nor gets does not choose the linear solver: the
   !> biaxial deck's Mohr-Coulomb sand (non-symmetric tangent, psi /= phi) kept beside an
   !> elastic material that the sample has leaves full Newton on CHOLMOD; the sand given to
   !> the sample in a later step (*CHANGE_MATERIAL) makes it UMFPACK.
   subroutine test_spare_material(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      character(len=:), allocatable :: base, deck
      character(len=*), parameter :: SECTION = '*SECTION, SET=sample, MATERIAL=sand'
      character(len=*), parameter :: STEP = '*STEP, NAME=compress'
      integer :: i
      call read_text(DATA//'biaxial_mc.inp', base)
      i = index(base, SECTION)
      base = base(:i - 1)//'*MATERIAL, NAME=stiff, TYPE=ELASTIC'//new_line('a')// &
         'E = 1e4, NU = 0.3'//new_line('a')//'*SECTION, SET=sample, MATERIAL=stiff'// &
         base(i + len(SECTION):)
      call make_directories(DIR)
      deck = DIR//'/spare.inp'
      call write_text(deck, base)
      call read_deck(deck, model, error)
      if (allocated(error)) return
      call check(error, linear_solver_name(model) == 'CHOLMOD', 'spare sand: CHOLMOD')
      if (allocated(error)) return
      i = index(base, STEP)
      call write_text(deck, base(:i - 1)//'*STEP, NAME=soften, INCREMENTS=1'//new_line('a')// &
         '*CHANGE_MATERIAL'//new_line('a')//'sample, sand'//new_line('a')//'*END STEP'// &
         new_line('a')//base(i:))
      call read_deck(deck, model, error)
      if (allocated(error)) return
      call check(error, linear_solver_name(model) == 'UMFPACK', 'sand from a phase on: UMFPACK')
   end subroutine test_spare_material

   !> Drucker–Prager with the plane strain match reaches the same strength (1e-8).
   subroutine test_biaxial_dp(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), allocatable :: load(:)
      call run('biaxial_dp', 'top', model, problem, load, error)
      if (allocated(error)) return
      call check_close(error, -load(size(load)), mc_strength(P, COH, PHI), 1.0e-8_wp, &
         'Drucker-Prager plane strain match: Mohr-Coulomb strength')
   end subroutine test_biaxial_dp

   !> Axisymmetric triaxial compression (radius 0.5): top ring reaction -334.641 pi 0.25
   !> (1e-8), every point on the edge sigma_rr = sigma_tt (two active planes), modified
   !> Newton with a single factorisation.
   subroutine test_triaxial(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), allocatable :: load(:)
      call run('triaxial_mc', 'top', model, problem, load, error)
      if (allocated(error)) return
      call check_close(error, -load(size(load)), mc_strength(P, COH, PHI)*PI*0.25_wp, &
         1.0e-8_wp, 'top ring reaction = -sigma_1 pi R^2')
      if (allocated(error)) return
      call check(error, all(nint(problem%state%sets(1)%hist(6, :, :)) == RETURN_EDGE) .and. &
         problem%stats%factorisations == 1, 'edge returns, one factorisation (modified Newton)')
   end subroutine test_triaxial

   !> Smooth rigid strip footing, Tresca c = 10, 196 T6 (footing_t6.inp): the footing
   !> pressure levels off (last 10 of 100 increments within 0.2 %) within 5 % of Prandtl's
   !> (2 + pi) c = 51.416 (measured 52.35, +1.8 %; a finer mesh gets closer, see
   !> make_footing.py).
   subroutine test_footing(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), allocatable :: load(:)
      real(wp) :: q, qu
      integer :: n
      call run('footing_t6', 'footing', model, problem, load, error)
      if (allocated(error)) return
      n = size(load)
      q = -load(n)/1.0_wp ! half-width b = 1: the half model carries q b
      qu = (2.0_wp + PI)*COH
      call report('footing/t6_nf4_q_over_c', q/COH)
      call check_close(error, q, qu, 0.05_wp, 'footing pressure vs Prandtl (2 + pi) c')
      if (allocated(error)) return
      call check(error, abs(load(n) - load(n - 10)) <= 2.0e-3_wp*abs(load(n)), &
         'the footing pressure has levelled off (limit load reached)')
   end subroutine test_footing

end module test_massif_plasticity_fe
