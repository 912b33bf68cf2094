!> Anchors and struts (doc/deck.md, Anchors): bars that carry an axial force only, on the
!> translations of their nodes. A node-to-node anchor joins two nodes (a ground anchor's
!> free length, a strut between two walls); a fixed-end anchor joins a node to a fixed point
!> along a given direction (a strut to the symmetry line, a prop). Each bar has the axial
!> stiffness EA (force) and the out-of-plane spacing L_s of the anchors it stands for, and
!> optional tension and compression limits (an elastic-perfectly plastic bar). The run
!> state of the bars is in pecplas_structures_anchor_state.
module pecplas_model_anchors
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: anchor_set_t, ANCHOR_NODE_TO_NODE, ANCHOR_FIXED_END, ANCHOR_TYPES, anchor_kind

   integer, parameter :: ANCHOR_NODE_TO_NODE = 1, ANCHOR_FIXED_END = 2
   !> Deck names of the kinds (*ANCHOR, TYPE=...).
   character(len=*), parameter :: ANCHOR_TYPES(2) = [character(len=12) :: 'NODE_TO_NODE', &
      'FIXED_END']

   !> A named set of bars with one section (one *ANCHOR block).
   type :: anchor_set_t
      character(len=:), allocatable :: name
      !> ANCHOR_NODE_TO_NODE or ANCHOR_FIXED_END.
      integer :: kind = 0
      !> Axial stiffness EA of one anchor [force], out-of-plane spacing L_s [length],
      !> tension and compression limits of one anchor [force] (huge: none).
      real(wp) :: ea = 0.0_wp, spacing = 1.0_wp
      real(wp) :: tension_limit = huge(1.0_wp), compression_limit = huge(1.0_wp)
      !> Internal node numbers (2, nbar); conn(2, :) = 0 for a fixed-end anchor.
      integer, allocatable :: conn(:, :)
      !> Length L of each bar (node-to-node: the distance of its nodes; fixed-end: the
      !> equivalent length of the deck) and its unit direction (node-to-node: from node 1
      !> to node 2; fixed-end: from the node to the fixed point) (2, nbar).
      real(wp), allocatable :: length(:), direction(:, :)
      !> Deck position of the *ANCHOR line (messages, results).
      character(len=:), allocatable :: file
      integer :: line = 0
   contains
      procedure :: nbar
      procedure :: type_name
   end type anchor_set_t

contains

   !> The kind of the deck name `name` (upper case), 0 if unknown.
   pure integer function anchor_kind(name) result(kind)
      character(len=*), intent(in) :: name
      integer :: i
      kind = 0
      do i = 1, size(ANCHOR_TYPES)
         if (name == ANCHOR_TYPES(i)) kind = i
      end do
   end function anchor_kind

   !> Number of bars.
   pure integer function nbar(this)
      class(anchor_set_t), intent(in) :: this
      nbar = 0
      if (allocated(this%conn)) nbar = size(this%conn, 2)
   end function nbar

   !> The kind as the deck names it.
   pure function type_name(this) result(name)
      class(anchor_set_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = '?'
      if (this%kind >= 1 .and. this%kind <= size(ANCHOR_TYPES)) name = trim(ANCHOR_TYPES(this%kind))
   end function type_name

end module pecplas_model_anchors
