!> Joint (interface) element sets of a model: node doublets connected through an
!> interface law of the PECJOIN family.
module pecplas_model_joints
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: joint_set_t, JOINT_TYPES, joint_kind

   !> Joint element kinds; JOINT_TYPES(kind) is the name written in the deck (*JOINTS,
   !> TYPE=...) and in the results file. Code compares kinds, never names.
   enum, bind(c)
      enumerator :: JOINT_SPRING = 1, JOINT_GOODMAN4, JOINT_GOODMAN6, JOINT_THIN_LAYER
   end enum
   public :: JOINT_SPRING, JOINT_GOODMAN4, JOINT_GOODMAN6, JOINT_THIN_LAYER
   character(len=*), parameter :: JOINT_TYPES(4) = [character(len=10) :: 'SPRING', 'GOODMAN4', &
      'GOODMAN6', 'THIN_LAYER']

   type :: joint_set_t
      character(len=:), allocatable :: name
      !> One of JOINT_SPRING, JOINT_GOODMAN4, JOINT_GOODMAN6, JOINT_THIN_LAYER.
      integer :: kind = 0
      !> Connectivity (nodes per element, nelem), internal node numbers. Node order as in
      !> (B.8): face 1 nodes first (1-2 [, mid 5]), then face 2 (3 facing 2, 4 facing 1 [, 6]);
      !> springs: (face-1 node, face-2 node).
      integer, allocatable :: conn(:, :)
      integer, allocatable :: ids(:)
      !> Interface law name and its index in model%laws.
      character(len=:), allocatable :: law
      integer :: law_index = 0
      !> 'GAUSS' or 'LOBATTO' (Newton–Cotes) integration along Goodman joints.
      character(len=:), allocatable :: integration
      !> Thin layer thickness e (THIN_LAYER only).
      real(wp) :: thickness = 0.0_wp
      !> Springs: tributary length (plane) or area (axisymmetric) of each doublet, and the
      !> unit tangent t of each doublet (normal n = (-t_y, t_x)).
      real(wp), allocatable :: tributary(:), tangent(:, :)
   contains
      procedure :: type_name
      procedure :: is_spring
      procedure :: is_thin_layer
   end type joint_set_t

contains

   !> The kind of the deck name `name` (upper case), 0 if unknown.
   pure integer function joint_kind(name) result(kind)
      character(len=*), intent(in) :: name
      integer :: i
      kind = 0
      do i = 1, size(JOINT_TYPES)
         if (name == JOINT_TYPES(i)) kind = i
      end do
   end function joint_kind

   !> The set's joint type as the deck and the results file name it ('?' when unset).
   pure function type_name(this) result(name)
      class(joint_set_t), intent(in) :: this
      character(len=:), allocatable :: name
      if (this%kind >= 1 .and. this%kind <= size(JOINT_TYPES)) then
         name = trim(JOINT_TYPES(this%kind))
      else
         name = '?'
      end if
   end function type_name

   !> Node-to-node springs (one doublet per element, tributary from the set).
   pure logical function is_spring(this)
      class(joint_set_t), intent(in) :: this
      is_spring = this%kind == JOINT_SPRING
   end function is_spring

   !> Thin continuum layer of thickness `thickness` (strains, not relative displacements).
   pure logical function is_thin_layer(this)
      class(joint_set_t), intent(in) :: this
      is_thin_layer = this%kind == JOINT_THIN_LAYER
   end function is_thin_layer

end module pecplas_model_joints
