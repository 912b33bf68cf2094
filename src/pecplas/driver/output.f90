!> What a run shows: the results file rows and the one-line progress per increment.
module pecplas_driver_output
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t
   use pecplas_model, only: model_t
   use pecplas_driver_problem, only: problem_t
   use pecplas_io_results_file, only: results_file_t
   use pecplas_io_results_increment, only: increment_result_t
   implicit none (type, external)
   private

   public :: write_increment, progress_line

contains

   !> Writes one converged increment; fields only every `output%every` increments and at the
   !> end of each step, the history row always.
   subroutine write_increment(model, problem, results, istep, inc, time, iters, residual, &
         cpu, reaction, last_of_step, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      type(results_file_t), intent(inout) :: results
      integer, intent(in) :: istep, inc, iters
      real(wp), intent(in) :: time, residual, cpu
      real(wp), intent(in) :: reaction(:, :)
      logical, intent(in) :: last_of_step
      type(error_t), allocatable, intent(out) :: error
      type(increment_result_t) :: r
      integer :: s

      r%step = istep
      r%increment = inc
      r%global_increment = problem%increments
      r%time = time
      r%pattern_factors = problem%state%factors
      r%iterations = iters
      r%residual = residual
      r%cpu_time = cpu
      r%write_fields = last_of_step .or. mod(inc, max(1, model%output%every)) == 0
      if (r%write_fields) then
         r%displacement = problem%state%u
         r%reaction = reaction
         allocate (r%set_fields(size(problem%state%sets)))
         do s = 1, size(problem%state%sets)
            r%set_fields(s)%stress = problem%state%sets(s)%stress
            r%set_fields(s)%strain = problem%state%sets(s)%strain
         end do
      end if
      call results%write_increment(r, error)
   end subroutine write_increment

   !> One line per converged increment: step, increment, step fraction, iterations, residual.
   subroutine progress_line(model, problem, istep, inc, tau, iters, residual)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      integer, intent(in) :: istep, inc, iters
      real(wp), intent(in) :: tau, residual
      write (*, '(a,i3,1x,a12,a,i5,a,f7.4,a,i3,a,es9.2,a,es10.3)') ' step', istep, &
         adjustl(model%steps(istep)%name), ' inc', inc, '  fraction ', tau, '  iter ', iters, &
         '  residual ', residual, '  max|u| ', maxval(abs(problem%state%u))
   end subroutine progress_line

end module pecplas_driver_output
