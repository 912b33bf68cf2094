!> Joint (interface) element sets of a model: node doublets connected through an
!> interface law of the PECJOIN family.
module pecplas_model_joints
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: joint_set_t, JOINT_TYPES

   !> Joint element types as written in the deck (*JOINTS, TYPE=...).
   character(len=*), parameter :: JOINT_TYPES(4) = [character(len=10) :: 'SPRING', 'GOODMAN4', &
      'GOODMAN6', 'THIN_LAYER']

   type :: joint_set_t
      character(len=:), allocatable :: name
      !> One of JOINT_TYPES.
      character(len=:), allocatable :: etype
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
   end type joint_set_t

end module pecplas_model_joints
