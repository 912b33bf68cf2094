!> THIN_LAYER (Ghaboussi): Goodman kinematics on 2 or 3 coincident doublets, with a
!> thickness e: the law receives strains (relative displacements / e) and gives stresses,
!> its stiffness is per unit strain. The virtual work of the layer, e * (jump / e) * sigma
!> per unit area, makes the point measure e dA and the strain matrix D / e.
module pecplas_joints_elements_thin_layer
   use pecplas_joints_elements_line, only: line_joint_t
   implicit none (type, external)
   private

   public :: thin_layer_t

   type, extends(line_joint_t) :: thin_layer_t
   contains
      procedure :: name => thin_layer_name
   end type thin_layer_t

contains

   pure function thin_layer_name(this) result(name)
      class(thin_layer_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = 'THIN_LAYER'
   end function thin_layer_name

end module pecplas_joints_elements_thin_layer
