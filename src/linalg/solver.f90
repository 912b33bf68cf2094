!> Linear solvers by deck name: the abstract type, its implementations and the factory.
module pecplas_linalg_solver
   use pecplas_base_error, only: error_t, input_error
   use pecplas_linalg_solver_type, only: linear_solver_t
   use pecplas_linalg_cholmod, only: cholmod_solver_t
   use pecplas_linalg_umfpack, only: umfpack_solver_t
   use pecplas_linalg_mumps, only: mumps_solver_t, mumps_available
   use pecplas_base_strings, only: upper
   implicit none (type, external)
   private

   public :: linear_solver_t, cholmod_solver_t, umfpack_solver_t, mumps_solver_t
   public :: mumps_available
   public :: new_linear_solver, KNOWN_SOLVERS

   !> Solver names accepted by `new_linear_solver` (any letter case); MUMPS only in the MPI
   !> build (`make build-mpi`).
   character(len=7), parameter :: KNOWN_SOLVERS(3) = [character(len=7) :: 'CHOLMOD', 'UMFPACK', &
      'MUMPS']

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
      case ('MUMPS')
         if (.not. mumps_available()) then
            call input_error(error, 'LINEAR=MUMPS: this build has no MUMPS; build with '// &
               'make build-mpi (CMake -DPECPLAS_MPI=ON) and run with mpirun')
            return
         end if
         allocate (mumps_solver_t :: solver)
      case default
         list = ''
         do i = 1, size(KNOWN_SOLVERS)
            list = list//' '//trim(KNOWN_SOLVERS(i))
         end do
         call input_error(error, 'unknown linear solver '''//trim(name)//'''; known solvers:'//list)
      end select
   end subroutine new_linear_solver

end module pecplas_linalg_solver
