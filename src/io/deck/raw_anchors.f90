!> What *ANCHOR blocks collect before node references are resolved
!> (pecplas_io_deck_reader_anchors): the section read from the keyword line and the lines
!> of the bars.
module pecplas_io_deck_raw_anchors
   use pecplas_base_kinds, only: wp
   use pecplas_model_anchors, only: anchor_set_t
   implicit none (type, external)
   private

   public :: raw_anchor_t

   type :: raw_anchor_t
      !> The set with its section (conn, length and direction not yet set).
      type(anchor_set_t) :: set
      !> ANGLE= of a fixed-end anchor [degrees].
      real(wp) :: angle = 0.0_wp
      !> Line of the keyword and of each data line.
      integer :: at = 0
      integer, allocatable :: where(:)
   end type raw_anchor_t

end module pecplas_io_deck_raw_anchors
