!> Linear solvers by deck name: the abstract type, its two implementations and the factory.
module pecplas_linalg_solver
   use pecplas_error, only: error_t, input_error
   use pecplas_linalg_solver_type, only: linear_solver_t
   use pecplas_linalg_cholmod, only: cholmod_solver_t
   use pecplas_linalg_umfpack, only: umfpack_solver_t
   use pecplas_strings, only: upper
   implicit none (type, external)
   private

   public :: linear_solver_t, cholmod_solver_t, umfpack_solver_t
   public :: new_linear_solver, KNOWN_SOLVERS

   !> Solver names accepted by `new_linear_solver` (any letter case).
   character(len=7), parameter :: KNOWN_SOLVERS(2) = [character(len=7) :: 'CHOLMOD', 'UMFPACK']

contains

   !> Allocates the solver called `name`; an unknown name is an input error listing the
   !> known ones.
   subroutine new_linear_solver(name, solver, error)
      character(len=*), intent(in) :: name
      class(linear_solver_t), allocatable, intent(out) :: solver
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: list
      integer :: i
      ! allocate(type :: x) rather than assignment: no temporary whose finaliser could free
      ! a C handle that the copy still uses.
      select case (upper(trim(adjustl(name))))
      case ('CHOLMOD')
         allocate (cholmod_solver_t :: solver)
      case ('UMFPACK')
         allocate (umfpack_solver_t :: solver)
      case default
         list = ''
         do i = 1, size(KNOWN_SOLVERS)
            list = list//' '//trim(KNOWN_SOLVERS(i))
         end do
         call input_error(error, 'unknown linear solver '''//trim(name)//'''; known solvers:'//list)
      end select
   end subroutine new_linear_solver

end module pecplas_linalg_solver
