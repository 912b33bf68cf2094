!> What the increment loops share: the run's progress (run_t), the chain of methods an
!> increment is tried with, and the acceptance of a converged increment (commit, results
!> row, progress line).
!>
!> The chain (when *SOLVER, FALLBACK=YES, the default): an increment the run's method cannot
!> converge is tried again from the last converged state by the next methods of its chain,
!>     NEWTON -> QUASI_NEWTON (on the last factorised tangent)       the default method
!>     MODIFIED_NEWTON -> QUASI_NEWTON -> NEWTON (with line search)  the thesis's method
!> and only then cut.
!> Modified and quasi-Newton, when a later method follows them, give up as soon as their
!> residual's rate shows they would crawl (pecplas_solve_iterate); the last method runs to
!> the iteration cap. When every method failed, those that gave up early are tried once more,
!> the strongest first, before the increment is cut: quasi-Newton running to the cap,
!> modified Newton with a budget of MN_RETRY_BUDGET, as the chain did before it remembered
!> (the early give-up saves time; every attempt that the chain without it makes from the same
!> first method is still made). The chain remembers: when a later, stronger method converged the last
!> increment in more than LEAD_ITERATIONS iterations, the next increment starts with it (its
!> own chain: QUASI_NEWTON -> NEWTON, NEWTON -> QUASI_NEWTON), so that a run whose
!> plastic zones make the cheaper methods crawl does not spend their failed attempts again
!> at every increment; an increment that the remembered method converged within
!> LEAD_ITERATIONS (nearly linear: unloading, an elastic stretch) hands the next one back
!> to the run's own method. The remembered method is part of the run's position
!> (problem%position%lead, kept in the restart data). Every method is one
!> increment solver (pecplas_solve_method) chosen for the model by
!> pecplas_solve_method_factory; Katona contact iterates its contact states inside modified
!> or full Newton (it has no quasi-Newton: modified Newton takes its place in the chain).
module pecplas_solve_attempts
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, ERR_RUN, ERR_SINGULAR
   use pecplas_model_type, only: model_t
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_output, only: write_increment, progress_line
   use pecplas_base_timers, only: wall_time
   use pecplas_solve_method, only: attempt_t, outcome_t, increment_method_t, CHAIN_BUDGET
   use pecplas_solve_method_factory, only: new_increment_method
   use pecplas_model_options, only: METHOD_MODIFIED, METHOD_QUASI, METHOD_NEWTON, method_name
   use pecplas_base_strings, only: itoa
   use pecplas_base_progress_eta, only: progress_eta_t
   use pecplas_solve_progress, only: begin_progress, progress_text, step_end_text
   use pecplas_io_results_file, only: results_file_t
   use pecplas_io_results_increment, only: limit_point_t
   implicit none (type, external)
   private

   public :: run_t, try_chain, accept_increment, method_chain

   !> An increment that a remembered later method converged within this many iterations
   !> hands the next one back to the run's own method (module header).
   integer, parameter :: LEAD_ITERATIONS = 1
   !> Budget of modified Newton's second attempt (its budget in the chain without early
   !> give-up of quasi-Newton: the retries make every attempt that chain makes).
   integer, parameter :: MN_RETRY_BUDGET = 60

   type :: run_t
      logical :: quiet = .false.
      real(wp) :: cpu_start = 0.0_wp
      !> Internal forces of the last converged state.
      real(wp), allocatable :: fint_conv(:, :)
      !> Free displacement increment of the last converged increment (empty at first).
      real(wp), allocatable :: du_prev(:)
      !> Step fraction / |Δu| of the step's first increment (the reference of the current
      !> stiffness parameter); 0 until known.
      real(wp) :: k_first = 0.0_wp
      !> Steps that ended on a plateau of their load-displacement path ('' for none): the
      !> run's warning (pecplas_solve_increments).
      character(len=:), allocatable :: plateau_warning
      !> Where the load had its maximum, when the run stops at a limit load.
      type(limit_point_t) :: limit
      !> The progress line's clock and estimate (pecplas_solve_progress), printed every few
      !> seconds of a long run (not with --quiet).
      type(progress_eta_t) :: eta
      !> A restarted run: its increments in all when it resumed (-1: not restarted).
      integer :: resumed_at = -1
   end type run_t

contains

   !> Methods tried for an increment, in order; `quasi_newton`: whether the increment
   !> solver can take quasi-Newton iterations; `lead`: the method the last increment
   !> needed (problem%position%lead, 0 for the run's own), whose chain is taken instead when
   !> it is a stronger method than the run's (METHOD_MODIFIED < METHOD_QUASI < METHOD_NEWTON)
   !> and the run falls back at all.
   function method_chain(model, quasi_newton, lead) result(methods)
      type(model_t), intent(in) :: model
      logical, intent(in) :: quasi_newton
      integer, intent(in), optional :: lead
      integer, allocatable :: methods(:)
      integer :: first
      first = model%solver%method
      if (present(lead)) then
         if (model%solver%fallback .and. lead > first) first = lead
      end if
      select case (first)
      case (METHOD_NEWTON)
         ! BFGS on the last factorised tangent: where a singular tangent stalls Newton
         ! (a mechanism forming at a limit load)
         methods = [METHOD_NEWTON, METHOD_QUASI]
      case (METHOD_QUASI)
         methods = [METHOD_QUASI, METHOD_NEWTON]
      case default
         methods = [METHOD_MODIFIED, METHOD_QUASI, METHOD_NEWTON]
      end select
      if (.not. quasi_newton) then
         where (methods == METHOD_QUASI) methods = METHOD_MODIFIED
         if (size(methods) == 3) methods = methods([1, 3])
      end if
      if (.not. model%solver%fallback) methods = methods(1:1)
   end function method_chain

   !> Tries `att` with each method of the chain until one converges; `out%reason` gathers
   !> why the others failed. The state is rolled back after each failure.
   subroutine try_chain(model, problem, run, att, u, fint, reaction, out, method, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(run_t), intent(in) :: run
      type(attempt_t), intent(inout) :: att
      real(wp), allocatable, intent(out) :: u(:, :), fint(:, :), reaction(:, :)
      type(outcome_t), intent(out) :: out
      integer, intent(out) :: method
      type(error_t), allocatable, intent(out) :: error
      class(increment_method_t), allocatable :: solver
      integer, allocatable :: methods(:)
      character(len=:), allocatable :: reasons
      logical, allocatable :: gave_up(:)
      integer :: i, k
      call new_increment_method(problem, solver)
      methods = method_chain(model, solver%has_quasi_newton(), problem%position%lead)
      reasons = ''
      allocate (gave_up(size(methods)), source=.false.)
      ! the chain, then the methods that gave up early once more, the strongest first, each
      ! run to the cap (a stronger method failed where a slow one would have converged: no
      ! early give-up may cut an increment that the chain without it converges)
      do k = 1, 2*size(methods)
         if (k > size(methods)) then
            i = 2*size(methods) - k + 1
            if (.not. gave_up(i)) cycle
         else
            i = k
         end if
         method = methods(i)
         att%method = method
         att%line_search = model%solver%line_search .and. method /= METHOD_MODIFIED
         ! the single-factorisation methods give up on a crawl when a later method follows;
         ! full Newton, and the chain's last method, run to the cap; a second attempt runs to
         ! the cap too, but modified Newton's, which gives up past MN_RETRY_BUDGET
         att%give_up_early = k < size(methods) .and. method /= METHOD_NEWTON
         att%budget = CHAIN_BUDGET
         if (k > size(methods) .and. method == METHOD_MODIFIED) then
            att%give_up_early = .true.
            att%budget = MN_RETRY_BUDGET
         end if
         call solver%solve_increment(model, problem, att, run%fint_conv, u, fint, reaction, &
            out, error)
         gave_up(i) = out%gave_up .and. k <= size(methods)
         if (allocated(error)) then
            ! a failed material return or a singular system of trial states fails the attempt
            if (error%kind /= ERR_RUN .and. error%kind /= ERR_SINGULAR) return
            out%converged = .false.
            out%singular = error%kind == ERR_SINGULAR
            out%reason = error%message
            if (.not. out%singular) out%reason = 'a material or law could not return: '// &
               error%message
            deallocate (error)
         end if
         problem%stats%iterations = problem%stats%iterations + out%iterations
         problem%stats%line_searches = problem%stats%line_searches + out%line_searches
         if (out%converged) return
         call problem%state%rollback()
         if (len(reasons) > 0) reasons = reasons//'; '
         reasons = reasons//method_name(method)//': '//out%reason
      end do
      out%reason = reasons
   end subroutine try_chain

   !> Commits a converged increment at step fraction out%tau, writes it and prints its line.
   !> `time` is the pseudo-time of the results file; `control` 0 load, 1 arc-length.
   !> `final`: the run certainly ends after this increment (written once, see
   !> results_file_t%write_increment).
   subroutine accept_increment(model, problem, results, run, att, out, method, u, fint, &
         reaction, istep, inc, time, last, control, error, final)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(results_file_t), intent(inout) :: results
      type(run_t), intent(inout) :: run
      type(attempt_t), intent(in) :: att
      type(outcome_t), intent(in) :: out
      integer, intent(in) :: method, istep, inc, control
      real(wp), intent(in) :: u(:, :), fint(:, :), reaction(:, :), time
      logical, intent(in) :: last
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: final
      real(wp) :: t_now, t_out, clock
      character(len=:), allocatable :: how
      ! the first increment of a step: its estimate starts from the state before it, when the
      ! last increment was accepted
      if (run%eta%step /= istep) call begin_progress(model, istep, att%tau0, problem%state%u, &
         run%eta%t_last, run%eta)
      problem%stats%increments = problem%stats%increments + 1
      problem%stats%by_method(method) = problem%stats%by_method(method) + 1
      if (control == 1) problem%stats%arc_increments = problem%stats%arc_increments + 1
      call problem%state%commit()
      problem%state%u = u
      problem%state%factors = att%factors(out%tau)
      ! the method the next increment starts with (module header)
      problem%position%lead = 0
      if (method /= model%solver%method .and. out%iterations > LEAD_ITERATIONS) &
         problem%position%lead = method
      run%fint_conv = fint
      if (allocated(out%du)) run%du_prev = out%du
      call cpu_time(t_now)
      t_out = wall_time()
      call write_increment(model, problem, results, istep, inc, time, out%iterations, &
         out%residual, t_now - run%cpu_start, reaction, last, &
         [method, out%line_searches, control], error, final)
      problem%stats%time%output = problem%stats%time%output + (wall_time() - t_out)
      clock = wall_time()
      run%eta%t_last = clock
      if (allocated(error)) return
      if (run%quiet) return
      how = ''
      if (method /= model%solver%method) how = '  '//method_name(method)
      if (out%line_searches > 0) how = how//'  ls '//itoa(out%line_searches)
      if (control == 1) how = how//'  arc'
      call progress_line(model, problem, istep, inc, out%tau, out%iterations, out%residual, how)
      if (run%eta%due(clock)) write (*, '(a)') ' progress: '//progress_text(model, istep, inc, &
         out%tau, problem%state%factors, problem%state%u, control == 1, run%eta, clock)
      ! the step's result in the deck's quantities (the load a settlement took, ...)
      if (last .and. .not. model%steps(istep)%safety%on) write (*, '(a)') ' end of '// &
         step_end_text(model, istep, &
         problem%state%factors, problem%state%u, reaction)
   end subroutine accept_increment

end module pecplas_solve_attempts
