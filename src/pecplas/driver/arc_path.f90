!> Arc-length path following over one step (pecplas_driver_arc_length for the constraint):
!> increments of adapted length from the current converged state, with the step's load
!> factor an unknown, until the step's target load (landed on exactly by one
!> load-controlled increment), a target displacement of a node, a number of increments, a
!> maximum of the load that the path has passed, or a failure.
!> Used by *STEP, CONTROL=ARC_LENGTH and, from a force-controlled step that cannot be
!> converged, as the probe that tells a limit load from a convergence failure.
module pecplas_driver_arc_path
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t
   use pecplas_model, only: model_t
   use pecplas_model_loads, only: step_t
   use pecplas_driver_problem, only: problem_t
   use pecplas_driver_iterate, only: attempt_t, outcome_t
   use pecplas_driver_attempts, only: run_t, try_chain, accept_increment
   use pecplas_driver_arc_length, only: adapt_length
   use pecplas_driver_residual, only: load_vectors, free_part
   use pecplas_io_results_file, only: results_file_t
   use pecplas_signals, only: interrupt_requested
   use pecplas_strings, only: g6
   implicit none (type, external)
   private

   public :: arc_request_t, arc_end_t, trace_arc
   public :: END_TARGET, END_PASSED, END_NODE, END_LIMIT, END_MAX, END_FAILED, END_UNLOADED, &
      END_INTERRUPTED

   integer, parameter :: END_TARGET = 1, END_PASSED = 2, END_NODE = 3, END_LIMIT = 4, &
      END_MAX = 5, END_FAILED = 6, END_UNLOADED = 7, END_INTERRUPTED = 8

   !> The path has become flat when |current stiffness parameter| stays below this for
   !> FLAT_COUNT increments (the load no longer grows with the displacement: a plateau); the
   !> limit is where the plateau began, traced FLAT_COUNT - 1 increments beyond.
   real(wp), parameter :: SP_FLAT = 2.0e-3_wp
   integer, parameter :: FLAT_COUNT = 3
   !> A maximum counts once the load has fallen in this many increments after it.
   integer, parameter :: BEYOND_PEAK = 2
   !> Load-controlled step that tests a singular tangent for a mechanism (step fraction).
   real(wp), parameter :: PROBE_STEP = 1.0e-3_wp

   type :: arc_request_t
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
   end type arc_request_t

   type :: arc_end_t
      integer :: kind = END_FAILED
      real(wp) :: tau = 0.0_wp
      integer :: increments = 0
      !> Peak: largest step fraction, where (global increment), increments traced beyond it,
      !> last current stiffness parameter; flat: the plateau criterion held.
      real(wp) :: tau_peak = -huge(1.0_wp), sp = 1.0_wp
      integer :: peak_increment = 0, beyond = 0
      real(wp), allocatable :: peak_factors(:)
      logical :: flat = .false.
      !> The arc iteration met singular states and no equilibrium exists a little further.
      logical :: mechanism = .false.
      !> Plateau: first increment of the flat run and its step fraction.
      integer :: flat_increment = 0
      real(wp) :: tau_flat = 0.0_wp
      character(len=:), allocatable :: reason
   end type arc_end_t

contains

   subroutine trace_arc(model, problem, results, run, istep, f0, ftarget, inc_in_step, req, &
         res, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(results_file_t), intent(inout) :: results
      type(run_t), intent(inout) :: run
      integer, intent(in) :: istep
      real(wp), intent(in) :: f0(:), ftarget(:)
      integer, intent(inout) :: inc_in_step
      type(arc_request_t), intent(in) :: req
      type(arc_end_t), intent(out) :: res
      type(error_t), allocatable, intent(out) :: error
      type(attempt_t) :: att
      type(outcome_t) :: out
      real(wp), allocatable :: u(:, :), fint(:, :), reaction(:, :)
      real(wp) :: dl, dl0, tau, k_inc, time
      integer :: level, method, nflat, wanted
      logical :: landed, lc_mode

      associate (step => model%steps(istep))
         att%f0 = f0
         att%ftarget = ftarget
         tau = req%tau_start
         dl = req%dl
         if (.not. (dl > 0.0_wp)) then
            call first_length(problem, f0, ftarget, req%dtau_first, dl, error)
            if (allocated(error)) return
         end if
         dl0 = dl
         wanted = step%iterations_wanted
         level = 0
         nflat = 0
         lc_mode = .false.
         res%tau = tau
         res%reason = ''
         do while (res%increments < req%max_increments)
            if (lc_mode) then
               ! load control where it converges (after a singular arc iteration that a
               ! load-controlled step passed): increments of 1/INCREMENTS of the step
               att%arc = .false.
               att%tau0 = tau
               att%tau1 = min(tau + 1.0_wp/step%increments, 1.0_wp)
               call try_chain(model, problem, run, att, u, fint, reaction, out, method, error)
               if (allocated(error)) return
               if (.not. out%converged) then
                  call problem%state%rollback()
                  lc_mode = .false.
                  dl = dl0
                  cycle
               end if
               landed = att%tau1 >= 1.0_wp
            else
               att%arc = .true.
               att%dl = dl
               att%tau0 = tau
               att%tau1 = tau
               if (allocated(run%du_prev)) att%du_prev = run%du_prev
               call try_chain(model, problem, run, att, u, fint, reaction, out, method, error)
               if (allocated(error)) return
               landed = .false.
               if (out%converged .and. out%tau > 1.0_wp + 1.0e-12_wp) then
                  ! beyond the step's target: land on it with one load-controlled increment
                  call problem%state%rollback()
                  att%arc = .false.
                  att%tau1 = 1.0_wp
                  call try_chain(model, problem, run, att, u, fint, reaction, out, method, error)
                  if (allocated(error)) return
                  landed = out%converged
               end if
               if (.not. out%converged .and. .not. landed .and. out%singular) then
                  ! the states the arc iteration tried make the tangent singular: is the
                  ! structure a mechanism here, or did the iteration pick wrong states? A
                  ! load-controlled step a little further decides (it converges: go on)
                  call problem%state%rollback()
                  att%arc = .false.
                  att%tau1 = min(tau + PROBE_STEP, 1.0_wp)
                  call try_chain(model, problem, run, att, u, fint, reaction, out, method, error)
                  if (allocated(error)) return
                  landed = out%converged .and. att%tau1 >= 1.0_wp
                  if (out%converged) then
                     level = 0
                     lc_mode = .true.
                  else
                     res%mechanism = .true.
                     out%reason = 'the tangent with the next slip/contact states is singular and '// &
                        'no equilibrium exists a little further (step fraction '// &
                        g6(att%tau1)//'): '//out%reason
                  end if
               end if
            end if
            if (.not. out%converged) then
               call problem%state%rollback()
               if (level >= model%solver%max_cuts .or. dl <= step%min_length*dl0) then
                  res%kind = END_FAILED
                  res%reason = out%reason
                  return
               end if
               level = level + 1
               problem%cuts = problem%cuts + 1
               dl = 0.5_wp*dl
               if (.not. run%quiet) write (*, '(a,es9.2)') '   no convergence: arc length cut to ', dl
               cycle
            end if
            res%mechanism = .false.
            k_inc = (out%tau - tau)/max(norm2(out%du), tiny(1.0_wp))
            if (run%k_first == 0.0_wp) run%k_first = k_inc
            res%sp = k_inc/run%k_first
            tau = out%tau
            res%tau = tau
            res%increments = res%increments + 1
            inc_in_step = inc_in_step + 1
            time = req%time0 + req%time_span*real(res%increments, wp)/real(req%max_increments + 1, wp)
            if (landed) time = real(istep, wp)
            call problem%position%record(istep, inc_in_step, tau, 0.0_wp, 0, run%k_first, &
               0.0_wp, f0, fint)
            ! landing on the target of the last step ends the run (END_TARGET below, and a
            ! load-control probe ends its step there): that increment is written once
            call accept_increment(model, problem, results, run, att, out, method, u, fint, &
               reaction, istep, inc_in_step, time, landed, merge(0, 1, landed .or. .not. att%arc), &
               error, landed .and. istep == size(model%steps))
            if (allocated(error)) return
            ! the load's maximum along the path, and whether it is flat
            if (tau > res%tau_peak) then
               res%tau_peak = tau
               res%peak_increment = problem%increments
               res%peak_factors = problem%state%factors
               res%beyond = 0
            else
               res%beyond = res%beyond + 1
            end if
            nflat = merge(nflat + 1, 0, abs(res%sp) < SP_FLAT)
            if (nflat == 1) then
               res%flat_increment = problem%increments
               res%tau_flat = tau
            end if
            res%flat = nflat >= FLAT_COUNT
            if (landed) then
               res%kind = END_TARGET
               return
            end if
            if (interrupt_requested() .or. problem%position%stop_now(.false., &
                problem%increments)) then
               res%kind = END_INTERRUPTED
               return
            end if
            if (req%tau_pass > 0.0_wp .and. tau > req%tau_pass .and. res%beyond == 0 .and. &
                .not. res%flat) then
               res%kind = END_PASSED
               return
            end if
            if (step%node > 0) then
               if ((u(step%dof, step%node) - step%displacement)*sign(1.0_wp, step%displacement) &
                   >= 0.0_wp) then
                  res%kind = END_NODE
                  return
               end if
            end if
            if (res%beyond >= BEYOND_PEAK .and. tau <= 0.0_wp) then
               res%kind = END_UNLOADED
               return
            end if
            if (req%stop_at_limit .and. (res%beyond >= BEYOND_PEAK .or. res%flat)) then
               res%kind = END_LIMIT
               return
            end if
            dl = adapt_length(dl, out%iterations, wanted, step%min_length*dl0, &
               step%max_length*dl0)
            level = 0
         end do
         res%kind = END_MAX
         if (res%beyond >= BEYOND_PEAK .or. res%flat) res%kind = END_LIMIT
      end associate
   end subroutine trace_arc

   !> Length of an increment that would raise the step fraction by dtau along the response
   !> of the run's factorised matrix to the step's load.
   subroutine first_length(problem, f0, ftarget, dtau, dl, error)
      type(problem_t), intent(inout) :: problem
      real(wp), intent(in) :: f0(:), ftarget(:), dtau
      real(wp), intent(out) :: dl
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: fbase(:, :), fq(:, :), up(:, :), q(:), v(:)
      call load_vectors(problem, f0, ftarget, 0.0_wp, fbase, fq, up)
      q = free_part(problem, fq)
      allocate (v(size(q)))
      call problem%solver%solve(q, v, error)
      if (allocated(error)) return
      problem%solves = problem%solves + 1
      dl = dtau*norm2(v)
   end subroutine first_length

end module pecplas_driver_arc_path
