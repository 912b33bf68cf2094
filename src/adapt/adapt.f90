!> The adaptive loop: solve, estimate (Zienkiewicz–Zhu, pecplas_estimate_estimator), mark
!> (bulk marking), refine locally (pecplas_model_refine_local), re-solve, until the estimated
!> error of the goal is below the target or the DOF budget is reached.
!> Goals: the energy norm (estimate eta / ||sigma_h||); one displacement component of a
!> node; the resultant of the support reactions on a node set (one component, by default the
!> loaded direction); the limit load of the run (the load factor at the peak that the
!> driver writes to /limit; a level whose run reports no limit load stops the loop with an
!> error). The error of a quantity goal is estimated by Aitken extrapolation over the last
!> three levels (the difference to the last level when the sequence is not yet contracting),
!> taking the larger of the estimates at the last two levels so that one lucky level does
!> not stop the loop.
!> Nonlinear and history-dependent runs: the whole load history is re-run on each new mesh
!> (no state transfer): the plastic state of a refined mesh then is that of its own
!> equilibrium path, with no transfer error, at a cost below twice that of the last level
!> when the DOFs grow geometrically.
module pecplas_adapt_adapt
   use pecplas_base_kinds, only: wp
   use pecplas_base_run_status, only: RUN_COMPLETED, RUN_LIMIT_LOAD, status_name
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_version, only: VERSION
   use pecplas_model_type, only: model_t
   use pecplas_model_refine_local, only: refine_marked
   use pecplas_model_refine_mark, only: bulk_marking
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_prepare, only: prepare_run
   use pecplas_solve_increments, only: run_increments
   use pecplas_solve_gauss, only: gauss_coordinates
   use pecplas_estimate_estimator, only: error_estimate_t, estimate_error
   use pecplas_base_timers, only: wall_time
   use pecplas_io_results_increment, only: joint_points_t, limit_point_t
   use pecplas_model_adapt_request, only: GOAL_ENERGY, GOAL_NODE, GOAL_REACTION, GOAL_LIMIT
   use pecplas_base_strings, only: itoa
   use pecplas_io_results_file, only: results_file_t
   implicit none (type, external)
   private

   public :: adapt_options_t, adapt_level_t, adapt_model, run_level, goal_extrapolation, &
      reaction_resultant, loaded_direction

   type :: adapt_options_t
      !> Target relative error of the goal, bulk-marking fraction, budgets.
      real(wp) :: target = 0.01_wp, theta = 0.5_wp
      integer :: max_dofs = 100000, max_levels = 12
      !> Goal: 0 = energy norm; else the internal node and its component (1 x/r, 2 y/z).
      integer :: goal_node = 0, goal_dof = 0
      !> Goal kind (pecplas_model_adapt_request GOAL_*); GOAL_ENERGY with goal_node > 0 is
      !> the node goal. Reaction goal: node set name, component goal_dof (0: the loaded
      !> direction).
      integer :: goal_kind = GOAL_ENERGY
      character(len=:), allocatable :: goal_set
      !> Results file of the runs (rewritten at each level: the last level stays when
      !> `keep`, else it is deleted).
      character(len=:), allocatable :: scratch
      logical :: keep = .false.
      !> Print a line per level.
      logical :: verbose = .false.
   end type adapt_options_t

   type :: adapt_level_t
      integer :: ndof = 0, nelem = 0
      !> Estimate eta / ||sigma_h|| of the level, the goal value (energy: ||sigma_h||) and
      !> the estimated relative error of the goal (-1: not yet known).
      real(wp) :: eta_rel = 0, goal = 0, goal_error = -1, wall = 0
   end type adapt_level_t

contains

   !> Adaptive sequence from `model`; `model` ends as the last mesh and `problem` its solution.
   subroutine adapt_model(model, opts, levels, problem, error)
      type(model_t), intent(inout) :: model
      type(adapt_options_t), intent(in) :: opts
      type(adapt_level_t), allocatable, intent(out) :: levels(:)
      type(problem_t), intent(out) :: problem
      type(error_t), allocatable, intent(out) :: error
      type(error_estimate_t) :: est
      type(adapt_level_t) :: lev
      type(model_t) :: fine
      character(len=:), allocatable :: reason
      real(wp) :: peak
      integer :: k, kind, iset, dof
      kind = opts%goal_kind
      if (kind == GOAL_ENERGY .and. opts%goal_node > 0) kind = GOAL_NODE
      allocate (levels(0))
      do k = 1, opts%max_levels
         if (kind == GOAL_LIMIT) then
            call run_level(model, opts%scratch, problem, lev%wall, error, opts%keep, peak)
            if (allocated(error)) error%message = 'level '//itoa(k)//': '//error%message
         else
            call run_level(model, opts%scratch, problem, lev%wall, error, opts%keep)
         end if
         if (allocated(error)) return
         call estimate_error(model, problem, est, error)
         if (allocated(error)) return
         lev%ndof = problem%system%dofs%neq
         lev%nelem = model%mesh%nelem()
         lev%eta_rel = est%eta/max(est%energy, tiny(1.0_wp))
         select case (kind)
         case (GOAL_NODE)
            lev%goal = problem%state%u(opts%goal_dof, opts%goal_node)
         case (GOAL_REACTION)
            iset = model%mesh%find_nset(opts%goal_set)
            if (iset == 0) then
               call fatal_error(error, "the refined mesh has no node set '"//opts%goal_set//"'")
               return
            end if
            dof = merge(opts%goal_dof, loaded_direction(model, problem), opts%goal_dof > 0)
            if (all(problem%system%dofs%eq(dof, model%mesh%nsets(iset)%nodes) > 0)) then
               call fatal_error(error, "node set '"//opts%goal_set//"' has no support or "// &
                  'imposed displacement in '//merge('x', 'y', dof == 1)//': its reaction is zero')
               return
            end if
            lev%goal = reaction_resultant(problem, model%mesh%nsets(iset)%nodes, dof)
         case (GOAL_LIMIT)
            lev%goal = peak
         case default
            lev%goal = est%energy
         end select
         levels = [levels, lev]
         if (kind /= GOAL_ENERGY) then
            ! the larger of the last two Aitken estimates: one lucky level does not stop
            levels(k)%goal_error = -1.0_wp
            if (k >= 3) levels(k)%goal_error = max(goal_extrapolation([levels%goal]), &
               goal_extrapolation([levels(1:k - 1)%goal]))
         else
            levels(k)%goal_error = levels(k)%eta_rel
         end if
         if (opts%verbose) call print_level(k, levels(k))
         if (levels(k)%goal_error >= 0.0_wp .and. levels(k)%goal_error <= opts%target) return
         if (k == opts%max_levels) return
         call refine_marked(model, bulk_marking(indicators(est), opts%theta), fine, reason)
         if (allocated(reason)) then
            call fatal_error(error, 'adaptive refinement refused: '//reason)
            return
         end if
         ! the next level would exceed the budget (at most 2 DOFs per node)
         if (2*fine%mesh%nnode() > opts%max_dofs) return
         model = fine
      end do
   end subroutine adapt_model

   !> Element indicators in model order (sets in order).
   function indicators(est) result(eta)
      type(error_estimate_t), intent(in) :: est
      real(wp), allocatable :: eta(:)
      integer :: s
      allocate (eta(0))
      do s = 1, size(est%sets)
         eta = [eta, est%sets(s)%eta]
      end do
   end function indicators

   !> Relative error of the last of a sequence of goal values q, by Aitken extrapolation of
   !> the last three (q_inf = q3 - d2^2/(d2 - d1)) when the differences contract
   !> (0 < d2/d1 < 1), else |d2|/|q3|; -1 with fewer than two values.
   pure real(wp) function goal_extrapolation(q) result(rel)
      real(wp), intent(in) :: q(:)
      real(wp) :: d1, d2, qinf
      integer :: n
      n = size(q)
      rel = -1.0_wp
      if (n < 2) return
      d2 = q(n) - q(n - 1)
      rel = abs(d2)/max(abs(q(n)), tiny(1.0_wp))
      if (n < 3) return
      d1 = q(n - 1) - q(n - 2)
      if (d1 == 0.0_wp) return
      if (d2/d1 <= 0.0_wp .or. d2/d1 >= 1.0_wp) return
      qinf = q(n) - d2**2/(d2 - d1)
      rel = abs(q(n) - qinf)/max(abs(qinf), tiny(1.0_wp))
   end function goal_extrapolation

   !> Resultant, component `dof`, of the reactions on `nodes` (internal numbers) at the
   !> converged end of the run: F_int - F_ext on their supported or imposed components, the
   !> force the supports exert on the body.
   real(wp) function reaction_resultant(problem, nodes, dof) result(r)
      type(problem_t), intent(in) :: problem
      integer, intent(in) :: nodes(:), dof
      integer :: i, n, p
      real(wp) :: fext
      r = 0.0_wp
      do i = 1, size(nodes)
         n = nodes(i)
         if (problem%system%dofs%eq(dof, n) > 0) cycle
         fext = problem%system%initial_force(dof, n)
         do p = 1, size(problem%state%factors)
            fext = fext + problem%state%factors(p)*problem%system%pattern_force(dof, n, p)
         end do
         r = r + problem%position%fint_conv(dof, n) - fext
      end do
   end function reaction_resultant

   !> The loaded direction: the component (1 x/r, 2 y/z) in which the patterns of the steps
   !> at factor 1 (forces and imposed displacements) have the larger sum of magnitudes.
   integer function loaded_direction(model, problem) result(dof)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      real(wp) :: w(2)
      integer :: s, j, p
      w = 0.0_wp
      do s = 1, size(model%steps)
         do j = 1, size(model%steps(s)%pattern)
            p = model%steps(s)%pattern(j)
            w = w + sum(abs(problem%system%pattern_force(:, :, p)), dim=2) + &
               sum(abs(problem%system%pattern_disp(:, :, p)), dim=2)
         end do
      end do
      dof = merge(1, 2, w(1) > w(2))
   end function loaded_direction

   !> One quiet run of the whole load history to a scratch results file (discarded).
   !> With `peak`, the run must end at a limit load and `peak` is the load factor there of
   !> the first pattern of the step where the limit is (as in /limit); a run that reports no
   !> limit load is an error that says so.
   subroutine run_level(model, scratch, problem, wall, error, keep, peak)
      type(model_t), intent(inout) :: model
      character(len=*), intent(in) :: scratch
      type(problem_t), intent(out) :: problem
      real(wp), intent(out) :: wall
      type(error_t), allocatable, intent(out) :: error
      !> Keep the results file (default: deleted).
      logical, intent(in), optional :: keep
      real(wp), intent(out), optional :: peak
      type(results_file_t) :: results
      type(limit_point_t) :: limit
      type(joint_points_t), allocatable :: jpoints(:)
      character(len=:), allocatable :: message
      integer :: nflipped, status
      wall = wall_time()
      if (.not. present(keep)) model%output%every = huge(1)
      call prepare_run(model, problem, nflipped, jpoints, error)
      if (allocated(error)) return
      call results%create(scratch, model, VERSION, gauss_coordinates(model, problem), error, &
         jpoints)
      if (allocated(error)) return
      call run_increments(model, problem, results, .true., status, message, error, limit)
      if (present(keep)) then
         if (keep .and. .not. allocated(error)) then
            call results%finish(status, message, error)
         else
            call results%discard()
         end if
      else
         call results%discard()
      end if
      if (allocated(error)) return
      wall = wall_time() - wall
      if (present(peak)) then
         peak = 0.0_wp
         if (status == RUN_LIMIT_LOAD) then
            peak = limit%pattern_factors(model%steps(limit%step)%pattern(1))
         else
            call fatal_error(error, "the run ended with status '"//status_name(status)//"' ("//message// &
               ') and reports no limit load: the limit goal needs a run whose load path '// &
               'has a maximum (a force-controlled step to a load beyond the collapse load; '// &
               'CONTROL=ARC_LENGTH traces the peak)')
         end if
      else if (status /= RUN_COMPLETED) then
         call fatal_error(error, 'adaptive level did not complete: '//status_name(status)//' '//message)
      end if
   end subroutine run_level

   !> level, DOFs, elements, eta / ||sigma_h|| [%], goal, goal error [%], wall [s].
   subroutine print_level(k, lev)
      integer, intent(in) :: k
      type(adapt_level_t), intent(in) :: lev
      character(len=12) :: est
      if (lev%goal_error < 0.0_wp) then
         est = '-'
      else
         write (est, '(f11.4)') 100*lev%goal_error
      end if
      write (*, '(2x,i5,2x,i10,2x,i9,2x,f10.4,2x,es14.6,2x,a12,2x,f9.2)') k, lev%ndof, &
         lev%nelem, 100*lev%eta_rel, lev%goal, adjustr(est), lev%wall
   end subroutine print_level

end module pecplas_adapt_adapt
