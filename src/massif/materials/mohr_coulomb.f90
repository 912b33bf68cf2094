!> Perfectly plastic Mohr–Coulomb soil with non-associated flow (dilatancy angle psi) and an
!> optional tension cut-off, integrated by an implicit return map in principal stresses
!> (sigma_zz is one of them: the out-of-plane stress in plane strain, the hoop stress in
!> axisymmetry) with the consistent tangent (see doc/theory.md, "Elastoplastic soil").
!> Deck: `*MATERIAL, TYPE=MOHR_COULOMB` with E, NU, C, PHI, PSI [, GAMMA] [, TENSION].
module pecplas_massif_materials_mohr_coulomb
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_base_params, only: params_t
   use pecplas_massif_materials_type, only: material_t, NCOMP
   use pecplas_massif_materials_soil, only: soil_params_t, read_soil_params, soil_hooke, &
      soil_plastic_state, NSTATE_SOIL, SOIL_STATE_NAMES, RETURN_ELASTIC, reduce_soil
   use pecplas_massif_materials_principal, only: principal_axes_t, principal_decompose, &
      principal_compose, principal_tangent
   use pecplas_massif_materials_mohr_coulomb_return, only: mohr_coulomb_return, &
      mohr_coulomb_yield
   implicit none (type, external)
   private

   public :: mohr_coulomb_t, new_mohr_coulomb

   type, extends(material_t) :: mohr_coulomb_t
      type(soil_params_t) :: soil
      !> Tension cut-off t on every principal stress; huge (none) by default, which leaves
      !> the apex c cot(phi) as the tensile limit.
      real(wp) :: tension = huge(1.0_wp)
   contains
      procedure :: nstate => mohr_coulomb_nstate
      procedure :: state_names => mohr_coulomb_state_names
      procedure :: elastic_tangent => mohr_coulomb_elastic_tangent
      procedure :: update => mohr_coulomb_update
      procedure :: with_cohesion => mohr_coulomb_with_cohesion
      procedure :: symmetric_tangent => mohr_coulomb_symmetric_tangent
      !> Yield function at a stress vector (<= 0 admissible; stress units).
      procedure :: yield => mohr_coulomb_yield_at
      !> c and tan(phi) divided by msf, psi_r = min(psi, phi_r); the tension cut-off kept.
      procedure :: reduced_strength => mohr_coulomb_reduced_strength
   end type mohr_coulomb_t

contains

   !> Builds from E, NU, C, PHI, PSI (degrees), optional GAMMA and TENSION (>= 0, at most
   !> the apex c cot(phi) to have an effect); see read_soil_params for the checks.
   subroutine new_mohr_coulomb(mat, name, params, error)
      type(mohr_coulomb_t), intent(out) :: mat
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      type(error_t), allocatable, intent(out) :: error
      mat%name = name
      call read_soil_params(params, [character(len=8) :: 'TENSION'], mat%soil, error)
      if (allocated(error)) return
      mat%unit_weight = mat%soil%unit_weight
      if (params%has('TENSION')) then
         call params%get('TENSION', mat%tension, error)
         if (allocated(error)) return
         if (.not. (mat%tension >= 0.0_wp)) then
            call deck_error(error, params%file, params%line, params%keyword, &
               'tensile strength TENSION must not be negative')
         end if
      end if
   end subroutine new_mohr_coulomb

   pure integer function mohr_coulomb_nstate(this) result(n)
      class(mohr_coulomb_t), intent(in) :: this
      n = NSTATE_SOIL
   end function mohr_coulomb_nstate

   pure subroutine mohr_coulomb_state_names(this, names)
      class(mohr_coulomb_t), intent(in) :: this
      character(len=16), allocatable, intent(out) :: names(:)
      allocate (names(NSTATE_SOIL))
      names = SOIL_STATE_NAMES
   end subroutine mohr_coulomb_state_names

   pure subroutine mohr_coulomb_elastic_tangent(this, tangent)
      class(mohr_coulomb_t), intent(in) :: this
      real(wp), intent(out) :: tangent(NCOMP, NCOMP)
      tangent = soil_hooke(this%soil)
   end subroutine mohr_coulomb_elastic_tangent

   !> Symmetric for associated flow (psi = phi; the tension cut-off is associated).
   pure logical function mohr_coulomb_symmetric_tangent(this)
      class(mohr_coulomb_t), intent(in) :: this
      mohr_coulomb_symmetric_tangent = this%soil%psi == this%soil%phi
   end function mohr_coulomb_symmetric_tangent

   pure real(wp) function mohr_coulomb_yield_at(this, stress) result(f)
      class(mohr_coulomb_t), intent(in) :: this
      real(wp), intent(in) :: stress(NCOMP)
      type(principal_axes_t) :: axes
      real(wp) :: s(3)
      call principal_decompose(stress, axes, s)
      f = mohr_coulomb_yield(this%soil, this%tension, s)
   end function mohr_coulomb_yield_at

   !> Elastic predictor, return of the principal trial stresses, rotation back to the
   !> axes of the trial stress (kept by an isotropic return), tangent = d sigma/d trial . De.
   subroutine mohr_coulomb_update(this, stress_old, dstrain, state, stress, tangent, error)
      class(mohr_coulomb_t), intent(in) :: this
      real(wp), intent(in) :: stress_old(NCOMP), dstrain(NCOMP)
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: stress(NCOMP), tangent(NCOMP, NCOMP)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: de(NCOMP, NCOMP), trial(NCOMP), s_trial(3), s(3), ds(3, 3)
      type(principal_axes_t) :: axes
      integer :: kind

      de = soil_hooke(this%soil)
      trial = stress_old + matmul(de, dstrain)
      call principal_decompose(trial, axes, s_trial)
      call mohr_coulomb_return(this%soil, this%tension, s_trial, s, ds, kind, error)
      if (allocated(error)) return
      if (kind == RETURN_ELASTIC) then
         stress = trial
         tangent = de
         state(6) = real(RETURN_ELASTIC, wp)
         return
      end if
      stress = principal_compose(axes, s)
      tangent = matmul(principal_tangent(axes, s_trial, s, ds), de)
      call soil_plastic_state(this%soil, trial, stress, kind, state)
   end subroutine mohr_coulomb_update

   subroutine mohr_coulomb_reduced_strength(this, msf, reduced)
      class(mohr_coulomb_t), intent(in) :: this
      real(wp), intent(in) :: msf
      class(material_t), allocatable, intent(out) :: reduced
      allocate (reduced, source=this)
      select type (r => reduced)
      class is (mohr_coulomb_t)
         r%soil = reduce_soil(this%soil, msf)
      end select
   end subroutine mohr_coulomb_reduced_strength

   !> A copy with the cohesion c (the soil's other parameters kept).
   subroutine mohr_coulomb_with_cohesion(this, cohesion, copy, error)
      class(mohr_coulomb_t), intent(in) :: this
      real(wp), intent(in) :: cohesion
      class(material_t), allocatable, intent(out) :: copy
      type(error_t), allocatable, intent(out) :: error
      allocate (copy, source=this)
      select type (copy)
      class is (mohr_coulomb_t)
         copy%soil%cohesion = cohesion
      end select
   end subroutine mohr_coulomb_with_cohesion

end module pecplas_massif_materials_mohr_coulomb
