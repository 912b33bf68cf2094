!> What *JOINTS blocks collect before references are resolved (see
!> pecplas_io_deck_resolve_joints): the keyword parameters and, for explicit joints, the
!> element ids and node ids as written, with the line of each.
module pecplas_io_deck_raw_joints
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: raw_joint_set_t

   type :: raw_joint_set_t
      !> SET=, TYPE= (upper case), LAW=, INTEGRATION= (upper case, 'GAUSS' by default).
      character(len=:), allocatable :: name, etype, law, integration
      !> EDGES= and SIDE= (generated joints); empty for explicit joints.
      character(len=:), allocatable :: edges, side
      !> THICKNESS= (thin layer), ANGLE= in degrees (springs; has_angle when given).
      real(wp) :: thickness = 0.0_wp, angle = 0.0_wp
      logical :: has_angle = .false.
      !> FACES=BOTH (joints on both faces of the EDGES line, no SIDE=) and EXTEND= (length
      !> of the cut beyond the line's ends, 0: none).
      logical :: both_faces = .false.
      real(wp) :: extend = 0.0_wp
      !> Line of the keyword; number of explicit elements and nodes per element.
      integer :: at = 0, n = 0, nen = 0
      !> Explicit elements: ids(n), node ids nodes(nen, n), line of each where(n).
      integer, allocatable :: ids(:), nodes(:, :), where(:)
   end type raw_joint_set_t

end module pecplas_io_deck_raw_joints
