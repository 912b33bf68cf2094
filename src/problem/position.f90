!> Where the step loop stands after the last converged increment: enough to resume it
!> (restart) exactly where it was. Kept by the driver in problem_t%position.
module pecplas_problem_position
   use pecplas_base_kinds, only: wp
   use pecplas_problem_arc_trace, only: arc_trace_t, PATH_NONE
   implicit none (type, external)
   private

   public :: run_position_t

   type :: run_position_t
      !> True when the step loop must start from this position (a restarted run).
      logical :: resume = .false.
      !> Step, converged increments in the step, step fraction reached, next increment size
      !> (fraction of the step) and halving level.
      integer :: istep = 1, inc_in_step = 0, level = 0
      real(wp) :: tau = 0.0_wp, dt = 0.0_wp
      !> Secant stiffness of the first loaded and of the last converged increment.
      real(wp) :: k_first = 0.0_wp, k_conv = 0.0_wp
      !> Pattern factors at the start of the step, internal forces of the converged state.
      real(wp), allocatable :: f0(:), fint_conv(:, :)
      !> Free displacement increment of the last converged increment (the arc-length
      !> predictor's direction and the limit probe's first length); may be unallocated.
      real(wp), allocatable :: du_prev(:)
      !> Step fraction that increment spanned when it was load controlled (the scale of the
      !> next increment's extrapolated start); 0 after an arc-length increment.
      real(wp) :: dtau_prev = 0.0_wp
      !> Displacement conjugate to the step's load, q.u, at the start of the step (the
      !> origin of a plateau's doubling, pecplas_solve_arc_path).
      real(wp) :: s_step0 = 0.0_wp
      !> The arc-length path under way (PATH_STEP, PATH_PROBE: pecplas_problem_arc_trace), or
      !> PATH_NONE, and its state.
      integer :: path = PATH_NONE
      type(arc_trace_t) :: arc
      !> The method the next increment's chain of methods starts with (pecplas_solve_attempts:
      !> a later method of the chain that converged the last increment), 0 for the run's own.
      integer :: lead = 0
      !> Test hook (--stop-after-increments N): stop with status 'interrupted' once the run
      !> has N converged increments in all (0: never).
      integer :: stop_after = 0
      !> The restart data written with the last increment make a restarted run exact (they
      !> carry the last factorised matrix and, when due, the points' tangents).
      logical :: exact = .false.
   contains
      procedure :: record => position_record
      procedure :: stop_now => position_stop_now
   end type run_position_t

contains

   !> Records the position after a converged increment, with `arc` the path it belongs to
   !> (absent: a load-controlled increment, of step fraction `dtau_prev`).
   subroutine position_record(this, istep, inc_in_step, tau, dt, level, k_first, k_conv, f0, &
         fint_conv, du_prev, arc, dtau_prev)
      class(run_position_t), intent(inout) :: this
      integer, intent(in) :: istep, inc_in_step, level
      real(wp), intent(in) :: tau, dt, k_first, k_conv, f0(:), fint_conv(:, :)
      !> The increment's free displacement increment (as accept_increment keeps it).
      real(wp), allocatable, intent(in) :: du_prev(:)
      type(arc_trace_t), intent(in), optional :: arc
      real(wp), intent(in), optional :: dtau_prev
      this%istep = istep
      this%inc_in_step = inc_in_step
      this%tau = tau
      this%dt = dt
      this%level = level
      this%k_first = k_first
      this%k_conv = k_conv
      this%f0 = f0
      this%fint_conv = fint_conv
      if (allocated(du_prev)) this%du_prev = du_prev
      this%dtau_prev = 0.0_wp
      if (present(dtau_prev)) this%dtau_prev = dtau_prev
      this%path = PATH_NONE
      if (present(arc)) then
         this%path = arc%req%origin
         this%arc = arc
      end if
   end subroutine position_record

   !> True when the --stop-after-increments hook stops the run after `increments` converged
   !> increments (never after the last one: that run is complete).
   pure logical function position_stop_now(this, finished, increments) result(stop)
      class(run_position_t), intent(in) :: this
      logical, intent(in) :: finished
      integer, intent(in) :: increments
      stop = this%stop_after > 0 .and. increments >= this%stop_after .and. .not. finished
   end function position_stop_now

end module pecplas_problem_position
