!> The pore pressures of one element set at its integration points (ngauss, nel), positive
!> in compression: the steady part (hydrostatic under the phase's level; a later
!> time-dependent phase may make it an unknown) and the excess part made by undrained
!> loading, converged and trial like the stresses. Unallocated in a model without water.
module pecplas_water_state
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: pore_state_t

   type :: pore_state_t
      real(wp), allocatable :: steady(:, :), excess(:, :), excess_trial(:, :)
   contains
      procedure :: init => pore_init
      procedure :: on => pore_on
      procedure :: commit => pore_commit
      procedure :: rollback => pore_rollback
   end type pore_state_t

contains

   !> Zero pore pressures at ngauss x nel points.
   subroutine pore_init(this, ngauss, nel)
      class(pore_state_t), intent(inout) :: this
      integer, intent(in) :: ngauss, nel
      allocate (this%steady(ngauss, nel), this%excess(ngauss, nel), &
         this%excess_trial(ngauss, nel), source=0.0_wp)
   end subroutine pore_init

   !> True when the set has pore pressures (a model with water).
   pure logical function pore_on(this)
      class(pore_state_t), intent(in) :: this
      pore_on = allocated(this%steady)
   end function pore_on

   subroutine pore_commit(this)
      class(pore_state_t), intent(inout) :: this
      if (allocated(this%excess)) this%excess = this%excess_trial
   end subroutine pore_commit

   subroutine pore_rollback(this)
      class(pore_state_t), intent(inout) :: this
      if (allocated(this%excess)) this%excess_trial = this%excess
   end subroutine pore_rollback

end module pecplas_water_state
