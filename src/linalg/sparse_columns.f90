!> Addition of a sequence of element blocks into a CSC matrix by threads that own disjoint
!> column ranges: each thread walks the whole sequence and adds the entries of its own
!> columns, so every entry receives its terms in the order of the sequence, as in a serial
!> addition block after block, to the last bit, whatever the number of threads. The
!> element loops compute their blocks in parallel; this takes their serial addition off
!> the main thread.
module pecplas_linalg_sparse_columns
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_linalg_sparse, only: csc_t
   implicit none (type, external)
   private

   public :: add_blocks_by_columns

contains

   !> k%values(idx(r, b), idx(c, b)) += kb(r, c, b) for the blocks b = 1..nb in order,
   !> as k%add_block does one block after the other (idx <= 0 skipped). first(1..nparts+1)
   !> splits the columns (csc_t%column_parts); part p is added by one thread. A missing
   !> entry: the error of the first block (and, in it, of the first part) that has one.
   subroutine add_blocks_by_columns(k, nb, idx, kb, first, error)
      type(csc_t), intent(inout) :: k
      integer, intent(in) :: nb
      integer, intent(in) :: idx(:, :)
      real(wp), intent(in) :: kb(:, :, :)
      integer, intent(in) :: first(:)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: err
      integer :: p, b, bad_b, bad_p
      bad_b = huge(bad_b)
      bad_p = huge(bad_p)
      !$omp parallel do default(shared) private(p, b, err) schedule(static, 1)
      do p = 1, size(first) - 1
         if (first(p + 1) <= first(p)) cycle
         do b = 1, nb
            call k%add_block(idx(:, b), kb(:, :, b), err, first=first(p), last=first(p + 1) - 1)
            if (allocated(err)) then
               !$omp critical (pecplas_sparse_columns_error)
               if (b < bad_b .or. (b == bad_b .and. p < bad_p)) then
                  bad_b = b
                  bad_p = p
                  call move_alloc(err, error)
               end if
               !$omp end critical (pecplas_sparse_columns_error)
               exit
            end if
         end do
      end do
      !$omp end parallel do
   end subroutine add_blocks_by_columns

end module pecplas_linalg_sparse_columns
