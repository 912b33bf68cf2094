!> The CSC pattern of an assembled matrix built straight from the element equation lists
!> (and a few extra triplets), without sorting one triplet per element-matrix entry: each
!> column j gathers the equations of the blocks that contain j (an equation-to-block
!> incidence), marked once, then sorted (a column holds some tens of rows); the columns of
!> one node, which lie in the same blocks, gather and sort their rows once. The cost is
!> that of touching every element-matrix entry once, in cache-friendly order, with no
!> triplet storage; the values are then scattered through `csc%locate`.
module pecplas_linalg_sparse_pattern
   use pecplas_base_kinds, only: wp, ik4
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_sort, only: sort_short
   use pecplas_linalg_sparse, only: coo_t, csc_t
   implicit none (type, external)
   private

   public :: pattern_from_blocks

   !> Fewer equations than this: one thread (the team costs more than it saves).
   integer, parameter :: PARALLEL_MIN = 20000

contains

   !> csc (n x n, values zero) with an entry (i, j) for every pair of equations i, j > 0 of
   !> one block b (elist(eptr(b) : eptr(b+1)-1)) and for every triplet of `extra`; with
   !> `upper`, only i <= j. Equation numbers outside 1..n are an error.
   subroutine pattern_from_blocks(n, upper, eptr, elist, extra, csc, error)
      integer, intent(in) :: n
      logical, intent(in) :: upper
      integer(ik4), intent(in) :: eptr(:), elist(:)
      type(coo_t), intent(in) :: extra
      type(csc_t), intent(out) :: csc
      type(error_t), allocatable, intent(out) :: error
      integer(ik4), allocatable :: iptr(:), inc(:), xptr(:), xrow(:), mark(:), cnt(:), &
         gfirst(:), buf(:)
      integer :: nb, b, p, j, k, nx, pass, q, i, g, ng, j1, jj, m, maxrows
      nb = size(eptr) - 1
      nx = extra%nnz
      if (any(elist > n)) then
         call fatal_error(error, 'pattern_from_blocks: equation number above n')
         return
      end if
      if (nx > 0) then
         if (minval(extra%rows(1:nx)) < 1 .or. maxval(extra%rows(1:nx)) > n .or. &
             minval(extra%cols(1:nx)) < 1 .or. maxval(extra%cols(1:nx)) > n) then
            call fatal_error(error, 'pattern_from_blocks: triplet index outside 1..n')
            return
         end if
      end if
      ! equation -> blocks holding it; extra triplets bucketed by column
      allocate (iptr(n + 1), xptr(n + 1), cnt(n))
      iptr = 0
      do p = 1, size(elist)
         if (elist(p) > 0) iptr(elist(p) + 1) = iptr(elist(p) + 1) + 1
      end do
      xptr = 0
      do k = 1, nx
         xptr(extra%cols(k) + 1) = xptr(extra%cols(k) + 1) + 1
      end do
      iptr(1) = 1; xptr(1) = 1
      do j = 1, n
         iptr(j + 1) = iptr(j + 1) + iptr(j)
         xptr(j + 1) = xptr(j + 1) + xptr(j)
      end do
      allocate (inc(iptr(n + 1) - 1), xrow(nx))
      cnt = iptr(1:n)
      do b = 1, nb
         do p = eptr(b), eptr(b + 1) - 1
            j = elist(p)
            if (j <= 0) cycle
            inc(cnt(j)) = int(b, ik4)
            cnt(j) = cnt(j) + 1
         end do
      end do
      cnt = xptr(1:n)
      do k = 1, nx
         j = extra%cols(k)
         xrow(cnt(j)) = extra%rows(k)
         cnt(j) = cnt(j) + 1
      end do
      ! Consecutive columns with the same blocks and no extra triplet (the equations of one
      ! node) have the same rows (full) or nested prefixes of them (upper): a group of such
      ! columns gathers and sorts its rows once.
      allocate (gfirst(n + 1))
      ng = 0
      do j = 1, n
         if (j > 1) then
            if (xptr(j + 1) == xptr(j) .and. xptr(j) == xptr(j - 1) .and. &
                iptr(j + 1) - iptr(j) == iptr(j) - iptr(j - 1)) then
               if (all(inc(iptr(j):iptr(j + 1) - 1) == inc(iptr(j - 1):iptr(j) - 1))) cycle
            end if
         end if
         ng = ng + 1
         gfirst(ng) = int(j, ik4)
      end do
      gfirst(ng + 1) = int(n + 1, ik4)
      ! the most rows a group can gather (with repeats): the buffer of each thread
      maxrows = 0
      do g = 1, ng
         j = gfirst(g)
         q = xptr(j + 1) - xptr(j)
         do k = iptr(j), iptr(j + 1) - 1
            q = q + eptr(inc(k) + 1) - eptr(inc(k))
         end do
         maxrows = max(maxrows, q)
      end do
      ! pass 1 counts the rows of each column, pass 2 writes them; mark(i) = g: row i is in
      ! group g already. Groups are independent: threads share them, each with its marks.
      csc%n = n
      csc%upper = upper
      allocate (csc%colptr(n + 1))
      do pass = 1, 2
         !$omp parallel default(shared) private(mark, buf, g, j, j1, jj, q, m, k, b, p, i) &
         !$omp if (n >= PARALLEL_MIN)
         allocate (mark(n), buf(max(maxrows, 1)))
         mark = 0
         !$omp do schedule(static)
         do g = 1, ng
            j = gfirst(g)
            j1 = gfirst(g + 1) - 1
            q = 0
            do k = iptr(j), iptr(j + 1) - 1
               b = inc(k)
               do p = eptr(b), eptr(b + 1) - 1
                  i = elist(p)
                  if (i <= 0) cycle
                  if (mark(i) == g .or. (upper .and. i > j1)) cycle
                  mark(i) = int(g, ik4)
                  q = q + 1
                  buf(q) = int(i, ik4)
               end do
            end do
            do k = xptr(j), xptr(j + 1) - 1
               i = xrow(k)
               if (mark(i) == g .or. (upper .and. i > j1)) cycle
               mark(i) = int(g, ik4)
               q = q + 1
               buf(q) = int(i, ik4)
            end do
            if (pass == 2) call sort_short(buf(1:q))
            do jj = j, j1
               m = q
               if (upper .and. jj < j1) m = count(buf(1:q) <= jj)
               if (pass == 1) then
                  cnt(jj) = int(m, ik4)
               else
                  ! 0-based, as csc_t stores them; the values' first touch on this thread
                  csc%rowind(csc%colptr(jj) + 1:csc%colptr(jj) + m) = buf(1:m) - 1_ik4
                  csc%values(csc%colptr(jj) + 1:csc%colptr(jj) + m) = 0.0_wp
               end if
            end do
         end do
         !$omp end do
         deallocate (mark, buf)
         !$omp end parallel
         if (pass == 1) then
            csc%colptr(1) = 0
            do j = 1, n
               csc%colptr(j + 1) = csc%colptr(j) + cnt(j)
            end do
            allocate (csc%rowind(csc%colptr(n + 1)), csc%values(csc%colptr(n + 1)))
         end if
      end do
   end subroutine pattern_from_blocks

end module pecplas_linalg_sparse_pattern
