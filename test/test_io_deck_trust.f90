!> Decks that used to crash, hang, exhaust memory or be accepted silently
!> (test/data/trust/): each bad one must fail with file:line and keyword; resource caps are
!> checked against the file's own content before anything is allocated.
module test_io_deck_trust
   use pecplas_error, only: error_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_model, only: model_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use fixtures_bad_decks, only: bad, run_bad_cases
   implicit none (type, external)
   private
   public :: collect_io_deck_trust

   character(len=*), parameter :: DIR = 'test/data/trust/'

contains

   subroutine collect_io_deck_trust(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('resource_caps', test_caps), &
               new_unittest('utf8_bom', test_bom)]
   end subroutine collect_io_deck_trust

   !> Reproducers: a 1e8-id GENERATE range, INCREMENTS=1000015, a Gmsh header announcing
   !> 1e6 elements with 8 given. Each is refused at its line (and fast: nothing allocated).
   subroutine test_caps(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DIR, [ &
         bad('generate_huge', 10, '*NSET', 'lists 100000000 ids', 'more than the 4 nodes'), &
         bad('increments_huge', 18, '*STEP', 'INCREMENTS must be <= 100000', 'Limits'), &
         bad('gmsh_count', 50, '$Elements', '1000000 elements announced', &
         'cannot hold them', file='header_count.msh')], error)
   end subroutine test_caps

   !> A UTF-8 byte order mark before the first keyword is skipped, not "a data line before
   !> the first keyword"; the deck reads like the same deck without it (4 nodes, 1 element).
   subroutine test_bom(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(model_t) :: model
      call read_deck(DIR//'good_bom.inp', model, e)
      call check(error, .not. allocated(e), 'BOM deck refused')
      if (allocated(error)) return
      call check(error, model%mesh%nnode() == 4 .and. model%mesh%nelem() == 1, &
         'BOM deck: expected 4 nodes and 1 element')
   end subroutine test_bom

end module test_io_deck_trust
