!> Chooses the increment solver of a model (pecplas_solve_method): Katona contact when the
!> model has Katona joint sets (their doublets built in problem%katona), else the Newton-type
!> methods.
module pecplas_solve_method_factory
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_method, only: increment_method_t
   use pecplas_solve_iterate, only: newton_method_t
   use pecplas_solve_katona_increment, only: katona_method_t
   implicit none (type, external)
   private

   public :: new_increment_method

contains

   !> The increment solver for `problem`.
   subroutine new_increment_method(problem, solver)
      type(problem_t), intent(in) :: problem
      class(increment_method_t), allocatable, intent(out) :: solver
      if (problem%katona%active) then
         allocate (katona_method_t :: solver)
      else
         allocate (newton_method_t :: solver)
      end if
   end subroutine new_increment_method

end module pecplas_solve_method_factory
