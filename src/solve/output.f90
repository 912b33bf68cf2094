!> What a run shows: the results file rows and the one-line progress per increment.
module pecplas_solve_output
   use, intrinsic :: iso_fortran_env, only: output_unit
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_problem_type, only: problem_t
   use pecplas_problem_counts, only: NCOUNT, whole_counts, C_FACTORISATIONS
   use pecplas_io_results_file, only: results_file_t
   use pecplas_io_results_increment, only: increment_result_t, plate_fields_t
   use pecplas_joints_laws_coulomb, only: plastic_slip
   use pecplas_solve_restart, only: pack_restart
   use pecplas_model_options, only: EXACT_ALWAYS, EXACT_ON_STOP
   use pecplas_base_signals, only: interrupt_requested
   use pecplas_base_parallel, only: parallel_any
   use pecplas_estimate_estimator, only: error_estimate_t, estimate_error
   use pecplas_fe_plate_output, only: plate_results
   use pecplas_model_columns, only: rotation_column
   use pecplas_model_plate_water_sides, only: plate_water_sides, planned_activity
   use pecplas_model_phases, only: TARGET_PATTERNS, TARGET_PLATES
   use pecplas_model_phase_plan, only: target_activity
   use pecplas_solve_held_warning, only: first_nil_step
   implicit none (type, external)
   private

   public :: write_increment, progress_line, stop_pending

contains

   !> Writes one converged increment; fields only every `output%every` increments and at the
   !> end of each step, the history row and the restart data (/restart) always.
   !> `how` = (method, line searches, control) of the increment (see the history columns).
   !> `final`: the run certainly ends after this increment (results_file_t%write_increment).
   !> The displacements and the massif's stresses, strains and histories are lent to the
   !> results (moved, not copied: 128+ MB each at 10^6 unknowns) and given back before the
   !> return, whatever happens.
   subroutine write_increment(model, problem, results, istep, inc, time, iters, residual, &
         cpu, reaction, last_of_step, how, error, final)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(results_file_t), intent(inout) :: results
      integer, intent(in) :: istep, inc, iters, how(3)
      real(wp), intent(in) :: time, residual, cpu
      real(wp), intent(in) :: reaction(:, :)
      logical, intent(in) :: last_of_step
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: final
      type(increment_result_t) :: r
      type(error_estimate_t) :: est

      r%step = istep
      r%increment = inc
      r%global_increment = problem%stats%increments
      r%time = time
      r%pattern_factors = problem%state%factors
      r%iterations = iters
      r%method = how(1)
      r%line_searches = how(2)
      r%control = how(3)
      r%residual = residual
      r%cpu_time = cpu
      r%write_fields = last_of_step .or. mod(inc, max(1, model%output%every)) == 0
      if (r%write_fields) then
         ! the estimate reads the state: before its arrays are lent
         if (model%output%error_estimate) call estimate_error(model, problem, est, error)
         if (allocated(error)) return
         ! the nodes' columns (the plates' rotations go with the plate fields)
         r%reaction = reaction(:, 1:model%mesh%nnode())
         call joint_fields(model, problem, r)
         call anchor_fields(model, problem, r)
         call plate_fields(model, problem, reaction, r, error)
         if (allocated(error)) return
         call lend(model, problem, r)
         if (model%output%error_estimate) call add_estimate(est, r)
      end if
      ! exact restart data with this increment when the run stops after it (or always)
      problem%position%exact = exact_due(model, problem)
      ! with the state to restart from, replaced at every converged increment (with the
      ! fields, its lent arrays by reference: pack_restart does not read them)
      call results%write_increment(r, error, pack_restart(model, problem, r%write_fields), final)
      ! rank 0 alone writes: when it cannot, every rank of an MPI run stops with it
      if (parallel_any(allocated(error)) .and. .not. allocated(error)) then
         call fatal_error(error, 'rank 0 could not write the results file (its message is '// &
            'on its standard error)')
         call results%note_failure(error%message)
      end if
      if (r%write_fields) call give_back(problem, r)
   end subroutine write_increment

   !> Converged plate fields of every plate set (pecplas_fe_plate_output), with the moment
   !> reactions at their held rotations.
   subroutine plate_fields(model, problem, reaction, r, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: reaction(:, :)
      type(increment_result_t), intent(inout) :: r
      type(error_t), allocatable, intent(out) :: error
      type(plate_fields_t) :: before, held
      integer :: s, k, step
      integer, allocatable :: sides0(:)
      real(wp) :: tau, wf, h
      real(wp), allocatable :: factors(:)
      if (.not. allocated(model%plates)) return
      if (size(model%plates) == 0) return
      allocate (r%plate_fields(size(model%plates)))
      step = max(problem%phase%index, 1)
      tau = problem%position%tau
      factors = plate_load_factors(model, problem, step, tau)
      do s = 1, size(model%plates)
         if (model%water%used()) then
            ! the water's pressure on the plate is one of its own loads (groundwater)
            call plate_results(model, problem%state%u, problem%state%plates, &
               factors, s, r%plate_fields(s), error, &
               model%water%level_at(step), step=step)
            if (allocated(error)) return
            ! a change of that water at the step's start is applied along the step (the
            ! phase's carried out-of-balance): the load the plate holds is the last step's
            ! water plus the fraction tau of the change, and its forces are linear in it
            if (tau < 1.0_wp .and. water_changed(model, s, step)) then
               call plate_results(model, problem%state%u, problem%state%plates, &
                  factors, s, before, error, &
                  model%water%level_at(step - 1), step=step - 1)
               if (allocated(error)) return
               associate (f => r%plate_fields(s))
                  f%end_forces = tau*f%end_forces + (1.0_wp - tau)*before%end_forces
                  f%node_forces = tau*f%node_forces + (1.0_wp - tau)*before%node_forces
               end associate
            end if
            ! under gravity loading the water comes in with the weight: the plate holds the
            ! factor wf of it (the fields without water are `before` with no level)
            wf = water_factor(problem)
            if (wf /= 1.0_wp) then
               call plate_results(model, problem%state%u, problem%state%plates, &
                  factors, s, before, error)
               if (allocated(error)) return
               associate (f => r%plate_fields(s))
                  f%end_forces = wf*f%end_forces + (1.0_wp - wf)*before%end_forces
                  f%node_forces = wf*f%node_forces + (1.0_wp - wf)*before%node_forces
               end associate
            end if
            ! the water on the plate before the first step is in the K0 state's out-of-balance,
            ! held (it does not load the plate) until the first nil step releases it: the
            ! plate's own load is less the share h of it still held (linear in it)
            h = held_k0_share(model, problem, step, tau)
            if (h > 0.0_wp .and. model%water%level_at(1) > 0) then
               sides0 = initial_water_sides(model, s)
               if (any(sides0 /= 0)) then
                  call plate_results(model, problem%state%u, problem%state%plates, &
                     factors, s, held, error, model%water%level_at(1), sides=sides0)
                  if (allocated(error)) return
                  call plate_results(model, problem%state%u, problem%state%plates, &
                     factors, s, before, error)
                  if (allocated(error)) return
                  associate (f => r%plate_fields(s))
                     f%end_forces = f%end_forces + h*(before%end_forces - held%end_forces)
                     f%node_forces = f%node_forces + h*(before%node_forces - held%node_forces)
                  end associate
               end if
            end if
         else
            call plate_results(model, problem%state%u, problem%state%plates, &
               factors, s, r%plate_fields(s), error)
         end if
         if (allocated(error)) return
         associate (f => r%plate_fields(s))
            allocate (f%moment_reaction(size(f%node_index)))
            do k = 1, size(f%node_index)
               f%moment_reaction(k) = reaction(1, rotation_column(model, f%node_index(k)))
            end do
         end associate
      end do
   end subroutine plate_fields

   !> The factors at which the load patterns load the plates in the converged state: their
   !> factors where they are active, none where they are not (a deactivated pattern keeps
   !> its factor but loads nothing), and inside a step that switches a pattern the fraction
   !> of the switch applied so far (the phase's carried out-of-balance takes the pattern's
   !> load at the step's start to zero, or brings it in, linearly in tau: doc/theory.md §10).
   function plate_load_factors(model, problem, step, tau) result(f)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      integer, intent(in) :: step
      real(wp), intent(in) :: tau
      real(wp), allocatable :: f(:)
      logical, allocatable :: before(:)
      integer :: p
      f = problem%state%factors
      if (.not. allocated(problem%phase%patterns_on)) return
      if (size(problem%phase%patterns_on) /= size(f)) return
      before = target_activity(model, TARGET_PATTERNS, step - 1)
      do p = 1, size(f)
         if (.not. problem%phase%patterns_on(p)) f(p) = 0.0_wp
         if (tau >= 1.0_wp .or. (problem%phase%patterns_on(p) .eqv. before(p))) cycle
         if (.not. allocated(problem%position%f0)) cycle
         ! switched on: f(tau) - (1 - tau) f0; switched off: (1 - tau) f0
         f(p) = f(p) + merge(-1.0_wp, 1.0_wp, problem%phase%patterns_on(p))* &
            (1.0_wp - tau)*problem%position%f0(p)
      end do
   end function plate_load_factors

   !> The share of the K0 state's out-of-balance still held in the converged state of step
   !> `step` at fraction tau (doc/theory.md §10): 1 before the first nil step (no pattern
   !> line, no change; a safety step releases nothing), 1 - tau inside it (it carries the
   !> out-of-balance to zero along its path), 0 after it; 0 without phases and under gravity
   !> loading with water (whose held load holds no water on the plates).
   real(wp) function held_k0_share(model, problem, step, tau) result(h)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      integer, intent(in) :: step
      real(wp), intent(in) :: tau
      integer :: first
      h = 0.0_wp
      if (.not. problem%phase%phased .or. problem%phase%water_pattern > 0) return
      first = first_nil_step(model)
      if (first == 0 .or. step < first) then
         h = 1.0_wp
      else if (step == first) then
         h = max(1.0_wp - tau, 0.0_wp)
      end if
   end function held_k0_share

   !> The faces of plate set s the water stood on in the K0 state's out-of-balance
   !> (pecplas_phases_start's k0_unbalance: the *PLATE_WATER modes before the first step,
   !> every element set active, the joint sets active at the start): none for a plate set
   !> not active at the start.
   function initial_water_sides(model, s) result(sides)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      integer, allocatable :: sides(:)
      logical, allocatable :: pon(:), eon(:), jon(:)
      allocate (sides(size(model%plates(s)%conn, 2)), source=0)
      pon = target_activity(model, TARGET_PLATES, 0)
      if (s > size(pon)) return
      if (.not. pon(s)) return
      call planned_activity(model, 0, eon, jon)
      eon = .true.
      sides = plate_water_sides(model, s, 0, eon, jon)
   end function initial_water_sides

   !> Whether the water on plate set s (the faces it stands on, element by element, or the
   !> level in force) changes at the start of step `step`.
   logical function water_changed(model, s, step)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s, step
      water_changed = any(plate_water_sides(model, s, step) /= &
         plate_water_sides(model, s, step - 1)) .or. &
         model%water%level_at(step) /= model%water%level_at(step - 1)
   end function water_changed

   !> Whether the restart data written now carry what makes a restarted run exact
   !> (*OUTPUT, EXACT_RESTART=): with every increment, never, or (ON_STOP) when the run is
   !> to stop after this one, on a termination signal or --stop-after-increments (a signal
   !> that comes while it is written stops the run after the next: stop_pending).
   logical function exact_due(model, problem) result(due)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      select case (model%output%exact_restart)
      case (EXACT_ALWAYS)
         due = .true.
      case (EXACT_ON_STOP)
         ! the ranks of an MPI run decide together (a signal may reach them apart)
         due = parallel_any(interrupt_requested()) .or. &
            problem%position%stop_now(.false., problem%stats%increments)
      case default
         due = .false.
      end select
   end function exact_due

   !> True when the run must stop after the increment just written: a termination signal
   !> (on any rank of an MPI run: all ranks stop together) or the --stop-after-increments
   !> hook (`finished`: the run ends there anyway). Under
   !> EXACT_RESTART=ON_STOP a signal that came after that increment's restart data were
   !> packed without the exact part is acted on after the next increment, which has it.
   logical function stop_pending(model, problem, finished) result(stop)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      logical, intent(in) :: finished
      stop = parallel_any(interrupt_requested()) .or. &
         problem%position%stop_now(finished, problem%stats%increments)
      if (stop .and. model%output%exact_restart == EXACT_ON_STOP) stop = problem%position%exact
   end function stop_pending

   !> Moves u and the massif's stress, strain and hist arrays of `problem` into `r` (with
   !> plates, u's node columns are copied: the rotations stay).
   subroutine lend(model, problem, r)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(increment_result_t), intent(inout) :: r
      integer :: s
      associate (st => problem%state)
         if (size(st%u, 2) > model%mesh%nnode()) then
            r%displacement = st%u(:, 1:model%mesh%nnode())
         else
            call move_alloc(st%u, r%displacement)
         end if
         allocate (r%set_fields(size(st%sets)))
         do s = 1, size(st%sets)
            call move_alloc(st%sets(s)%stress, r%set_fields(s)%stress)
            call move_alloc(st%sets(s)%strain, r%set_fields(s)%strain)
            call move_alloc(st%sets(s)%hist, r%set_fields(s)%state)
            if (st%sets(s)%pore%on()) then
               ! under gravity loading the steady pore pressures act with the gravity
               ! pattern's factor (pecplas_phases_start's gravity_water)
               r%set_fields(s)%pore_steady = water_factor(problem)*st%sets(s)%pore%steady
               r%set_fields(s)%pore_excess = st%sets(s)%pore%excess
            end if
         end do
      end associate
   end subroutine lend

   !> The factor the steady pore pressures act with: the water pattern's factor under
   !> gravity loading while that pattern is on (doc/theory.md, Groundwater), else 1.
   real(wp) function water_factor(problem) result(f)
      type(problem_t), intent(in) :: problem
      integer :: k
      f = 1.0_wp
      k = problem%phase%water_pattern
      if (k <= 0) return
      if (allocated(problem%phase%patterns_on)) then
         if (.not. problem%phase%patterns_on(k)) return
      end if
      f = problem%state%factors(k)
   end function water_factor

   !> Gives back to `problem` what `lend` moved into `r`.
   subroutine give_back(problem, r)
      type(problem_t), intent(inout) :: problem
      type(increment_result_t), intent(inout) :: r
      integer :: s
      associate (st => problem%state)
         if (allocated(st%u)) then
            deallocate (r%displacement)
         else
            call move_alloc(r%displacement, st%u)
         end if
         do s = 1, size(st%sets)
            call move_alloc(r%set_fields(s)%stress, st%sets(s)%stress)
            call move_alloc(r%set_fields(s)%strain, st%sets(s)%strain)
            call move_alloc(r%set_fields(s)%state, st%sets(s)%hist)
         end do
      end associate
   end subroutine give_back

   !> Error indicators of the massif and joint elements with the fields.
   subroutine add_estimate(est, r)
      type(error_estimate_t), intent(in) :: est
      type(increment_result_t), intent(inout) :: r
      integer :: s
      r%estimated = .true.
      r%error_estimate = est%eta
      r%energy_norm = est%energy
      do s = 1, size(r%set_fields)
         r%set_fields(s)%error_indicator = est%sets(s)%eta
      end do
      if (.not. allocated(r%joint_fields)) return
      do s = 1, size(r%joint_fields)
         r%joint_fields(s)%error_indicator = est%joints(s)%eta
      end do
   end subroutine add_estimate

   !> Converged forces of every anchor set (N of one anchor and N / L_s).
   subroutine anchor_fields(model, problem, r)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      type(increment_result_t), intent(inout) :: r
      integer :: s
      if (.not. allocated(model%anchors)) return
      allocate (r%anchor_fields(size(model%anchors)))
      do s = 1, size(model%anchors)
         associate (f => r%anchor_fields(s), st => problem%state%anchors%sets(s))
            f%name = model%anchors(s)%name
            f%active = st%active
            f%force = st%force
            ! a prestress step: the force acting on the wall at the fraction tau applied so
            ! far, N0 + tau (P - N0) (the rest is still the carried out-of-balance)
            if (st%prestressing .and. problem%position%tau < 1.0_wp) f%force = &
               st%force_start + problem%position%tau*(st%force - st%force_start)
            f%force_per_width = f%force/model%anchors(s)%spacing
         end associate
      end do
   end subroutine anchor_fields

   !> Converged joint fields of every joint set; the plastic slip is the law's own
   !> (pecplas_joints_laws_coulomb: plastic_slip, 0 for a law without one and for a Katona
   !> set, which has no law at its points).
   subroutine joint_fields(model, problem, r)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      type(increment_result_t), intent(inout) :: r
      integer :: s, e, ip
      associate (js => problem%state%joints)
         if (.not. allocated(js%sets)) return
         allocate (r%joint_fields(size(js%sets)))
         do s = 1, size(js%sets)
            associate (st => js%sets(s), f => r%joint_fields(s), set => model%joint_sets(s))
               f%eps = st%eps
               f%sigma = st%sigma
               f%mode = st%mode
               f%state = st%hist
               allocate (f%slip(size(st%mode, 1), size(st%mode, 2)), source=0.0_wp)
               if (set%is_katona()) cycle
               do e = 1, size(st%mode, 2)
                  do ip = 1, size(st%mode, 1)
                     f%slip(ip, e) = plastic_slip(model%laws(set%law_index)%law, &
                        st%hist(:, ip, e))
                  end do
               end do
            end associate
         end do
      end associate
   end subroutine joint_fields

   !> One line per converged increment: step, increment, step fraction, iterations, residual
   !> (and, with joints, the number of joint points in slip and in separation), then the
   !> method when it is not the run's own, line searches, and 'arc' under arc-length control.
   subroutine progress_line(model, problem, istep, inc, tau, iters, residual, how_text)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      integer, intent(in) :: istep, inc, iters
      real(wp), intent(in) :: tau, residual
      character(len=*), intent(in) :: how_text
      character(len=120) :: joints
      integer :: nslip, nopen, counts(NCOUNT)
      joints = ''
      counts = whole_counts(problem)
      if (allocated(model%joint_sets)) then
         if (size(model%joint_sets) > 0) then
            call problem%state%joints%count_modes(nslip, nopen)
            write (joints, '(a,i0,a,i0)') '  slip ', nslip, ' open ', nopen
         end if
      end if
      ! Katona contact: state iterations of the increment, numeric factorisations so far
      if (problem%katona%active) write (joints, '(a,a,i0,a,i0)') trim(joints), '  states ', &
         problem%katona%last_state_iterations, ' factorisations ', counts(C_FACTORISATIONS)
      write (*, '(a,i3,1x,a12,a,i5,a,f7.4,a,i3,a,es9.2,a,es10.3,a)') ' step', istep, &
         adjustl(model%steps(istep)%name), ' inc', inc, '  fraction ', tau, '  iter ', iters, &
         '  residual ', residual, '  max|u| ', maxval(abs(problem%state%u)), trim(joints)// &
         how_text
      ! one line per increment reaches a redirected log at once (a killed run keeps it)
      flush (output_unit)
   end subroutine progress_line

end module pecplas_solve_output
