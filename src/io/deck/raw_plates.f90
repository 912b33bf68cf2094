!> What *PLATE blocks collect before references are resolved (pecplas_io_deck_reader_plates):
!> the keyword parameters and, for explicit elements, node ids as written with their lines.
module pecplas_io_deck_raw_plates
   use pecplas_model_plates, only: plate_section_t
   implicit none (type, external)
   private

   public :: raw_plate_set_t

   type :: raw_plate_set_t
      !> SET=; NODES= (node set) or EDGES= (edge set) as written, '' when absent.
      character(len=:), allocatable :: name, nodes, edges
      type(plate_section_t) :: section
      !> Line of the keyword; explicit elements: count, nodes per element, node ids
      !> (nen, n) and the line of each.
      integer :: at = 0, n = 0, nen = 0
      integer, allocatable :: conn(:, :), where(:)
   end type raw_plate_set_t

end module pecplas_io_deck_raw_plates
