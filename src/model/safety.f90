!> The plan of a safety step (*STEP, CONTROL=SAFETY; doc/deck.md, Safety; doc/theory.md, Factor of
!> safety): the strengths of the soils and Coulomb interface laws named by *REDUCE (all that have
!> a c, tan(phi) strength when none is named) are divided by Msf, raised from 1 by Msf steps that
!> follow the failure, until no equilibrium exists. Resolved to indices by the reader.
module pecplas_model_safety
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: safety_plan_t

   type :: safety_plan_t
      !> The step is a safety step.
      logical :: on = .false.
      !> First (and largest) Msf increment; smallest one tried before the failure is declared
      !> (the resolution of the factor).
      real(wp) :: msf_step = 0.1_wp, resolution = 0.002_wp
      !> Increment budget of the step: the factor is a lower bound when it is used up.
      integer :: max_increments = 100
      !> Displacement of the curve Msf - displacement: node (internal index) and dof
      !> (1 x/r, 2 y/z); 0: the largest displacement magnitude of the phase over all nodes.
      integer :: node = 0, dof = 0
      !> The materials (model%materials) and laws (model%laws) whose strength is reduced.
      logical, allocatable :: materials(:), laws(:)
   end type safety_plan_t

end module pecplas_model_safety
