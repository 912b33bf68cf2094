!> The adaptive loop: solve, estimate (Zienkiewicz–Zhu, pecplas_driver_estimator), mark
!> (bulk marking), refine locally (pecplas_model_refine_local), re-solve, until the estimated
!> error of the goal is below the target or the DOF budget is reached.
!> Goals: the energy norm (estimate eta / ||sigma_h||), or one displacement component of a
!> node, whose error is estimated by Aitken extrapolation over the last three levels (the
!> difference to the last level when the sequence is not yet contracting), taking the larger
!> of the estimates at the last two levels so that one lucky level does not stop the loop.
!> Nonlinear and history-dependent runs: the whole load history is re-run on each new mesh
!> (no state transfer): the plastic state of a refined mesh then is that of its own
!> equilibrium path, with no transfer error, at a cost below twice that of the last level
!> when the DOFs grow geometrically.
module pecplas_driver_adapt
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t, fatal_error
   use pecplas_version, only: VERSION
   use pecplas_model, only: model_t
   use pecplas_model_refine_local, only: refine_marked
   use pecplas_model_refine_mark, only: bulk_marking
   use pecplas_driver_problem, only: problem_t
   use pecplas_driver_prepare, only: prepare_run
   use pecplas_driver_increments, only: run_increments
   use pecplas_driver_gauss, only: gauss_coordinates
   use pecplas_driver_estimator, only: error_estimate_t, estimate_error
   use pecplas_driver_timers, only: wall_time
   use pecplas_io_results_increment, only: joint_points_t
   use pecplas_io_results_file, only: results_file_t
   implicit none (type, external)
   private

   public :: adapt_options_t, adapt_level_t, adapt_model, run_level, goal_extrapolation

   type :: adapt_options_t
      !> Target relative error of the goal, bulk-marking fraction, budgets.
      real(wp) :: target = 0.01_wp, theta = 0.5_wp
      integer :: max_dofs = 100000, max_levels = 12
      !> Goal: 0 = energy norm; else the internal node and its component (1 x/r, 2 y/z).
      integer :: goal_node = 0, goal_dof = 0
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
      integer :: k
      allocate (levels(0))
      do k = 1, opts%max_levels
         call run_level(model, opts%scratch, problem, lev%wall, error, opts%keep)
         if (allocated(error)) return
         call estimate_error(model, problem, est, error)
         if (allocated(error)) return
         lev%ndof = problem%dofs%neq
         lev%nelem = model%mesh%nelem()
         lev%eta_rel = est%eta/max(est%energy, tiny(1.0_wp))
         if (opts%goal_node > 0) then
            lev%goal = problem%state%u(opts%goal_dof, opts%goal_node)
         else
            lev%goal = est%energy
         end if
         levels = [levels, lev]
         if (opts%goal_node > 0) then
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

   !> One quiet run of the whole load history to a scratch results file (discarded).
   subroutine run_level(model, scratch, problem, wall, error, keep)
      type(model_t), intent(inout) :: model
      character(len=*), intent(in) :: scratch
      type(problem_t), intent(out) :: problem
      real(wp), intent(out) :: wall
      type(error_t), allocatable, intent(out) :: error
      !> Keep the results file (default: deleted).
      logical, intent(in), optional :: keep
      type(results_file_t) :: results
      type(joint_points_t), allocatable :: jpoints(:)
      character(len=:), allocatable :: status, message
      integer :: nflipped
      wall = wall_time()
      if (.not. present(keep)) model%output%every = huge(1)
      call prepare_run(model, problem, nflipped, jpoints, error)
      if (allocated(error)) return
      call results%create(scratch, model, VERSION, gauss_coordinates(model, problem), error, &
         jpoints)
      if (allocated(error)) return
      call run_increments(model, problem, results, .true., status, message, error)
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
      if (status /= 'completed') call fatal_error(error, 'adaptive level did not complete: '// &
         status//' '//message)
      wall = wall_time() - wall
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

end module pecplas_driver_adapt
