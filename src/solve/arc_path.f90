!> Arc-length path following over one step (pecplas_solve_arc_length for the constraint):
!> increments of adapted length from the current converged state, with the step's load
!> factor an unknown, until the step's target load (landed on exactly by one
!> load-controlled increment), a target displacement of a node, a number of increments, a
!> maximum of the load that the path has passed, or a failure.
!> Used by *STEP, CONTROL=ARC_LENGTH and, from a force-controlled step that cannot be
!> converged, as the probe that tells a limit load from a convergence failure.
!>
!> The path starts at its first state, which is its first candidate for the peak, and goes
!> forward: its first increment raises the step fraction (the operator's response at a state
!> where the tangent fails is no guide to the direction), later ones follow the previous
!> increment. A maximum counts as passed only when the load has fallen below the peak by more
!> than the convergence test leaves undecided (load_noise) and by more than FALL_MIN of the
!> peak, and the displacement conjugate to
!> the step's load, s = q.u, has moved on beyond the peak's; an arc increment that ends below
!> the peak with s back behind it has turned onto an unloading branch (its load fell because the
!> structure unloaded, not because it passed a maximum) and is refused like one that did not
!> converge: the length is halved.
module pecplas_solve_arc_path
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_loads, only: step_t
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_method, only: attempt_t, outcome_t
   use pecplas_solve_attempts, only: run_t, try_chain, accept_increment
   use pecplas_solve_arc_length, only: adapt_length
   use pecplas_problem_arc_trace, only: arc_trace_t, arc_request_t, arc_end_t, END_TARGET, &
      END_PASSED, END_NODE, END_LIMIT, END_MAX, END_FAILED, END_UNLOADED, END_INTERRUPTED, &
      PATH_STEP
   use pecplas_solve_residual, only: load_vectors, free_part
   use pecplas_io_results_file, only: results_file_t
   use pecplas_solve_output, only: stop_pending
   use pecplas_base_strings, only: g6
   implicit none (type, external)
   private

   public :: trace_arc, BEYOND_PEAK, conjugate_displacement

   !> A plateau window opens where |current stiffness parameter| falls below SP_FLAT and
   !> counts once it has stayed there FLAT_COUNT increments.
   real(wp), parameter, public :: SP_FLAT = 2.0e-3_wp
   integer, parameter :: FLAT_COUNT = 3
   !> The window is a plateau (a limit load to this tolerance) when the displacement
   !> conjugate to the step's load, measured from the step's start, has doubled in it while
   !> the load rose by at most this share of itself; a window whose load rose more is closed
   !> and the next one opens there. Over a doubling of the displacement a load approaching
   !> its limit as 1/u rises by half its remaining distance to it, so the limit is then at
   !> most 2 PLATEAU_RISE above the load traced; a locking mesh climbs on by about the same
   !> share per doubling (doc/theory.md section 4, "Convergence, increment cutting and
   !> statuses").
   real(wp), parameter, public :: PLATEAU_RISE = 1.0e-3_wp
   !> On a plateau window the length may grow to this share of the free displacements'
   !> norm (beyond MAX_LENGTH times the first length), so that the displacement can double
   !> within the increments of the step or probe.
   real(wp), parameter :: PLATEAU_STRIDE = 0.5_wp
   !> ... and grows by at least this factor from one increment to the next (an arc too
   !> long for the path costs two halvings to come back).
   real(wp), parameter :: PLATEAU_GROWTH = 4.0_wp
   !> A maximum counts once the load has fallen in this many increments after it, each
   !> below the peak by more than the load noise of the convergence test (load_noise).
   integer, parameter :: BEYOND_PEAK = 2
   !> ... and below it by more than this share of the peak's step fraction: a fall smaller
   !> than 0.1 % of the load is no maximum an engineer reads off the curve, and near a
   !> singular tangent (a stiff penalty joint) two converged states of a rising path were
   !> measured 1.04 times the load noise apart. A path that levels off is caught by the
   !> flatness test (SP_FLAT) instead.
   real(wp), parameter :: FALL_MIN = 1.0e-3_wp
   !> Load-controlled step that tests a singular tangent for a mechanism (step fraction).
   real(wp), parameter :: PROBE_STEP = 1.0e-3_wp
   !> An arc-length step with a target displacement v of a node ends within this share of
   !> |v| of it (land_on_node), found in at most MAX_LANDINGS solves of the last increment.
   real(wp), parameter :: NODE_LANDING = 1.0e-6_wp
   integer, parameter :: MAX_LANDINGS = 12

contains

   !> Follows the path of `tr` (its request set up, or a path restored from a restart with
   !> tr%started) until it ends (tr%res%kind). After every converged increment the trace,
   !> updated as the next increment will need it, is recorded in the run's position before
   !> the increment is written, so that a restart goes on exactly where the path was.
   subroutine trace_arc(model, problem, results, run, istep, f0, ftarget, inc_in_step, tr, &
         error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(results_file_t), intent(inout) :: results
      type(run_t), intent(inout) :: run
      integer, intent(in) :: istep
      real(wp), intent(in) :: f0(:), ftarget(:)
      integer, intent(inout) :: inc_in_step
      type(arc_trace_t), intent(inout) :: tr
      type(error_t), allocatable, intent(out) :: error
      type(attempt_t) :: att
      type(outcome_t) :: out
      real(wp), allocatable :: u(:, :), fint(:, :), reaction(:, :), fq(:, :)
      real(wp) :: tau, k_inc, time, s, noise, tau_before, dl_ok
      integer :: method, wanted
      logical :: landed

      associate (step => model%steps(istep), req => tr%req, res => tr%res, dl => tr%dl, &
                 dl0 => tr%dl0, level => tr%level, nflat => tr%nflat, lc_mode => tr%lc_mode)
         att%f0 = f0
         att%ftarget = ftarget
         wanted = step%iterations_wanted
         call step_load(problem, f0, ftarget, fq)
         if (tr%started) then
            ! a restored path: the checks the interrupted run made after its last increment
            tau = res%tau
            res%kind = path_end(step, res, req, problem%state%u)
            if (res%kind /= 0) return
         else
            tau = req%tau_start
            dl = req%dl
            if (.not. (dl > 0.0_wp)) then
               call first_length(problem, f0, ftarget, req%dtau_first, dl, error)
               if (allocated(error)) return
            end if
            dl0 = dl
            level = 0
            nflat = 0
            lc_mode = .false.
            res%tau = tau
            res%reason = ''
            ! the first state of the path: the peak until an increment rises above it
            res%tau_peak = tau
            res%peak_increment = problem%stats%increments
            res%peak_factors = att%factors(tau)
            res%s_peak = sum(fq*problem%state%u)
            res%s_now = res%s_peak - req%s_step0
            res%rise = -1.0_wp
            res%beyond = 0
            tr%started = .true.
         end if
         do while (res%increments < req%max_increments)
            if (lc_mode) then
               ! load control where it converges (after a singular arc iteration that a
               ! load-controlled step passed): increments of 1/INCREMENTS of the step
               att%arc = .false.
               att%tau0 = tau
               att%tau1 = min(tau + 1.0_wp/step%increments, 1.0_wp)
               call try_chain(model, problem, run, att, u, fint, reaction, out, method, error)
               if (allocated(error)) return
               noise = 0.0_wp
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
               ! the first increment of the path raises the load (no previous increment
               ! directs the predictor), the next ones follow the previous increment
               if (allocated(att%du_prev)) deallocate (att%du_prev)
               if (allocated(run%du_prev) .and. res%increments > 0) att%du_prev = run%du_prev
               ! on a plateau window: a secant predictor where the tangent is not at hand
               att%secant = nflat >= FLAT_COUNT .and. res%increments > 0
               call try_chain(model, problem, run, att, u, fint, reaction, out, method, error)
               if (allocated(error)) return
               landed = .false.
               noise = 0.0_wp
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
                  else if (out%singular) then
                     ! singular again: no equilibrium under any states the iteration finds
                     res%mechanism = .true.
                     out%reason = 'the tangent with the next slip/contact states is singular and '// &
                        'no equilibrium exists a little further (step fraction '// &
                        g6(att%tau1)//'): '//out%reason
                  else
                     ! the step failed otherwise (contact states that do not settle, a law
                     ! that cannot return): that proves no mechanism, the load may go on
                     res%mechanism = .false.
                     out%reason = 'the load-controlled step to step fraction '//g6(att%tau1)// &
                        ' that tests the singular tangent for a mechanism failed without a '// &
                        'singular system (no mechanism established): '//out%reason
                  end if
               end if
               ! past the step's target displacement of a node: shortened so that it ends
               ! there, as the target load is landed on (the end state of the step is the
               ! state at that displacement, whatever the increments)
               if (att%arc .and. out%converged .and. step%node > 0 .and. &
                   req%origin == PATH_STEP) then
                  call land_on_node(model, problem, run, step, att, u, fint, reaction, out, &
                     method, error)
                  if (allocated(error)) return
               end if
               if (att%arc .and. out%converged) then
                  noise = load_noise(problem, model%solver%tolerance, att, out%tau, reaction, fq)
                  if (turned_back(res, out%tau, sum(fq*u), noise)) then
                     out%converged = .false.
                     res%mechanism = .false.
                     out%reason = 'the path turns back: the arc increment ends at step '// &
                        'fraction '//g6(out%tau)//', below the largest '//g6(res%tau_peak)// &
                        ', with the loaded points moved back (an unloading branch, no '// &
                        'maximum passed)'
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
               problem%stats%cuts = problem%stats%cuts + 1
               ! (an arc grown on a plateau window is halved but not below the last
               ! converged arc, which the path followed: once that fails too, halving goes on)
               dl_ok = 0.0_wp
               if (nflat >= FLAT_COUNT .and. res%increments > 0 .and. allocated(run%du_prev)) &
                  dl_ok = norm2(run%du_prev)
               if (dl > dl_ok) then
                  dl = max(0.5_wp*dl, dl_ok)
               else
                  dl = 0.5_wp*dl
               end if
               if (.not. run%quiet) write (*, '(a,es9.2)') '   no convergence: arc length cut to ', dl
               cycle
            end if
            res%mechanism = .false.
            tau_before = tau
            k_inc = (out%tau - tau)/max(norm2(out%du), tiny(1.0_wp))
            if (run%k_first == 0.0_wp) run%k_first = k_inc
            res%sp = k_inc/run%k_first
            tau = out%tau
            res%tau = tau
            res%increments = res%increments + 1
            inc_in_step = inc_in_step + 1
            time = req%time0 + req%time_span*real(res%increments, wp)/real(req%max_increments + 1, wp)
            if (landed) time = real(istep, wp)
            ! the load's maximum along the path, and whether it is flat (this increment will
            ! be the run's number problem%stats%increments + 1, at the factors accept_increment sets)
            s = sum(fq*u)
            if (tau > res%tau_peak) then
               res%tau_peak = tau
               res%peak_increment = problem%stats%increments + 1
               res%peak_factors = att%factors(tau)
               res%s_peak = s
               res%beyond = 0
            else if (tau < res%tau_peak - max(noise, FALL_MIN*res%tau_peak)) then
               ! below the peak by more than the convergence test leaves undecided and by
               ! more than FALL_MIN of it: the load fell (a fall within `noise` proves no
               ! maximum: two converged states of a rising path may lie that far apart, e.g.
               ! a stiff penalty joint whose states each converge just under the tolerance)
               res%beyond = res%beyond + 1
            end if
            res%s_now = s - req%s_step0
            ! the plateau window: opened by a flat increment (a small stiffness parameter, or
            ! a change of load the convergence test does not resolve: tiny arcs near a
            ! mechanism, whose stiffness is noise), kept while the load stays within
            ! PLATEAU_RISE of where it opened (plateau_test)
            call plateau_test(res, nflat, problem%stats%increments + 1, tau, &
               abs(res%sp) < SP_FLAT .or. abs(tau - tau_before) <= noise)
            ! the next increment's length, should the path go on (on a plateau window not yet
            ! established, up to PLATEAU_STRIDE of the displacements, so that they can double)
            if (nflat >= FLAT_COUNT .and. .not. res%flat) then
               ! (PLATEAU_GROWTH times longer at least: a plateau traced in increments of a
               ! fixed length, e.g. a rigid-plastic interface that converges each just under
               ! the tolerance, or arcs cut short where the tangent failed, would take
               ! thousands of them; an arc that grew too long is cut back as any, by halving)
               dl = min(max(adapt_length(dl, out%iterations, wanted, step%min_length*dl0, &
                  huge(1.0_wp)), PLATEAU_GROWTH*dl), max(step%max_length*dl0, &
                  PLATEAU_STRIDE*norm2(free_part(problem, u))))
            else
               dl = adapt_length(dl, out%iterations, wanted, step%min_length*dl0, &
                  step%max_length*dl0)
            end if
            level = 0
            ! (an increment that lands on the target ends the path: none goes on)
            if (landed) then
               call problem%position%record(istep, inc_in_step, tau, 0.0_wp, 0, run%k_first, &
                  0.0_wp, f0, fint, out%du)
            else
               call problem%position%record(istep, inc_in_step, tau, 0.0_wp, 0, run%k_first, &
                  0.0_wp, f0, fint, out%du, tr)
            end if
            ! landing on the target of the last step ends the run (END_TARGET below, and a
            ! load-control probe ends its step there): that increment is written once
            call accept_increment(model, problem, results, run, att, out, method, u, fint, &
               reaction, istep, inc_in_step, time, landed, merge(0, 1, landed .or. .not. att%arc), &
               error, landed .and. istep == size(model%steps))
            if (allocated(error)) return
            if (landed) then
               res%kind = END_TARGET
               return
            end if
            if (stop_pending(model, problem, .false.)) then
               res%kind = END_INTERRUPTED
               return
            end if
            res%kind = path_end(step, res, req, u)
            if (res%kind /= 0) return
         end do
         res%kind = END_MAX
         if (res%beyond >= BEYOND_PEAK .or. res%flat) res%kind = END_LIMIT
      end associate
   end subroutine trace_arc

   !> An arc increment (att, converged: u, fint, reaction, out, method) that ends past the
   !> step's target displacement v of its node (step%node, step%dof) is solved again with a
   !> shorter length, by regula falsi on the node's distance to v between the converged
   !> state (length 0, before v) and the lengths tried, until it ends within NODE_LANDING of
   !> |v| of it or MAX_LANDINGS solves were made (the path then goes on, or ends past v, from
   !> the last one). A solve that does not converge returns that outcome (the caller cuts).
   subroutine land_on_node(model, problem, run, step, att, u, fint, reaction, out, method, &
         error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(run_t), intent(in) :: run
      type(step_t), intent(in) :: step
      type(attempt_t), intent(inout) :: att
      real(wp), allocatable, intent(inout) :: u(:, :), fint(:, :), reaction(:, :)
      type(outcome_t), intent(inout) :: out
      integer, intent(inout) :: method
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: dir, tol, a, ga, b, gb, g
      integer :: k
      dir = sign(1.0_wp, step%displacement)
      tol = NODE_LANDING*abs(step%displacement)
      gb = (u(step%dof, step%node) - step%displacement)*dir
      ga = (problem%state%u(step%dof, step%node) - step%displacement)*dir
      ! not past, or the path started at or beyond v (path_end ends it)
      if (gb <= tol .or. ga >= 0.0_wp) return
      a = 0.0_wp
      b = att%dl
      do k = 1, MAX_LANDINGS
         call problem%state%rollback()
         att%dl = a - ga*(b - a)/(gb - ga)
         call try_chain(model, problem, run, att, u, fint, reaction, out, method, error)
         if (allocated(error) .or. .not. out%converged) return
         g = (u(step%dof, step%node) - step%displacement)*dir
         if (abs(g) <= tol) return
         if (g > 0.0_wp) then
            b = att%dl
            gb = g
         else
            a = att%dl
            ga = g
         end if
      end do
   end subroutine land_on_node

   !> A plateau window opens at global increment `inc`, step fraction tau, at the last
   !> converged state (res%s_now).
   pure subroutine open_window(res, inc, tau)
      type(arc_end_t), intent(inout) :: res
      integer, intent(in) :: inc
      real(wp), intent(in) :: tau
      res%flat_increment = inc
      res%tau_flat = tau
      res%s_flat = res%s_now
   end subroutine open_window

   !> Whether the path is on a plateau (res%flat), after a converged increment (global
   !> number `inc`, step fraction tau, res%s_now; `flat`: its stiffness parameter is small or
   !> its change of load unresolved). A flat increment opens a window when none is open;
   !> `nflat` counts the increments of the open window (0: none). The window closes when the
   !> load has risen above where it opened by more than PLATEAU_RISE of itself (this
   !> increment, if flat, opens the next one), and is a plateau once it holds FLAT_COUNT
   !> increments and the displacement conjugate to the load, from the step's start
   !> (res%s_flat, res%s_now), has doubled in it (res%rise: the window's rise then).
   pure subroutine plateau_test(res, nflat, inc, tau, flat)
      type(arc_end_t), intent(inout) :: res
      integer, intent(inout) :: nflat
      integer, intent(in) :: inc
      real(wp), intent(in) :: tau
      logical, intent(in) :: flat
      real(wp) :: top, rise
      res%flat = .false.
      if (nflat > 0) then
         ! the largest load in the window: the path's peak when it lies in the window
         top = tau
         if (res%peak_increment >= res%flat_increment) top = max(top, res%tau_peak)
         rise = (top - res%tau_flat)/max(abs(top), tiny(1.0_wp))
         if (rise > PLATEAU_RISE) then
            ! risen beyond the tolerance: no plateau here (the rise is kept for the message
            ! of a path that ends still rising)
            res%rise = rise
            nflat = 0
         else
            nflat = nflat + 1
         end if
      end if
      if (nflat == 0) then
         if (.not. flat) return
         call open_window(res, inc, tau)
         nflat = 1
      end if
      ! no displacement along the load yet (or against it): no doubling to measure
      if (nflat < FLAT_COUNT .or. .not. (res%s_flat > 0.0_wp)) return
      if (res%s_now < 2.0_wp*res%s_flat) return
      top = tau
      if (res%peak_increment >= res%flat_increment) top = max(top, res%tau_peak)
      res%rise = (top - res%tau_flat)/max(abs(top), tiny(1.0_wp))
      res%flat = .true.
   end subroutine plateau_test

   !> The displacement conjugate to the step's load (factors f0 -> ftarget), q.u, of the
   !> current state: the origin of the plateau's doubling when taken at the step's start.
   function conjugate_displacement(problem, f0, ftarget) result(s)
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: f0(:), ftarget(:)
      real(wp) :: s
      real(wp), allocatable :: fq(:, :)
      call step_load(problem, f0, ftarget, fq)
      s = sum(fq*problem%state%u)
   end function conjugate_displacement

   !> How the path ends after a converged, written increment that did not land on the
   !> target (0: it goes on), from the path so far and the displacements `u`.
   integer function path_end(step, res, req, u) result(kind)
      type(step_t), intent(in) :: step
      type(arc_end_t), intent(in) :: res
      type(arc_request_t), intent(in) :: req
      real(wp), intent(in) :: u(:, :)
      kind = 0
      if (req%tau_pass > 0.0_wp .and. res%tau > req%tau_pass .and. res%beyond == 0 .and. &
          .not. res%flat) then
         kind = END_PASSED
      else if (step%node > 0) then
         if ((u(step%dof, step%node) - step%displacement)*sign(1.0_wp, step%displacement) &
             >= -NODE_LANDING*abs(step%displacement)) kind = END_NODE
      end if
      if (kind /= 0) return
      if (res%beyond >= BEYOND_PEAK .and. res%tau <= 0.0_wp) then
         kind = END_UNLOADED
      else if (req%stop_at_limit .and. (res%beyond >= BEYOND_PEAK .or. res%flat)) then
         kind = END_LIMIT
      end if
   end function path_end

   !> The step's load per unit fraction, q (nodal layout), whose product with the
   !> displacements, s = q.u, is the displacement conjugate to the step's load.
   subroutine step_load(problem, f0, ftarget, fq)
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: f0(:), ftarget(:)
      real(wp), allocatable, intent(out) :: fq(:, :)
      real(wp), allocatable :: fbase(:, :), up(:, :)
      call load_vectors(problem, f0, ftarget, 0.0_wp, fbase, fq, up)
   end subroutine step_load

   !> An arc increment to step fraction tau with conjugate displacement s has turned back:
   !> it ends below the peak of the path with s not beyond the peak's, before a maximum is
   !> established (after that the path may go back, e.g. a snap-back).
   pure logical function turned_back(res, tau, s, noise)
      type(arc_end_t), intent(in) :: res
      real(wp), intent(in) :: tau, s, noise
      turned_back = tau < res%tau_peak - noise .and. s <= res%s_peak .and. &
         res%beyond < BEYOND_PEAK .and. .not. res%flat
   end function turned_back

   !> How far the step fraction of two converged states may differ by the convergence test
   !> alone: each leaves a residual up to tol max(||F_ext||, ||reactions||), worth that over
   !> ||q|| in step fraction (q the step's load on the free equations).
   real(wp) function load_noise(problem, tol, att, tau, reaction, fq) result(noise)
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: tol, tau, reaction(:, :), fq(:, :)
      type(attempt_t), intent(in) :: att
      real(wp), allocatable :: fbase(:, :), fq_(:, :), up(:, :)
      real(wp) :: qn
      noise = 0.0_wp
      qn = norm2(free_part(problem, fq))
      if (.not. (qn > 0.0_wp)) return
      call load_vectors(problem, att%f0, att%ftarget, tau, fbase, fq_, up)
      if (allocated(problem%phase%base_reaction)) then
         noise = 2.0_wp*tol*max(norm2(free_part(problem, fbase + tau*fq_ - &
            problem%system%initial_force)), norm2(reaction - problem%phase%base_reaction))/qn
      else
         noise = 2.0_wp*tol*max(norm2(free_part(problem, fbase + tau*fq_ - &
            problem%system%initial_force)), norm2(reaction))/qn
      end if
   end function load_noise

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
      call problem%linear%solver%solve(q, v, error)
      if (allocated(error)) return
      problem%stats%solves = problem%stats%solves + 1
      dl = dtau*norm2(v)
   end subroutine first_length

end module pecplas_solve_arc_path
