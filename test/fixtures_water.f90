!> Shared decks of the water tests (test_water, test_water_free): the plate wall standing in
!> the water of a pit.
module fixtures_water
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private
   public :: write_wall

contains

   !> Writes to `path` the wall of the water tests: nodes 1 to n + 1 at x = 0, y = 0 to n
   !> (n 2-node plate elements of 1 m walked upwards), plate set `wall` (EA = 1e7, EI = 1e5)
   !> clamped at its base node, the water `pit` (GAMMA_W = 10) at y = `level`; `title` the
   !> deck's title, `tail` its lines after the *WATER line (*PLATE_WATER, loads, steps).
   subroutine write_wall(path, title, n, level, tail)
      character(len=*), intent(in) :: path, title, level, tail(:)
      integer, intent(in) :: n
      integer :: u, i
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', title, '*UNITS', 'kN, m, kPa', '*NODES'
      do i = 0, n
         write (u, '(i0,a,i0)') i + 1, ', 0, ', i
      end do
      write (u, '(a)') '*NSET, NAME=wall, GENERATE', '1, '//itoa(n + 1)//', 1', &
         '*PLATE, SET=wall, NODES=wall, EA=1e7, EI=1e5', '*BOUNDARY', '1, ALL', &
         '*WATER, NAME=pit, GAMMA_W=10, LEVEL='//level
      do i = 1, size(tail)
         write (u, '(a)') trim(tail(i))
      end do
      close (u)
   end subroutine write_wall

end module fixtures_water
