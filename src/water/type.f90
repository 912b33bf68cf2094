!> The groundwater of a model (doc/deck.md, Groundwater): its phreatic levels, the level in
!> force in each phase, the water properties of each material, the dry element sets. The
!> pore pressures themselves are a field of the run state (pecplas_water_state).
module pecplas_water_type
   use pecplas_base_kinds, only: wp
   use pecplas_water_phreatic, only: phreatic_t
   use pecplas_water_drainage, only: water_material_t, NON_POROUS
   implicit none (type, external)
   private

   public :: water_model_t, LEVEL_KEEP, LEVEL_NONE, PLATE_KEEP, PLATE_FREE

   !> step_level values besides a level index: keep the level of the step before; no water.
   integer, parameter :: LEVEL_KEEP = 0, LEVEL_NONE = -1
   !> step_plate value: the plate set keeps the water side of the step before.
   integer, parameter :: PLATE_KEEP = 2
   !> plate_side / step_plate value (*PLATE_WATER FREE): the water stands on every face of
   !> the set's elements that no active element or joint lies against
   !> (pecplas_model_plate_water_sides).
   integer, parameter :: PLATE_FREE = 3

   type :: water_model_t
      !> Phreatic levels (*WATER), in deck order; the first is in force from the start.
      type(phreatic_t), allocatable :: levels(:)
      !> Water properties of model%materials(k) (same index).
      type(water_material_t), allocatable :: mats(:)
      !> dry(s): element set s ignores the water (*DRY).
      logical, allocatable :: dry(:)
      !> Per step: the level it brings in (index, LEVEL_KEEP or LEVEL_NONE) and whether
      !> its start sets the excess pore pressures to zero (*CHANGE_WATER).
      integer, allocatable :: step_level(:)
      logical, allocatable :: step_reset(:)
      !> Per plate set (model%plates): the side the water stands on (*PLATE_WATER):
      !> +1 left, -1 right of the plate walked from its first node to its last, 0 none,
      !> PLATE_FREE its free faces (the deck's default for a set *PLATE_WATER does not name).
      integer, allocatable :: plate_side(:)
      !> step_plate(s, i): the side plate set s takes from the start of step i on
      !> (*PLATE_WATER inside a step: +1, -1, 0 none, PLATE_FREE) or PLATE_KEEP.
      integer, allocatable :: step_plate(:, :)
   contains
      procedure :: plate_side_at => water_plate_side_at
      procedure :: used => water_used
      procedure :: level_at => water_level_at
      procedure :: wet => water_wet
      procedure :: pressure => water_pressure
      procedure :: unit_weight => water_unit_weight
      procedure :: kwn => water_kwn
   end type water_model_t

contains

   !> True when the model has water: a level or an undrained material. A model without is
   !> run as before groundwater existed, to the last bit.
   pure logical function water_used(this)
      class(water_model_t), intent(in) :: this
      water_used = .false.
      if (allocated(this%levels)) water_used = size(this%levels) > 0
      if (allocated(this%mats)) water_used = water_used .or. any(this%mats%undrained())
   end function water_used

   !> Index of the level in force in step istep (0: none; istep = 0: before the first step).
   pure integer function water_level_at(this, istep) result(k)
      class(water_model_t), intent(in) :: this
      integer, intent(in) :: istep
      integer :: i
      k = 0
      if (.not. allocated(this%levels)) return
      if (size(this%levels) == 0) return
      k = 1
      if (.not. allocated(this%step_level)) return
      ! the last step up to istep that changes the level decides: searched backwards with an
      ! early exit (a forward loop with two conditional assignments to k was vectorised wrongly
      ! by gfortran 12 at -O3: from step 4 on it returned the first level again)
      do i = min(istep, size(this%step_level)), 1, -1
         if (this%step_level(i) == LEVEL_NONE) then
            k = 0
            return
         end if
         if (this%step_level(i) > 0) then
            k = this%step_level(i)
            return
         end if
      end do
   end function water_level_at

   !> The water side of plate set s in step istep (0: before the first step): +1 left,
   !> -1 right, 0 none, PLATE_FREE the free faces; the *PLATE_WATER before the steps, then
   !> those of steps 1 .. istep.
   pure integer function water_plate_side_at(this, s, istep) result(side)
      class(water_model_t), intent(in) :: this
      integer, intent(in) :: s, istep
      integer :: i
      side = 0
      if (.not. allocated(this%plate_side)) return
      if (s < 1 .or. s > size(this%plate_side)) return
      side = this%plate_side(s)
      if (.not. allocated(this%step_plate)) return
      do i = min(istep, size(this%step_plate, 2)), 1, -1
         if (this%step_plate(s, i) /= PLATE_KEEP) then
            side = this%step_plate(s, i)
            return
         end if
      end do
   end function water_plate_side_at

   !> True when element set s with material m takes water: porous and not dry.
   pure logical function water_wet(this, s, m)
      class(water_model_t), intent(in) :: this
      integer, intent(in) :: s, m
      water_wet = .true.
      if (allocated(this%dry)) then
         if (s >= 1 .and. s <= size(this%dry)) water_wet = .not. this%dry(s)
      end if
      if (allocated(this%mats)) then
         if (m >= 1 .and. m <= size(this%mats)) water_wet = water_wet .and. &
            this%mats(m)%drainage /= NON_POROUS
      end if
   end function water_wet

   !> Steady pore pressure at xy in element set s (material m) under level k (0: none).
   pure real(wp) function water_pressure(this, k, s, m, xy) result(p)
      class(water_model_t), intent(in) :: this
      integer, intent(in) :: k, s, m
      real(wp), intent(in) :: xy(2)
      p = 0.0_wp
      if (k <= 0) return
      if (.not. this%wet(s, m)) return
      p = this%levels(k)%pressure(xy)
   end function water_pressure

   !> Unit weight at xy of element set s (material m, its own weight `gamma`) under level
   !> k: gamma_sat below the level in a wet set, else gamma.
   pure real(wp) function water_unit_weight(this, k, s, m, gamma, xy) result(w)
      class(water_model_t), intent(in) :: this
      integer, intent(in) :: k, s, m
      real(wp), intent(in) :: gamma, xy(2)
      w = gamma
      if (k <= 0) return
      if (.not. allocated(this%mats)) return
      if (.not. this%wet(s, m)) return
      if (xy(2) < this%levels(k)%head(xy(1))) w = this%mats(m)%gamma_sat
   end function water_unit_weight

   !> K_w/n of element set s with material m: the material's when it is undrained and the
   !> set wet, else 0 (no excess pore pressure).
   pure real(wp) function water_kwn(this, s, m) result(kwn)
      class(water_model_t), intent(in) :: this
      integer, intent(in) :: s, m
      kwn = 0.0_wp
      if (.not. allocated(this%mats)) return
      if (m < 1 .or. m > size(this%mats)) return
      if (.not. this%mats(m)%undrained()) return
      if (.not. this%wet(s, m)) return
      kwn = this%mats(m)%kwn
   end function water_kwn

end module pecplas_water_type
