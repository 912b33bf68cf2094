!> Element blocks added by threads owning column ranges (pecplas_linalg_sparse_columns):
!> every entry gets its terms in the order of the block sequence, so the values must equal
!> those of csc%add_block block after block exactly (the same floating-point additions in
!> the same order: no rounding can differ), for any split of the columns and any number
!> of threads; an entry missing from the pattern is reported.
module test_linalg_sparse_columns
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_linalg_sparse_reuse, only: csc_builder_t
   use pecplas_linalg_sparse_columns, only: add_blocks_by_columns
   use pecplas_linalg_threads, only: thread_setting_t, apply_threads, openmp_threads
   use pecplas_testing, only: unittest_t, new_unittest, check
   use fixtures_linalg, only: det_vector
   implicit none (type, external)
   private
   public :: collect_linalg_sparse_columns

   integer, parameter :: N = 3000, NB = 2500, ND = 6

contains

   subroutine collect_linalg_sparse_columns(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('columns_equal_block_order', test_equal), &
               new_unittest('columns_missing_entry', test_missing)]
   end subroutine collect_linalg_sparse_columns

   !> Blocks of ND pseudo-random equations in 0..N (0: a supported one, skipped), values
   !> of both signs, on the pattern of the blocks (upper or whole storage).
   subroutine blocks(upper, idx, kb, k, error)
      logical, intent(in) :: upper
      integer, allocatable, intent(out) :: idx(:, :)
      real(wp), allocatable, intent(out) :: kb(:, :, :)
      type(csc_t), intent(out) :: k
      type(error_t), allocatable, intent(out) :: error
      type(csc_builder_t) :: b
      integer, allocatable :: eptr(:)
      integer :: i
      idx = reshape(max(0, min(N, int((det_vector(ND*NB, 4) + 1.0_wp)/2.0_wp*(N + 3)) - 2)), &
         [ND, NB])
      kb = reshape(det_vector(ND*ND*NB, 5), [ND, ND, NB])
      eptr = [(1 + ND*i, i=0, NB)]
      call b%start(N, 16, upper_only=upper)
      call b%pattern(eptr, reshape(idx, [ND*NB]), k, error)
   end subroutine blocks

   subroutine test_equal(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: ref, k
      type(thread_setting_t) :: setting
      integer, allocatable :: idx(:, :)
      real(wp), allocatable :: kb(:, :, :)
      integer :: i, nthreads, nparts, before, u
      logical :: upper
      character(len=60) :: msg
      before = openmp_threads()
      do u = 1, 2
         upper = u == 1
         call blocks(upper, idx, kb, ref, error)
         if (allocated(error)) exit
         k = ref
         do i = 1, NB
            call ref%add_block(idx(:, i), kb(:, :, i), error)
            if (allocated(error)) exit
         end do
         if (allocated(error)) exit
         do nthreads = 1, 2
            setting%n = nthreads
            call apply_threads(setting)
            do nparts = 1, 7, 3
               k%values = 0.0_wp
               call add_blocks_by_columns(k, NB, idx, kb, k%column_parts(nparts), error)
               if (allocated(error)) exit
               write (msg, '(a,i0,a,i0,a,l1)') 'parts ', nparts, ', threads ', nthreads, &
                  ', upper ', upper
               call check(error, all(k%values == ref%values), trim(msg)//': values equal')
               if (allocated(error)) exit
            end do
            if (allocated(error)) exit
         end do
         if (allocated(error)) exit
      end do
      setting%n = before
      call apply_threads(setting)
   end subroutine test_equal

   !> A block with an entry the pattern lacks: an error, from the first such block.
   subroutine test_missing(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: err
      type(csc_t) :: k
      integer, allocatable :: idx(:, :)
      real(wp), allocatable :: kb(:, :, :)
      integer :: j
      call blocks(.false., idx, kb, k, error)
      if (allocated(error)) return
      ! an equation j that shares no block with equation 1 (most do not)
      j = N
      do while (j > 1)
         if (k%locate(1, j) == 0) exit
         j = j - 1
      end do
      call check(error, j > 1, 'an equation shares no block with equation 1')
      if (allocated(error)) return
      idx(:, 7) = [1, j, 0, 0, 0, 0]
      call add_blocks_by_columns(k, NB, idx, kb, k%column_parts(3), err)
      call check(error, allocated(err), 'an entry outside the pattern is an error')
      if (allocated(error)) return
      call check(error, index(err%text(), 'not in the pattern') > 0, &
         'the error names the missing entry: '//err%text())
   end subroutine test_missing

end module test_linalg_sparse_columns
