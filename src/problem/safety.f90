!> What a safety step (strength reduction, doc/theory.md, Factor of safety) found: the factor and
!> how it was found, the curve Msf - displacement, and the mechanism. Filled by
!> pecplas_solve_safety, written to /safety of the results file.
module pecplas_problem_safety
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: safety_result_t, safety_walk_t
   public :: SAFETY_NONE, SAFETY_FACTOR, SAFETY_LOWER_BOUND, SAFETY_UNSTABLE, &
      SAFETY_KIND_NAMES

   !> How the safety step ended: not run; the factor found (no equilibrium at Msf +
   !> resolution); the increment budget used first (the Msf reached is a lower bound); the model
   !> was unstable before any reduction (no factor).
   integer, parameter :: SAFETY_NONE = 0, SAFETY_FACTOR = 1, SAFETY_LOWER_BOUND = 2, &
      SAFETY_UNSTABLE = 3
   character(len=*), parameter :: SAFETY_KIND_NAMES(0:3) = [character(len=24) :: 'none', &
      'factor', 'lower bound', 'unstable before reduction']

   !> Where the reduction stands after its last converged increment (pecplas_solve_safety):
   !> what the next trial is sized from, kept in the restart data so that a run stopped
   !> inside the safety step goes on with the same trials.
   type :: safety_walk_t
      !> True once the step has converged an increment (the state below is that of it).
      logical :: on = .false.
      !> Increments converged in the step.
      integer :: inc = 0
      !> The Msf reached, the next Msf step, the displacement rate of the last increment
      !> (|du| / dM, -1 before one was measured), the smallest step allowed (RESOLUTION, or
      !> RESOLUTION/SUBSTEPS while a failed trial is sought again) and the Msf sought
      !> again (-1: none), the wall time spent in the step before [s].
      real(wp) :: msf = 1.0_wp, dm = 0.0_wp, rate_prev = -1.0_wp, smallest = 0.0_wp, &
         confirm_until = -1.0_wp, wall = 0.0_wp
      !> The displacements at the step's start and after each of the last increments (the
      !> mechanism: 2, columns, 0:MECHANISM_INCREMENTS).
      real(wp), allocatable :: u0(:, :), ulast(:, :, :)
   end type safety_walk_t

   type :: safety_result_t
      integer :: kind = SAFETY_NONE
      !> The Msf reached (the last converged one) and the Msf step that failed after it (the
      !> resolution: no equilibrium was found at factor + resolution).
      real(wp) :: factor = 0.0_wp, resolution = 0.0_wp
      !> The curve: Msf and the chosen displacement after each converged increment (first
      !> point Msf = 1, displacement 0).
      real(wp), allocatable :: msf(:), displacement(:)
      !> What the displacement of the curve is (node and dof, or the largest magnitude).
      character(len=:), allocatable :: displacement_of
      !> The materials and laws reduced and those kept ('name, name', '' for none).
      character(len=:), allocatable :: reduced, kept
      !> The incremental displacements of the last increments (2, nnode): the mechanism.
      real(wp), allocatable :: mechanism(:, :)
      !> Increments converged and wall time of the step [s].
      integer :: increments = 0
      real(wp) :: wall = 0.0_wp
      !> The step under way (restart data).
      type(safety_walk_t) :: walk
   end type safety_result_t

end module pecplas_problem_safety
