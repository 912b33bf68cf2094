!> Phases (staged construction, doc/theory.md Phases): excavation of a K0 column against the
!> oedometric closed form, whatever the number of phases and increments; add-then-remove
!> returns the state; a nil step on a horizontal K0 ground inside the yield surface does not
!> move it; material changes inside and outside the yield surface; equilibrium of a 2-D
!> Mohr–Coulomb excavation; bad phase decks stop with file:line and write nothing.
module test_phases
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_massif_element_matrices, only: massif_gauss_coordinates
   use pecplas_fe_assembly, only: internal_forces
   use pecplas_base_strings, only: itoa
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_bad_decks, only: check_refused
   use fixtures_runs, only: read_text, write_text
   implicit none (type, external)
   private
   public :: collect_phases
   ! (shared with test_phases_switch)
   public :: write_column, write_block, oedometric, H, GAMMA, K0, E, NU, ELASTIC

   real(wp), parameter :: H = 10.0_wp, GAMMA = 20.0_wp, K0 = 0.5_wp, E = 3.0e4_wp, NU = 0.25_wp
   character(len=*), parameter :: OUT = 'build/test_out/phases/'
   character(len=*), parameter :: ELASTIC = '*MATERIAL, NAME=soil'//new_line('a')// &
      'E = 3e4, NU = 0.25, GAMMA = 20'
   character(len=*), parameter :: MC = '*MATERIAL, NAME=soil, TYPE=MOHR_COULOMB'// &
      new_line('a')//'E = 3e4, NU = 0.25, GAMMA = 20, C = 0, PHI = 30, PSI = 0'

contains

   subroutine collect_phases(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('column_excavation_exact', test_column_exact), &
               new_unittest('column_excavation_paths', test_column_paths), &
               new_unittest('add_then_remove', test_add_remove), &
               new_unittest('nil_step_horizontal_mc', test_nil_horizontal), &
               new_unittest('nil_step_slope', test_nil_slope), &
               new_unittest('material_change_inside_yield', test_material_inside), &
               new_unittest('material_change_outside_yield', test_material_outside), &
               new_unittest('excavation_mc_equilibrium', test_mc_equilibrium), &
               new_unittest('restart_in_phase_two', test_restart), &
               new_unittest('change_law', test_change_law), &
               new_unittest('increment_methods', test_methods), &
               new_unittest('arc_length_phase', test_arc_length), &
               new_unittest('katona_off_and_on', test_katona), &
               new_unittest('bad_decks', test_bad_decks)]
   end subroutine collect_phases

   !> A column of nel Q4 elements (width 1, height H, base at y = 0, sides on rollers) under
   !> a geostatic state (surface y = H, K0), the top ntop elements each a set t1 (top) ...
   !> tn, the rest set 'rest'. Each phase k deactivates the next groups(k) sets from the
   !> top in `increments` increments. `material`: the *MATERIAL lines; `steps`: replaces the
   !> generated steps when given.
   subroutine write_column(path, nel, ntop, groups, increments, material, steps, tolerance)
      character(len=*), intent(in) :: path
      integer, intent(in) :: nel, ntop, groups(:), increments
      character(len=*), intent(in) :: material
      character(len=*), intent(in), optional :: steps
      real(wp), intent(in), optional :: tolerance
      integer :: u, i, k, g, next
      real(wp) :: dy
      character(len=32) :: buf
      dy = H/nel
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'K0 column, phases', '*NODES'
      do i = 0, nel
         write (u, '(i0,a,es23.16)') 2*i + 1, ', 0.0, ', i*dy
         write (u, '(i0,a,es23.16)') 2*i + 2, ', 1.0, ', i*dy
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=rest'
      do i = 1, nel - ntop
         write (u, '(i0,4(", ",i0))') i, 2*i - 1, 2*i, 2*i + 2, 2*i + 1
      end do
      do k = 1, ntop
         i = nel - k + 1
         write (u, '(a,i0)') '*ELEMENTS, TYPE=Q4, SET=t', k
         write (u, '(i0,4(", ",i0))') i, 2*i - 1, 2*i, 2*i + 2, 2*i + 1
      end do
      write (u, '(a)') material
      write (u, '(a)') '*SECTION, SET=rest, MATERIAL=soil'
      do k = 1, ntop
         write (u, '(a,i0,a)') '*SECTION, SET=t', k, ', MATERIAL=soil'
      end do
      write (u, '(a)') '*NSET, NAME=base', '1, 2', '*NSET, NAME=sides, GENERATE'
      write (u, '(a,i0)') '1, ', 2*nel + 2
      write (u, '(a)') '*BOUNDARY', 'base, XY', 'sides, X'
      write (u, '(a)') '*INITIAL_STRESS, TYPE=GEOSTATIC'
      write (buf, '(es23.16)') K0
      write (u, '(a)') 'ALL, 10.0, '//trim(adjustl(buf))
      if (present(tolerance)) then
         write (buf, '(es10.3)') tolerance
         write (u, '(a)') '*SOLVER, TOLERANCE='//trim(adjustl(buf))
      end if
      if (present(steps)) then
         write (u, '(a)') steps
      else
         next = 1
         do k = 1, size(groups)
            write (u, '(a,i0,a,i0)') '*STEP, NAME=dig', k, ', INCREMENTS=', increments
            write (u, '(a)') '*DEACTIVATE'
            do g = 1, groups(k)
               write (u, '(a,i0)') 't', next
               next = next + 1
            end do
         end do
      end if
      close (u)
   end subroutine write_column

   !> Oedometric modulus.
   pure real(wp) function oedometric() result(m)
      m = E*(1.0_wp - NU)/((1.0_wp + NU)*(1.0_wp - 2.0_wp*NU))
   end function oedometric

   !> The top h = 2.5 of a 40-element column removed in one phase, one increment: every
   !> remaining node heaves gamma h y / M (the uniform oedometric unloading by gamma h, which
   !> Q4 elements represent exactly) and the stresses are the geostatic ones less gamma h
   !> vertically and nu/(1 - nu) gamma h horizontally. Round-off bound: 1e-10 of the scale.
   subroutine test_column_exact(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp) :: hdig, m, worst, xg(2, 4), sv, expect(4), scale
      integer :: code, n, el, g
      call make_directories(OUT)
      call write_column(OUT//'column1.inp', 40, 10, [10], 1, ELASTIC)
      code = run_deck(OUT//'column1.inp', OUT//'column1.h5', .true., model, problem)
      call check(error, code == 0, 'column excavation runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      hdig = 2.5_wp
      m = oedometric()
      scale = GAMMA*hdig*H/m
      worst = 0.0_wp
      do n = 1, 2*31
         worst = max(worst, abs(problem%state%u(2, n) - GAMMA*hdig*model%mesh%x(2, n)/m))
         worst = max(worst, abs(problem%state%u(1, n)))
      end do
      call check_close(error, worst, 0.0_wp, 0.0_wp, 'heave = gamma h y / M', atol=1.0e-10_wp*scale)
      if (allocated(error)) return
      worst = 0.0_wp
      associate (set => model%mesh%esets(1), st => problem%state%sets(1))
         do el = 1, size(set%conn, 2)
            call massif_gauss_coordinates(problem%system%rules(1), model%mesh%x(:, set%conn(:, el)), xg)
            do g = 1, 4
               sv = GAMMA*(H - xg(2, g))
               expect = [-K0*sv + NU/(1.0_wp - NU)*GAMMA*hdig, -sv + GAMMA*hdig, &
                  -K0*sv + NU/(1.0_wp - NU)*GAMMA*hdig, 0.0_wp]
               worst = max(worst, maxval(abs(st%stress(:, g, el) - expect)))
            end do
         end do
      end associate
      call check_close(error, worst, 0.0_wp, 0.0_wp, 'stresses = geostatic - gamma h (oedometric)', &
         atol=1.0e-10_wp*GAMMA*H)
   end subroutine test_column_exact

   !> The same removal in 3 and 10 phases, and in one phase of 20 increments: the same end
   !> state as one phase of one increment (elastic: the end state does not depend on the
   !> path), to 1e-10 of the heave and of gamma H.
   subroutine test_column_paths(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: ref, other
      real(wp) :: m, du, ds
      integer :: code, v
      character(len=*), parameter :: names(3) = [character(len=8) :: 'three', 'ten', 'twenty']
      call make_directories(OUT)
      call write_column(OUT//'path_ref.inp', 40, 10, [10], 1, ELASTIC)
      code = run_deck(OUT//'path_ref.inp', OUT//'path_ref.h5', .true., model, ref)
      call check(error, code == 0, 'one phase runs')
      if (allocated(error)) return
      m = oedometric()
      do v = 1, 3
         select case (v)
         case (1)
            call write_column(OUT//'path_'//trim(names(v))//'.inp', 40, 10, [3, 3, 4], 1, ELASTIC)
         case (2)
            call write_column(OUT//'path_'//trim(names(v))//'.inp', 40, 10, [1, 1, 1, 1, 1, 1, 1, &
               1, 1, 1], 1, ELASTIC)
         case (3)
            call write_column(OUT//'path_'//trim(names(v))//'.inp', 40, 10, [10], 20, ELASTIC)
         end select
         code = run_deck(OUT//'path_'//trim(names(v))//'.inp', OUT//'path_'//trim(names(v))// &
            '.h5', .true., model, other)
         call check(error, code == 0, trim(names(v))//' runs')
         if (allocated(error)) return
         ! the remaining column (the removed nodes keep the displacement they had)
         du = maxval(abs(other%state%u(:, 1:62) - ref%state%u(:, 1:62)))
         ds = maxval(abs(other%state%sets(1)%stress - ref%state%sets(1)%stress))
         call check_close(error, du, 0.0_wp, 0.0_wp, trim(names(v))//': displacements', &
            atol=1.0e-10_wp*GAMMA*2.5_wp*H/m)
         if (allocated(error)) return
         call check_close(error, ds, 0.0_wp, 0.0_wp, trim(names(v))//': stresses', &
            atol=1.0e-10_wp*GAMMA*H)
         if (allocated(error)) return
      end do
   end subroutine test_column_paths

   !> A layer activated stress-free on top of the K0 column (it loads it with its weight),
   !> then removed: the column returns to the state before (displacements and stresses), to
   !> 1e-10 of the settlement the layer caused and of gamma H. (The geostatic surface is the
   !> top of the layer: a nil step first brings the column below to equilibrium without it.)
   subroutine test_add_remove(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem, start
      real(wp) :: du, ds
      integer :: code
      call make_directories(OUT)
      ! 't1' (the top element, y 9.75..10) is activated by step 2: inactive before
      call write_column(OUT//'add_remove.inp', 40, 1, [1], 1, ELASTIC, steps= &
         '*STEP, NAME=nil'//new_line('a')// &
         '*STEP, NAME=build, INCREMENTS=2'//new_line('a')//'*ACTIVATE'//new_line('a')//'t1'// &
         new_line('a')//'*STEP, NAME=remove, INCREMENTS=3'//new_line('a')//'*DEACTIVATE'// &
         new_line('a')//'t1')
      code = run_deck(OUT//'add_remove.inp', OUT//'add_remove.h5', .true., model, start, &
         stop_after=1)
      call check(error, code == 4, 'nil step runs')
      if (allocated(error)) return
      code = run_deck(OUT//'add_remove.inp', OUT//'add_remove.h5', .true., model, problem, &
         stop_after=3)
      call check(error, code == 4, 'add runs')
      if (allocated(error)) return
      du = maxval(abs(problem%state%u(:, 1:80) - start%state%u(:, 1:80)))
      call check(error, du > 0.0_wp, 'the added layer settles the column')
      if (allocated(error)) return
      code = run_deck(OUT//'add_remove.inp', OUT//'add_remove.h5', .true., model, problem)
      call check(error, code == 0, 'add then remove runs')
      if (allocated(error)) return
      ! the column (the removed element's top nodes keep the displacement they had)
      call check_close(error, maxval(abs(problem%state%u(:, 1:80) - start%state%u(:, 1:80))), &
         0.0_wp, 0.0_wp, 'displacements back to those before', atol=1.0e-10_wp*du)
      if (allocated(error)) return
      ds = maxval(abs(problem%state%sets(1)%stress - start%state%sets(1)%stress))
      call check_close(error, ds, 0.0_wp, 0.0_wp, 'stresses back to those before', &
         atol=1.0e-10_wp*GAMMA*H)
   end subroutine test_add_remove

   !> A nil step on a horizontal K0 ground (K0 = 0.5 inside the Mohr–Coulomb surface for
   !> phi = 30: Ka = 1/3): the weight balances the K0 stresses (exact quadrature of the
   !> linear stress), nothing moves: |u| <= 1e-12 of the settlement scale gamma H^2 / M.
   subroutine test_nil_horizontal(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call make_directories(OUT)
      call write_column(OUT//'nil.inp', 10, 0, [integer ::], 1, MC, steps= &
         '*STEP, NAME=nil, INCREMENTS=2')
      code = run_deck(OUT//'nil.inp', OUT//'nil.h5', .true., model, problem)
      call check(error, code == 0, 'nil step runs')
      if (allocated(error)) return
      call check_close(error, maxval(abs(problem%state%u)), 0.0_wp, 0.0_wp, &
         'nil step on a horizontal K0 ground: no displacement', &
         atol=1.0e-12_wp*GAMMA*H**2/oedometric())
   end subroutine test_nil_horizontal

   !> A nil step under a sloping surface (rising 3 over 20, the K0 state taken from the
   !> highest point, so too heavy where the ground is lower): the ground moves and ends in
   !> equilibrium with the weight of the soil (reactions = weight to the solver tolerance,
   !> as in excavation_mc_equilibrium), and the run reports it (completed).
   subroutine test_nil_slope(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), allocatable :: fint(:, :), fext(:, :)
      real(wp) :: w, ry, tol
      integer :: code
      character(len=*), parameter :: deck = OUT//'slope.inp'
      call make_directories(OUT)
      call write_pit(deck, 3.0_wp, '*STEP, NAME=nil, INCREMENTS=5')
      code = run_deck(deck, OUT//'slope.h5', .true., model, problem)
      call check(error, code == 0, 'nil step under a slope completes (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check(error, maxval(abs(problem%state%u)) > 1.0e-6_wp*18.0_wp*9.0_wp**2/3.0e4_wp, &
         'the ground moves')
      if (allocated(error)) return
      allocate (fint, mold=problem%state%u)
      call internal_forces(model, problem%system%rules, problem%state%u, problem%state, fint, &
         error)
      if (allocated(error)) return
      call problem%state%rollback()
      fext = problem%system%initial_force
      w = -sum(fext(2, :))
      ry = sum(pack(fint(2, :) - fext(2, :), problem%system%dofs%eq(2, :) == 0))
      tol = sqrt(real(problem%system%dofs%neq, wp))*1.0e-8_wp*max(w, norm2(fint - fext))
      call check_close(error, ry, w, 0.0_wp, 'vertical reactions = weight', atol=tol)
      if (allocated(error)) return
      ! the weight of the sloping block: 18 (20 x 9 + 20 x 3 / 2)
      call check_close(error, w, 18.0_wp*(180.0_wp + 30.0_wp), 1.0e-12_wp, 'weight')
   end subroutine test_nil_slope

   !> An elastic K0 phase, then the material changed to Mohr–Coulomb (phi = 30) with the K0
   !> state inside its surface: nothing moves (1e-12 of gamma H^2 / M).
   subroutine test_material_inside(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call make_directories(OUT)
      call write_column(OUT//'mat_in.inp', 10, 0, [integer ::], 1, ELASTIC//new_line('a')// &
         '*MATERIAL, NAME=mc, TYPE=MOHR_COULOMB'//new_line('a')// &
         'E = 3e4, NU = 0.25, GAMMA = 20, C = 0, PHI = 30, PSI = 0', steps= &
         '*STEP, NAME=k0'//new_line('a')//'*STEP, NAME=plastic, INCREMENTS=2'//new_line('a')// &
         '*CHANGE_MATERIAL'//new_line('a')//'rest, mc')
      code = run_deck(OUT//'mat_in.inp', OUT//'mat_in.h5', .true., model, problem)
      call check(error, code == 0, 'material change runs')
      if (allocated(error)) return
      call check(error, problem%state%sets(1)%material == 2, 'the set has the new material')
      if (allocated(error)) return
      call check_close(error, maxval(abs(problem%state%u)), 0.0_wp, 0.0_wp, &
         'inside the yield surface: no displacement', atol=1.0e-12_wp*GAMMA*H**2/oedometric())
   end subroutine test_material_inside

   !> The same with K0 = 0.5 and a Mohr–Coulomb friction angle of 45 degrees with cohesion
   !> 0 ... no: phi = 10 (Ka = 0.70 > K0 = 0.5, the K0 state violates the criterion): the
   !> plastic redistribution converges, the column settles, and every point ends on or
   !> inside the surface.
   subroutine test_material_outside(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp) :: s1, s3, worst, sinphi
      integer :: code, el, g
      call make_directories(OUT)
      call write_column(OUT//'mat_out.inp', 10, 0, [integer ::], 1, ELASTIC//new_line('a')// &
         '*MATERIAL, NAME=mc, TYPE=MOHR_COULOMB'//new_line('a')// &
         'E = 3e4, NU = 0.25, GAMMA = 20, C = 0, PHI = 10, PSI = 0', steps= &
         '*STEP, NAME=k0'//new_line('a')//'*STEP, NAME=plastic, INCREMENTS=5'//new_line('a')// &
         '*CHANGE_MATERIAL'//new_line('a')//'rest, mc', tolerance=1.0e-8_wp)
      code = run_deck(OUT//'mat_out.inp', OUT//'mat_out.h5', .true., model, problem)
      call check(error, code == 0, 'material change outside the yield surface converges')
      if (allocated(error)) return
      call check(error, minval(problem%state%u(2, :)) < 0.0_wp, 'the column settles')
      if (allocated(error)) return
      sinphi = sin(10.0_wp*acos(-1.0_wp)/180.0_wp)
      worst = 0.0_wp
      associate (st => problem%state%sets(1))
         do el = 1, size(st%stress, 3)
            do g = 1, st%ngauss
               ! plane strain, sigma_xy = 0 by symmetry: principal stresses xx, yy (zz between)
               s1 = max(st%stress(1, g, el), st%stress(2, g, el), st%stress(3, g, el))
               s3 = min(st%stress(1, g, el), st%stress(2, g, el), st%stress(3, g, el))
               ! f = (s1 - s3) + (s1 + s3) sin(phi) <= 0 (tension positive, c = 0)
               worst = max(worst, ((s1 - s3) + (s1 + s3)*sinphi)/(GAMMA*H))
            end do
         end do
      end associate
      call check(error, worst <= 1.0e-8_wp, 'every point on or inside the surface (f/(gamma H) = '// &
         trim(g10(worst))//')')
   end subroutine test_material_outside

   function g10(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=24) :: buf
      write (buf, '(es12.4)') x
      s = trim(adjustl(buf))
   end function g10

   !> A 2-D Mohr–Coulomb block under K0 with a pit dug in two phases: after each phase the
   !> vertical reactions balance the weight of the active elements to the solver tolerance:
   !> |sum R_y - W| <= sqrt(neq) tol max(W, |R|) (the residual the test admits, summed).
   subroutine test_mc_equilibrium(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), allocatable :: fint(:, :), fext(:, :)
      real(wp) :: w, ry, tol
      integer :: code, stop_at
      character(len=*), parameter :: deck = OUT//'pit.inp'
      call make_directories(OUT)
      call write_pit(deck)
      do stop_at = 4, 8, 4
         code = run_deck(deck, OUT//'pit.h5', .true., model, problem, stop_after=stop_at)
         call check(error, code == 0 .or. code == 4, 'pit runs to increment '//itoa(stop_at)// &
            ' (exit '//itoa(code)//')')
         if (allocated(error)) return
         allocate (fint, mold=problem%state%u)
         call internal_forces(model, problem%system%rules, problem%state%u, problem%state, fint, &
            error)
         if (allocated(error)) return
         call problem%state%rollback()
         fext = problem%system%initial_force
         ! the active weight (no pattern; the carried load is zero at the phase end)
         w = -sum(fext(2, :))
         ry = sum(pack(fint(2, :) - fext(2, :), problem%system%dofs%eq(2, :) == 0))
         tol = sqrt(real(problem%system%dofs%neq, wp))*1.0e-8_wp*max(w, norm2(fint - fext))
         call check_close(error, ry, w, 0.0_wp, 'phase '//itoa(stop_at/4)//': vertical '// &
            'reactions = weight of the active elements', atol=tol)
         if (allocated(error)) return
         ! the weight is that of the active elements: 18 x area
         call check_close(error, w, 18.0_wp*(20.0_wp*9.0_wp - 7.5_wp*1.5_wp*(stop_at/4)), &
            1.0e-12_wp, 'active weight')
         if (allocated(error)) return
         deallocate (fint)
      end do
   end subroutine test_mc_equilibrium

   !> A 2-D Mohr–Coulomb block 20 x 9 (8 x 6 Q4) under K0, sides on rollers, a pit of 3
   !> columns dug in two phases of 4 increments (pit1 the top row, pit2 the one below).
   subroutine write_pit(deck, slope, steps, method)
      character(len=*), intent(in) :: deck
      !> *SOLVER METHOD= (default: the deck's default, full Newton).
      character(len=*), intent(in), optional :: method
      !> Rise of the top surface from x = 0 to x = 20 (the nodes above the base follow in
      !> proportion) and the steps, replacing the two excavation phases.
      real(wp), intent(in), optional :: slope
      character(len=*), intent(in), optional :: steps
      integer :: u, i, j, nx, ny, el, s
      real(wp) :: rise
      rise = 0.0_wp
      if (present(slope)) rise = slope
      nx = 8; ny = 6
      open (newunit=u, file=deck, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'pit', '*NODES'
      do j = 0, ny
         do i = 0, nx
            write (u, '(i0,", ",f8.3,", ",f8.3)') j*(nx + 1) + i + 1, 2.5_wp*i, &
               1.5_wp*j + rise*(real(i, wp)/nx)*(real(j, wp)/ny)
         end do
      end do
      ! the pit: columns 1-3 of the top two rows; pit1 the top row, pit2 the one below
      do s = 1, 3
         select case (s)
         case (1)
            write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=soil'
         case (2)
            write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=pit2'
         case (3)
            write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=pit1'
         end select
         do j = 0, ny - 1
            do i = 0, nx - 1
               if (i < 3 .and. j == ny - 1) then
                  if (s /= 3) cycle
               else if (i < 3 .and. j == ny - 2) then
                  if (s /= 2) cycle
               else
                  if (s /= 1) cycle
               end if
               el = j*nx + i + 1
               write (u, '(i0,4(", ",i0))') el, j*(nx + 1) + i + 1, j*(nx + 1) + i + 2, &
                  (j + 1)*(nx + 1) + i + 2, (j + 1)*(nx + 1) + i + 1
            end do
         end do
      end do
      write (u, '(a)') '*MATERIAL, NAME=sand, TYPE=MOHR_COULOMB', &
         'E = 3e4, NU = 0.3, GAMMA = 18, C = 2, PHI = 30, PSI = 0', &
         '*SECTION, SET=soil, MATERIAL=sand', '*SECTION, SET=pit1, MATERIAL=sand', &
         '*SECTION, SET=pit2, MATERIAL=sand', '*NSET, NAME=base, GENERATE', '1, 9, 1', &
         '*NSET, NAME=left, GENERATE', '1, 55, 9', '*NSET, NAME=right, GENERATE', '9, 63, 9', &
         '*BOUNDARY', 'base, XY', 'left, X', 'right, X'
      if (present(method)) then
         write (u, '(a)') '*SOLVER, TOLERANCE=1e-8, METHOD='//method
      else
         write (u, '(a)') '*SOLVER, TOLERANCE=1e-8'
      end if
      write (u, '(a)') '*INITIAL_STRESS, TYPE=GEOSTATIC'
      if (present(steps)) then
         write (u, '(a,f8.3,a)') 'ALL, ', 9.0_wp + rise, ', 0.5'
         write (u, '(a)') steps
      else
         write (u, '(a)') 'ALL, 9.0, 0.5', &
            '*STEP, NAME=dig1, INCREMENTS=4', '*DEACTIVATE', 'pit1', &
            '*STEP, NAME=dig2, INCREMENTS=4', '*DEACTIVATE', 'pit2'
      end if
      close (u)
   end subroutine write_pit

   !> The pit run interrupted in its second phase (after increment 6) and restarted equals
   !> the run without interruption, to 1e-12 of its largest displacement and of gamma H
   !> (the restart carries the phase's out-of-balance and replays the phases before).
   subroutine test_restart(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: whole, resumed
      character(len=*), parameter :: deck = OUT//'pit_restart.inp'
      real(wp) :: umax
      integer :: code, s
      call make_directories(OUT)
      call write_pit(deck)
      code = run_deck(deck, OUT//'pit_whole.h5', .true., model, whole)
      call check(error, code == 0, 'pit runs')
      if (allocated(error)) return
      code = run_deck(deck, OUT//'pit_part.h5', .true., model, resumed, stop_after=6)
      call check(error, code == 4, 'pit interrupted after increment 6 (exit '//itoa(code)//')')
      if (allocated(error)) return
      code = run_deck(deck, OUT//'pit_resumed.h5', .true., model, resumed, &
         restart=OUT//'pit_part.h5')
      call check(error, code == 0, 'pit restarted (exit '//itoa(code)//')')
      if (allocated(error)) return
      umax = maxval(abs(whole%state%u))
      call check_close(error, maxval(abs(resumed%state%u - whole%state%u)), 0.0_wp, 0.0_wp, &
         'restarted = uninterrupted: displacements', atol=1.0e-12_wp*umax)
      if (allocated(error)) return
      do s = 1, size(whole%state%sets)
         if (.not. whole%state%sets(s)%active) cycle
         call check_close(error, maxval(abs(resumed%state%sets(s)%stress - &
            whole%state%sets(s)%stress)), 0.0_wp, 0.0_wp, 'restarted = uninterrupted: '// &
            'stresses of set '//itoa(s), atol=1.0e-12_wp*18.0_wp*9.0_wp)
         if (allocated(error)) return
      end do
   end subroutine test_restart

   !> *CHANGE_LAW: the S2 pile installed wished in place (input/examples/pile_wished_in_place.inp)
   !> with its shaft joints changed to another law in the installation phase, then loaded,
   !> ends as the same deck whose shaft has that law from the start (the law's history restarts
   !> from the joint stresses, as at activation): equal to 1e-12 of the head settlement.
   subroutine test_change_law(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: changed, direct
      character(len=:), allocatable :: head, body
      character(len=*), parameter :: law = '*INTERFACE_LAW, NAME=rough, TYPE=GOODMAN'// &
         new_line('a')//'KN = 2e+07, KT = 40000, PHI = 35, C = 0'
      character(len=*), parameter :: steps = '*STEP, NAME=load, INCREMENTS=10'// &
         new_line('a')//'head, 1'//new_line('a')//'*SOLVER, METHOD=NEWTON, MAX_ITERATIONS=50, '// &
         'MAX_CUTS=6'
      integer :: code, i
      real(wp) :: umax
      call make_directories(OUT)
      call read_text('input/examples/pile_wished_in_place.inp', head)
      i = index(head, new_line('a')//'*STEP')
      call check(error, i > 0, 'the example deck has steps')
      if (allocated(error)) return
      body = head(1:i)
      call write_text(OUT//'law_change.inp', body//law//new_line('a')// &
         '*STEP, NAME=install'//new_line('a')//'*ACTIVATE, STRESS=WISHED_IN_PLACE'// &
         new_line('a')//'pile'//new_line('a')//'*ACTIVATE'//new_line('a')// &
         'shaft, tip, below'//new_line('a')//'*CHANGE_LAW'//new_line('a')//'shaft, rough'// &
         new_line('a')//steps)
      i = index(body, 'SET=shaft, LAW=iface')
      call check(error, i > 0, 'the example deck has the shaft joints')
      if (allocated(error)) return
      body = body(1:i - 1)//'SET=shaft, LAW=rough'//body(i + len('SET=shaft, LAW=iface'):)
      call write_text(OUT//'law_direct.inp', body//law//new_line('a')// &
         '*STEP, NAME=install'//new_line('a')//'*ACTIVATE, STRESS=WISHED_IN_PLACE'// &
         new_line('a')//'pile'//new_line('a')//'*ACTIVATE'//new_line('a')// &
         'shaft, tip, below'//new_line('a')//steps)
      code = run_deck(OUT//'law_change.inp', OUT//'law_change.h5', .true., model, changed)
      call check(error, code == 0, 'law change runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check(error, changed%state%joints%sets(1)%law == 2, 'the shaft has the new law')
      if (allocated(error)) return
      code = run_deck(OUT//'law_direct.inp', OUT//'law_direct.h5', .true., model, direct)
      call check(error, code == 0, 'the same law from the start runs')
      if (allocated(error)) return
      umax = maxval(abs(direct%state%u))
      call check(error, umax > 0.0_wp, 'the pile moves under its load')
      if (allocated(error)) return
      call check_close(error, maxval(abs(changed%state%u - direct%state%u)), 0.0_wp, 0.0_wp, &
         'law changed at installation = law from the start', atol=1.0e-12_wp*umax)
   end subroutine test_change_law


   !> The pit dug with each increment method (quasi-Newton, full Newton) ends where modified
   !> Newton does: the carried out-of-balance is the same load for every method. The
   !> converged states differ by the residual the tolerance admits (1e-8 of the load): 1e-5 of
   !> the largest displacement is a safe bound for a plastic path of 8 increments.
   subroutine test_methods(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: ref, other
      character(len=*), parameter :: methods(2) = [character(len=12) :: 'QUASI_NEWTON', 'NEWTON']
      integer :: code, k
      real(wp) :: umax
      call make_directories(OUT)
      call write_pit(OUT//'pit_modified.inp')
      code = run_deck(OUT//'pit_modified.inp', OUT//'pit_modified.h5', .true., model, ref)
      call check(error, code == 0, 'pit (modified Newton) runs')
      if (allocated(error)) return
      umax = maxval(abs(ref%state%u))
      do k = 1, size(methods)
         call write_pit(OUT//'pit_'//trim(methods(k))//'.inp', method=trim(methods(k)))
         code = run_deck(OUT//'pit_'//trim(methods(k))//'.inp', OUT//'pit_'//trim(methods(k))// &
            '.h5', .true., model, other)
         call check(error, code == 0, 'pit ('//trim(methods(k))//') runs')
         if (allocated(error)) return
         call check_close(error, maxval(abs(other%state%u - ref%state%u)), 0.0_wp, 0.0_wp, &
            trim(methods(k))//' = modified Newton', atol=1.0e-5_wp*umax)
         if (allocated(error)) return
      end do
   end subroutine test_methods

   !> An excavation step under arc-length control (with a small force pattern, which such a
   !> step needs) ends, for the elastic column, where the same step under load control does
   !> (linear: the end state does not depend on the path), to 1e-9 of the heave.
   subroutine test_arc_length(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: ref, arc
      character(len=*), parameter :: load = '*NSET, NAME=mid'//new_line('a')//'41, 42'// &
         new_line('a')//'*LOAD, NAME=p, TYPE=FORCE'//new_line('a')//'mid, Y, -1'//new_line('a')
      character(len=*), parameter :: dig = new_line('a')//'p, 1'//new_line('a')//'*DEACTIVATE'// &
         new_line('a')//'t1, t2, t3, t4'
      integer :: code
      call make_directories(OUT)
      call write_column(OUT//'arc_load.inp', 40, 4, [4], 1, ELASTIC, steps=load// &
         '*STEP, NAME=dig, INCREMENTS=4'//dig)
      code = run_deck(OUT//'arc_load.inp', OUT//'arc_load.h5', .true., model, ref)
      call check(error, code == 0, 'load control runs')
      if (allocated(error)) return
      call write_column(OUT//'arc_arc.inp', 40, 4, [4], 1, ELASTIC, steps=load// &
         '*STEP, NAME=dig, INCREMENTS=4, CONTROL=ARC_LENGTH'//dig)
      code = run_deck(OUT//'arc_arc.inp', OUT//'arc_arc.h5', .true., model, arc)
      call check(error, code == 0, 'arc-length control runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check(error, arc%stats%arc_increments > 0, 'the step went under arc-length control')
      if (allocated(error)) return
      call check_close(error, maxval(abs(arc%state%u(:, 1:74) - ref%state%u(:, 1:74))), 0.0_wp, &
         0.0_wp, 'arc-length = load control at the end of the phase', &
         atol=1.0e-9_wp*maxval(abs(ref%state%u)))
   end subroutine test_arc_length

   !> A Katona contact set between a K0 column (y 0..7.5) and a block on it (7.5..10):
   !> removing the block and its doublets heaves the column by the oedometric gamma h y / M;
   !> putting them back (stress-free block, doublets in stick from where they are) loads it
   !> again: the column returns to its state before, displacements and stresses (elastic,
   !> 1e-10 of the heave and of gamma H).
   subroutine test_katona(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: before, removed, back
      character(len=*), parameter :: deck = OUT//'katona.inp', NL = new_line('a')
      real(wp) :: heave, worst
      integer :: code, n
      call make_directories(OUT)
      call write_block(deck, '', steps='*STEP, NAME=nil'//NL//'*STEP, NAME=remove, '// &
         'INCREMENTS=2'//NL//'*DEACTIVATE'//NL//'block, iface'//NL//'*STEP, NAME=back, '// &
         'INCREMENTS=3'//NL//'*ACTIVATE'//NL//'block, iface')
      code = run_deck(deck, OUT//'katona_1.h5', .true., model, before, stop_after=1)
      call check(error, code == 4, 'nil step (exit '//itoa(code)//')')
      if (allocated(error)) return
      code = run_deck(deck, OUT//'katona_2.h5', .true., model, removed, stop_after=3)
      call check(error, code == 4, 'removal (exit '//itoa(code)//')')
      if (allocated(error)) return
      heave = GAMMA*2.5_wp*7.5_wp/oedometric()
      worst = 0.0_wp
      do n = 1, 62
         worst = max(worst, abs(removed%state%u(2, n) - before%state%u(2, n) - &
            GAMMA*2.5_wp*model%mesh%x(2, n)/oedometric()))
      end do
      call check_close(error, worst, 0.0_wp, 0.0_wp, 'block and doublets removed: heave gamma h '// &
         'y / M', atol=1.0e-10_wp*heave)
      if (allocated(error)) return
      call check(error, all(removed%katona%off), 'the doublets are off')
      if (allocated(error)) return
      code = run_deck(deck, OUT//'katona_3.h5', .true., model, back)
      call check(error, code == 0, 'block and doublets back (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check_close(error, maxval(abs(back%state%u(:, 1:62) - before%state%u(:, 1:62))), &
         0.0_wp, 0.0_wp, 'the column back where it was', atol=1.0e-10_wp*heave)
      if (allocated(error)) return
      call check_close(error, maxval(abs(back%state%sets(1)%stress - before%state%sets(1)%stress)), &
         0.0_wp, 0.0_wp, 'the column stresses back to those before', atol=1.0e-10_wp*GAMMA*H)
      if (allocated(error)) return
      ! the doublets carry the block's weight: N = gamma 2.5 x 1 in all
      call check_close(error, sum(back%katona%f(1, :)), GAMMA*2.5_wp, 1.0e-10_wp, &
         'the doublets carry the block''s weight')
   end subroutine test_katona

   !> The K0 column of katona_off_and_on (Q4 1-30, set 'rest') and the block on it (Q4 31-40,
   !> set 'block') on Katona contact (joint set 'iface'), with the block and the contact set
   !> off until the first step activates them (`how`: the *ACTIVATE options of the contact set).
   !> `law`, `steps`: another law for the joint set 'iface', other steps (all sets active at
   !> the start).
   subroutine write_block(path, how, law, steps)
      character(len=*), intent(in) :: path, how
      character(len=*), intent(in), optional :: law, steps
      integer :: u, i
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'K0 column with a block on Katona contact', '*NODES'
      do i = 0, 40
         write (u, '(i0,a,es23.16)') 2*i + 1, ', 0.0, ', i*0.25_wp
         write (u, '(i0,a,es23.16)') 2*i + 2, ', 1.0, ', i*0.25_wp
      end do
      write (u, '(a)') '1001, 0.0, 7.5', '1002, 1.0, 7.5', '*ELEMENTS, TYPE=Q4, SET=rest'
      do i = 1, 30
         write (u, '(i0,4(", ",i0))') i, 2*i - 1, 2*i, 2*i + 2, 2*i + 1
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=block', '31, 1001, 1002, 64, 63'
      do i = 32, 40
         write (u, '(i0,4(", ",i0))') i, 2*i - 1, 2*i, 2*i + 2, 2*i + 1
      end do
      write (u, '(a)') ELASTIC, '*SECTION, SET=rest, MATERIAL=soil', &
         '*SECTION, SET=block, MATERIAL=soil'
      if (present(law)) then
         write (u, '(a)') '*INTERFACE_LAW, NAME=kat, '//law
      else
         write (u, '(a)') '*INTERFACE_LAW, NAME=kat, TYPE=KATONA', 'PHI = 30'
      end if
      write (u, '(a)') '*JOINTS, TYPE=GOODMAN4, SET=iface, LAW=kat', '500, 61, 62, 1002, 1001', &
         '*NSET, NAME=base', '1, 2', '*NSET, NAME=sides, GENERATE', '1, 82', &
         '*NSET, NAME=pair', '1001, 1002', '*BOUNDARY', 'base, XY', 'sides, X', 'pair, X', &
         '*INITIAL_STRESS, TYPE=GEOSTATIC', 'ALL, 10.0, 0.5'
      if (present(steps)) then
         write (u, '(a)') steps
      else
         write (u, '(a)') '*STEP, NAME=install, INCREMENTS=2', &
            '*ACTIVATE, STRESS=WISHED_IN_PLACE', 'block', '*ACTIVATE'//how, 'iface'
      end if
      close (u)
   end subroutine write_block

   !> Bad phase decks: exit 2, file:line and keyword in the message, no results file.
   subroutine test_bad_decks(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: cases(5) = [character(len=200) :: &
         '*STEP, NAME=a|*DEACTIVATE|nosuch', &
         '*STEP, NAME=a|*DEACTIVATE|t1|*STEP, NAME=b|*ACTIVATE|t1|*STEP, NAME=c|*ACTIVATE|t1', &
         '*STEP, NAME=a|*DEACTIVATE|t1|*STEP, NAME=b|*DEACTIVATE|t1', &
         '*STEP, NAME=a|*CHANGE_MATERIAL|rest, granite', &
         '*STEP, NAME=a|*DEACTIVATE|t1|*STEP, NAME=b|top, 1']
      character(len=*), parameter :: expect(5) = [character(len=56) :: &
         "joint set, load pattern or named support 'nosuch'", "'t1' is already active", &
         "'t1' is not active", "no material 'granite'", 'which no active element']
      character(len=*), parameter :: marker(5) = [character(len=16) :: 'nosuch', 't1', 't1', &
         'rest, granite', '*STEP, NAME=b']
      character(len=:), allocatable :: deck, steps
      integer :: k, i
      call make_directories(OUT)
      do k = 1, size(cases)
         steps = trim(cases(k))
         do i = 1, len(steps)
            if (steps(i:i) == '|') steps(i:i) = new_line('a')
         end do
         if (k == 5) steps = '*NSET, NAME=topn'//new_line('a')//'21, 22'//new_line('a')// &
            '*LOAD, NAME=top, TYPE=FORCE'//new_line('a')//'topn, Y, -1'//new_line('a')//steps
         deck = OUT//'bad'//itoa(k)//'.inp'
         call write_column(deck, 10, 1, [1], 1, ELASTIC, steps=steps)
         call check_refused(error, deck, trim(marker(k)), trim(expect(k)), OUT//'bad.h5', &
            'bad deck '//itoa(k))
         if (allocated(error)) return
      end do
   end subroutine test_bad_decks

end module test_phases
