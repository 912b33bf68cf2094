!> The incremental–iterative solution (Annex A): load steps split into increments, each
!> solved by modified Newton (stiffness factorised once, residual forces re-applied, as in
!> the thesis) or full Newton (consistent tangent re-factorised every iteration).
!> An increment that does not converge is halved; after `max_cuts` halvings the run stops.
module pecplas_driver_increments
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t, fatal_error, run_error, ERR_SINGULAR, ERR_RUN
   use pecplas_model, only: model_t
   use pecplas_model_loads, only: step_t
   use pecplas_driver_problem, only: problem_t
   use pecplas_driver_stiffness, only: factorise_stiffness
   use pecplas_driver_output, only: write_increment, progress_line
   use pecplas_fe_assembly, only: internal_forces
   use pecplas_io_results_file, only: results_file_t
   use pecplas_driver_timers, only: wall_time
   use pecjoin_katona_increment, only: katona_increment
   use pecplas_signals, only: interrupt_requested, interrupt_signal
   use pecplas_strings, only: itoa
   implicit none (type, external)
   private

   public :: run_increments

contains

   !> Runs every step. `status` is 'completed', 'diverged' or 'failed'; `message` says why
   !> a run stopped. Converged increments are written to `results` as they come.
   subroutine run_increments(model, problem, results, quiet, status, message, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(results_file_t), intent(inout) :: results
      logical, intent(in) :: quiet
      character(len=:), allocatable, intent(out) :: status, message
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: f0(:), ftarget(:), factors(:), fint_conv(:, :), u(:, :)
      real(wp), allocatable :: fint(:, :), reaction(:, :)
      real(wp) :: tau, dt, dt0, residual, t_start, t_now, t_out
      !> Secant stiffness of the first loaded increment, the last converged and the last
      !> failed one (current stiffness parameter = k / k_first, Bergan).
      real(wp) :: k_first, k_conv, k_fail
      integer :: istep, inc_in_step, iters, level
      logical :: converged, last, blowup
      character(len=160) :: buf

      call cpu_time(t_start)
      status = 'completed'; message = 'all steps completed'
      k_first = 0.0_wp; k_conv = 0.0_wp
      ! the initial stresses are in equilibrium with their own nodal forces
      fint_conv = problem%initial_force
      do istep = 1, size(model%steps)
         associate (step => model%steps(istep))
            f0 = problem%state%factors
            ftarget = f0
            ftarget(step%pattern) = step%target
            dt0 = 1.0_wp/step%increments
            dt = dt0; tau = 0.0_wp; level = 0; inc_in_step = 0
            do while (tau < 1.0_wp - 1.0e-12_wp)
               dt = min(dt, 1.0_wp - tau)
               factors = f0 + (ftarget - f0)*(tau + dt)
               if (problem%katona%active) then
                  call katona_increment(model, problem, factors, fint_conv, u, fint, reaction, &
                     converged, blowup, iters, residual, error)
               else
                  call solve_increment(model, problem, factors, fint_conv, u, fint, reaction, &
                     converged, blowup, iters, residual, error)
               end if
               if (allocated(error)) then
                  if (error%kind /= ERR_RUN) return
                  deallocate (error)
                  converged = .false.
               end if
               problem%iterations = problem%iterations + iters
               if (.not. converged) then
                  k_fail = secant_stiffness(problem, problem%state%factors, factors, u)
                  call problem%state%rollback()
                  if (level >= model%solver%max_cuts) then
                     call stop_reason(model, step, istep, f0, ftarget, tau, tau + dt, level, &
                        blowup, stiffness_ratio(k_first, k_conv, k_fail), status, message)
                     return
                  end if
                  level = level + 1
                  problem%cuts = problem%cuts + 1
                  dt = 0.5_wp*dt
                  if (.not. quiet) write (*, '(a,es9.2,a)') '   no convergence: increment cut to ', &
                     dt, ' of the step'
                  cycle
               end if
               k_conv = secant_stiffness(problem, problem%state%factors, factors, u)
               if (k_first == 0.0_wp) k_first = k_conv
               tau = tau + dt
               inc_in_step = inc_in_step + 1
               problem%increments = problem%increments + 1
               call problem%state%commit()
               problem%state%u = u
               problem%state%factors = factors
               fint_conv = fint
               last = tau >= 1.0_wp - 1.0e-12_wp
               call cpu_time(t_now)
               t_out = wall_time()
               call write_increment(model, problem, results, istep, inc_in_step, &
                  real(istep - 1, wp) + tau, iters, residual, t_now - t_start, reaction, last, error)
               problem%time%output = problem%time%output + (wall_time() - t_out)
               if (allocated(error)) return
               if (.not. quiet) call progress_line(model, problem, istep, inc_in_step, tau, iters, &
                  residual)
               if (interrupt_requested()) then
                  status = 'interrupted'
                  message = 'stopped by '//interrupt_signal()//' after increment '// &
                     itoa(inc_in_step)//' of step '//itoa(istep)
                  return
               end if
               if (level > 0) then
                  level = level - 1
                  dt = min(dt0, 2.0_wp*dt)
               end if
            end do
         end associate
      end do
   end subroutine run_increments

   !> One increment to the pattern `factors`: imposes the displacement patterns, iterates
   !> on the free equations until ||FR|| <= tol * max(||F_ext||, ||reactions||).
   subroutine solve_increment(model, problem, factors, fint_conv, u, fint, reaction, &
         converged, blowup, iters, residual, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      real(wp), intent(in) :: factors(:), fint_conv(:, :)
      real(wp), allocatable, intent(out) :: u(:, :), fint(:, :), reaction(:, :)
      !> converged: equilibrium found; blowup: the residual became non-finite.
      logical, intent(out) :: converged, blowup
      integer, intent(out) :: iters
      real(wp), intent(out) :: residual
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: fext(:, :), up(:, :), r(:), du(:)
      real(wp) :: rnorm, ref, t0
      integer :: p, i, d, k
      logical :: newton

      newton = model%solver%method == 'NEWTON'
      fext = problem%initial_force
      allocate (up(2, size(fint_conv, 2)), source=0.0_wp)
      do p = 1, size(factors)
         fext = fext + factors(p)*problem%pattern_force(:, :, p)
         up = up + factors(p)*problem%pattern_disp(:, :, p)
      end do
      u = problem%state%u
      where (problem%dofs%eq == 0) u = up
      if (any(u /= problem%state%u)) then
         allocate (fint, mold=fint_conv)
         t0 = wall_time()
         call internal_forces(model, problem%rules, u, problem%state, fint, error, &
            problem%time%laws)
         problem%time%residual = problem%time%residual + (wall_time() - t0)
         if (allocated(error)) call as_run_error(error)
         if (allocated(error)) return
      else
         fint = fint_conv
      end if
      allocate (r(problem%dofs%neq), du(problem%dofs%neq), reaction(2, size(u, 2)))
      converged = .false.
      blowup = .false.
      iters = 0
      do
         reaction = fint - fext
         do i = 1, size(u, 2)
            do d = 1, 2
               k = problem%dofs%eq(d, i)
               if (k > 0) then
                  r(k) = fext(d, i) - fint(d, i)
                  reaction(d, i) = 0.0_wp
               end if
            end do
         end do
         rnorm = norm2(r)
         ! reference: the applied loads and reactions (not the initial-stress forces, which
         ! would loosen the criterion); those only when nothing else acts
         ref = max(norm2(pack(fext - problem%initial_force, problem%dofs%eq > 0)), norm2(reaction))
         if (ref == 0.0_wp) ref = norm2(pack(problem%initial_force, problem%dofs%eq > 0))
         residual = 0.0_wp
         if (ref > 0.0_wp) residual = rnorm/ref
         if (rnorm <= model%solver%tolerance*ref .or. rnorm == 0.0_wp) then
            converged = .true.
            return
         end if
         blowup = .not. (rnorm < huge(1.0_wp))
         if (iters >= model%solver%max_iterations .or. blowup) return
         if (newton .and. iters > 0) then
            call factorise_stiffness(model, problem, .true., error)
            if (allocated(error)) then
               ! A singular consistent tangent (perfectly plastic zones near a limit load)
               ! is no mechanism of the model: this iteration uses the elastic stiffness.
               if (error%kind /= ERR_SINGULAR) return
               deallocate (error)
               call factorise_stiffness(model, problem, .false., error)
               if (allocated(error)) return
            end if
         end if
         t0 = wall_time()
         call problem%solver%solve(r, du, error)
         problem%time%solve = problem%time%solve + (wall_time() - t0)
         if (allocated(error)) return
         problem%solves = problem%solves + 1
         iters = iters + 1
         do k = 1, problem%dofs%neq
            u(problem%dofs%eq_dir(k), problem%dofs%eq_node(k)) = &
               u(problem%dofs%eq_dir(k), problem%dofs%eq_node(k)) + du(k)
         end do
         t0 = wall_time()
         call internal_forces(model, problem%rules, u, problem%state, fint, error, &
            problem%time%laws)
         problem%time%residual = problem%time%residual + (wall_time() - t0)
         if (allocated(error)) call as_run_error(error)
         if (allocated(error)) return
      end do
   end subroutine solve_increment

   !> Why a step stopped. Under increasing force control (no imposed displacement changes in
   !> the step, some load grows) an increment that finds no equilibrium however small it is cut means the structure
   !> cannot carry more load: a limit load, reported with the last converged load factors.
   !> Under displacement control, or when the residual blows up, the run has diverged.
   !> The stiffness must also have dropped: current stiffness parameter `sp` < 0.5 (an elastic
   !> structure that fails to converge for another reason has sp = 1 and is 'diverged').
   subroutine stop_reason(model, step, istep, f0, ftarget, tau_ok, tau_failed, cuts, blowup, &
         sp, status, message)
      type(model_t), intent(in) :: model
      type(step_t), intent(in) :: step
      integer, intent(in) :: istep, cuts
      real(wp), intent(in) :: f0(:), ftarget(:), tau_ok, tau_failed, sp
      logical, intent(in) :: blowup
      character(len=:), allocatable, intent(out) :: status, message
      character(len=400) :: buf
      logical :: force_control
      integer :: p
      ! a limit load needs a load that grows: some force pattern increasing in magnitude and
      ! no imposed displacement changing (unloading that fails is a divergence)
      force_control = .false.
      do p = 1, size(f0)
         if (model%patterns(p)%kind == 'DISPLACEMENT') then
            if (ftarget(p) /= f0(p)) then
               force_control = .false.
               exit
            end if
         else if (abs(ftarget(p)) > abs(f0(p))) then
            force_control = .true.
         end if
      end do
      if (force_control .and. .not. blowup .and. sp < 0.5_wp) then
         status = 'limit load'
         write (buf, '(a,i0,a,a,a,f6.4,a,f6.4,a,i0,a,es9.2,a)') 'limit load in step ', istep, &
            ' (', step%name, '): equilibrium holds up to step fraction ', tau_ok, &
            ' but not at ', tau_failed, ' (', cuts, ' increment cuts, current stiffness '// &
            'parameter ', sp, '); load factors at the limit:'
         message = trim(buf)
         do p = 1, size(f0)
            if (ftarget(p) == f0(p)) cycle
            write (buf, '(a,a,a,g0.6)') ' ', model%patterns(p)%name, ' = ', &
               f0(p) + (ftarget(p) - f0(p))*tau_ok
            message = message//trim(buf)
         end do
      else
         status = 'diverged'
         write (buf, '(a,i0,a,a,a,f6.4,a,i0,a,es9.2,a)') 'step ', istep, ' (', step%name, &
            ') did not converge at step fraction ', tau_failed, ' after ', cuts, &
            ' increment cuts (current stiffness parameter ', sp, ')'
         message = trim(buf)
         if (blowup) message = message//' (the residual became infinite or NaN)'
      end if
      message = message//'; last converged state kept in the results file'
   end subroutine stop_reason

   !> Secant stiffness |df|^2 / (df . du) of an increment from factors `fa` to `fb` with
   !> trial displacements `u` (free equations, force patterns); 0 when no force changes.
   real(wp) function secant_stiffness(problem, fa, fb, u) result(k)
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: fa(:), fb(:), u(:, :)
      real(wp) :: df(2, size(u, 2)), num, den
      integer :: p
      df = 0.0_wp
      do p = 1, size(fa)
         if (fb(p) /= fa(p)) df = df + (fb(p) - fa(p))*problem%pattern_force(:, :, p)
      end do
      where (problem%dofs%eq == 0) df = 0.0_wp
      num = sum(df**2)
      den = sum(df*(u - problem%state%u))
      k = 0.0_wp
      if (num > 0.0_wp) k = num/max(den, tiny(1.0_wp))
   end function secant_stiffness

   !> Current stiffness parameter min(k_conv, k_fail) / k_first (1 when unknown).
   pure real(wp) function stiffness_ratio(k_first, k_conv, k_fail) result(sp)
      real(wp), intent(in) :: k_first, k_conv, k_fail
      sp = 1.0_wp
      if (k_first <= 0.0_wp) return
      if (k_conv > 0.0_wp) sp = min(sp, k_conv/k_first)
      if (k_fail > 0.0_wp) sp = min(sp, k_fail/k_first)
   end function stiffness_ratio

   !> A material that cannot return (e.g. a failed local iteration) cuts the increment.
   subroutine as_run_error(error)
      type(error_t), allocatable, intent(inout) :: error
      if (error%kind /= ERR_SINGULAR) error%kind = ERR_RUN
   end subroutine as_run_error

end module pecplas_driver_increments
