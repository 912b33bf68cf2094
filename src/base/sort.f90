!> Ascending order of short lists in place (insertion sort: tens of entries, e.g. the rows of
!> one sparse column, the element sets around a node, the cut points of an element side;
!> stable, no work array).
module pecplas_base_sort
   use pecplas_base_kinds, only: ik4, wp
   implicit none (type, external)
   private

   public :: sort_short

   interface sort_short
      module procedure sort_short_int, sort_short_real
   end interface sort_short

contains

   !> Sorts `a` ascending; O(n^2) comparisons, meant for lists of some tens of entries.
   pure subroutine sort_short_int(a)
      integer(ik4), intent(inout) :: a(:)
      integer(ik4) :: v
      integer :: i, k
      do i = 2, size(a)
         v = a(i)
         k = i - 1
         do while (k >= 1)
            if (a(k) <= v) exit
            a(k + 1) = a(k)
            k = k - 1
         end do
         a(k + 1) = v
      end do
   end subroutine sort_short_int

   !> Sorts `a` ascending (as sort_short_int; a NaN stays where it is met).
   pure subroutine sort_short_real(a)
      real(wp), intent(inout) :: a(:)
      real(wp) :: v
      integer :: i, k
      do i = 2, size(a)
         v = a(i)
         k = i - 1
         do while (k >= 1)
            if (.not. a(k) > v) exit
            a(k + 1) = a(k)
            k = k - 1
         end do
         a(k + 1) = v
      end do
   end subroutine sort_short_real

end module pecplas_base_sort
