!> Explicit interfaces to the LAPACK/BLAS routines that element-level code uses (double
!> precision), and a small dense solve. The interface blocks keep LAPACK's own
!> assumed-size dummies: they describe the Fortran 77 routines as they are.
module pecplas_linalg_lapack
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error, singular_error
   implicit none (type, external)
   private

   public :: dgesv, dgetrf, dgetrs, dsyev, dgemm, dgemv, dpotrf, dpotrs
   public :: solve_dense

   interface
      !> Solves A X = B by LU with partial pivoting (A, B overwritten).
      subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: wp
         integer, intent(in) :: n, nrhs, lda, ldb
         real(wp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgesv
      !> LU factorisation with partial pivoting.
      subroutine dgetrf(m, n, a, lda, ipiv, info)
         import :: wp
         integer, intent(in) :: m, n, lda
         real(wp), intent(inout) :: a(lda, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgetrf
      !> Solves with the LU factors of dgetrf.
      subroutine dgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: wp
         character(len=1), intent(in) :: trans
         integer, intent(in) :: n, nrhs, lda, ldb
         real(wp), intent(in) :: a(lda, *)
         integer, intent(in) :: ipiv(*)
         real(wp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dgetrs
      !> Eigenvalues (ascending) and optionally eigenvectors of a symmetric matrix.
      subroutine dsyev(jobz, uplo, n, a, lda, w, work, lwork, info)
         import :: wp
         character(len=1), intent(in) :: jobz, uplo
         integer, intent(in) :: n, lda, lwork
         real(wp), intent(inout) :: a(lda, *)
         real(wp), intent(out) :: w(*), work(*)
         integer, intent(out) :: info
      end subroutine dsyev
      !> C = alpha op(A) op(B) + beta C.
      subroutine dgemm(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc)
         import :: wp
         character(len=1), intent(in) :: transa, transb
         integer, intent(in) :: m, n, k, lda, ldb, ldc
         real(wp), intent(in) :: alpha, beta, a(lda, *), b(ldb, *)
         real(wp), intent(inout) :: c(ldc, *)
      end subroutine dgemm
      !> y = alpha op(A) x + beta y.
      subroutine dgemv(trans, m, n, alpha, a, lda, x, incx, beta, y, incy)
         import :: wp
         character(len=1), intent(in) :: trans
         integer, intent(in) :: m, n, lda, incx, incy
         real(wp), intent(in) :: alpha, beta, a(lda, *), x(*)
         real(wp), intent(inout) :: y(*)
      end subroutine dgemv
      !> Cholesky factorisation of a symmetric positive definite matrix.
      subroutine dpotrf(uplo, n, a, lda, info)
         import :: wp
         character(len=1), intent(in) :: uplo
         integer, intent(in) :: n, lda
         real(wp), intent(inout) :: a(lda, *)
         integer, intent(out) :: info
      end subroutine dpotrf
      !> Solves with the Cholesky factor of dpotrf.
      subroutine dpotrs(uplo, n, nrhs, a, lda, b, ldb, info)
         import :: wp
         character(len=1), intent(in) :: uplo
         integer, intent(in) :: n, nrhs, lda, ldb
         real(wp), intent(in) :: a(lda, *)
         real(wp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dpotrs
   end interface

contains

   !> Solves the square system a x = b in place of b (a is not modified). An exactly zero
   !> pivot is a singular-matrix error; no condition estimate is made (small local systems).
   subroutine solve_dense(a, b, error)
      real(wp), intent(in) :: a(:, :)
      real(wp), intent(inout) :: b(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: lu(:, :), rhs(:, :)
      integer, allocatable :: ipiv(:)
      integer :: n, info
      character(len=64) :: buf
      n = size(a, 1)
      if (size(a, 2) /= n .or. size(b) /= n) then
         call fatal_error(error, 'solve_dense: matrix not square or size of b differs')
         return
      end if
      if (n == 0) return
      allocate (lu, source=a)
      allocate (rhs(n, 1), ipiv(n))
      rhs(:, 1) = b
      call dgesv(n, 1, lu, n, ipiv, rhs, n, info)
      if (info > 0) then
         write (buf, '(a,i0,a,i0,a)') 'U(', info, ',', info, ') = 0'
         call singular_error(error, 'solve_dense: singular matrix, '//trim(buf))
         return
      else if (info < 0) then
         call fatal_error(error, 'solve_dense: invalid argument to dgesv')
         return
      end if
      b = rhs(:, 1)
   end subroutine solve_dense

end module pecplas_linalg_lapack
