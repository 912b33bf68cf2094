!> Bulk (Dörfler) marking for adaptive refinement: the fewest elements, largest indicators
!> first, whose squared indicators sum to at least theta times the total.
module pecplas_model_refine_mark
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: bulk_marking

contains

   !> marked(i) for the smallest set of the largest eta(i) with
   !> sum eta(marked)^2 >= theta sum eta^2 (0 < theta <= 1; all zero: nothing marked).
   function bulk_marking(eta, theta) result(marked)
      real(wp), intent(in) :: eta(:), theta
      logical, allocatable :: marked(:)
      real(wp) :: total, acc
      integer :: k, i
      integer, allocatable :: order(:)
      allocate (marked(size(eta)), source=.false.)
      total = sum(eta**2)
      if (.not. (total > 0.0_wp)) return
      order = ranked(eta)
      acc = 0.0_wp
      do k = 1, size(order)
         i = order(k)
         marked(i) = .true.
         acc = acc + eta(i)**2
         if (acc >= theta*total) exit
      end do
   end function bulk_marking

   !> Indices of eta, largest first (a stable merge sort: ties keep their order).
   function ranked(eta) result(order)
      real(wp), intent(in) :: eta(:)
      integer, allocatable :: order(:)
      integer, allocatable :: work(:)
      integer :: width, lo, mid, hi, i, j, k, n
      n = size(eta)
      order = [(i, i=1, n)]
      allocate (work(n))
      width = 1
      do while (width < n)
         do lo = 1, n, 2*width
            mid = min(lo + width, n + 1)
            hi = min(lo + 2*width, n + 1)
            i = lo
            j = mid
            do k = lo, hi - 1
               if (j >= hi) then
                  work(k) = order(i); i = i + 1
               else if (i >= mid) then
                  work(k) = order(j); j = j + 1
               else if (eta(order(j)) > eta(order(i))) then
                  work(k) = order(j); j = j + 1
               else
                  work(k) = order(i); i = i + 1
               end if
            end do
         end do
         order = work
         width = 2*width
      end do
   end function ranked

end module pecplas_model_refine_mark
