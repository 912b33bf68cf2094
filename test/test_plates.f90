!> Plates (beams with rotations, doc/theory.md §12): Timoshenko cantilevers against the closed
!> form (the linked 2-node element and the reduced-integration 3-node element are exact at the
!> nodes for a tip load; the 2-node element also for a uniform load), a thin beam free of shear
!> locking, an axisymmetric cylinder under internal pressure, a beam on Winkler springs
!> (Hetényi), the plastic hinges of a fixed-fixed beam, the dof map (rotations only on plate
!> nodes, a deck without plates unchanged), restart across a phase that activates a plate, and
!> bad plate decks (exit 2 with file:line).
module test_plates
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_model_columns, only: nodal_columns, rotation_column, rotation_count
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_io_results_increment, only: plate_fields_t
   use pecplas_fe_plate_output, only: plate_results
   use pecplas_base_strings, only: itoa
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use pecplas_model_plates, only: plate_section_t
   use pecplas_structures_hinge, only: hinge_stiffness, hinge_update
   use pecplas_structures_section, only: NHIST, section_update
   use pecplas_structures_beam, only: NGEN
   use test_plates_arc, only: test_arc_symmetric, test_arc_length
   implicit none (type, external)
   private
   public :: collect_plates

   character(len=*), parameter :: OUT = 'build/test_out/plates/'
   !> Section of the cantilevers (kN, m): EA, EI, and the shear stiffness 5 EA / 12 (nu = 0).
   real(wp), parameter :: EA = 1.0e7_wp, EI = 1.0e5_wp, GAS = 5.0_wp*EA/12.0_wp, L = 10.0_wp
   !> The exact elements: nodal values to the roundoff of a 30-60 equation solve with a
   !> condition number ~ (EA/EI) (L/h)^2 ~ 1e4: 1e-10 relative leaves a margin of 1e2.
   real(wp), parameter :: EXACT = 1.0e-10_wp
   !> The 3-node element is exact at the nodes for a tip load too, but its system (mid-side
   !> nodes, 60 equations) is worse conditioned: roundoff measured 5e-11; 1e-9 bounds it.
   real(wp), parameter :: EXACT3 = 1.0e-9_wp

contains

   subroutine collect_plates(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('cantilever_tip_2node', test_tip2), &
               new_unittest('cantilever_uniform_2node', test_uniform2), &
               new_unittest('cantilever_tip_3node', test_tip3), &
               new_unittest('cantilever_uniform_3node', test_uniform3), &
               new_unittest('uniform_load_on_a_curved_element', test_arc_symmetric), &
               new_unittest('uniform_load_arc_length', test_arc_length), &
               new_unittest('thin_beam_no_locking', test_thin), &
               new_unittest('axisymmetric_cylinder', test_cylinder), &
               new_unittest('hetenyi_winkler_beam', test_hetenyi), &
               new_unittest('plastic_hinge_fixed_fixed', test_hinge), &
               new_unittest('plastic_tangents_fd', test_tangents_fd), &
               new_unittest('dof_map', test_dof_map), &
               new_unittest('restart_plate_activation', test_restart), &
               new_unittest('bad_decks', test_bad_decks)]
   end subroutine collect_plates

   !> A straight beam along x of n elements (nen = 2 or 3) from x = 0 to `length`, node ids
   !> 1.. along it, plate set 'beam'; `rest`: the lines after *PLATE (supports, loads, steps).
   subroutine write_beam(path, n, nen, length, section, rest, axis)
      character(len=*), intent(in) :: path, section, rest
      integer, intent(in) :: n, nen
      real(wp), intent(in) :: length
      !> (x0, y0, dx, dy): the line's start and direction (default (0, 0, 1, 0)).
      real(wp), intent(in), optional :: axis(4)
      real(wp) :: ax(4)
      integer :: u, i, m
      ax = [0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp]
      if (present(axis)) ax = axis
      call make_directories(OUT)
      m = n*(nen - 1)
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'plate test', '*UNITS', 'kN, m, kPa', '*NODES'
      do i = 0, m
         write (u, '(i0,a,es24.16,a,es24.16)') i + 1, ', ', ax(1) + ax(3)*length*i/m, ', ', &
            ax(2) + ax(4)*length*i/m
      end do
      if (nen == 2) then
         write (u, '(a)') '*NSET, NAME=beam, GENERATE', '1, '//itoa(m + 1)//', 1', &
            '*PLATE, SET=beam, NODES=beam, '//section
      else
         write (u, '(a)') '*PLATE, SET=beam, '//section
         do i = 1, n
            write (u, '(i0,a,i0,a,i0)') 2*i - 1, ', ', 2*i + 1, ', ', 2*i
         end do
      end if
      write (u, '(a)') rest
      close (u)
   end subroutine write_beam

   !> Runs `deck` (exit code 0 expected) and gives the fields of plate set 1.
   subroutine run_plate(deck, model, problem, f, error)
      character(len=*), intent(in) :: deck
      type(model_t), intent(out) :: model
      type(problem_t), intent(out) :: problem
      type(plate_fields_t), intent(out) :: f
      type(error_t), allocatable, intent(out) :: error
      integer :: code
      code = run_deck(deck, deck(1:len(deck) - 4)//'.h5', .true., model, problem)
      if (code /= 0) then
         call fatal_error(error, deck//': exit code '//itoa(code))
         return
      end if
      call plate_results(model, problem%state%u, problem%state%plates, problem%state%factors, &
         1, f, error)
   end subroutine run_plate

   !> Deflection, rotation at node `node` and N, Q, M at the plate's first node.
   subroutine tip_values(model, problem, f, node, w, theta, q0, m0)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      type(plate_fields_t), intent(in) :: f
      integer, intent(in) :: node
      real(wp), intent(out) :: w, theta, q0, m0
      w = problem%state%u(2, node)
      theta = problem%state%u(1, rotation_column(model, node))
      q0 = f%node_forces(2, 1)
      m0 = f%node_forces(3, 1)
   end subroutine tip_values

   !> Tip load P: w = P L^3 / 3EI + P L / GAs, theta = P L^2 / 2EI, M(0) = P L, Q = P.
   subroutine test_tip2(error)
      type(error_t), allocatable, intent(out) :: error
      call tip_case(2, error)
   end subroutine test_tip2

   subroutine test_tip3(error)
      type(error_t), allocatable, intent(out) :: error
      call tip_case(3, error)
   end subroutine test_tip3

   subroutine tip_case(nen, error)
      integer, intent(in) :: nen
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: P = 100.0_wp
      type(model_t) :: model
      type(problem_t) :: problem
      type(plate_fields_t) :: f
      character(len=:), allocatable :: deck
      real(wp) :: w, theta, q0, m0, tol
      integer :: tip
      tol = merge(EXACT, EXACT3, nen == 2)
      deck = OUT//'tip'//itoa(nen)//'.inp'
      tip = 10*(nen - 1) + 1
      call write_beam(deck, 10, nen, L, 'EA=1.0e7, EI=1.0e5', '*BOUNDARY'//new_line('a')// &
         '1, ALL'//new_line('a')//'*LOAD, NAME=tip, TYPE=FORCE'//new_line('a')// &
         itoa(tip)//', Y, 100.0'//new_line('a')//'*STEP, NAME=load'//new_line('a')//'tip, 1.0')
      call run_plate(deck, model, problem, f, error)
      if (allocated(error)) return
      call tip_values(model, problem, f, tip, w, theta, q0, m0)
      write (*, '(a,i0,a,4es23.15)') '        tip load, ', nen, '-node: w, theta, Q(0), M(0) ', &
         w, theta, q0, m0
      call check_close(error, w, P*L**3/(3.0_wp*EI) + P*L/GAS, tol, 'tip deflection')
      if (.not. allocated(error)) call check_close(error, theta, P*L**2/(2.0_wp*EI), tol, &
         'tip rotation')
      if (.not. allocated(error)) call check_close(error, q0, P, tol, 'Q at the support')
      if (.not. allocated(error)) call check_close(error, m0, P*L, tol, 'M at the support')
   end subroutine tip_case

   !> Uniform load q (PLATE_LOAD, -y): w = q L^4 / 8EI + q L^2 / 2GAs, theta = q L^3 / 6EI,
   !> M(0) = q L^2 / 2, Q(0) = q L (signs with q < 0). The linked 2-node element is exact at
   !> the nodes (its shape functions solve the homogeneous beam: Tong's theorem).
   subroutine test_uniform2(error)
      type(error_t), allocatable, intent(out) :: error
      call uniform_case(2, EXACT, error)
   end subroutine test_uniform2

   !> The 3-node element is not exact under a uniform load (w is quartic): 0.1 % on 10
   !> elements (measured 4e-11 on the deflection and the support moment: it is exact at
   !> the nodes in practice; not exact in theory, so no round-off bound can be derived:
   !> 0.1 % is the bound this suite gives an element that is not exact, as test_thin's).
   subroutine test_uniform3(error)
      type(error_t), allocatable, intent(out) :: error
      call uniform_case(3, 1.0e-3_wp, error)
   end subroutine test_uniform3

   subroutine uniform_case(nen, tol, error)
      integer, intent(in) :: nen
      real(wp), intent(in) :: tol
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: Q = -10.0_wp
      type(model_t) :: model
      type(problem_t) :: problem
      type(plate_fields_t) :: f
      character(len=:), allocatable :: deck
      real(wp) :: w, theta, q0, m0
      integer :: tip
      deck = OUT//'uniform'//itoa(nen)//'.inp'
      tip = 10*(nen - 1) + 1
      call write_beam(deck, 10, nen, L, 'EA=1.0e7, EI=1.0e5', '*BOUNDARY'//new_line('a')// &
         '1, ALL'//new_line('a')//'*LOAD, NAME=q, TYPE=PLATE_LOAD'//new_line('a')// &
         'beam, 0.0, -10.0'//new_line('a')//'*STEP, NAME=load'//new_line('a')//'q, 1.0')
      call run_plate(deck, model, problem, f, error)
      if (allocated(error)) return
      call tip_values(model, problem, f, tip, w, theta, q0, m0)
      write (*, '(a,i0,a,4es23.15)') '        uniform load, ', nen, &
         '-node: w, theta, Q(0), M(0) ', w, theta, q0, m0
      call check_close(error, w, Q*L**4/(8.0_wp*EI) + Q*L**2/(2.0_wp*GAS), tol, 'tip deflection')
      if (.not. allocated(error)) call check_close(error, theta, Q*L**3/(6.0_wp*EI), tol, &
         'tip rotation')
      if (.not. allocated(error)) call check_close(error, q0, Q*L, tol, 'Q at the support')
      if (.not. allocated(error)) call check_close(error, m0, Q*L**2/2.0_wp, tol, &
         'M at the support')
   end subroutine uniform_case

   !> L/t = 1000 (t = 0.01, E = 2e8: EA = E t, EI = E t^3 / 12), 10 elements, tip load:
   !> within 0.1 % of Euler-Bernoulli P L^3 / 3EI (the shear part is 1e-6 of it); a locking
   !> element would be stiffer by orders of magnitude.
   subroutine test_thin(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: E = 2.0e8_wp, T = 0.01_wp, P = 1.0e-3_wp
      type(model_t) :: model
      type(problem_t) :: problem
      type(plate_fields_t) :: f
      character(len=:), allocatable :: deck, section
      character(len=40) :: a, b
      integer :: nen, tip
      write (a, '(es22.15)') E*T
      write (b, '(es22.15)') E*T**3/12.0_wp
      section = 'EA='//trim(adjustl(a))//', EI='//trim(adjustl(b))
      do nen = 2, 3
         deck = OUT//'thin'//itoa(nen)//'.inp'
         tip = 10*(nen - 1) + 1
         call write_beam(deck, 10, nen, L, section, '*BOUNDARY'//new_line('a')//'1, ALL'// &
            new_line('a')//'*LOAD, NAME=tip, TYPE=FORCE'//new_line('a')//itoa(tip)// &
            ', Y, 1.0e-3'//new_line('a')//'*STEP, NAME=load'//new_line('a')//'tip, 1.0')
         call run_plate(deck, model, problem, f, error)
         if (allocated(error)) return
         write (*, '(a,i0,a,es23.15,a,es23.15)') '        thin beam, ', nen, '-node: w ', &
            problem%state%u(2, tip), ' Euler-Bernoulli ', P*L**3/(3.0_wp*E*T**3/12.0_wp)
         call check_close(error, problem%state%u(2, tip), P*L**3/(3.0_wp*E*T**3/12.0_wp), &
            1.0e-3_wp, 'thin beam tip deflection, '//itoa(nen)//'-node')
         if (allocated(error)) return
      end do
   end subroutine test_thin

   !> Axisymmetric cylinder R = 5, t = 0.1, E = 2e7, nu = 0.3, free ends (N_s = 0), internal
   !> pressure p (PLATE_LOAD along +r): u_r = p R^2 / (E t) exactly (with N_s = 0 the hoop
   !> force p R = A (1 - nu^2) eps_theta = E t u_r / R: no nu term), the rotation zero.
   !> 1e-6: the 1/r of the shell varies by t/R over nothing here (r constant): roundoff.
   subroutine test_cylinder(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: R = 5.0_wp, T = 0.1_wp, E = 2.0e7_wp, P = 10.0_wp
      type(model_t) :: model
      type(problem_t) :: problem
      type(plate_fields_t) :: f
      character(len=:), allocatable :: deck
      character(len=40) :: a, b
      integer :: u, i
      deck = OUT//'cylinder.inp'
      call make_directories(OUT)
      write (a, '(es22.15)') E*T
      write (b, '(es22.15)') E*T**3/12.0_wp
      open (newunit=u, file=deck, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'cylinder', '*ANALYSIS, TYPE=AXISYMMETRIC', '*NODES'
      do i = 0, 20
         write (u, '(i0,a,es24.16,a,es24.16)') i + 1, ', ', R, ', ', 20.0_wp*i/20
      end do
      write (u, '(a)') '*NSET, NAME=shell, GENERATE', '1, 21, 1', &
         '*PLATE, SET=shell, NODES=shell, NU=0.3, EA='//trim(adjustl(a))//', EI='// &
         trim(adjustl(b)), '*BOUNDARY', '1, Z', '*LOAD, NAME=p, TYPE=PLATE_LOAD', &
         'shell, 10.0, 0.0', '*STEP, NAME=load', 'p, 1.0'
      close (u)
      call run_plate(deck, model, problem, f, error)
      if (allocated(error)) return
      write (*, '(a,2es23.15)') '        cylinder: u_r at mid height, p R^2 / (E t) ', &
         problem%state%u(1, 11), P*R**2/(E*T)
      do i = 1, 21
         call check_close(error, problem%state%u(1, i), P*R**2/(E*T), 1.0e-6_wp, &
            'radial displacement of node '//itoa(i))
         if (allocated(error)) return
      end do
   end subroutine test_cylinder

   !> Hetényi: an infinite beam on a Winkler foundation k under a point load P: deflection
   !> P beta / 2k and moment P / 4 beta under the load, beta = (k / 4 EI)^(1/4). A beam of
   !> length 40 (beta L / 2 = 8: the ends' influence e^-8 ~ 3e-4), 320 elements (beta h = 0.05:
   !> the springs lumped at the nodes err by ~(beta h)^2), EA = 1e8 (shear flexibility
   !> EI beta^2 / GAs = 4e-4 of the deflection), spring joints (elastic law, KN = k) to held
   !> nodes under the plate: within 1 %.
   subroutine test_hetenyi(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: K = 1.0e4_wp, P = 100.0_wp, LB = 40.0_wp
      integer, parameter :: N = 320
      type(model_t) :: model
      type(problem_t) :: problem
      type(plate_fields_t) :: f
      character(len=:), allocatable :: deck
      real(wp) :: beta, w0, m0
      integer :: u, i, mid
      deck = OUT//'hetenyi.inp'
      call make_directories(OUT)
      mid = N/2 + 1
      open (newunit=u, file=deck, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'beam on Winkler springs', '*NODES'
      do i = 0, N
         write (u, '(i0,a,es24.16,a)') i + 1, ', ', LB*i/N - LB/2, ', 0.0'
         write (u, '(i0,a,es24.16,a)') N + 2 + i, ', ', LB*i/N - LB/2, ', 0.0'
      end do
      write (u, '(a)') '*NSET, NAME=beam, GENERATE', '1, '//itoa(N + 1)//', 1', &
         '*NSET, NAME=ground, GENERATE', itoa(N + 2)//', '//itoa(2*N + 2)//', 1', &
         '*PLATE, SET=beam, NODES=beam, EA=1.0e8, EI=1.0e5', &
         '*INTERFACE_LAW, NAME=winkler, TYPE=ELASTIC', 'KN = 1.0e4, KT = 1.0', &
         '*JOINTS, TYPE=SPRING, SET=springs, LAW=winkler, ANGLE=180'
      do i = 0, N
         write (u, '(i0,a,i0,a,i0)') 1000 + i, ', ', i + 1, ', ', N + 2 + i
      end do
      write (u, '(a)') '*BOUNDARY', 'ground, XY', itoa(mid)//', X', &
         '*LOAD, NAME=p, TYPE=FORCE', itoa(mid)//', Y, -100.0', '*STEP, NAME=load', 'p, 1.0'
      close (u)
      call run_plate(deck, model, problem, f, error)
      if (allocated(error)) return
      beta = (K/(4.0_wp*1.0e5_wp))**0.25_wp
      ! internal numbers follow the *NODES lines (beam and ground nodes alternate)
      i = findloc(model%mesh%node_id, mid, 1)
      w0 = -problem%state%u(2, i)
      m0 = f%node_forces(3, findloc(f%node_index, i, 1))
      write (*, '(a,4es23.15)') '        Hetenyi: w0, closed form, M0, closed form ', w0, &
         P*beta/(2.0_wp*K), m0, P/(4.0_wp*beta)
      call check_close(error, w0, P*beta/(2.0_wp*K), 1.0e-2_wp, 'deflection under the load')
      if (.not. allocated(error)) call check_close(error, m0, P/(4.0_wp*beta), 1.0e-2_wp, &
         'moment under the load')
   end subroutine test_hetenyi

   !> Fixed-fixed beam with Mp = 100 under a uniform load, arc-length past the collapse load
   !> q_c = 16 Mp / L^2 = 16: the run stops with 'limit load' (the existing limit detection)
   !> within 1 % of q_c on 20 elements. The hinges form at the element ends (nodes 1, 11, 21:
   !> the exact mechanism), the consistent loads' end moments cancel at interior nodes and are
   !> held at the clamps, so the only departure is the arc-length limit detection's own
   !> (measured 16.0003).
   subroutine test_hinge(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: QC = 16.0_wp
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp) :: q
      integer :: n, code
      character(len=:), allocatable :: deck
      n = 20
      deck = OUT//'hinge'//itoa(n)//'.inp'
      call write_beam(deck, n, 2, L, 'EA=1.0e7, EI=1.0e5, MP=100.0', '*BOUNDARY'// &
         new_line('a')//'1, ALL'//new_line('a')//itoa(n + 1)//', ALL'//new_line('a')// &
         '*LOAD, NAME=q, TYPE=PLATE_LOAD'//new_line('a')//'beam, 0.0, -1.0'//new_line('a')// &
         '*STEP, NAME=collapse, INCREMENTS=20, CONTROL=ARC_LENGTH, MAX_INCREMENTS=200'// &
         new_line('a')//'q, 20.0')
      code = run_deck(deck, OUT//'hinge'//itoa(n)//'.h5', .true., model, problem)
      if (code /= 3) then
         call fatal_error(error, 'fixed-fixed beam: exit code '//itoa(code)// &
            ' (3: stopped at the limit load)')
         return
      end if
      q = problem%position%arc%res%peak_factors(1)
      write (*, '(a,i0,a,es23.15)') '        plastic hinge, ', n, ' elements: limit q ', q
      call check_close(error, q, QC, 1.0e-2_wp, 'collapse load 16 Mp / L^2')
   end subroutine test_hinge

   !> The consistent tangents of the end hinges (dq/dv) and of the point section (ds/de) against
   !> central differences, at states with N and M both yielding (Np = 1e3, Mp = 1e2): step
   !> 1e-7 of the deformation, the differences' truncation O(step^2) and roundoff eps/step
   !> ~ 1e-9 of the entries: agreement to 1e-5 relative to the largest entry.
   subroutine test_tangents_fd(error)
      type(error_t), allocatable, intent(out) :: error
      type(plate_section_t) :: sec
      real(wp) :: kb(3, 3), v(3), vp0(3), q(3), vp(3), dl(2), kalg(3, 3), qp(3), qm(3), fd(3, 3)
      real(wp) :: s0(NGEN), de(NGEN), h0(NHIST), s(NGEN), h(NHIST), c(NGEN, NGEN), sp(NGEN)
      real(wp) :: sm(NGEN), fdc(NGEN, NGEN), step, dv(3), dd(NGEN)
      integer :: i
      sec%ea = 1.0e6_wp
      sec%ei = 1.0e4_wp
      sec%nu = 0.2_wp
      sec%np = 1.0e3_wp
      sec%mp = 1.0e2_wp
      kb = hinge_stiffness(sec, 0.5_wp)
      v = [4.0e-4_wp, 6.0e-3_wp, -1.0e-3_wp]
      vp0 = [1.0e-5_wp, 2.0e-4_wp, 0.0_wp]
      call hinge_update(sec, kb, v, vp0, q, vp, dl, kalg, error)
      if (allocated(error)) return
      write (*, '(a,3es12.4,a,2es12.4)') '        hinge state q ', q, ' dl ', dl
      call check(error, any(dl > 0.0_wp), 'the hinge state is plastic')
      if (allocated(error)) return
      do i = 1, 3
         step = 1.0e-7_wp*max(maxval(abs(v)), 1.0e-12_wp)
         dv = 0.0_wp
         dv(i) = step
         call hinge_update(sec, kb, v + dv, vp0, qp, vp, dl, kalg, error)
         if (.not. allocated(error)) call hinge_update(sec, kb, v - dv, vp0, qm, vp, dl, kalg, error)
         if (allocated(error)) return
         fd(:, i) = (qp - qm)/(2.0_wp*step)
      end do
      call hinge_update(sec, kb, v, vp0, q, vp, dl, kalg, error)
      write (*, '(a,es10.2)') '        hinge tangent: max |kalg - fd| / max |kalg| ', &
         maxval(abs(kalg - fd))/maxval(abs(kalg))
      call check(error, maxval(abs(kalg - fd)) <= 1.0e-5_wp*maxval(abs(kalg)), &
         'hinge tangent against central differences')
      if (allocated(error)) return
      s0 = 0.0_wp
      h0 = 0.0_wp
      de = [8.0e-4_wp, 1.0e-4_wp, 1.2e-2_wp, 0.0_wp, 0.0_wp]
      call section_update(sec, .false., s0, de, h0, s, h, c, error)
      if (allocated(error)) return
      do i = 1, 3
         step = 1.0e-7_wp*maxval(abs(de))
         dd = 0.0_wp
         dd(i) = step
         call section_update(sec, .false., s0, de + dd, h0, sp, h, c, error)
         if (.not. allocated(error)) call section_update(sec, .false., s0, de - dd, h0, sm, h, &
            c, error)
         if (allocated(error)) return
         fdc(:, i) = (sp - sm)/(2.0_wp*step)
      end do
      call section_update(sec, .false., s0, de, h0, s, h, c, error)
      write (*, '(a,es10.2)') '        section tangent: max |C - fd| / max |C| ', &
         maxval(abs(c(1:3, 1:3) - fdc(1:3, 1:3)))/maxval(abs(c(1:3, 1:3)))
      call check(error, h(3) > 0.0_wp .and. maxval(abs(c(1:3, 1:3) - fdc(1:3, 1:3))) <= &
         1.0e-5_wp*maxval(abs(c(1:3, 1:3))), 'section tangent against central differences')
   end subroutine test_tangents_fd

   !> A plate on the top edge of a Q4 block: rotation equations only at its nodes, each right
   !> after the node's translations; the same block without the plate: one column per node,
   !> two equations per free node (the numbering of a deck without plates).
   subroutine test_dof_map(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code, i, c, u, k
      character(len=*), parameter :: BLOCK = '*NODES'//new_line('a')//'1, 0, 0'// &
         new_line('a')//'2, 1, 0'//new_line('a')//'3, 2, 0'//new_line('a')//'4, 0, 1'// &
         new_line('a')//'5, 1, 1'//new_line('a')//'6, 2, 1'//new_line('a')// &
         '*ELEMENTS, TYPE=Q4, SET=soil'//new_line('a')//'1, 1, 2, 5, 4'//new_line('a')// &
         '2, 2, 3, 6, 5'//new_line('a')//'*MATERIAL, NAME=m'//new_line('a')// &
         'E = 1e4, NU = 0.3'//new_line('a')//'*SECTION, SET=soil, MATERIAL=m'//new_line('a')// &
         '*BOUNDARY'//new_line('a')//'1, XY'//new_line('a')//'2, XY'//new_line('a')// &
         '3, XY'//new_line('a')//'*LOAD, NAME=top, TYPE=FORCE'//new_line('a')// &
         '5, Y, -1.0'//new_line('a')//'*STEP, NAME=load'//new_line('a')//'top, 1.0'
      call make_directories(OUT)
      do k = 1, 2
         open (newunit=u, file=OUT//'dofmap'//itoa(k)//'.inp', status='replace', &
            action='write')
         write (u, '(a)') BLOCK
         if (k == 2) write (u, '(a)') '*NSET, NAME=top', '4, 5, 6', &
            '*PLATE, SET=cap, NODES=top, EA=1e5, EI=1e2'
         close (u)
         code = run_deck(OUT//'dofmap'//itoa(k)//'.inp', OUT//'dofmap'//itoa(k)//'.h5', .true., &
            model, problem)
         if (code /= 0) then
            call fatal_error(error, 'dof map deck '//itoa(k)//': exit code '//itoa(code))
            return
         end if
         associate (d => problem%system%dofs)
            if (k == 1) then
               call check(error, nodal_columns(model) == 6 .and. d%neq == 6 .and. &
                  all(d%eq(:, 4:6) == reshape([1, 2, 3, 4, 5, 6], [2, 3])), &
                  'no plate: 2 equations per free node, numbered node by node')
            else
               call check(error, rotation_count(model) == 3 .and. nodal_columns(model) == 9 &
                  .and. d%neq == 9, 'plate on 3 nodes: 3 rotations, 9 equations')
               if (allocated(error)) return
               do i = 4, 6
                  c = rotation_column(model, i)
                  call check(error, d%eq(1, c) == d%eq(2, i) + 1 .and. d%eq(2, c) == 0, &
                     'rotation equation of node '//itoa(i)//' after its translations')
                  if (allocated(error)) return
               end do
               call check(error, all([(rotation_column(model, i), i=1, 3)] == 0), &
                  'no rotation on the nodes without plate')
            end if
         end associate
         if (allocated(error)) return
      end do
   end subroutine test_dof_map

   !> A cantilever activated in step 2 (loaded in step 3): the run stopped after step 2 and
   !> restarted gives the uninterrupted run's displacements and rotations (roundoff: the
   !> restart carries the converged state to the last bit; 1e-12 relative).
   subroutine test_restart(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: whole, resumed
      character(len=:), allocatable :: deck
      integer :: code, i
      deck = OUT//'restart.inp'
      call write_beam(deck, 10, 2, L, 'EA=1.0e7, EI=1.0e5', '*BOUNDARY'//new_line('a')// &
         '1, ALL'//new_line('a')//'*LOAD, NAME=tip, TYPE=FORCE'//new_line('a')// &
         '11, Y, 100.0'//new_line('a')//'*STEP, NAME=nothing, INCREMENTS=1'//new_line('a')// &
         '*DEACTIVATE'//new_line('a')//'beam'//new_line('a')// &
         '*STEP, NAME=install, INCREMENTS=1'//new_line('a')//'*ACTIVATE'//new_line('a')// &
         'beam'//new_line('a')//'*STEP, NAME=load, INCREMENTS=2'//new_line('a')//'tip, 1.0')
      code = run_deck(deck, OUT//'restart_whole.h5', .true., model, whole)
      if (code /= 0) then
         call fatal_error(error, 'restart deck: exit code '//itoa(code))
         return
      end if
      code = run_deck(deck, OUT//'restart_part.h5', .true., model, resumed, stop_after=2)
      code = run_deck(deck, OUT//'restart_resumed.h5', .true., model, resumed, &
         restart=OUT//'restart_part.h5')
      if (code /= 0) then
         call fatal_error(error, 'restarted run: exit code '//itoa(code))
         return
      end if
      write (*, '(a,2es23.15)') '        restart: tip w whole, resumed ', whole%state%u(2, 11), &
         resumed%state%u(2, 11)
      call check_close(error, whole%state%u(2, 11), P_TIP(), 1.0e-10_wp, &
         'tip deflection after the plate is installed')
      if (allocated(error)) return
      do i = 1, size(whole%state%u, 2)
         call check_close(error, resumed%state%u(1, i), whole%state%u(1, i), 1.0e-12_wp, &
            'restarted column '//itoa(i), 1.0e-14_wp)
         if (allocated(error)) return
      end do
   contains
      pure real(wp) function P_TIP()
         P_TIP = 100.0_wp*L**3/(3.0_wp*EI) + 100.0_wp*L/GAS
      end function P_TIP
   end subroutine test_restart

   !> Bad plate decks: exit 2 at the reader, the message naming file:line.
   subroutine test_bad_decks(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: NODES = '*NODES'//new_line('a')//'1, 0, 0'// &
         new_line('a')//'2, 1, 0'//new_line('a')//'3, 2, 0'//new_line('a')// &
         '*NSET, NAME=line'//new_line('a')//'1, 2, 3'//new_line('a')
      character(len=*), parameter :: TAIL = new_line('a')//'*BOUNDARY'//new_line('a')// &
         '1, ALL'//new_line('a')//'*STEP, NAME=s'
      call bad(NODES//'*PLATE, SET=p, NODES=line, EA=1e5, EI=0'//TAIL, 'bad_ei', 7, &
         'EI must be positive', error)
      if (.not. allocated(error)) call bad(NODES//'*PLATE, SET=p, NODES=line, EA=-1, EI=1'// &
         TAIL, 'bad_ea', 7, 'EA must be positive', error)
      if (.not. allocated(error)) call bad(NODES//'*PLATE, SET=p, NODES=nowhere, EA=1, EI=1'// &
         TAIL, 'unknown_set', 7, "undefined node set 'nowhere'", error)
      if (.not. allocated(error)) call bad(NODES//'*PLATE, SET=p, NODES=line, EA=1, EI=1'// &
         new_line('a')//'*BOUNDARY'//new_line('a')//'1, ALL'//new_line('a')//'*NODES'// &
         new_line('a')//'4, 0, 1'//new_line('a')//'5, 1, 1'//new_line('a')// &
         '*ELEMENTS, TYPE=Q4, SET=s'//new_line('a')//'1, 1, 2, 5, 4'//new_line('a')// &
         '*MATERIAL, NAME=m'//new_line('a')//'E = 1, NU = 0'//new_line('a')// &
         '*SECTION, SET=s, MATERIAL=m'//new_line('a')//'*STEP, NAME=s', 'not_on_line', 7, &
         'is not on a line', error)
      if (.not. allocated(error)) call bad(NODES//'*PLATE, SET=p, NODES=line, EA=1, EI=1'// &
         new_line('a')//'*NODES'//new_line('a')//'9, 5, 5'//new_line('a')//'*BOUNDARY'// &
         new_line('a')//'9, ROT'//new_line('a')//'*STEP, NAME=s', 'rot_no_plate', 11, &
         'carries no rotation', error)
   end subroutine test_bad_decks

   !> Writes `text` to OUT//name//'.inp', reads it: an input error (exit 2) at `line`
   !> whose message holds `words`.
   subroutine bad(text, name, line, words, error)
      character(len=*), intent(in) :: text, name, words
      integer, intent(in) :: line
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(error_t), allocatable :: err
      character(len=:), allocatable :: path, msg
      integer :: u
      call make_directories(OUT)
      path = OUT//name//'.inp'
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') text
      close (u)
      call read_deck(path, model, err)
      if (.not. allocated(err)) then
         call fatal_error(error, name//': read without error')
         return
      end if
      msg = err%text()
      write (*, '(a)') '        '//name//': '//msg
      call check(error, err%exit_code() == 2 .and. index(msg, path//':'//itoa(line)) > 0 .and. &
         index(msg, words) > 0, name//': expected exit 2 at '//path//':'//itoa(line)// &
         ' with "'//words//'", got: '//msg)
   end subroutine bad

end module test_plates
