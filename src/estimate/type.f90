!> Result of the a posteriori error estimate (pecplas_estimate_estimator): element
!> indicators per massif and joint set, the global estimate and the energy norm.
module pecplas_estimate_type
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: eta_set_t, error_estimate_t

   !> Indicators of the elements of one set.
   type :: eta_set_t
      !> eta(nel): energy-norm error indicator of each element (units of sqrt(energy)).
      real(wp), allocatable :: eta(:)
   end type eta_set_t

   type :: error_estimate_t
      !> Per element set eta(nel), and per joint set eta(nel) (model%joint_sets order).
      type(eta_set_t), allocatable :: sets(:), joints(:)
      !> Global estimate sqrt(sum eta_e^2) over the massif elements.
      real(wp) :: eta = 0
      !> Energy norm of the FE solution (for relative errors eta / energy).
      real(wp) :: energy = 0
   end type error_estimate_t

end module pecplas_estimate_type
