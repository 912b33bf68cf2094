!> User id -> position lookup (node and element ids of a deck): a stable sort of the ids
!> and binary search, O(n log n) to build and O(log n) per query, and detection of the
!> first repeated id in reading order.
module pecplas_io_deck_lookup
   implicit none (type, external)
   private

   public :: id_lookup_t, new_id_lookup

   type :: id_lookup_t
      !> Sorted ids and the position of each in the original list.
      integer, allocatable :: ids(:), pos(:)
   contains
      procedure :: find => lookup_find
   end type id_lookup_t

contains

   !> Builds the lookup of ids(1:n). dup = (first, second) positions of the repeated id
   !> whose second occurrence comes first in the list, (0, 0) when all ids differ.
   subroutine new_id_lookup(lookup, ids, dup)
      type(id_lookup_t), intent(out) :: lookup
      integer, intent(in) :: ids(:)
      integer, intent(out) :: dup(2)
      integer, allocatable :: work(:)
      integer :: i, n
      n = size(ids)
      allocate (lookup%pos(n), work(n))
      lookup%pos = [(i, i=1, n)]
      call merge_sort(ids, lookup%pos, work)
      lookup%ids = ids(lookup%pos)
      dup = 0
      do i = 2, n
         if (lookup%ids(i) /= lookup%ids(i - 1)) cycle
         if (dup(2) == 0 .or. lookup%pos(i) < dup(2)) dup = [lookup%pos(i - 1), lookup%pos(i)]
      end do
   end subroutine new_id_lookup

   !> Position of `id` in the original list, 0 if absent (the first one if repeated).
   pure integer function lookup_find(this, id) result(k)
      class(id_lookup_t), intent(in) :: this
      integer, intent(in) :: id
      integer :: lo, hi, mid
      k = 0
      if (.not. allocated(this%ids)) return
      lo = 1
      hi = size(this%ids)
      do while (lo < hi)
         mid = (lo + hi)/2
         if (this%ids(mid) < id) then
            lo = mid + 1
         else
            hi = mid
         end if
      end do
      if (lo <= size(this%ids)) then
         if (this%ids(lo) == id) k = this%pos(lo)
      end if
   end function lookup_find

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

end module pecplas_io_deck_lookup
