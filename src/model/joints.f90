!> Joint (interface) element sets of a model: node doublets connected through an
!> interface law of the PECJOIN family (penalty joints), or held by Katona contact
!> (Lagrange multipliers on the doublets).
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
   !> How a joint set holds its doublets: an interface law at its points (penalty: springs
   !> of the law's stiffness) or Katona contact (multipliers on its node doublets).
   enum, bind(c)
      enumerator :: JOINT_PENALTY = 1, JOINT_KATONA
   end enum
   public :: JOINT_PENALTY, JOINT_KATONA
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
      !> Interface law name; JOINT_PENALTY or JOINT_KATONA (set by the deck reader from the
      !> law's type); the law's index in model%laws (penalty) or model%contacts (Katona).
      character(len=:), allocatable :: law
      integer :: method = JOINT_PENALTY
      integer :: law_index = 0, contact_index = 0
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
      procedure :: is_katona
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

   !> True for a set held by Katona contact (no interface law at its points).
   pure logical function is_katona(this)
      class(joint_set_t), intent(in) :: this
      is_katona = this%method == JOINT_KATONA
   end function is_katona

end module pecplas_model_joints
