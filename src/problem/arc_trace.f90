!> The state of an arc-length path under way (pecplas_solve_arc_path): what was asked, the
!> length and cut level of the next increment, and what the path has shown so far (its
!> peak, a plateau). Kept after every converged increment of the path in the run's position
!> (pecplas_problem_position), so that a restarted run goes on along the same path, and
!> packed for the restart data as one vector of reals (`to_vector`, `from_vector`).
module pecplas_problem_arc_trace
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: arc_request_t, arc_end_t, arc_trace_t, PATH_NONE, PATH_STEP, PATH_PROBE
   public :: END_TARGET, END_PASSED, END_NODE, END_LIMIT, END_MAX, END_FAILED, END_UNLOADED, &
      END_INTERRUPTED

   integer, parameter :: END_TARGET = 1, END_PASSED = 2, END_NODE = 3, END_LIMIT = 4, &
      END_MAX = 5, END_FAILED = 6, END_UNLOADED = 7, END_INTERRUPTED = 8
   !> What a path is: none under way, a *STEP, CONTROL=ARC_LENGTH, or the probe of a
   !> load-controlled step that could not be converged at any cut.
   integer, parameter :: PATH_NONE = 0, PATH_STEP = 1, PATH_PROBE = 2
   !> Length of the packed vector (ARC_VECTOR_V1: restart data written before s_peak;
   !> ARC_VECTOR_V2: before the plateau's displacements s_step0, s_flat, s_now, rise).
   integer, parameter, public :: ARC_VECTOR = 31, ARC_VECTOR_V2 = 27, ARC_VECTOR_V1 = 26

   type :: arc_request_t
      integer :: origin = PATH_STEP
      !> Start: step fraction of the converged state; pass: stop as soon as the path is
      !> beyond this fraction and rising (the probe; <= 0 for none).
      real(wp) :: tau_start = 0.0_wp, tau_pass = -1.0_wp
      !> First length (<= 0: from dtau_first along the stiffness response) and increments.
      real(wp) :: dl = 0.0_wp, dtau_first = 0.1_wp
      integer :: max_increments = 10
      !> Stop as soon as a limit is established (the probe), else trace on.
      logical :: stop_at_limit = .false.
      !> Pseudo-time of the results file at the start of the path and its span.
      real(wp) :: time0 = 0.0_wp, time_span = 1.0_wp
      !> The probe: cuts of the load-controlled increment that failed, and why it failed.
      integer :: cuts = 0
      !> Displacement conjugate to the step's load, q.u, at the start of the step: the
      !> origin of the displacement whose doubling a plateau is measured over.
      real(wp) :: s_step0 = 0.0_wp
      character(len=:), allocatable :: why
   end type arc_request_t

   type :: arc_end_t
      integer :: kind = END_FAILED
      real(wp) :: tau = 0.0_wp
      integer :: increments = 0
      !> Peak: largest step fraction, where (global increment), increments traced beyond it,
      !> last current stiffness parameter; flat: the plateau criterion held. The path starts
      !> at its first state (tau_start), so the peak is never below the load it started from.
      real(wp) :: tau_peak = -huge(1.0_wp), sp = 1.0_wp
      !> Displacement conjugate to the step's load, q.u, at the peak: an increment counts as
      !> beyond the peak only when the loaded points have moved on past it (else the path
      !> turned back onto an unloading branch).
      real(wp) :: s_peak = -huge(1.0_wp)
      integer :: peak_increment = 0, beyond = 0
      real(wp), allocatable :: peak_factors(:)
      logical :: flat = .false.
      !> The arc iteration met singular states and no equilibrium exists a little further.
      logical :: mechanism = .false.
      !> Plateau: first increment of the open window, its step fraction and q.u there, q.u
      !> of the last converged state (both from the step's start, s_step0), and the load's
      !> rise (relative to the load) over the plateau, or over the last window that closed
      !> (< 0 while there is neither).
      integer :: flat_increment = 0
      real(wp) :: tau_flat = 0.0_wp, s_flat = 0.0_wp, s_now = 0.0_wp, rise = -1.0_wp
      character(len=:), allocatable :: reason
   end type arc_end_t

   !> A path: the request, the path so far (res), and the next increment's length dl (dl0
   !> the first), cut level, increments in the open plateau window, and whether it goes on by
   !> load control (lc_mode). `started`: set up (a first length chosen), to be continued.
   type :: arc_trace_t
      type(arc_request_t) :: req
      type(arc_end_t) :: res
      real(wp) :: dl = 0.0_wp, dl0 = 0.0_wp
      integer :: level = 0, nflat = 0
      logical :: lc_mode = .false., started = .false.
   contains
      procedure :: to_vector => trace_to_vector
      procedure :: from_vector => trace_from_vector
   end type arc_trace_t

contains

   !> The numbers of the trace (not the peak factors nor the texts) as reals, integers and
   !> logicals exactly.
   pure function trace_to_vector(this) result(v)
      class(arc_trace_t), intent(in) :: this
      real(wp) :: v(ARC_VECTOR)
      associate (q => this%req, r => this%res)
         v = [real(q%origin, wp), q%tau_start, q%tau_pass, q%dl, q%dtau_first, &
            real(q%max_increments, wp), flag(q%stop_at_limit), q%time0, q%time_span, &
            real(q%cuts, wp), this%dl, this%dl0, real(this%level, wp), real(this%nflat, wp), &
            flag(this%lc_mode), flag(this%started), r%tau, real(r%increments, wp), &
            r%tau_peak, r%sp, real(r%peak_increment, wp), real(r%beyond, wp), flag(r%flat), &
            flag(r%mechanism), real(r%flat_increment, wp), r%tau_flat, r%s_peak, q%s_step0, &
            r%s_flat, r%s_now, r%rise]
      end associate
   end function trace_to_vector

   !> The trace of `v` (from to_vector, ARC_VECTOR, ARC_VECTOR_V2 or ARC_VECTOR_V1 long: V1
   !> has no s_peak, so every increment below the peak counts as beyond it, as then; V1 and
   !> V2 no plateau displacements, so a plateau window begins afresh), with its peak factors
   !> and the probe's reason.
   subroutine trace_from_vector(this, v, peak_factors, why)
      class(arc_trace_t), intent(out) :: this
      real(wp), intent(in) :: v(:), peak_factors(:)
      character(len=*), intent(in) :: why
      associate (q => this%req, r => this%res)
         q%origin = nint(v(1)); q%tau_start = v(2); q%tau_pass = v(3); q%dl = v(4)
         q%dtau_first = v(5); q%max_increments = nint(v(6)); q%stop_at_limit = v(7) /= 0.0_wp
         q%time0 = v(8); q%time_span = v(9); q%cuts = nint(v(10)); q%why = why
         this%dl = v(11); this%dl0 = v(12); this%level = nint(v(13)); this%nflat = nint(v(14))
         this%lc_mode = v(15) /= 0.0_wp; this%started = v(16) /= 0.0_wp
         r%tau = v(17); r%increments = nint(v(18)); r%tau_peak = v(19); r%sp = v(20)
         r%peak_increment = nint(v(21)); r%beyond = nint(v(22)); r%flat = v(23) /= 0.0_wp
         r%mechanism = v(24) /= 0.0_wp; r%flat_increment = nint(v(25)); r%tau_flat = v(26)
         if (size(v) >= ARC_VECTOR_V2) r%s_peak = v(27)
         if (size(v) >= ARC_VECTOR) then
            q%s_step0 = v(28); r%s_flat = v(29); r%s_now = v(30); r%rise = v(31)
         else
            this%nflat = 0
         end if
         r%peak_factors = peak_factors
         r%reason = ''
      end associate
   end subroutine trace_from_vector

   pure real(wp) function flag(b)
      logical, intent(in) :: b
      flag = merge(1.0_wp, 0.0_wp, b)
   end function flag

end module pecplas_problem_arc_trace
