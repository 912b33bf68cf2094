!> Triplet assembly and COO -> CSC conversion, checked against dense matrices built
!> independently from the same triplets.
module test_linalg_sparse
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_linalg_sparse, only: coo_t, csc_t, coo_to_csc
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_linalg, only: laplacian, det_vector
   implicit none (type, external)
   private
   public :: collect_linalg_sparse

contains

   subroutine collect_linalg_sparse(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('duplicates_summed_rows_sorted', test_duplicates), &
               new_unittest('matvec_vs_dense', test_matvec), &
               new_unittest('add_block_skips_eliminated', test_add_block), &
               new_unittest('upper_only_storage', test_upper), &
               new_unittest('reassembly_on_pattern', test_reassembly), &
               new_unittest('symmetry_check', test_symmetry), &
               new_unittest('index_out_of_range', test_out_of_range), &
               new_unittest('diagonal_full_and_upper', test_diagonal)]
   end subroutine collect_linalg_sparse

   !> csc%diagonal equals the dense diagonal, zero where none is stored (the last third of
   !> the diagonal is left empty), in full and in upper storage (where it reads
   !> the last entry of a column). Duplicates summed in another order: 1e-14 relative.
   subroutine test_diagonal(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: N = 30, NT = 600
      type(coo_t) :: coo, up
      type(csc_t) :: a
      real(wp) :: dense(N, N), d(N), ref(N)
      integer :: i, storage
      call random_coo(N, NT, coo, dense)
      do i = 1, 2*N/3
         call coo%add(i, i, real(i, wp))
         dense(i, i) = dense(i, i) + real(i, wp)
      end do
      ref = [(dense(i, i), i=1, N)]
      call up%init(N, 1, upper_only=.true.)
      do i = 1, coo%nnz
         call up%add(int(coo%rows(i)), int(coo%cols(i)), coo%vals(i))
      end do
      do storage = 1, 2
         if (storage == 1) then
            call coo_to_csc(coo, a, error)
         else
            call coo_to_csc(up, a, error)
         end if
         if (allocated(error)) return
         call a%diagonal(d)
         call check(error, all(abs(d - ref) <= 1.0e-14_wp*maxval(abs(ref))) .and. &
            any(ref == 0.0_wp) .and. any(ref /= 0.0_wp), 'diagonal of the assembled matrix')
         if (allocated(error)) return
      end do
   end subroutine test_diagonal

   !> Pseudo-random triplets with many duplicates, grown from a capacity of 1.
   subroutine random_coo(n, nt, coo, dense)
      integer, intent(in) :: n, nt
      type(coo_t), intent(out) :: coo
      real(wp), intent(out) :: dense(n, n)
      real(wp) :: v(nt), r(nt), c(nt)
      integer :: k, i, j
      v = det_vector(nt, 1)
      r = det_vector(nt, 2)
      c = det_vector(nt, 3)
      call coo%init(n, 1)
      dense = 0.0_wp
      do k = 1, nt
         i = 1 + int((r(k) + 1.0_wp)/3.0_wp*n)
         j = 1 + int((c(k) + 1.0_wp)/3.0_wp*n)
         call coo%add(i, j, v(k))
         dense(i, j) = dense(i, j) + v(k)
      end do
   end subroutine random_coo

   function to_dense(a) result(d)
      type(csc_t), intent(in) :: a
      real(wp) :: d(a%n, a%n)
      integer :: j, p
      d = 0.0_wp
      do j = 1, a%n
         do p = a%colptr(j) + 1, a%colptr(j + 1)
            d(a%rowind(p) + 1, j) = d(a%rowind(p) + 1, j) + a%values(p)
         end do
      end do
   end function to_dense

   subroutine test_duplicates(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: n = 9, nt = 300
      type(coo_t) :: coo
      type(csc_t) :: a
      real(wp) :: dense(n, n), back(n, n)
      logical :: seen(n, n)
      integer :: k, j, p
      call random_coo(n, nt, coo, dense)
      call check(error, coo%nnz == nt, 'all triplets kept after growing from capacity 1')
      if (allocated(error)) return
      seen = .false.
      do k = 1, nt
         seen(coo%rows(k), coo%cols(k)) = .true.
      end do
      call coo_to_csc(coo, a, error)
      if (allocated(error)) return
      ! one stored entry per distinct (i, j): ~300 triplets on 81 slots must collapse
      call check(error, a%nnz() == count(seen) .and. a%colptr(1) == 0, 'duplicates merged')
      if (allocated(error)) return
      do j = 1, n
         do p = a%colptr(j) + 1, a%colptr(j + 1) - 1
            call check(error, a%rowind(p) < a%rowind(p + 1), 'rows strictly ascending in a column')
            if (allocated(error)) return
         end do
      end do
      back = to_dense(a)
      ! the same values summed (order may differ): a few ulps of the largest partial sum
      call check(error, maxval(abs(back - dense)) <= 1.0e-14_wp*maxval(abs(dense)), &
         'CSC equals the dense sum of the triplets')
   end subroutine test_duplicates

   subroutine test_matvec(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: n = 200, nt = 5000
      type(coo_t) :: coo
      type(csc_t) :: a
      real(wp), allocatable :: dense(:, :)
      real(wp) :: x(n), y(n), yref(n), scale
      allocate (dense(n, n))
      call random_coo(n, nt, coo, dense)
      call coo_to_csc(coo, a, error)
      if (allocated(error)) return
      x = det_vector(n, 7)
      call a%matvec(x, y)
      yref = matmul(dense, x)
      ! rounding of n-term sums, relative to sum |a_ij x_j|
      scale = maxval(matmul(abs(dense), abs(x)))
      call check(error, maxval(abs(y - yref)) <= 1.0e-14_wp*scale, 'matvec = dense matmul')
   end subroutine test_matvec

   subroutine test_add_block(error)
      type(error_t), allocatable, intent(out) :: error
      type(coo_t) :: coo
      type(csc_t) :: a
      real(wp) :: kb(4, 4), dense(3, 3), expect(3, 3)
      integer :: r, c
      integer, parameter :: idx(4) = [3, 0, 1, -2]
      do c = 1, 4
         do r = 1, 4
            kb(r, c) = 10*r + c
         end do
      end do
      call coo%init(3, 2)
      call coo%add_block(idx, kb)
      call coo%add_block(idx, kb) ! twice: every kept entry doubles
      call coo_to_csc(coo, a, error)
      if (allocated(error)) return
      dense = to_dense(a)
      expect = 0.0_wp
      expect(3, 3) = 2*kb(1, 1); expect(3, 1) = 2*kb(1, 3)
      expect(1, 3) = 2*kb(3, 1); expect(1, 1) = 2*kb(3, 3)
      ! small integers: exact
      call check(error, maxval(abs(dense - expect)) <= 0.0_wp .and. a%nnz() == 4, &
         'idx <= 0 skipped, blocks summed')
   end subroutine test_add_block

   subroutine test_upper(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: full, up
      real(wp) :: x(64), yf(64), yu(64)
      integer :: j, p
      call laplacian(8, .true., full, error)
      if (allocated(error)) return
      call laplacian(8, .true., up, error, upper_only=.true.)
      if (allocated(error)) return
      do j = 1, up%n
         do p = up%colptr(j) + 1, up%colptr(j + 1)
            call check(error, up%rowind(p) + 1 <= j, 'upper storage has no entry below the diagonal')
            if (allocated(error)) return
         end do
      end do
      ! 8x8 grid: 64 diagonal + 2*56 edges off-diagonal in the upper triangle
      call check(error, up%upper .and. up%nnz() == 64 + 112 .and. full%nnz() == 64 + 224, &
         'entry counts of the 8x8 5-point Laplacian')
      if (allocated(error)) return
      x = det_vector(64, 4)
      call full%matvec(x, yf)
      call up%matvec(x, yu)
      ! small integer matrix entries: the mirrored product is the same to rounding
      call check(error, maxval(abs(yf - yu)) <= 1.0e-14_wp*maxval(abs(yf)), &
         'upper-only matvec mirrors the lower triangle')
   end subroutine test_upper

   subroutine test_reassembly(error)
      type(error_t), allocatable, intent(out) :: error
      type(coo_t) :: coo
      type(csc_t) :: a, b
      real(wp) :: kb(3, 3)
      type(error_t), allocatable :: e
      kb = reshape([2, -1, 0, -1, 2, -1, 0, -1, 2]*1.0_wp, [3, 3])
      call coo%init(5, 9)
      call coo%add_block([1, 2, 3], kb)
      call coo%add_block([3, 4, 5], kb)
      call coo_to_csc(coo, a, error)
      if (allocated(error)) return
      b = a
      b%values = 0.0_wp
      call b%add_block([1, 2, 3], kb, error)
      if (allocated(error)) return
      call b%add_block([3, 4, 5], kb, error)
      if (allocated(error)) return
      ! same integer-valued sums: exact
      call check(error, maxval(abs(b%values - a%values)) <= 0.0_wp, &
         're-assembly on the pattern = conversion')
      if (allocated(error)) return
      call check_close(error, b%values(b%locate(3, 3)), 4.0_wp, 0.0_wp, 'shared node sums 2+2')
      if (allocated(error)) return
      call b%add_block([1, 5], kb(1:2, 1:2), e)
      call check(error, allocated(e), 'entry (1,5) is not in the pattern: error')
   end subroutine test_reassembly

   subroutine test_symmetry(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a
      call laplacian(6, .true., a, error)
      if (allocated(error)) return
      call check(error, a%is_symmetric(1.0e-14_wp), 'Laplacian is symmetric')
      if (allocated(error)) return
      a%values(a%locate(2, 1)) = a%values(a%locate(2, 1)) + 1.0e-6_wp
      call check(error, .not. a%is_symmetric(1.0e-8_wp), 'a 1e-6 perturbation breaks symmetry')
   end subroutine test_symmetry

   subroutine test_out_of_range(error)
      type(error_t), allocatable, intent(out) :: error
      type(coo_t) :: coo
      type(csc_t) :: a
      type(error_t), allocatable :: e
      call coo%init(3, 4)
      call coo%add(1, 1, 1.0_wp)
      call coo%add(4, 1, 1.0_wp)
      call coo_to_csc(coo, a, e)
      call check(error, allocated(e), 'row 4 in a 3x3 matrix is an error')
   end subroutine test_out_of_range

end module test_linalg_sparse
