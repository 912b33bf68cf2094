!> The linear system of a run: the stiffness matrix, its re-assembly map, and the solvers
!> that hold its factorisations (reused between iterations and increments).
module pecplas_problem_linear
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_linalg_sparse_reuse, only: csc_builder_t
   use pecplas_linalg_solver_type, only: linear_solver_t
   implicit none (type, external)
   private

   public :: linear_system_t

   !> linear_system_t%k_owner values.
   integer, parameter, public :: K_SOLVER = 1, K_TSOLVER = 2

   type :: linear_system_t
      class(linear_solver_t), allocatable :: solver
      !> Full-Newton fallback of a modified/quasi-Newton run: the consistent tangent is
      !> factorised by its own solver so that the run's stiffness factorisation stays.
      class(linear_solver_t), allocatable :: tsolver
      logical :: separate_tangent = .false., tangent_factorised = .false.
      type(csc_t) :: k
      !> The solver whose factorisation holds the values now in k (K_SOLVER, K_TSOLVER, or
      !> 0: an assembly not, or not yet, factorised), and whether the solver's factorisation
      !> is still that of the set-up stiffness: the restart data carries the matrices
      !> factorised during the run (pecplas_solve_restart).
      integer :: k_owner = 0
      logical :: solver_moved = .false.
      !> Triplet storage and scatter map of the stiffness re-assembly (pecplas_linalg_sparse_reuse).
      type(csc_builder_t) :: kbuild
   end type linear_system_t

end module pecplas_problem_linear
