!> The incremental–iterative solution (thesis Annex A, extended): each load step is split
!> into increments, under load control (fixed fractions of the step) or arc-length control
!> (*STEP, CONTROL=ARC_LENGTH: pecplas_solve_arc_path). An increment is tried by the chain
!> of methods (pecplas_solve_attempts), then halved up to `max_cuts` times.
!>
!> Statuses, each a claim about the run:
!>   completed   every step reached its end;
!>   limit load  the load-displacement path has a maximum: the arc-length path passed it (the
!>               load fell in two increments after it, each below the peak by more than the
!>               convergence test's load noise, while the loaded points moved on) or
!>               has a plateau (the load rose by at most PLATEAU_RISE = 0.1 % while the
!>               displacement conjugate to it doubled: pecplas_solve_arc_path); a step that
!>               completes on a plateau says so in a warning; under load control a step
!>               that cannot be converged is probed by arc-length from the last converged
!>               state, which either passes the failed load (the run goes on) or establishes
!>               the maximum; /limit stores the largest converged load of the path (the
!>               probe's start included), never a load the path fell to;
!>   diverged    no equilibrium was found, with the reason of each method and the last
!>               converged state (increment, load factors);
!>   stopped     an arc-length step used its MAX_INCREMENTS before its target, a safety step
!>               (pecplas_solve_safety) its MAX_INCREMENTS before failure (a lower bound);
!>   interrupted a termination signal or --stop-after-increments: the run stopped after a
!>               converged increment and goes on with --restart.
module pecplas_solve_increments
   use pecplas_base_kinds, only: wp
   use pecplas_base_run_status, only: RUN_COMPLETED, RUN_LIMIT_LOAD, RUN_DIVERGED, RUN_STOPPED, &
      RUN_INTERRUPTED
   use pecplas_base_error, only: error_t, ERR_SINGULAR
   use pecplas_model_type, only: model_t
   use pecplas_model_loads, only: step_t, LOAD_DISPLACEMENT
   use pecplas_problem_type, only: problem_t
   use pecplas_problem_counts, only: mark_resume
   use pecplas_solve_method, only: attempt_t, outcome_t
   use pecplas_solve_attempts, only: run_t, try_chain, accept_increment
   use pecplas_solve_arc_path, only: trace_arc, BEYOND_PEAK, conjugate_displacement, SP_FLAT, &
      PLATEAU_RISE
   use pecplas_problem_arc_trace, only: arc_trace_t, arc_end_t, END_TARGET, END_PASSED, END_NODE, &
      END_LIMIT, END_MAX, END_FAILED, END_UNLOADED, END_INTERRUPTED, PATH_STEP, PATH_PROBE
   use pecplas_io_results_file, only: results_file_t
   use pecplas_io_results_increment, only: limit_point_t
   use pecplas_base_strings, only: itoa, g6
   use pecplas_base_timers, only: wall_time
   use pecplas_base_signals, only: interrupt_requested, interrupt_signal
   use pecplas_solve_output, only: stop_pending
   use pecplas_solve_progress, only: pattern_value, step_end_text
   use pecplas_phases_start, only: start_phase, LINE_LEN
   use pecplas_problem_phase, only: PROCEDURE_NAMES
   use pecplas_solve_stiffness, only: factorise_stiffness
   use pecplas_io_results_phases, only: write_phase
   use pecplas_solve_safety, only: safety_step, safety_not_started
   implicit none (type, external)
   private

   public :: run_increments

contains

   !> Runs every step. `status`: RUN_COMPLETED, RUN_LIMIT_LOAD, RUN_DIVERGED, RUN_STOPPED or
   !> RUN_INTERRUPTED (a termination signal, or the --stop-after-increments test hook);
   !> `message` says why a run stopped. Converged increments are written as they come.
   !> `limit`: where the limit is, when the status is RUN_LIMIT_LOAD (as written to /limit).
   !> `warning`: the steps that ended on a plateau of their load-displacement path, where
   !> the displacement reached is set by how slowly the load still rises ('' for none).
   subroutine run_increments(model, problem, results, quiet, status, message, error, limit, &
         warning)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(results_file_t), intent(inout) :: results
      logical, intent(in) :: quiet
      integer, intent(out) :: status
      character(len=:), allocatable, intent(out) :: message
      type(error_t), allocatable, intent(out) :: error
      type(limit_point_t), intent(out), optional :: limit
      character(len=:), allocatable, intent(out), optional :: warning
      type(run_t) :: run
      real(wp), allocatable :: f0(:), ftarget(:)
      integer :: istep, istep0

      call cpu_time(run%cpu_start)
      run%quiet = quiet
      run%plateau_warning = ''
      call run%eta%start(wall_time(), sum(model%steps%increments), 10.0_wp)
      status = RUN_COMPLETED
      message = 'all steps completed'
      ! the initial stresses are in equilibrium with their own nodal forces
      run%fint_conv = problem%system%initial_force
      istep0 = 1
      ! restart: resume the step loop where the run read back stopped (pecplas_solve_restart)
      if (problem%position%resume) then
         run%fint_conv = problem%position%fint_conv
         istep0 = problem%position%istep
         if (allocated(problem%position%du_prev)) run%du_prev = problem%position%du_prev
         run%resumed_at = problem%stats%increments
         ! the set-up and restore of this process are no part of the whole run's counts
         call mark_resume(problem)
         ! a phased run goes on in the phase in force: the new file records it (a safety
         ! step records its own below)
         if (problem%phase%phased .and. .not. model%steps(istep0)%safety%on) then
            call record_phase(model, problem, results, run, istep0, [character(len=LINE_LEN) :: &
               'resumed by a restart (the changes of this phase were made by the run before)'], &
               error)
            if (allocated(error)) return
         end if
      end if
      do istep = istep0, size(model%steps)
         ! a safety step (strength reduction) is the last: from the state the steps before
         ! left (pecplas_solve_safety)
         if (model%steps(istep)%safety%on) then
            if (problem%phase%phased) then
               call record_phase(model, problem, results, run, istep, &
                  [character(len=LINE_LEN) :: &
                  'safety: strengths divided by Msf until no equilibrium exists'], error)
               if (allocated(error)) return
            end if
            call safety_step(model, problem, results, run, istep, status, message, error)
            ! stopped after an increment of it (a signal, --stop-after-increments)
            if (.not. allocated(error) .and. status == RUN_INTERRUPTED) &
               call interrupted_status(problem, status, message)
            exit
         end if
         ! a phased run: the step's changes at its start (a resumed step has them already)
         if (problem%phase%phased .and. .not. problem%position%resume) then
            call begin_phase(model, problem, results, run, istep, error)
            if (allocated(error)) then
               ! the phase's changes leave a mechanism: no equilibrium, the run stops here
               if (error%kind /= ERR_SINGULAR) return
               call phase_mechanism(model, problem, istep, error, status, message)
               deallocate (error)
               exit
            end if
         end if
         f0 = problem%state%factors
         if (problem%position%resume) f0 = problem%position%f0
         ftarget = f0
         ftarget(model%steps(istep)%pattern) = model%steps(istep)%target
         run%k_first = 0.0_wp
         if (problem%position%resume) run%k_first = problem%position%k_first
         ! the origin of a plateau's doubling (kept in the position for a restart)
         if (.not. problem%position%resume) problem%position%s_step0 = &
            conjugate_displacement(problem, f0, ftarget)
         if (model%steps(istep)%arc_length) then
            call arc_step(model, problem, results, run, istep, f0, ftarget, status, message, &
               error)
         else
            call load_step(model, problem, results, run, istep, f0, ftarget, status, message, &
               error)
         end if
         if (allocated(error) .or. status /= RUN_COMPLETED) exit
      end do
      if (allocated(error)) return
      ! a run that fails before its safety step: unstable before reduction, no factor
      if ((status == RUN_LIMIT_LOAD .or. status == RUN_DIVERGED) .and. &
          model%steps(size(model%steps))%safety%on) then
         call safety_not_started(model, problem, results, size(model%steps), message, error)
         if (allocated(error)) return
      end if
      if (status == RUN_LIMIT_LOAD) call results%write_limit(run%limit, error)
      if (present(limit) .and. status == RUN_LIMIT_LOAD) limit = run%limit
      if (present(warning)) warning = run%plateau_warning
   end subroutine run_increments

   !> The start of step istep of a phased run (pecplas_phases_start): its changes applied,
   !> the stiffness factorised again when they changed it, the phase in the results file.
   subroutine begin_phase(model, problem, results, run, istep, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(results_file_t), intent(inout) :: results
      type(run_t), intent(inout) :: run
      integer, intent(in) :: istep
      type(error_t), allocatable, intent(out) :: error
      character(len=LINE_LEN), allocatable :: lines(:)
      logical :: refactorise
      call start_phase(model, problem, istep, run%fint_conv, refactorise, lines, error)
      if (allocated(error)) return
      ! equations numbered again: the last increment's displacement is of the old numbering
      if (problem%phase%renumbered .and. allocated(run%du_prev)) deallocate (run%du_prev)
      if (refactorise) then
         call factorise_stiffness(model, problem, .false., error)
         if (allocated(error)) return
      end if
      call record_phase(model, problem, results, run, istep, lines, error)
      if (allocated(error)) return
      if (.not. run%quiet .and. size(lines) > 0) then
         write (*, '(a)') ' phase '//itoa(istep)//' ('//model%steps(istep)%name//'):'
         block
            integer :: i
            do i = 1, size(lines)
               write (*, '(a)') '   '//trim(lines(i))
            end do
         end block
      end if
   end subroutine begin_phase

   !> The phase of step istep in the results file (/phases), with the sets active in it.
   !> The first phase a restarted run writes (the records before its first increment replace
   !> each other) also says how the initial state came about, as phase 1 of the run did (the
   !> file's attribute initial_procedure).
   subroutine record_phase(model, problem, results, run, istep, lines, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      type(results_file_t), intent(inout) :: results
      type(run_t), intent(in) :: run
      integer, intent(in) :: istep
      character(len=*), intent(in) :: lines(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: KEY = 'initial procedure: '
      logical, allocatable :: eactive(:), jactive(:)
      character(len=LINE_LEN), allocatable :: told(:)
      integer :: i
      eactive = problem%state%sets%active
      allocate (jactive(0))
      if (allocated(problem%state%joints%sets)) jactive = problem%state%joints%sets%active
      if (run%resumed_at >= 0 .and. problem%stats%increments == run%resumed_at .and. &
          .not. any(index(lines, KEY) == 1)) then
         allocate (told(size(lines) + 1))
         told(1) = KEY//trim(PROCEDURE_NAMES(problem%phase%procedure))
         do i = 1, size(lines)
            told(i + 1) = lines(i)
         end do
         call write_phase(results, istep, model%steps(istep)%name, told, eactive, jactive, error)
      else
         call write_phase(results, istep, model%steps(istep)%name, lines, eactive, jactive, error)
      end if
   end subroutine record_phase

   !> A load-controlled step: fractions 1/INCREMENTS of the step, halved on failure and
   !> grown back after success.
   subroutine load_step(model, problem, results, run, istep, f0, ftarget, status, message, &
         error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(results_file_t), intent(inout) :: results
      type(run_t), intent(inout) :: run
      integer, intent(in) :: istep
      real(wp), intent(in) :: f0(:), ftarget(:)
      integer, intent(inout) :: status
      character(len=:), allocatable, intent(inout) :: message
      type(error_t), allocatable, intent(out) :: error
      type(attempt_t) :: att
      type(outcome_t) :: out
      type(arc_trace_t) :: probe
      real(wp), allocatable :: u(:, :), fint(:, :), reaction(:, :)
      real(wp) :: tau, dt, dt0, sp_last
      integer :: level, inc, method
      logical :: probing

      associate (step => model%steps(istep))
         att%f0 = f0
         att%ftarget = ftarget
         dt0 = 1.0_wp/step%increments
         dt = dt0
         tau = 0.0_wp
         level = 0
         inc = 0
         probing = .false.
         sp_last = 1.0_wp
         if (problem%position%resume) then
            associate (pos => problem%position)
               dt = pos%dt; tau = pos%tau; level = pos%level; inc = pos%inc_in_step
               ! (restart data of an older version stopped inside a probe hold no size)
               if (.not. (dt > 0.0_wp)) dt = dt0
               ! stopped in the middle of a limit probe: go on with it
               probing = pos%path == PATH_PROBE
               if (probing) then
                  probe = pos%arc
                  tau = probe%req%tau_start; dt = probe%req%dtau_first; level = probe%req%cuts
               end if
               pos%resume = .false.
            end associate
         end if
         do while (tau < 1.0_wp - 1.0e-12_wp)
            if (.not. probing) then
               dt = min(dt, 1.0_wp - tau)
               att%arc = .false.
               att%tau0 = tau
               att%tau1 = tau + dt
               call extrapolated_start(problem, run, inc, dt, att)
               call try_chain(model, problem, run, att, u, fint, reaction, out, method, error)
               if (allocated(error)) return
            end if
            if (probing .or. .not. out%converged) then
               if (.not. probing) then
                  if (level < model%solver%max_cuts) then
                     level = level + 1
                     problem%stats%cuts = problem%stats%cuts + 1
                     dt = 0.5_wp*dt
                     if (.not. run%quiet) write (*, '(a,es9.2,a)') &
                        '   no convergence: increment cut to ', dt, ' of the step'
                     cycle
                  end if
                  if (.not. probe_allowed(model, f0, ftarget)) then
                     call diverged(model, problem, istep, tau + dt, level, out%reason, status, &
                        message)
                     return
                  end if
                  ! cannot be converged at any cut: is it a maximum of the load?
                  if (.not. run%quiet) write (*, '(a)') '   no convergence at any cut: '// &
                     'probing the path by arc-length from the last converged state'
                  call probe_request(model, istep, tau, dt, level, out%reason, run%k_first, &
                     problem%position%s_step0, probe)
               end if
               probing = .false.
               call trace_arc(model, problem, results, run, istep, f0, ftarget, inc, probe, &
                  error)
               if (allocated(error)) return
               associate (res => probe%res, why => probe%req%why)
                  select case (res%kind)
                  case (END_INTERRUPTED)
                     call interrupted_status(problem, status, message)
                  case (END_PASSED, END_TARGET)
                     ! a convergence failure, not a limit: load control goes on from here
                     ! (a probe that landed on the target: the run may have to stop there)
                     if (res%kind == END_TARGET) then
                        sp_last = res%sp
                        if (interrupted(model, problem, istep, 1.0_wp, status, message)) return
                     end if
                     tau = res%tau
                     level = 0
                     dt = dt0
                     cycle
                  case (END_LIMIT, END_UNLOADED)
                     call limit_reached(model, problem, run, step, istep, res, status, message)
                  case (END_FAILED)
                     if (mechanism(res)) then
                        call limit_reached(model, problem, run, step, istep, res, status, message)
                     else
                        call diverged(model, problem, istep, tau + dt, level, why//'; the '// &
                           'arc-length probe from fraction '//g6(tau)//' '//probe_failure(res), &
                           status, message)
                     end if
                  case default
                     call diverged(model, problem, istep, tau + dt, level, why//'; the '// &
                        'arc-length probe from fraction '//g6(tau)//' '//probe_failure(res), &
                        status, message)
                  end select
               end associate
               return
            end if
            tau = att%tau1
            inc = inc + 1
            if (run%k_first == 0.0_wp .and. allocated(out%du)) &
               run%k_first = dt/max(norm2(out%du), tiny(1.0_wp))
            ! the current stiffness parameter of this increment (the step's end on a plateau)
            sp_last = 1.0_wp
            if (run%k_first > 0.0_wp .and. allocated(out%du)) &
               sp_last = dt/max(norm2(out%du), tiny(1.0_wp))/run%k_first
            ! the loop's position after this increment (the size grows back below), for the
            ! restart data written with the increment
            call problem%position%record(istep, inc, tau, merge(min(dt0, 2.0_wp*dt), dt, &
               level > 0), max(level - 1, 0), run%k_first, 0.0_wp, f0, fint, out%du, &
               dtau_prev=dt)
            ! the end of the last step ends the run: that increment is written once
            call accept_increment(model, problem, results, run, att, out, method, u, fint, &
               reaction, istep, inc, real(istep - 1, wp) + tau, tau >= 1.0_wp - 1.0e-12_wp, 0, &
               error, tau >= 1.0_wp - 1.0e-12_wp .and. istep == size(model%steps))
            if (allocated(error)) return
            if (interrupted(model, problem, istep, tau, status, message)) return
            if (level > 0) then
               level = level - 1
               dt = min(dt0, 2.0_wp*dt)
            end if
         end do
         ! reached its end on a plateau: say so (the displacement is not the soil's answer)
         if (abs(sp_last) < SP_FLAT .and. force_driven(model, f0, ftarget)) &
            call plateau_end(model, istep, sp_last, run)
      end associate
   end subroutine load_step

   !> Step istep reached its target with its last increment on a plateau of the
   !> load-displacement path (current stiffness parameter sp, |sp| < SP_FLAT): the run's
   !> warning says that the displacement reached is set by how slowly the load still rises
   !> there and is unbounded in small-strain terms.
   subroutine plateau_end(model, istep, sp, run)
      type(model_t), intent(in) :: model
      integer, intent(in) :: istep
      real(wp), intent(in) :: sp
      type(run_t), intent(inout) :: run
      if (len(run%plateau_warning) > 0) run%plateau_warning = run%plateau_warning//'; '
      run%plateau_warning = run%plateau_warning//'step '//itoa(istep)//' ('// &
         model%steps(istep)%name//') reached its load on a plateau of the load-displacement '// &
         'path (its last increment''s stiffness is '//g6(sp)//' times its first, below '// &
         g6(SP_FLAT)//'): the load is at or near the limit of this model, and the '// &
         'displacement reached is set by how slowly the load still rises there (unbounded in '// &
         'small-strain terms, not a settlement of the soil); an arc-length step shows whether '// &
         'the path still rises (doc/theory.md section 4)'
   end subroutine plateau_end

   !> The extrapolated start of a load-controlled increment of size `dt` (att%du_start): the
   !> previous converged increment of the same step (`inc` > 0 of them converged), when it
   !> was load controlled too, scaled by dt over its size. Along one step the imposed
   !> displacements and loads grow in proportion to the step fraction, so the scaled
   !> increment continues the path the last one followed (iterate_increment decides whether
   !> to start from it).
   subroutine extrapolated_start(problem, run, inc, dt, att)
      type(problem_t), intent(in) :: problem
      type(run_t), intent(in) :: run
      integer, intent(in) :: inc
      real(wp), intent(in) :: dt
      type(attempt_t), intent(inout) :: att
      if (allocated(att%du_start)) deallocate (att%du_start)
      if (inc < 1 .or. .not. allocated(run%du_prev)) return
      if (.not. (problem%position%dtau_prev > 0.0_wp)) return
      if (size(run%du_prev) /= problem%system%dofs%neq) return
      att%du_start = (dt/problem%position%dtau_prev)*run%du_prev
   end subroutine extrapolated_start

   !> A step under arc-length control.
   subroutine arc_step(model, problem, results, run, istep, f0, ftarget, status, message, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(results_file_t), intent(inout) :: results
      type(run_t), intent(inout) :: run
      integer, intent(in) :: istep
      real(wp), intent(in) :: f0(:), ftarget(:)
      integer, intent(inout) :: status
      character(len=:), allocatable, intent(inout) :: message
      type(error_t), allocatable, intent(out) :: error
      type(arc_trace_t) :: path
      integer :: inc
      associate (step => model%steps(istep), res => path%res)
         inc = 0
         path%req%tau_start = 0.0_wp
         if (problem%position%resume) then
            path%req%tau_start = problem%position%tau
            inc = problem%position%inc_in_step
            ! the path under way when the run stopped (restart data of an older version
            ! hold none: a new path starts from the converged state)
            if (problem%position%path == PATH_STEP) path = problem%position%arc
            problem%position%resume = .false.
            ! stopped after the increment that landed on the step's target: step done
            if (path%req%tau_start >= 1.0_wp - 1.0e-12_wp) return
         end if
         if (.not. path%started) then
            path%req%origin = PATH_STEP
            path%req%dl = 0.0_wp
            path%req%dtau_first = 1.0_wp/step%increments
            path%req%max_increments = step%max_increments
            path%req%time0 = real(istep - 1, wp)
            path%req%s_step0 = problem%position%s_step0
         end if
         call trace_arc(model, problem, results, run, istep, f0, ftarget, inc, path, error)
         if (allocated(error)) return
         select case (res%kind)
         case (END_TARGET)
            ! the step ends on its target (on a plateau: say so); the run may have to stop
            ! after that increment
            if (abs(res%sp) < SP_FLAT) call plateau_end(model, istep, res%sp, run)
            if (interrupted(model, problem, istep, 1.0_wp, status, message)) return
         case (END_INTERRUPTED)
            call interrupted_status(problem, status, message)
         case (END_NODE)
            if (res%beyond > 0 .and. res%tau < res%tau_peak) then
               call limit_reached(model, problem, run, step, istep, res, status, message)
            else if (.not. run%quiet) then
               ! stopped at its node's displacement: the loads it reached (force patterns
               ! only under arc-length control, so no reaction sums are needed)
               write (*, '(a)') ' end of '//step_end_text(model, istep, problem%state%factors, &
                  problem%state%u, reshape([real(wp) ::], [2, 0]))
            end if
         case (END_LIMIT, END_UNLOADED)
            call limit_reached(model, problem, run, step, istep, res, status, message)
         case (END_FAILED)
            if (mechanism(res)) then
               call limit_reached(model, problem, run, step, istep, res, status, message)
            else
               call diverged(model, problem, istep, res%tau, model%solver%max_cuts, &
                  res%reason, status, message)
            end if
         case (END_MAX)
            status = RUN_STOPPED
            message = 'step '//itoa(istep)//' ('//step%name//'): MAX_INCREMENTS='// &
               itoa(step%max_increments)//' arc-length increments used at step fraction '// &
               g6(res%tau)//' before the target ('//peak_note(res)//')'
         case default
            call diverged(model, problem, istep, res%tau, model%solver%max_cuts, res%reason, &
               status, message)
         end select
      end associate
   end subroutine arc_step

   !> The limit probe of a load-controlled step whose increment from fraction `tau` (size
   !> `dt`, `cuts` halvings) failed for `why`: an arc-length path from the last converged
   !> state that ends as soon as it passes tau + dt rising or shows a limit. Its first
   !> length is the displacement the step's initial stiffness `k_first` (fraction per unit
   !> displacement of its first increment) gives for dt; without a converged increment in
   !> the step, the response of the factorised operator to dt. Not the length of the last
   !> increment: near a limit that increment may have run far along the plateau, and an arc
   !> that long from a state where the tangent fails converges, if at all, on an unloading
   !> branch.
   subroutine probe_request(model, istep, tau, dt, cuts, why, k_first, s_step0, probe)
      type(model_t), intent(in) :: model
      integer, intent(in) :: istep, cuts
      real(wp), intent(in) :: tau, dt, k_first, s_step0
      character(len=*), intent(in) :: why
      type(arc_trace_t), intent(out) :: probe
      associate (req => probe%req)
         req%origin = PATH_PROBE
         req%tau_start = tau
         req%tau_pass = tau + dt
         req%dl = 0.0_wp
         if (k_first > 0.0_wp) req%dl = dt/k_first
         req%dtau_first = dt
         req%max_increments = model%solver%limit_probe
         req%stop_at_limit = .true.
         req%s_step0 = s_step0
         req%time0 = real(istep - 1, wp) + tau
         req%time_span = 0.5_wp*dt
         req%cuts = cuts
         req%why = why
      end associate
   end subroutine probe_request

   !> A probe needs a growing force and no changing imposed displacement (unloading that
   !> fails is no limit), and a budget.
   logical function probe_allowed(model, f0, ftarget) result(ok)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: f0(:), ftarget(:)
      ok = model%solver%limit_probe > 0
      if (ok) ok = force_driven(model, f0, ftarget)
   end function probe_allowed

   !> The step (factors f0 -> ftarget) raises a force and changes no imposed displacement:
   !> its load-displacement path can have a limit.
   logical function force_driven(model, f0, ftarget) result(ok)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: f0(:), ftarget(:)
      integer :: p
      ok = .false.
      do p = 1, size(f0)
         if (model%patterns(p)%kind == LOAD_DISPLACEMENT) then
            if (ftarget(p) /= f0(p)) then
               ok = .false.
               return
            end if
         else if (abs(ftarget(p)) > abs(f0(p))) then
            ok = .true.
         end if
      end do
   end function force_driven

   subroutine limit_reached(model, problem, run, step, istep, res, status, message)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      type(run_t), intent(inout) :: run
      type(step_t), intent(in) :: step
      integer, intent(in) :: istep
      type(arc_end_t), intent(in) :: res
      integer, intent(inout) :: status
      character(len=:), allocatable, intent(inout) :: message
      status = RUN_LIMIT_LOAD
      run%limit%step = istep
      run%limit%stiffness_parameter = res%sp
      message = 'limit load in step '//itoa(istep)//' ('//step%name//'): '
      ! every kind reports the largest load traced; the plateau its start as the increment
      run%limit%global_increment = res%peak_increment
      run%limit%fraction = res%tau_peak
      run%limit%pattern_factors = res%peak_factors
      if (mechanism(res)) then
         ! the path rose to here; the next states make the tangent singular
         run%limit%kind = 'mechanism'
         message = message//'the structure becomes a mechanism at step fraction '// &
            g6(res%tau_peak)//' (increment '//itoa(res%peak_increment)//'): beyond it the '// &
            'tangent with the next slip/contact states is singular and no equilibrium exists '// &
            'a little further'
      else if (res%beyond >= 2 .or. .not. res%flat) then
         run%limit%kind = 'passed'
         message = message//'the load-displacement path has a maximum at step fraction '// &
            g6(res%tau_peak)//' (increment '//itoa(res%peak_increment)//'), traced '// &
            itoa(res%beyond)//' increments beyond it'
      else
         ! the plateau: where it began, and the largest load traced on it
         run%limit%kind = 'flat'
         run%limit%global_increment = res%flat_increment ! where the plateau began
         message = message//'the load-displacement path has a plateau, no maximum: from '// &
            'step fraction '//g6(res%tau_flat)//' (increment '//itoa(res%flat_increment)// &
            ') the load '//merge('rose by', 'fell by', res%rise >= 0.0_wp)//' '// &
            pct(abs(res%rise))//' (a plateau: a rise of at most '//pct(PLATEAU_RISE)// &
            ') while the displacement conjugate to it grew '//g6(growth(res))//' times '// &
            '(from the step''s start; current stiffness parameter '//g6(res%sp)//'), traced '// &
            itoa(problem%stats%increments - res%flat_increment)//' increments along it; its '// &
            'largest load, at step fraction '//g6(res%tau_peak)//', is the limit to that '// &
            'tolerance (a path approaching its limit as 1/u has it at most twice that rise '// &
            'above; a larger load may still be carried at a larger displacement)'
      end if
      message = message//'; load factors at the peak:'//factors_text(model, step, &
         run%limit%pattern_factors)
      if (problem%stats%increments > 0) message = message//'; every converged increment is in '// &
         'the results file (/limit says where the peak is)'
   end subroutine limit_reached

   !> True (with status RUN_INTERRUPTED) when the run must stop after this increment: a
   !> termination signal (SIGTERM, SIGINT, SIGHUP: pecplas_base_signals) or the
   !> --stop-after-increments test hook.
   logical function interrupted(model, problem, istep, tau, status, message)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      integer, intent(in) :: istep
      real(wp), intent(in) :: tau
      integer, intent(inout) :: status
      character(len=:), allocatable, intent(inout) :: message
      interrupted = stop_pending(model, problem, tau >= 1.0_wp - 1.0e-12_wp .and. &
         istep == size(model%steps))
      if (interrupted) call interrupted_status(problem, status, message)
   end function interrupted

   subroutine interrupted_status(problem, status, message)
      type(problem_t), intent(in) :: problem
      integer, intent(inout) :: status
      character(len=:), allocatable, intent(inout) :: message
      status = RUN_INTERRUPTED
      if (interrupt_requested()) then
         message = 'stopped by '//interrupt_signal()//' after increment '// &
            itoa(problem%stats%increments)//'; continue with --restart'
      else if (problem%position%stop_now(.false., problem%stats%increments)) then
         message = 'stopped after the requested number of increments '// &
            '(--stop-after-increments); continue with --restart'
      else
         message = 'stopped by a termination signal to another MPI rank after increment '// &
            itoa(problem%stats%increments)//'; continue with --restart'
      end if
   end subroutine interrupted_status

   !> An arc-length path that rose to its last converged point and cannot go on because the
   !> tangent with the next slip/contact states is singular, and a load-controlled step a
   !> little further (1e-3 of the step) finds no equilibrium either: the load-displacement
   !> path ends at a mechanism (a zero pivot: the limit of a rigid-plastic interface).
   logical function mechanism(res)
      type(arc_end_t), intent(in) :: res
      mechanism = res%kind == END_FAILED .and. res%increments > 0 .and. res%beyond == 0 .and. &
         res%mechanism
   end function mechanism

   !> Status RUN_DIVERGED for a stiffness that is singular after the changes at the start of
   !> phase istep (a support or the elements holding a part removed): the structure is a
   !> mechanism and no equilibrium exists; `error` names the free node and direction. The
   !> increments converged before stay in the results file.
   subroutine phase_mechanism(model, problem, istep, error, status, message)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      integer, intent(in) :: istep
      type(error_t), intent(in) :: error
      integer, intent(inout) :: status
      character(len=:), allocatable, intent(inout) :: message
      status = RUN_DIVERGED
      message = 'step '//itoa(istep)//' ('//model%steps(istep)%name//'): no equilibrium: '// &
         'the changes at the start of the phase leave a mechanism (singular stiffness): '// &
         error%text()//'; last converged state: '
      if (problem%stats%increments > 0) then
         message = message//'increment '//itoa(problem%stats%increments)
      else
         message = message//'the initial state'
      end if
      message = message//', kept in the results file'
   end subroutine phase_mechanism

   !> Status RUN_DIVERGED: where and why, and the last converged state (its increment and
   !> load factors), kept in the results file.
   subroutine diverged(model, problem, istep, tau_failed, cuts, reason, status, message)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      integer, intent(in) :: istep, cuts
      real(wp), intent(in) :: tau_failed
      character(len=*), intent(in) :: reason
      integer, intent(inout) :: status
      character(len=:), allocatable, intent(inout) :: message
      associate (step => model%steps(istep))
         status = RUN_DIVERGED
         message = 'step '//itoa(istep)//' ('//step%name//') did not converge at step '// &
            'fraction '//g6(tau_failed)//' after '//itoa(cuts)//' increment cuts ('//reason// &
            '); last converged state: '
         if (problem%stats%increments > 0) then
            message = message//'increment '//itoa(problem%stats%increments)
            if (len(factors_text(model, step, problem%state%factors)) > 0) message = &
               message//', load factors'//factors_text(model, step, problem%state%factors)
         else
            message = message//'the initial state'
         end if
         message = message//', kept in the results file'
      end associate
   end subroutine diverged

   !> ' name = value' for each pattern that has a factor or that the step drives, with what
   !> the factor means in the deck's quantities: ' push = 0.5 (resultant F_y = -73.4 kN)'.
   function factors_text(model, step, factors) result(text)
      type(model_t), intent(in) :: model
      type(step_t), intent(in) :: step
      real(wp), intent(in) :: factors(:)
      character(len=:), allocatable :: text
      character(len=:), allocatable :: value
      integer :: p
      text = ''
      do p = 1, size(factors)
         if (factors(p) /= 0.0_wp .or. any(step%pattern == p)) then
            text = text//' '//model%patterns(p)%name//' = '//g6(factors(p))
            ! what the factor means in the deck's units: '(resultant F_y = -160 kN)'
            value = pattern_value(model, p, factors(p))
            if (len(value) > 2) text = text//' ('//value(3:)//')'
         end if
      end do
   end function factors_text

   function probe_failure(res) result(text)
      type(arc_end_t), intent(in) :: res
      character(len=:), allocatable :: text
      select case (res%kind)
      case (END_MAX)
         text = 'traced '//itoa(res%increments)//' increments to fraction '//g6(res%tau)// &
            ' without passing the failed load ('//peak_note(res)//')'//window_note(res)
      case (END_NODE)
         text = 'reached the step''s target displacement'
      case default
         text = 'failed after '//itoa(res%increments)//' increments: '//res%reason// &
            window_note(res)
      end select
   end function probe_failure

   !> What an open plateau window had shown when a path failed: the load's change and the
   !> displacement's growth in it ('' for none).
   function window_note(res) result(text)
      type(arc_end_t), intent(in) :: res
      character(len=:), allocatable :: text
      real(wp) :: top
      text = ''
      if (res%flat_increment <= 0 .or. .not. (res%s_flat > 0.0_wp)) return
      top = res%tau
      if (res%peak_increment >= res%flat_increment) top = max(top, res%tau_peak)
      text = ' (the path was nearly flat from step fraction '//g6(res%tau_flat)// &
         ' (increment '//itoa(res%flat_increment)//'): the load changed by '// &
         pct((top - res%tau_flat)/max(abs(top), tiny(1.0_wp)))//' while the displacement '// &
         'conjugate to it grew '//g6(growth(res))//' times, short of the doubling that '// &
         'establishes a plateau: no limit load is claimed)'
   end function window_note

   !> What a path that used its increments says of a maximum: none when it still rises;
   !> otherwise its largest load and how many falls beyond the noise followed it (a maximum
   !> is established by BEYOND_PEAK of them, pecplas_solve_arc_path), so that a path whose
   !> load had fallen is not said to have met no maximum.
   function peak_note(res) result(text)
      type(arc_end_t), intent(in) :: res
      character(len=:), allocatable :: text
      if (.not. (res%tau < res%tau_peak)) then
         text = 'no maximum of the load on the way'
         if (res%rise >= 0.0_wp) text = text//'; the path is nearly flat but still rises: '// &
            'its last plateau window closed when the load had risen by '//pct(res%rise)// &
            ', more than the '//pct(PLATEAU_RISE)//' a plateau allows while the displacement '// &
            'conjugate to it doubles'
         return
      end if
      text = 'no maximum established: the largest load, at step fraction '// &
         g6(res%tau_peak)//' (increment '//itoa(res%peak_increment)//'), was followed by '// &
         itoa(res%beyond)//' fall(s) beyond the convergence noise and 0.1 % of it, of the '// &
         itoa(BEYOND_PEAK)//' that establish a maximum'
   end function peak_note

   !> A share as a percentage, e.g. '0.140 %' or '7.14E-03 %'.
   function pct(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=16) :: b
      if (abs(x) >= 1.0e-3_wp) then
         write (b, '(f10.3)') 100.0_wp*x
      else
         write (b, '(es9.2)') 100.0_wp*x
      end if
      text = trim(adjustl(b))//' %'
   end function pct

   !> How many times the displacement conjugate to the step's load, from the step's start,
   !> grew over the plateau window.
   real(wp) function growth(res)
      type(arc_end_t), intent(in) :: res
      growth = 0.0_wp
      if (res%s_flat > 0.0_wp) growth = res%s_now/res%s_flat
   end function growth

end module pecplas_solve_increments
