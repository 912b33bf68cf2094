!> Where an id is repeated (node and element ids of a deck), so that the error can name
!> both lines: a stable sort of positions by id, O(n log n). Lookups of ids go through
!> pecplas_model_node_lookup; this only answers "which two entries clash".
module pecplas_io_deck_repeats
   implicit none (type, external)
   private

   public :: first_repeat

contains

   !> Positions (first, second) of the repeated id whose second occurrence comes first in
   !> the list, (0, 0) when all ids differ.
   pure function first_repeat(ids) result(dup)
      integer, intent(in) :: ids(:)
      integer :: dup(2)
      integer, allocatable :: perm(:), work(:)
      integer :: i, n
      n = size(ids)
      allocate (perm(n), work(n))
      perm = [(i, i=1, n)]
      call merge_sort(ids, perm, work)
      dup = 0
      do i = 2, n
         if (ids(perm(i)) /= ids(perm(i - 1))) cycle
         ! stable sort: perm(i - 1) < perm(i) for equal ids
         if (dup(2) == 0 .or. perm(i) < dup(2)) dup = [perm(i - 1), perm(i)]
      end do
   end function first_repeat

   !> Stable bottom-up merge sort of the permutation `perm` by key(perm).
   pure subroutine merge_sort(key, perm, work)
      integer, intent(in) :: key(:)
      integer, intent(inout) :: perm(:), work(:)
      integer :: n, width, lo, mid, hi, i, j, k
      logical :: left
      n = size(perm)
      width = 1
      do while (width < n)
         lo = 1
         do while (lo <= n)
            mid = min(lo + width, n + 1)
            hi = min(lo + 2*width, n + 1)
            i = lo; j = mid; k = lo
            do while (k < hi)
               left = i < mid
               if (left .and. j < hi) left = key(perm(i)) <= key(perm(j))
               if (left) then
                  work(k) = perm(i); i = i + 1
               else
                  work(k) = perm(j); j = j + 1
               end if
               k = k + 1
            end do
            lo = hi
         end do
         perm = work
         width = 2*width
      end do
   end subroutine merge_sort

end module pecplas_io_deck_repeats
