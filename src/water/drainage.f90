!> How a material takes the pore water (doc/theory.md, Groundwater): its drainage type,
!> its unit weights above and below the phreatic level, the volumetric stiffness of the
!> pore water K_w/n of an undrained material and the undrained shear strength c_u of
!> UNDRAINED_B.
!>
!>   DRAINED     the pore pressure is the steady (hydrostatic) one; no excess (default);
!>   UNDRAINED_A effective stiffness and strength; a volumetric strain increment d eps_v
!>               makes an excess pore pressure d p = -(K_w/n) d eps_v;
!>   UNDRAINED_B the same, with the strength c = c_u, phi = 0, psi = 0;
!>   NON_POROUS  no pore pressure at all (as a dry set); unit weight gamma_unsat.
module pecplas_water_drainage
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: water_material_t, default_water_stiffness, DRAINAGE_NAMES
   public :: DRAINED, UNDRAINED_A, UNDRAINED_B, NON_POROUS, NU_UNDRAINED

   integer, parameter :: DRAINED = 1, UNDRAINED_A = 2, UNDRAINED_B = 3, NON_POROUS = 4
   character(len=*), parameter :: DRAINAGE_NAMES(4) = [character(len=11) :: 'DRAINED', &
      'UNDRAINED_A', 'UNDRAINED_B', 'NON_POROUS']
   !> Undrained Poisson ratio of the default K_w/n (the PLAXIS rule, doc/theory.md).
   real(wp), parameter :: NU_UNDRAINED = 0.495_wp

   type :: water_material_t
      integer :: drainage = DRAINED
      !> Unit weights above (gamma_unsat, the material's GAMMA) and below the level.
      real(wp) :: gamma_unsat = 0.0_wp, gamma_sat = 0.0_wp
      !> K_w/n of an undrained material (0 otherwise).
      real(wp) :: kwn = 0.0_wp
      !> UNDRAINED_B: c_u = cu + cu_inc (cu_yref - y) below cu_yref (cu above it).
      real(wp) :: cu = 0.0_wp, cu_inc = 0.0_wp, cu_yref = 0.0_wp
   contains
      procedure :: porous => water_material_porous
      procedure :: undrained => water_material_undrained
      procedure :: cu_at => water_material_cu_at
      procedure :: cu_varies => water_material_cu_varies
   end type water_material_t

contains

   !> True unless NON_POROUS.
   elemental logical function water_material_porous(this)
      class(water_material_t), intent(in) :: this
      water_material_porous = this%drainage /= NON_POROUS
   end function water_material_porous

   !> True for UNDRAINED_A and UNDRAINED_B.
   elemental logical function water_material_undrained(this)
      class(water_material_t), intent(in) :: this
      water_material_undrained = this%drainage == UNDRAINED_A .or. this%drainage == UNDRAINED_B
   end function water_material_undrained

   !> K_w/n from the skeleton's bulk and shear moduli: the value that makes the undrained
   !> Poisson ratio nu_u = NU_UNDRAINED, K_w/n = 3 (nu_u - nu') / ((1 - 2 nu_u)(1 + nu')) K'
   !> (Skempton's B = K_w/n / (K_w/n + K') then follows, doc/theory.md).
   pure real(wp) function default_water_stiffness(bulk, shear) result(kwn)
      real(wp), intent(in) :: bulk, shear
      real(wp) :: nu
      nu = (3.0_wp*bulk - 2.0_wp*shear)/(2.0_wp*(3.0_wp*bulk + shear))
      kwn = max(3.0_wp*(NU_UNDRAINED - nu)/((1.0_wp - 2.0_wp*NU_UNDRAINED)*(1.0_wp + nu))*bulk, &
         0.0_wp)
   end function default_water_stiffness

   !> UNDRAINED_B: the undrained shear strength at height y.
   elemental real(wp) function water_material_cu_at(this, y) result(cu)
      class(water_material_t), intent(in) :: this
      real(wp), intent(in) :: y
      cu = this%cu + this%cu_inc*max(this%cu_yref - y, 0.0_wp)
   end function water_material_cu_at

   !> True for UNDRAINED_B with c_u rising with depth.
   elemental logical function water_material_cu_varies(this)
      class(water_material_t), intent(in) :: this
      water_material_cu_varies = this%drainage == UNDRAINED_B .and. this%cu_inc > 0.0_wp
   end function water_material_cu_varies

end module pecplas_water_drainage
