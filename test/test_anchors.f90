!> Anchors and struts (doc/theory.md, Anchors): a prestressed fixed-end anchor against an
!> elastic block keeps its prestress exactly and then takes a load as a spring in parallel
!> with the block; a node-to-node bar pulling the block (series springs), and at its
!> tension limit; a prestressed ground anchor pulling a wall strip in elastic soil
!> (equilibrium of the wall and of the whole model); restart across the prestress phase;
!> bad anchor decks stop with file:line.
!>
!> The block: one Q4 [0, W] x [0, H], E, nu = 0, its left side on rollers (x fixed) and its
!> bottom held in y: equal x forces F at its right nodes give the uniform stress 2F/H, a
!> state Q4 represents exactly, so u_x = 2 F W / (E H) at both right nodes: the block is a
!> spring of stiffness K_b = E H / W for the sum of the two forces. The problems are linear:
!> the solver reaches them to roundoff, hence the 1e-10 bounds.
module test_anchors
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_fe_assembly, only: internal_forces
   use pecplas_base_strings, only: itoa
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_bad_decks, only: check_refused
   implicit none (type, external)
   private
   public :: collect_anchors

   character(len=*), parameter :: OUT = 'build/test_out/anchors/'
   real(wp), parameter :: E = 1.0e4_wp, W = 2.0_wp, H = 1.0_wp, EA = 2.0e4_wp, LA = 4.0_wp, &
      LS = 2.0_wp, P = 100.0_wp
   character(len=1), parameter :: NL = new_line('a')

contains

   subroutine collect_anchors(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('prestress_kept_fixed_end', test_prestress_fixed), &
               new_unittest('bar_pulls_block', test_bar_pulls), &
               new_unittest('tension_limit', test_limit), &
               new_unittest('wall_in_soil_equilibrium', test_wall), &
               new_unittest('restart_after_prestress', test_restart), &
               new_unittest('propped_cantilever', test_propped), &
               new_unittest('bad_decks', test_bad_decks)]
   end subroutine collect_anchors

   !> The block deck; `extra`: lines after the material (anchors, loads, steps).
   subroutine write_block(path, extra)
      character(len=*), intent(in) :: path, extra
      integer :: u
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'anchor on a block', '*NODES', '1, 0, 0', '2, 2, 0', &
         '3, 2, 1', '4, 0, 1', '5, 6, 0', '6, 6, 1', '*ELEMENTS, TYPE=Q4, SET=block', &
         '1, 1, 2, 3, 4', '*MATERIAL, NAME=m', 'E = 1e4, NU = 0', '*SECTION, SET=block, MATERIAL=m', &
         '*NSET, NAME=right', '2, 3', '*NSET, NAME=far', '5, 6', '*BOUNDARY', '1, XY', '4, X', &
         '2, Y', '*SOLVER, TOLERANCE=1e-9', extra
      close (u)
   end subroutine write_block

   !> Phase 1 prestresses two fixed-end anchors (EA, LENGTH = LA, spacing LS, pointing +x to
   !> their fixed point) at the block's right nodes to P: N = P, and the block stretches
   !> under 2 P / LS: u = 2 P W / (LS E H). Phase 2 (nothing applied) keeps N = P. Phase 3
   !> pulls both nodes by Q in +x: the anchors (k = EA/LA each, k/LS at a node) and the block
   !> in parallel: du = 2 Q / (K_b + 2 k / LS), N = P - k du.
   subroutine test_prestress_fixed(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: Q = 30.0_wp
      real(wp) :: k, kb, u1, du
      integer :: code, stop_at
      call make_directories(OUT)
      call write_block(OUT//'fixed.inp', '*ANCHOR, NAME=prop, TYPE=FIXED_END, EA=2e4, '// &
         'LENGTH=4, ANGLE=0, SPACING=2'//NL//'right'//NL// &
         '*LOAD, NAME=pull, TYPE=FORCE'//NL//'right, X, 30'//NL// &
         '*STEP, NAME=prestress, INCREMENTS=2'//NL//'*ACTIVATE'//NL//'prop'//NL// &
         '*PRESTRESS'//NL//'prop, 100'//NL//'*END STEP'//NL// &
         '*STEP, NAME=nil'//NL//'*END STEP'//NL// &
         '*STEP, NAME=load, INCREMENTS=3'//NL//'pull, 1'//NL//'*END STEP')
      k = EA/LA
      kb = E*H/W
      u1 = 2.0_wp*P*W/(LS*E*H)
      ! the end of phase 1 (2 increments), then of the nil phase (1 increment)
      do stop_at = 2, 3
         code = run_deck(OUT//'fixed.inp', OUT//'fixed.h5', .true., model, problem, &
            stop_after=stop_at)
         call check(error, code == 4, 'stopped after increment '//itoa(stop_at)//' (exit '// &
            itoa(code)//')')
         if (allocated(error)) return
         call check_close(error, problem%state%anchors%sets(1)%force(1), P, 1.0e-10_wp, &
            'N = P after increment '//itoa(stop_at))
         if (allocated(error)) return
         call check_close(error, problem%state%u(1, 3), u1, 1.0e-10_wp, &
            'block stretch under P after increment '//itoa(stop_at))
         if (allocated(error)) return
      end do
      code = run_deck(OUT//'fixed.inp', OUT//'fixed.h5', .true., model, problem)
      call check(error, code == 0, 'fixed-end anchor deck runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      du = 2.0_wp*Q/(kb + 2.0_wp*k/LS)
      call check_close(error, problem%state%u(1, 2), u1 + du, 1.0e-10_wp, 'block stretch')
      if (allocated(error)) return
      call check_close(error, problem%state%anchors%sets(1)%force(1), P - k*du, 1.0e-10_wp, &
         'anchor force after the load')
      if (allocated(error)) return
      call check_close(error, problem%state%anchors%sets(1)%force(2), P - k*du, 1.0e-10_wp, &
         'second anchor force after the load')
   end subroutine test_prestress_fixed

   !> Node-to-node bars from the block's right nodes to the supported nodes 5, 6 (length
   !> LA): phase 1 prestresses them to P (u = 2 P W / (LS E H), N = P); phase 2 moves nodes
   !> 5, 6 by d in +x: bars and block in series, du = 2 (k/LS) d / (K_b + 2 k/LS),
   !> N = P + k (d - du).
   subroutine test_bar_pulls(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: D = 0.01_wp
      real(wp) :: k, kb, u1, du
      integer :: code
      call make_directories(OUT)
      call write_block(OUT//'bar.inp', '*ANCHOR, NAME=bar, TYPE=NODE_TO_NODE, EA=2e4, '// &
         'SPACING=2'//NL//'2, 5'//NL//'3, 6'//NL//'*BOUNDARY'//NL//'5, Y'//NL//'6, Y'//NL// &
         '*LOAD, NAME=move, TYPE=DISPLACEMENT'//NL//'far, X, 0.01'//NL// &
         '*STEP, NAME=prestress'//NL//'*ACTIVATE'//NL//'bar'//NL//'*PRESTRESS'//NL// &
         'bar, 100'//NL//'*END STEP'//NL//'*STEP, NAME=nil'//NL//'*END STEP')
      code = run_deck(OUT//'bar.inp', OUT//'bar.h5', .true., model, problem)
      call check(error, code == 0, 'node-to-node prestress runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      k = EA/LA
      kb = E*H/W
      u1 = 2.0_wp*P*W/(LS*E*H)
      call check_close(error, problem%state%u(1, 3), u1, 1.0e-10_wp, 'block stretch under P')
      if (allocated(error)) return
      call check_close(error, problem%state%anchors%sets(1)%force(1), P, 1.0e-10_wp, &
         'prestress kept through a nil phase')
      if (allocated(error)) return
      call write_block(OUT//'bar2.inp', '*ANCHOR, NAME=bar, TYPE=NODE_TO_NODE, EA=2e4, '// &
         'SPACING=2'//NL//'2, 5'//NL//'3, 6'//NL//'*BOUNDARY'//NL//'5, Y'//NL//'6, Y'//NL// &
         '*LOAD, NAME=move, TYPE=DISPLACEMENT'//NL//'far, X, 0.01'//NL// &
         '*STEP, NAME=prestress'//NL//'*ACTIVATE'//NL//'bar'//NL//'*PRESTRESS'//NL// &
         'bar, 100'//NL//'*END STEP'//NL//'*STEP, NAME=pull, INCREMENTS=2'//NL//'move, 1'// &
         NL//'*END STEP')
      code = run_deck(OUT//'bar2.inp', OUT//'bar2.h5', .true., model, problem)
      call check(error, code == 0, 'node-to-node pull runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      du = 2.0_wp*(k/LS)*D/(kb + 2.0_wp*k/LS)
      call check_close(error, problem%state%u(1, 2), u1 + du, 1.0e-10_wp, 'block stretch')
      if (allocated(error)) return
      call check_close(error, problem%state%anchors%sets(1)%force(2), P + k*(D - du), &
         1.0e-10_wp, 'bar force (series springs)')
   end subroutine test_bar_pulls

   !> A bar with TENSION_LIMIT = 150 pulled (no prestress) far beyond it: N = 150 exactly
   !> (the return to the limit), the block under 2 * 150 / LS: u = 300 W / (LS E H); the
   !> plastic elongation is the rest of the imposed displacement.
   subroutine test_limit(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: FT = 150.0_wp, D = 0.2_wp
      real(wp) :: ub
      integer :: code
      call make_directories(OUT)
      call write_block(OUT//'limit.inp', '*ANCHOR, NAME=bar, TYPE=NODE_TO_NODE, EA=2e4, '// &
         'SPACING=2, TENSION_LIMIT=150'//NL//'2, 5'//NL//'3, 6'//NL//'*BOUNDARY'//NL// &
         '5, Y'//NL//'6, Y'//NL//'*LOAD, NAME=move, TYPE=DISPLACEMENT'//NL//'far, X, 0.2'//NL// &
         '*SOLVER, METHOD=NEWTON, TOLERANCE=1e-9'//NL// &
         '*STEP, NAME=pull, INCREMENTS=4'//NL//'move, 1'//NL//'*END STEP')
      code = run_deck(OUT//'limit.inp', OUT//'limit.h5', .true., model, problem)
      call check(error, code == 0, 'bar at its limit runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      ub = 2.0_wp*FT*W/(LS*E*H)
      call check_close(error, problem%state%anchors%sets(1)%force(1), FT, 1.0e-10_wp, &
         'force at the tension limit')
      if (allocated(error)) return
      call check_close(error, problem%state%u(1, 2), ub, 1.0e-10_wp, 'block stretch at the limit')
      if (allocated(error)) return
      call check_close(error, problem%state%anchors%sets(1)%plastic(1), D - ub - FT*LA/EA, &
         1.0e-10_wp, 'plastic elongation')
   end subroutine test_limit

   !> A wall strip (one Q4 column, E_wall) in an elastic soil block, pulled at its head by a
   !> prestressed node-to-node anchor whose other end lies in the soil behind (a grouted
   !> end). Nothing else acts: the support reactions sum to zero, and the soil's forces on
   !> the wall balance the anchor's (the wall's own element forces sum to zero over its
   !> nodes). Bound: each nodal residual is at most ||r|| <= TOL ref (the convergence
   !> test), so a sum over n equations is within sqrt(n) TOL ref; ref is at least the
   !> anchor's nodal force P/LS.
   subroutine test_wall(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), allocatable :: f(:, :), reaction(:, :)
      real(wp) :: bound, sx, sy, ref
      integer :: code, head, anchor_end, nx, ny, i
      logical, allocatable :: wall_node(:), keep(:)
      call make_directories(OUT)
      nx = 12; ny = 10
      call write_wall(OUT//'wall.inp', nx, ny, head, anchor_end)
      code = run_deck(OUT//'wall.inp', OUT//'wall.h5', .true., model, problem)
      call check(error, code == 0, 'wall with an anchor runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check_close(error, problem%state%anchors%sets(1)%force(1), 200.0_wp, 1.0e-10_wp, &
         'anchor force = prestress')
      if (allocated(error)) return
      ! internal forces of the soil and the anchor alone (the wall set off)
      allocate (f(2, model%mesh%nnode()), reaction(2, model%mesh%nnode()))
      call internal_forces(model, problem%system%rules, problem%state%u, problem%state, &
         reaction, error)
      if (allocated(error)) return
      keep = problem%state%sets%active
      problem%state%sets(2)%active = .false.
      call internal_forces(model, problem%system%rules, problem%state%u, problem%state, f, error)
      problem%state%sets%active = keep
      call problem%state%rollback()
      if (allocated(error)) return
      allocate (wall_node(model%mesh%nnode()), source=.false.)
      do i = 1, size(model%mesh%esets(2)%conn, 2)
         wall_node(model%mesh%esets(2)%conn(:, i)) = .true.
      end do
      ref = max(200.0_wp/LS, norm2(pack(reaction, problem%system%dofs%eq == 0)))
      bound = sqrt(real(2*count(wall_node), wp))*1.0e-9_wp*ref
      sx = sum(pack(f(1, :), wall_node))
      sy = sum(pack(f(2, :), wall_node))
      call check_close(error, sx, 0.0_wp, 0.0_wp, 'wall free body, x: soil + anchor', atol=bound)
      if (allocated(error)) return
      call check_close(error, sy, 0.0_wp, 0.0_wp, 'wall free body, y: soil + anchor', atol=bound)
      if (allocated(error)) return
      ! the soil alone pushes the wall with the anchor's force
      call check(error, abs(sx) < 1.0e-6_wp*200.0_wp/LS, 'soil force on the wall balances P')
      if (allocated(error)) return
      bound = sqrt(real(2*model%mesh%nnode(), wp))*1.0e-9_wp*ref
      call check_close(error, sum(pack(reaction(1, :), problem%system%dofs%eq(1, :) == 0)), &
         0.0_wp, 0.0_wp, 'sum of x reactions', atol=bound)
      if (allocated(error)) return
      call check_close(error, sum(pack(reaction(2, :), problem%system%dofs%eq(2, :) == 0)), &
         0.0_wp, 0.0_wp, 'sum of y reactions', atol=bound)
   end subroutine test_wall

   !> Soil [0, 12] x [-10, 0] in nx x ny Q4 (1 m), the column x in [5, 6], y >= -6 the
   !> wall (set 'wall', stiffer); an anchor from the wall head (6, 0) down to (10, -3),
   !> prestressed to 200 in one phase; base fixed, sides on rollers.
   subroutine write_wall(path, nx, ny, head, anchor_end)
      character(len=*), intent(in) :: path
      integer, intent(in) :: nx, ny
      integer, intent(out) :: head, anchor_end
      integer :: u, i, j, n
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'anchored wall strip', '*NODES'
      do j = 0, ny
         do i = 0, nx
            write (u, '(i0,a,i0,a,i0)') j*(nx + 1) + i + 1, ', ', i, ', ', j - ny
         end do
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=soil'
      do j = 1, ny
         do i = 1, nx
            if (i == 6 .and. j > ny - 6) cycle
            n = (j - 1)*(nx + 1) + i
            write (u, '(i0,4(", ",i0))') (j - 1)*nx + i, n, n + 1, n + nx + 2, n + nx + 1
         end do
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=wall'
      do j = ny - 5, ny
         n = (j - 1)*(nx + 1) + 6
         write (u, '(i0,4(", ",i0))') (j - 1)*nx + 6, n, n + 1, n + nx + 2, n + nx + 1
      end do
      head = ny*(nx + 1) + 7
      anchor_end = (ny - 3)*(nx + 1) + 11
      write (u, '(a)') '*MATERIAL, NAME=soil', 'E = 3e4, NU = 0.3', '*MATERIAL, NAME=concrete', &
         'E = 3e7, NU = 0.2', '*SECTION, SET=soil, MATERIAL=soil', &
         '*SECTION, SET=wall, MATERIAL=concrete', '*NSET, NAME=base, GENERATE'
      write (u, '(i0,a,i0)') 1, ', ', nx + 1
      write (u, '(a)') '*NSET, NAME=sides'
      do j = 0, ny
         write (u, '(i0,a,i0)') j*(nx + 1) + 1, ', ', j*(nx + 1) + nx + 1
      end do
      write (u, '(a)') '*BOUNDARY', 'base, XY', 'sides, X', &
         '*ANCHOR, NAME=tie, TYPE=NODE_TO_NODE, EA=1e5, SPACING=2'
      write (u, '(i0,a,i0)') head, ', ', anchor_end
      write (u, '(a)') '*SOLVER, TOLERANCE=1e-9', '*STEP, NAME=prestress, INCREMENTS=2', &
         '*ACTIVATE', 'tie', '*PRESTRESS', 'tie, 200', '*END STEP'
      close (u)
   end subroutine write_wall

   !> The fixed-end deck stopped after its first increment of phase 3 and restarted: the
   !> same end state as the run without a stop (the anchors' reference elongations and
   !> forces come back from the restart data), to 1e-10.
   subroutine test_restart(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: ref, other
      integer :: code
      call make_directories(OUT)
      call write_block(OUT//'restart.inp', '*ANCHOR, NAME=prop, TYPE=FIXED_END, EA=2e4, '// &
         'LENGTH=4, ANGLE=0, SPACING=2'//NL//'right'//NL// &
         '*LOAD, NAME=pull, TYPE=FORCE'//NL//'right, X, 30'//NL// &
         '*STEP, NAME=prestress, INCREMENTS=2'//NL//'*ACTIVATE'//NL//'prop'//NL// &
         '*PRESTRESS'//NL//'prop, 100'//NL//'*END STEP'//NL// &
         '*STEP, NAME=load, INCREMENTS=3'//NL//'pull, 1'//NL//'*END STEP')
      code = run_deck(OUT//'restart.inp', OUT//'restart_ref.h5', .true., model, ref)
      call check(error, code == 0, 'reference runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      code = run_deck(OUT//'restart.inp', OUT//'restart_a.h5', .true., model, other, &
         stop_after=3)
      call check(error, code == 4, 'run stopped after 3 increments (exit '//itoa(code)//')')
      if (allocated(error)) return
      code = run_deck(OUT//'restart.inp', OUT//'restart_b.h5', .true., model, other, &
         restart=OUT//'restart_a.h5')
      call check(error, code == 0, 'restarted run completes (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check_close(error, other%state%anchors%sets(1)%force(1), &
         ref%state%anchors%sets(1)%force(1), 1.0e-10_wp, 'anchor force after restart')
      if (allocated(error)) return
      call check_close(error, other%state%u(1, 2), ref%state%u(1, 2), 1.0e-10_wp, &
         'displacement after restart')
   end subroutine test_restart

   !> A plate cantilever (L = 10, EI = 1e5, EA = 1e7: GA_s = 5/12 EA, ten 2-node elements)
   !> clamped at x = 0 under q = 10 downwards, propped at its tip by a fixed-end anchor
   !> (EA_a = 2e6, LENGTH = 5, spacing 2: k = EA_a / (5 * 2) per unit width). Compatibility
   !> of the tip: R (c + 1/k) = delta_q with the Timoshenko cantilever's tip deflection
   !> delta_q = q L^4 / (8 EI) + q L^2 / (2 GA_s) and compliance c = L^3 / (3 EI) + L / GA_s
   !> (R -> 3/8 q L for a rigid prop and no shear deformation). The plate element's nodal
   !> values are exact under a uniform load and the problem is linear: 1e-10.
   subroutine test_propped(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: L = 10.0_wp, Q = 10.0_wp, EI = 1.0e5_wp, GAS = 5.0_wp/12.0_wp*1.0e7_wp
      real(wp) :: k, dq, c, r
      integer :: code, u, i
      call make_directories(OUT)
      open (newunit=u, file=OUT//'propped.inp', status='replace', action='write')
      write (u, '(a)') '*TITLE', 'propped cantilever', '*NODES'
      do i = 0, 10
         write (u, '(i0,a,i0,a)') i + 1, ', ', i, ', 0'
      end do
      write (u, '(a)') '*NSET, NAME=beam, GENERATE', '1, 11, 1', &
         '*PLATE, SET=beam, NODES=beam, EA=1.0e7, EI=1.0e5', &
         '*ANCHOR, NAME=prop, TYPE=FIXED_END, EA=2e6, LENGTH=5, ANGLE=-90, SPACING=2', '11', &
         '*BOUNDARY', '1, ALL', '*LOAD, NAME=q, TYPE=PLATE_LOAD', 'beam, 0, -10', &
         '*SOLVER, TOLERANCE=1e-10', '*STEP, NAME=load, INCREMENTS=1', 'q, 1.0', '*END STEP'
      close (u)
      code = run_deck(OUT//'propped.inp', OUT//'propped.h5', .true., model, problem)
      call check(error, code == 0, 'propped cantilever runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      k = 2.0e6_wp/(5.0_wp*LS)
      dq = Q*L**4/(8.0_wp*EI) + Q*L**2/(2.0_wp*GAS)
      c = L**3/(3.0_wp*EI) + L/GAS
      r = dq/(c + 1.0_wp/k)
      ! the prop is in compression: N = -R L_s (force of one prop)
      call check_close(error, problem%state%anchors%sets(1)%force(1), -r*LS, 1.0e-10_wp, &
         'prop force (redundant of the propped cantilever)')
      if (allocated(error)) return
      call check(error, abs(r/(0.375_wp*Q*L) - 1.0_wp) < 0.01_wp, 'close to 3/8 q L')
   end subroutine test_propped

   !> Bad anchor decks: exit 2, the file:line of the culprit and the message.
   subroutine test_bad_decks(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: cases(8) = [character(len=200) :: &
         '*ANCHOR, NAME=a, TYPE=NODE_TO_NODE, EA=1e4|2, 2', &
         '*ANCHOR, NAME=a, TYPE=NODE_TO_NODE, EA=1e4|2, 99', &
         '*ANCHOR, NAME=a, TYPE=FIXED_END, EA=1e4, LENGTH=1, ANGLE=0|nosuchset', &
         '*ANCHOR, NAME=a, TYPE=NODE_TO_NODE, EA=-5|2, 5', &
         '*ANCHOR, NAME=a, TYPE=NODE_TO_NODE, EA=1e4|2, 5|*STEP, NAME=s|*PRESTRESS|b, 10', &
         '*ANCHOR, NAME=a, TYPE=NODE_TO_NODE, EA=1e4|2, 5|*STEP, NAME=s|*DEACTIVATE|a|'// &
         '*STEP, NAME=t|*PRESTRESS|a, 10', &
         '*ANCHOR, NAME=a, TYPE=FIXED_END, EA=1e4, ANGLE=0|2', &
         '*ANALYSIS, TYPE=AXISYMMETRIC|*ANCHOR, NAME=a, TYPE=NODE_TO_NODE, EA=1e4|2, 5']
      character(len=*), parameter :: expect(8) = [character(len=40) :: &
         'zero length', 'no node 99', "undefined node set 'nosuchset'", &
         'EA must be positive', "no anchor 'b'", "anchor 'a' is not active", &
         'missing required parameter LENGTH', 'plane strain only']
      character(len=*), parameter :: marker(8) = [character(len=48) :: '2, 2', '2, 99', &
         'nosuchset', '*ANCHOR, NAME=a, TYPE=NODE_TO_NODE, EA=-5', 'b, 10', 'a, 10', &
         '*ANCHOR, NAME=a, TYPE=FIXED_END, EA=1e4, ANGLE=0', &
         '*ANCHOR, NAME=a, TYPE=NODE_TO_NODE, EA=1e4']
      character(len=:), allocatable :: deck, extra
      integer :: k, i
      call make_directories(OUT)
      do k = 1, size(cases)
         extra = trim(cases(k))
         do i = 1, len(extra)
            if (extra(i:i) == '|') extra(i:i) = NL
         end do
         if (index(extra, '*STEP') == 0) extra = extra//NL//'*STEP, NAME=s'//NL//'*END STEP'
         deck = OUT//'bad'//itoa(k)//'.inp'
         call write_block(deck, extra)
         call check_refused(error, deck, trim(marker(k)), trim(expect(k)), OUT//'bad.h5', &
            'bad deck '//itoa(k))
         if (allocated(error)) return
      end do
   end subroutine test_bad_decks

end module test_anchors
