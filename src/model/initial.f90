!> Initial stresses of the massif (§II.1.1 of the thesis): homogeneous values given by the
!> user, or geostatic (oedometric) sigma_v = q + gamma (y_s - y), sigma_h = K0 sigma_v.
module pecplas_model_initial
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: initial_stress_t, geostatic_stress

   type :: initial_stress_t
      !> 'HOMOGENEOUS' or 'GEOSTATIC'.
      character(len=:), allocatable :: kind
      !> Element set name as written ('ALL' for every set) and its index (0 = all).
      character(len=:), allocatable :: set
      integer :: eset = 0
      !> HOMOGENEOUS: (xx, yy, zz, xy), tension positive.
      real(wp) :: stress(4) = 0.0_wp
      !> GEOSTATIC: level of the top of the layer y_s, K0, vertical stress q at y_s
      !> (compression positive: the weight of what lies above, or a surcharge).
      real(wp) :: surface = 0.0_wp, k0 = 0.0_wp, surcharge = 0.0_wp
      !> Deck position (messages).
      character(len=:), allocatable :: file
      integer :: line = 0
   end type initial_stress_t

contains

   !> Geostatic stress (xx, yy, zz, xy), tension positive, at height y for unit weight gamma.
   pure function geostatic_stress(init, gamma, y) result(s)
      type(initial_stress_t), intent(in) :: init
      real(wp), intent(in) :: gamma, y
      real(wp) :: s(4), sv
      sv = init%surcharge + gamma*(init%surface - y)
      s = [-init%k0*sv, -sv, -init%k0*sv, 0.0_wp]
   end function geostatic_stress

end module pecplas_model_initial
