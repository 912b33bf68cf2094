!> The adaptive loop (pecplas_adapt_adapt) on the L-shaped plate of test/data/adapt (a
!> re-entrant corner, stress singular with exponent 0.544): the adaptive sequence reaches the
!> energy error of the fourth uniform refinement with at least 3x fewer DOFs (true errors,
!> against the Aitken extrapolation of the uniform energies); the loop stops once the goal
!> (tip deflection) is estimated within its target; the Aitken estimate is exact on a
!> geometric sequence.
module test_adapt
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_refine_local, only: refine_marked
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_estimate_estimator, only: error_estimate_t, estimate_error
   use pecplas_adapt_adapt, only: adapt_options_t, adapt_level_t, adapt_model, run_level, &
      goal_extrapolation
   use pecplas_testing, only: unittest_t, new_unittest, check
   use pecplas_model_adapt_request, only: goal_spec_t, parse_goal_spec, GOAL_ENERGY, &
      GOAL_NODE, GOAL_REACTION, GOAL_LIMIT
   implicit none (type, external)
   private
   public :: collect_adapt

   character(len=*), parameter :: DECK = 'test/data/adapt/lshape.inp'
   character(len=*), parameter :: DIR = 'build/test_out/adapt'

contains

   subroutine collect_adapt(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('aitken_geometric', test_aitken), &
               new_unittest('goal_forms', test_goal_forms), &
               new_unittest('lshape_fewer_dofs', test_lshape), &
               new_unittest('goal_target_stops', test_goal)]
   end subroutine collect_adapt

   !> q_k = 1 - 2^-k: Aitken gives q_inf = 1 exactly, so the error of 0.875 is 0.125.
   subroutine test_aitken(error)
      type(error_t), allocatable, intent(out) :: error
      call check(error, abs(goal_extrapolation([0.5_wp, 0.75_wp, 0.875_wp]) - 0.125_wp) < &
         1.0e-14_wp, 'Aitken exact on a geometric sequence (1e-14)')
      if (allocated(error)) return
      call check(error, goal_extrapolation([1.0_wp]) < 0.0_wp, 'one level: unknown (-1)')
   end subroutine test_aitken

   !> Every accepted goal form gives its kind, node, set and component; malformed ones a
   !> message naming the accepted forms.
   subroutine test_goal_forms(error)
      type(error_t), allocatable, intent(out) :: error
      type(goal_spec_t) :: g
      character(len=:), allocatable :: msg
      character(len=20), parameter :: bad(8) = [character(len=20) :: 'node:0:y', 'node:3', &
         'node:3:w', 'node:a b:y', 'reaction:', 'reaction:a:w', 'limits', 'reaction:a b']
      integer :: i
      call parse_goal_spec('', g, msg)
      call check(error, .not. allocated(msg) .and. g%kind == GOAL_ENERGY, "'' is energy")
      if (allocated(error)) return
      call parse_goal_spec('node:12:z', g, msg)
      call check(error, .not. allocated(msg) .and. g%kind == GOAL_NODE .and. g%node_id == 12 &
         .and. g%dof == 2, 'node:12:z')
      if (allocated(error)) return
      ! a name where the node id goes: a node set of one node, resolved with the mesh
      call parse_goal_spec('node:x3:y', g, msg)
      call check(error, .not. allocated(msg) .and. g%kind == GOAL_NODE .and. g%node_id == 0 &
         .and. g%set == 'x3' .and. g%dof == 2, 'node:x3:y (node set x3)')
      if (allocated(error)) return
      call parse_goal_spec('reaction:base', g, msg)
      call check(error, .not. allocated(msg) .and. g%kind == GOAL_REACTION .and. &
         g%set == 'base' .and. g%dof == 0, 'reaction:base: the loaded direction (dof 0)')
      if (allocated(error)) return
      call parse_goal_spec('reaction:base:x', g, msg)
      call check(error, .not. allocated(msg) .and. g%set == 'base' .and. g%dof == 1, &
         'reaction:base:x')
      if (allocated(error)) return
      call parse_goal_spec('limit', g, msg)
      call check(error, .not. allocated(msg) .and. g%kind == GOAL_LIMIT, 'limit')
      if (allocated(error)) return
      do i = 1, size(bad)
         call parse_goal_spec(trim(bad(i)), g, msg)
         call check(error, allocated(msg), 'refused: '//trim(bad(i)))
         if (allocated(error)) return
         call check(error, index(msg, 'reaction:SET') > 0 .and. index(msg, 'limit') > 0, &
            'the message names the accepted forms: '//msg)
         if (allocated(error)) return
      end do
   end subroutine test_goal_forms

   !> Uniform levels 0..4 (all marked) and the adaptive sequence (theta 0.5) up to half the
   !> DOFs of uniform level 4. The energy error is ||e||^2 = ||u||^2 - ||u_h||^2 (Galerkin,
   !> prescribed loads, fixed supports), ||u||^2 extrapolated (Aitken) from uniform 2..4.
   subroutine test_lshape(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model, fine
      type(problem_t) :: problem
      type(error_estimate_t) :: est
      type(adapt_options_t) :: opts
      type(adapt_level_t), allocatable :: levels(:)
      character(len=:), allocatable :: reason
      real(wp) :: e2(0:4), nd(0:4), e2inf, target, wall
      real(wp), allocatable :: err(:)
      logical, allocatable :: all_marked(:)
      integer :: k, nadapt
      character(len=120) :: buf
      call make_directories(DIR)
      call read_deck(DECK, model, error)
      if (allocated(error)) return
      do k = 0, 4
         call run_level(model, DIR//'/u.h5', problem, wall, error)
         if (allocated(error)) return
         call estimate_error(model, problem, est, error)
         if (allocated(error)) return
         e2(k) = est%energy**2
         nd(k) = problem%system%dofs%neq
         if (k == 4) exit
         allocate (all_marked(model%mesh%nelem()), source=.true.)
         call refine_marked(model, all_marked, fine, reason)
         deallocate (all_marked)
         call check(error, .not. allocated(reason), 'uniform refinement')
         if (allocated(error)) return
         model = fine
      end do
      e2inf = e2(4) - (e2(4) - e2(3))**2/((e2(4) - e2(3)) - (e2(3) - e2(2)))
      target = sqrt(max(e2inf - e2(4), 0.0_wp)/e2inf)
      call read_deck(DECK, model, error)
      if (allocated(error)) return
      opts%target = 0.0_wp
      opts%max_dofs = nint(nd(4)/2)
      opts%scratch = DIR//'/a.h5'
      call adapt_model(model, opts, levels, problem, error)
      if (allocated(error)) return
      ! energy of each adaptive level = its goal (energy goal)
      err = sqrt(max(e2inf - levels%goal**2, 0.0_wp)/e2inf)
      ! DOFs where the adaptive sequence crosses the target (log-log interpolation)
      nadapt = 0
      do k = 2, size(levels)
         if (err(k) <= target .and. err(k - 1) > target) nadapt = nint(exp(log(real( &
            levels(k - 1)%ndof, wp)) + log(err(k - 1)/target)/log(err(k - 1)/err(k))* &
            log(real(levels(k)%ndof, wp)/levels(k - 1)%ndof)))
      end do
      write (buf, '(a,f6.3,a,i0,a,i0,a,i0)') 'energy error ', 100*target, &
         ' %: uniform DOFs ', nint(nd(4)), ', adaptive DOFs ', nadapt, ' after levels ', &
         size(levels)
      write (*, '(8x,a)') trim(buf)
      do k = 1, size(levels)
         write (*, '(8x,a,i2,a,i6,a,f7.3,a,f7.3)') 'level ', k, ' DOFs ', levels(k)%ndof, &
            '  true error % ', 100*err(k), '  ZZ estimate % ', 100*levels(k)%eta_rel
      end do
      call check(error, nadapt > 0 .and. 3*nadapt <= nint(nd(4)), trim(buf)// &
         ': at least 3x fewer DOFs')
   end subroutine test_lshape

   !> Goal: vertical displacement of the overhang's tip (2, 2), target 1 %: the loop stops
   !> with the estimate below 1 % within the DOF budget, the DOFs growing at every level.
   subroutine test_goal(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(adapt_options_t) :: opts
      type(adapt_level_t), allocatable :: levels(:)
      integer :: k, n
      character(len=100) :: buf
      call make_directories(DIR)
      call read_deck(DECK, model, error)
      if (allocated(error)) return
      do k = 1, model%mesh%nnode()
         if (all(abs(model%mesh%x(:, k) - [2.0_wp, 2.0_wp]) < 1.0e-12_wp)) opts%goal_node = k
      end do
      opts%goal_dof = 2
      opts%target = 0.01_wp
      opts%max_dofs = 20000
      opts%scratch = DIR//'/g.h5'
      call adapt_model(model, opts, levels, problem, error)
      if (allocated(error)) return
      n = size(levels)
      write (buf, '(a,i0,a,i0,a,es10.3,a,f6.3,a)') 'levels ', n, ', DOFs ', levels(n)%ndof, &
         ', tip v ', levels(n)%goal, ', estimate ', 100*levels(n)%goal_error, ' %'
      write (*, '(8x,a)') trim(buf)
      call check(error, levels(n)%goal_error >= 0.0_wp .and. levels(n)%goal_error <= 0.01_wp &
         .and. all([(levels(k + 1)%ndof > levels(k)%ndof, k=1, n - 1)]), trim(buf))
   end subroutine test_goal

end module test_adapt
