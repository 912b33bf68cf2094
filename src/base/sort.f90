!> Ascending order of short integer lists in place (insertion sort: tens of entries, e.g. the
!> rows of one sparse column or the element sets around a node; stable, no work array).
module pecplas_base_sort
   use pecplas_base_kinds, only: ik4
   implicit none (type, external)
   private

   public :: sort_short

contains

   !> Sorts `a` ascending; O(n^2) comparisons, meant for lists of some tens of entries.
   pure subroutine sort_short(a)
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
   end subroutine sort_short

end module pecplas_base_sort
