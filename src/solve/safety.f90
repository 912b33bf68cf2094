!> The safety step (*STEP, CONTROL=SAFETY; doc/theory.md, Factor of safety): strength reduction
!> from the state the step before converged to. The loads keep their factors; the strengths c and
!> tan(phi) of the materials and interface laws of the plan (pecplas_model_safety) are those of
!> the deck divided by Msf, with psi_r = min(psi, phi_r) (reduced_strength of each type).
!>
!> Control: Msf rises from 1 by increments dM; each is an increment of the ordinary solver
!> (the chain of methods) on a copy of the model whose strengths are reduced to the trial Msf,
!> its first residual the internal forces of the converged state returned onto the reduced
!> strengths. The size follows the failure: after a converged increment dM is scaled by the
!> ratio of the displacement rates |du| / dM of the increment before and this one, times 3/2
!> when the increment converged in at most EASY_ITERATIONS iterations (the displacement of
!> an increment may grow while the curve is gentle), clamped to [1/4, 3/2] and to MSF_STEP:
!> as the mechanism forms the rate grows without bound and dM shrinks with it; a failed
!> increment is halved, down to RESOLUTION. An increment of RESOLUTION that fails too may be
!> the solver stalling from a state reached by coarse steps (non-associated soil near its
!> factor), not the failure: the same Msf is sought again from the last equilibrium in
!> increments of RESOLUTION/SUBSTEPS (each by the whole chain, growing again as above once
!> converged), and only when one of those fails is no equilibrium found beyond the Msf
!> reached: that Msf is the factor, the failed step (at most RESOLUTION/SUBSTEPS) its
!> resolution. Past the Msf sought again the smallest step is RESOLUTION again.
!> MAX_INCREMENTS used before makes the Msf reached a lower bound (status stopped).
!> The walk (Msf reached, next step, rates, the sub-step stage, the curve and the mechanism's
!> displacements) is kept after every converged increment in problem%safety%walk and the
!> restart data: a run stopped inside the step (signal, --stop-after-increments) and
!> restarted makes the same trials as the uninterrupted one.
module pecplas_solve_safety
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error, ERR_RUN, ERR_SINGULAR
   use pecplas_base_run_status, only: RUN_COMPLETED, RUN_STOPPED, RUN_INTERRUPTED
   use pecplas_base_strings, only: itoa, g6
   use pecplas_base_timers, only: wall_time
   use pecplas_model_type, only: model_t
   use pecplas_model_safety, only: safety_plan_t
   use pecplas_massif_materials_type, only: material_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_problem_type, only: problem_t
   use pecplas_problem_safety, only: safety_result_t, safety_walk_t, SAFETY_FACTOR, &
      SAFETY_LOWER_BOUND, &
      SAFETY_UNSTABLE, SAFETY_KIND_NAMES
   use pecplas_solve_method, only: attempt_t, outcome_t
   use pecplas_solve_attempts, only: run_t, try_chain, accept_increment
   use pecplas_solve_residual, only: internal_forces_at
   use pecplas_solve_output, only: stop_pending
   use pecplas_io_results_file, only: results_file_t
   use pecplas_io_results_safety, only: safety_record_t
   implicit none (type, external)
   private

   public :: safety_step, safety_not_started, write_safety, reduce_model

   !> Bounds of the scaling of dM by the ratio of displacement rates (module header).
   real(wp), parameter :: SHRINK_MOST = 0.25_wp, GROW_MOST = 1.5_wp
   !> An increment converged in at most this many iterations lets the displacement of the
   !> next grow by GROW_MOST (the Msf - displacement curve is still gentle there).
   integer, parameter :: EASY_ITERATIONS = 4
   !> The mechanism: the displacements of the last MECHANISM_INCREMENTS increments.
   integer, parameter :: MECHANISM_INCREMENTS = 3
   !> A failed trial of RESOLUTION is sought again in this many increments from the last
   !> equilibrium before the factor is claimed (module header).
   real(wp), parameter :: SUBSTEPS = 4.0_wp

contains

   !> Runs safety step `istep` (module header); `status` RUN_COMPLETED (factor found),
   !> RUN_STOPPED (budget used: lower bound), `message` says which and the factor, or
   !> RUN_INTERRUPTED (a termination signal or --stop-after-increments after an increment: the
   !> walk is in problem%safety%walk and the restart data, and a restarted run resumes it).
   subroutine safety_step(model, problem, results, run, istep, status, message, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(results_file_t), intent(inout) :: results
      type(run_t), intent(inout) :: run
      integer, intent(in) :: istep
      integer, intent(inout) :: status
      character(len=:), allocatable, intent(inout) :: message
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: work
      type(attempt_t) :: att
      type(outcome_t) :: out
      real(wp), allocatable :: u(:, :), fint(:, :), reaction(:, :), u0(:, :), fred(:, :), &
         ulast(:, :, :)
      real(wp) :: msf, dm, trial, rate, rate_prev, t0, grow, smallest, confirm_until
      integer :: inc, method, k, nnode
      logical :: ok, returned
      character(len=:), allocatable :: why

      t0 = wall_time()
      associate (plan => model%steps(istep)%safety, res => problem%safety)
         work = model
         att%f0 = problem%state%factors
         att%ftarget = problem%state%factors
         att%tau0 = 1.0_wp
         att%tau1 = 1.0_wp
         ! the nodes' columns of the nodal arrays (plate rotations follow them)
         nnode = model%mesh%nnode()
         res%displacement_of = curve_name(model, plan)
         if (problem%position%resume) then
            ! a restarted run stopped inside this step: its walk goes on where it stopped
            ! (the restart data carry it: pecplas_solve_restart)
            problem%position%resume = .false.
            if (.not. res%walk%on) then
               call fatal_error(error, "step '"//model%steps(istep)%name//"' is a safety "// &
                  'step and the restart data hold no state of it')
               return
            end if
            associate (w => res%walk)
               inc = w%inc; msf = w%msf; dm = w%dm; rate_prev = w%rate_prev
               smallest = w%smallest; confirm_until = w%confirm_until
               u0 = w%u0
               ulast = w%ulast
               t0 = t0 - w%wall
            end associate
         else
            u0 = problem%state%u
            allocate (ulast(2, size(u0, 2), 0:MECHANISM_INCREMENTS))
            do k = 0, MECHANISM_INCREMENTS
               ulast(:, :, k) = u0
            end do
            res%msf = [1.0_wp]
            res%displacement = [0.0_wp]
            msf = 1.0_wp
            dm = plan%msf_step
            rate_prev = -1.0_wp
            smallest = plan%resolution
            confirm_until = -1.0_wp
            inc = 0
         end if
         call plan_names(model, plan, res%reduced, res%kept)
         if (.not. run%quiet) write (*, '(a)') ' safety step '//itoa(istep)//' ('// &
            model%steps(istep)%name//'): strength reduction from Msf = '//g6(msf)//' of '// &
            res%reduced//'; kept: '//res%kept
         do
            if (inc >= plan%max_increments) then
               res%kind = SAFETY_LOWER_BOUND
               res%factor = msf
               res%resolution = dm
               exit
            end if
            trial = msf + dm
            call reduce_model(model, plan, trial, work)
            ! the converged state returned onto the reduced strengths: the first residual
            allocate (fred, mold=run%fint_conv)
            call internal_forces_at(work, problem, problem%state%u, fred, error)
            call problem%state%rollback()
            ok = .not. allocated(error)
            returned = ok
            if (allocated(error)) then
               if (error%kind /= ERR_RUN .and. error%kind /= ERR_SINGULAR) return
               deallocate (error)
            end if
            if (ok) then
               run%fint_conv = fred
               call try_chain(work, problem, run, att, u, fint, reaction, out, method, error)
               if (allocated(error)) return
               ok = out%converged
            end if
            deallocate (fred)
            if (.not. ok) then
               if (dm <= smallest*(1.0_wp + 1.0e-12_wp)) then
                  if (smallest < plan%resolution*(1.0_wp - 1.0e-9_wp)) then
                     ! the sub-steps of a failed trial of RESOLUTION fail too: the factor
                     res%kind = SAFETY_FACTOR
                     res%factor = msf
                     res%resolution = dm
                     why = failure_reason(returned, out)
                     exit
                  end if
                  ! a trial of RESOLUTION failed: before the claim, the same Msf is sought
                  ! from the last equilibrium in SUBSTEPS increments (module header)
                  smallest = plan%resolution/SUBSTEPS
                  confirm_until = trial
                  dm = smallest
                  if (.not. run%quiet) write (*, '(a)') '   no equilibrium found at Msf = '// &
                     g6(trial)//' ('//failure_reason(returned, out)//'): sought again in '// &
                     'steps of '//g6(dm)
                  cycle
               end if
               dm = max(0.5_wp*dm, smallest)
               if (.not. run%quiet) write (*, '(a)') '   no equilibrium at Msf = '// &
                  g6(trial)//' ('//failure_reason(returned, out)//'): Msf step cut to '//g6(dm)
               cycle
            end if
            inc = inc + 1
            rate = max_move(u(:, 1:nnode), ulast(:, 1:nnode, MECHANISM_INCREMENTS))/dm
            ulast = cshift(ulast, 1, dim=3)
            ulast(:, :, MECHANISM_INCREMENTS) = u
            msf = trial
            res%msf = [res%msf, msf]
            res%displacement = [res%displacement, curve_value(plan, u(:, 1:nnode), &
               u0(:, 1:nnode))]
            ! the next size from the displacement rates (module header)
            grow = GROW_MOST
            if (out%iterations > EASY_ITERATIONS) grow = 1.0_wp
            if (rate_prev > 0.0_wp .and. rate > 0.0_wp) then
               dm = dm*min(GROW_MOST, max(SHRINK_MOST, grow*rate_prev/rate))
            else
               dm = dm*grow
            end if
            ! past the Msf sought again in sub-steps, the resolution is the step's again
            if (msf >= confirm_until*(1.0_wp - 1.0e-12_wp)) smallest = plan%resolution
            dm = min(plan%msf_step, max(dm, smallest))
            if (rate > 0.0_wp) rate_prev = rate
            ! the walk after this increment, written with it for a restart
            res%walk = safety_walk_t(on=.true., inc=inc, msf=msf, dm=dm, rate_prev=rate_prev, &
               smallest=smallest, confirm_until=confirm_until, wall=wall_time() - t0, u0=u0, &
               ulast=ulast)
            call problem%position%record(istep, inc, problem%position%tau, 0.0_wp, 0, 0.0_wp, &
               0.0_wp, att%f0, fint, out%du)
            call accept_increment(work, problem, results, run, att, out, method, u, fint, &
               reaction, istep, inc, real(istep - 1, wp) + (1.0_wp - 1.0_wp/trial), .true., &
               0, error)
            if (allocated(error)) return
            if (.not. run%quiet) write (*, '(a)') '   Msf = '//g6(msf)//'  '// &
               res%displacement_of//' = '//g6(res%displacement(size(res%displacement)))
            ! a termination signal or --stop-after-increments: the run stops after this
            ! increment (the caller says so), to go on with --restart
            if (stop_pending(model, problem, inc >= plan%max_increments)) then
               status = RUN_INTERRUPTED
               return
            end if
         end do
         res%increments = inc
         res%mechanism = ulast(:, 1:nnode, MECHANISM_INCREMENTS) - ulast(:, 1:nnode, 0)
         res%wall = wall_time() - t0
         select case (res%kind)
         case (SAFETY_FACTOR)
            status = RUN_COMPLETED
            message = 'safety factor Msf = '//g6(res%factor)//' (resolution '// &
               g6(res%resolution)//': no equilibrium found at Msf = '// &
               g6(res%factor + res%resolution)//' by any method of the chain: '//why// &
               ') after '//itoa(inc)// &
               ' strength-reduction increments in step '//itoa(istep)//' ('// &
               model%steps(istep)%name//'); its displacements are not physical'
         case default
            status = RUN_STOPPED
            message = 'safety factor >= '//g6(res%factor)//' (a lower bound): step '// &
               itoa(istep)//' ('//model%steps(istep)%name//') used its MAX_INCREMENTS='// &
               itoa(plan%max_increments)//' increments before failure (last Msf step '// &
               g6(res%resolution)//')'
         end select
         if (.not. run%quiet) write (*, '(a)') ' '//message
      end associate
      call write_safety(results, problem%safety, error)
   end subroutine safety_step

   !> The safety step `istep` was not reached: the run ended before it with `status` (a limit
   !> load, a divergence): the model is unstable before reduction and has no factor.
   subroutine safety_not_started(model, problem, results, istep, message, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(results_file_t), intent(inout) :: results
      integer, intent(in) :: istep
      character(len=:), allocatable, intent(inout) :: message
      type(error_t), allocatable, intent(out) :: error
      problem%safety%kind = SAFETY_UNSTABLE
      problem%safety%msf = [real(wp) ::]
      problem%safety%displacement = [real(wp) ::]
      problem%safety%displacement_of = curve_name(model, model%steps(istep)%safety)
      call plan_names(model, model%steps(istep)%safety, problem%safety%reduced, &
         problem%safety%kept)
      message = 'unstable before reduction: '//message//'; the safety step '//itoa(istep)// &
         ' ('//model%steps(istep)%name//') was not started (no factor of safety)'
      call write_safety(results, problem%safety, error)
   end subroutine safety_not_started

   !> Why a trial Msf found no equilibrium, for the console: the methods' reasons, or the
   !> converged state that could not be returned onto the reduced strengths.
   function failure_reason(returned, out) result(text)
      logical, intent(in) :: returned
      type(outcome_t), intent(in) :: out
      character(len=:), allocatable :: text
      text = 'the converged state could not be returned onto the reduced strengths'
      if (.not. returned) return
      text = 'no method converged'
      if (allocated(out%reason)) then
         if (len(out%reason) > 0) text = out%reason
      end if
   end function failure_reason

   !> /safety of the results file.
   subroutine write_safety(results, res, error)
      type(results_file_t), intent(inout) :: results
      type(safety_result_t), intent(in) :: res
      type(error_t), allocatable, intent(out) :: error
      type(safety_record_t) :: rec
      rec%kind = trim(SAFETY_KIND_NAMES(res%kind))
      rec%factor = res%factor
      rec%resolution = res%resolution
      rec%msf = res%msf
      rec%displacement = res%displacement
      rec%displacement_of = res%displacement_of
      if (allocated(res%mechanism)) rec%mechanism = res%mechanism
      rec%increments = res%increments
      if (allocated(res%reduced)) rec%reduced = res%reduced
      if (allocated(res%kept)) rec%kept = res%kept
      rec%wall = res%wall
      call results%write_safety(rec, error)
   end subroutine write_safety

   !> `work` (a copy of `model`) with the strengths of the plan divided by msf.
   subroutine reduce_model(model, plan, msf, work)
      type(model_t), intent(in) :: model
      type(safety_plan_t), intent(in) :: plan
      real(wp), intent(in) :: msf
      type(model_t), intent(inout) :: work
      class(material_t), allocatable :: m
      class(interface_law_t), allocatable :: l
      integer :: k
      do k = 1, size(plan%materials)
         if (.not. plan%materials(k)) cycle
         call model%materials(k)%m%reduced_strength(msf, m)
         call move_alloc(m, work%materials(k)%m)
      end do
      do k = 1, size(plan%laws)
         if (.not. plan%laws(k)) cycle
         call model%laws(k)%law%reduced_strength(msf, l)
         call move_alloc(l, work%laws(k)%law)
      end do
      ! UNDRAINED_B with c_u rising with depth: the profile is the strength of its points
      if (.not. allocated(model%water%mats)) return
      do k = 1, min(size(plan%materials), size(model%water%mats))
         if (.not. plan%materials(k)) cycle
         if (.not. model%water%mats(k)%cu_varies()) cycle
         work%water%mats(k)%cu = model%water%mats(k)%cu/msf
         work%water%mats(k)%cu_inc = model%water%mats(k)%cu_inc/msf
      end do
   end subroutine reduce_model

   !> 'name, name' of the materials and laws the plan reduces, and of the others ('none').
   subroutine plan_names(model, plan, reduced, kept)
      type(model_t), intent(in) :: model
      type(safety_plan_t), intent(in) :: plan
      character(len=:), allocatable, intent(out) :: reduced, kept
      integer :: k
      reduced = ''
      kept = ''
      do k = 1, size(plan%materials)
         call add(plan%materials(k), 'material '//model%materials(k)%m%name)
      end do
      do k = 1, size(plan%laws)
         call add(plan%laws(k), 'law '//model%laws(k)%law%name)
      end do
      if (len(reduced) == 0) reduced = 'none'
      if (len(kept) == 0) kept = 'none'
   contains
      subroutine add(yes, name)
         logical, intent(in) :: yes
         character(len=*), intent(in) :: name
         if (yes) then
            if (len(reduced) > 0) reduced = reduced//', '
            reduced = reduced//name
         else
            if (len(kept) > 0) kept = kept//', '
            kept = kept//name
         end if
      end subroutine add
   end subroutine plan_names

   !> Largest nodal displacement magnitude between two fields.
   pure real(wp) function max_move(a, b) result(d)
      real(wp), intent(in) :: a(:, :), b(:, :)
      d = 0.0_wp
      if (size(a, 2) > 0) d = sqrt(maxval(sum((a - b)**2, dim=1)))
   end function max_move

   !> The displacement of the curve: node and dof of the plan, else the largest magnitude.
   pure real(wp) function curve_value(plan, u, u0) result(d)
      type(safety_plan_t), intent(in) :: plan
      real(wp), intent(in) :: u(:, :), u0(:, :)
      if (plan%node > 0) then
         d = u(plan%dof, plan%node) - u0(plan%dof, plan%node)
      else
         d = max_move(u, u0)
      end if
   end function curve_value

   function curve_name(model, plan) result(text)
      type(model_t), intent(in) :: model
      type(safety_plan_t), intent(in) :: plan
      character(len=:), allocatable :: text
      if (plan%node > 0) then
         text = 'u'//merge('x', 'y', plan%dof == 1)//'(node '// &
            itoa(model%mesh%node_id(plan%node))//')'
      else
         text = 'max |u|'
      end if
   end function curve_name

end module pecplas_solve_safety
