!> Abstract massif material. Stress and strain vectors have four components
!> (xx, yy, zz, xy): zz is the out-of-plane (plane strain, strain 0) or hoop
!> (axisymmetric, strain u_r/r) component, xy an engineering shear strain.
!> Continuum stresses are tension positive.
module pecplas_massif_materials_type
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   implicit none (type, external)
   private

   public :: material_t, material_box_t, NCOMP

   !> Number of stress / strain components.
   integer, parameter :: NCOMP = 4

   type, abstract :: material_t
      !> Name given in the deck (*MATERIAL, NAME=...).
      character(len=:), allocatable :: name
      !> Unit weight gamma (force / volume) used by GRAVITY loads and geostatic stresses.
      real(wp) :: unit_weight = 0.0_wp
   contains
      !> Number of history variables per integration point.
      procedure(nstate_ifc), deferred :: nstate
      !> Elastic (initial) tangent, used by modified Newton.
      procedure(elastic_ifc), deferred :: elastic_tangent
      !> Stress update from a strain increment; tangent is consistent with the update.
      procedure(update_ifc), deferred :: update
      !> False when the consistent tangent can be non-symmetric (non-associated flow):
      !> full Newton then factorises with UMFPACK instead of CHOLMOD.
      procedure :: symmetric_tangent => material_symmetric_tangent
      !> True when every update's tangent is the elastic tangent (a linear material): the
      !> solver then keeps no tangent per integration point.
      procedure :: constant_tangent => material_constant_tangent
      !> Names of the history variables (results file `state_names`); none by default.
      procedure :: state_names => material_state_names
      !> The material with its strength divided by `msf` (strength reduction, doc/theory.md,
      !> Factor of safety); unallocated for a material without a c, tan(phi) strength (the
      !> default).
      procedure :: reduced_strength => material_reduced_strength
      !> A copy of the material with another cohesion (an undrained shear strength varying
      !> with depth, doc/deck.md Groundwater); an error for a material without one.
      procedure :: with_cohesion => material_with_cohesion
   end type material_t

   !> Holder so that arrays of polymorphic materials can be built.
   type :: material_box_t
      class(material_t), allocatable :: m
   end type material_box_t

   abstract interface
      pure integer function nstate_ifc(this)
         import :: material_t
         class(material_t), intent(in) :: this
      end function nstate_ifc

      pure subroutine elastic_ifc(this, tangent)
         import :: material_t, wp, NCOMP
         class(material_t), intent(in) :: this
         real(wp), intent(out) :: tangent(NCOMP, NCOMP)
      end subroutine elastic_ifc

      subroutine update_ifc(this, stress_old, dstrain, state, stress, tangent, error)
         import :: material_t, wp, NCOMP, error_t
         class(material_t), intent(in) :: this
         real(wp), intent(in) :: stress_old(NCOMP), dstrain(NCOMP)
         !> History variables of the point: in = converged values, out = updated values.
         real(wp), intent(inout) :: state(:)
         real(wp), intent(out) :: stress(NCOMP), tangent(NCOMP, NCOMP)
         type(error_t), allocatable, intent(out) :: error
      end subroutine update_ifc
   end interface

contains

   pure logical function material_symmetric_tangent(this)
      class(material_t), intent(in) :: this
      material_symmetric_tangent = .true.
   end function material_symmetric_tangent

   pure logical function material_constant_tangent(this)
      class(material_t), intent(in) :: this
      material_constant_tangent = .false.
   end function material_constant_tangent

   pure subroutine material_state_names(this, names)
      class(material_t), intent(in) :: this
      character(len=16), allocatable, intent(out) :: names(:)
      allocate (names(0))
   end subroutine material_state_names

   subroutine material_reduced_strength(this, msf, reduced)
      class(material_t), intent(in) :: this
      real(wp), intent(in) :: msf
      class(material_t), allocatable, intent(out) :: reduced
   end subroutine material_reduced_strength

   subroutine material_with_cohesion(this, cohesion, copy, error)
      class(material_t), intent(in) :: this
      real(wp), intent(in) :: cohesion
      class(material_t), allocatable, intent(out) :: copy
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: name
      character(len=24) :: buf
      name = 'material'
      if (allocated(this%name)) name = "material '"//this%name//"'"
      write (buf, '(es12.4)') cohesion
      call fatal_error(error, name//' has no cohesion to set to '//trim(adjustl(buf))// &
         ' (c_u varying with depth needs MOHR_COULOMB or DRUCKER_PRAGER)')
   end subroutine material_with_cohesion

end module pecplas_massif_materials_type
