!> CHOLMOD and UMFPACK behind linear_solver_t: known solutions, factorisation reuse,
!> singular and indefinite systems, the factory, and the dense LAPACK wrappers.
module test_linalg_solvers
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, ERR_SINGULAR, ERR_INPUT
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_linalg_solver, only: linear_solver_t, new_linear_solver
   use pecplas_linalg_cholmod, only: pecplas_cholmod_new, pecplas_cholmod_delete, &
      pecplas_cholmod_analyse, pecplas_cholmod_factorise
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int
   use pecplas_linalg_lapack, only: solve_dense, dgemm, dgemv, dsyev, dpotrf, dpotrs, dgetrf, dgetrs
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_linalg, only: laplacian, convection_diffusion, elastic_square, det_vector, &
      SUPPORT_NONE, SUPPORT_ROLLER, SUPPORT_FIXED
   implicit none (type, external)
   private
   public :: collect_linalg_solvers

   character(len=7), parameter :: BOTH(2) = [character(len=7) :: 'CHOLMOD', 'UMFPACK']

contains

   subroutine collect_linalg_solvers(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('spd_known_solution', test_spd), &
               new_unittest('reuse_analysis_many_rhs', test_reuse), &
               new_unittest('umfpack_nonsymmetric', test_nonsymmetric), &
               new_unittest('singular_floating', test_floating), &
               new_unittest('singular_part_supported', test_partly_supported), &
               new_unittest('singular_tiny_springs', test_tiny_springs), &
               new_unittest('unconnected_dof', test_unconnected), &
               new_unittest('well_posed_not_flagged', test_well_posed), &
               new_unittest('cholmod_indefinite', test_indefinite), &
               new_unittest('unknown_solver_name', test_unknown), &
               new_unittest('dense_lapack', test_dense)]
   end subroutine collect_linalg_solvers

   !> Analyse + factorise `a` with solver `name`; the error of either step is returned.
   subroutine setup(name, a, s, error)
      character(len=*), intent(in) :: name
      type(csc_t), intent(in) :: a
      class(linear_solver_t), allocatable, intent(out) :: s
      type(error_t), allocatable, intent(out) :: error
      call new_linear_solver(name, s, error)
      if (allocated(error)) return
      call s%analyse(a, error)
      if (allocated(error)) return
      call s%factorise(a, error)
   end subroutine setup

   !> Solves A x = A x_ref and checks x against x_ref within rtol (max norm).
   subroutine check_solves(s, a, rtol, error)
      class(linear_solver_t), intent(inout) :: s
      type(csc_t), intent(in) :: a
      real(wp), intent(in) :: rtol
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: xref(a%n), b(a%n), x(a%n)
      xref = det_vector(a%n, 11)
      call a%matvec(xref, b)
      call s%solve(b, x, error)
      if (allocated(error)) return
      call check_close(error, maxval(abs(x - xref)), 0.0_wp, 0.0_wp, s%name()//' error in x', &
         atol=rtol*maxval(abs(xref)))
   end subroutine check_solves

   subroutine test_spd(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a
      class(linear_solver_t), allocatable :: s
      real(wp) :: b(900), x1(900), x2(900)
      integer :: k
      call laplacian(30, .true., a, error)
      if (allocated(error)) return
      call a%matvec(det_vector(900, 11), b)
      do k = 1, 2
         call setup(BOTH(k), a, s, error)
         if (allocated(error)) return
         ! cond(A) ~ 4e2 for the 30x30 grid: backward-stable solvers give ~1e-13
         call check_solves(s, a, 1.0e-10_wp, error)
         if (allocated(error)) return
         if (k == 1) call s%solve(b, x1, error)
         if (k == 2) call s%solve(b, x2, error)
         if (allocated(error)) return
         call check(error, s%nnz_factor >= 900 .and. allocated(s%ordering), s%name()//' statistics')
         if (allocated(error)) return
         call s%free()
      end do
      call check(error, maxval(abs(x1 - x2)) <= 1.0e-10_wp*maxval(abs(x1)), &
         'CHOLMOD and UMFPACK agree')
   end subroutine test_spd

   subroutine test_reuse(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a
      class(linear_solver_t), allocatable :: s
      real(wp) :: xref(400, 3), b(400, 3), x(400, 3)
      integer :: k, j
      do k = 1, 2
         call laplacian(20, .true., a, error)
         if (allocated(error)) return
         call setup(BOTH(k), a, s, error)
         if (allocated(error)) return
         do j = 1, 3
            xref(:, j) = det_vector(400, j)
            call a%matvec(xref(:, j), b(:, j))
         end do
         call s%solve(b, x, error)
         if (allocated(error)) return
         ! cond ~ 2e2: three right-hand sides in one call, each to 1e-10
         call check(error, maxval(abs(x - xref)) <= 1.0e-10_wp*maxval(abs(xref)), s%name()//' multi-RHS')
         if (allocated(error)) return
         ! new values on the same pattern (2A + diagonal shift): factorise only
         a%values = 2.0_wp*a%values
         do j = 1, a%n
            a%values(a%locate(j, j)) = a%values(a%locate(j, j)) + 0.5_wp
         end do
         call s%factorise(a, error)
         if (allocated(error)) return
         call check_solves(s, a, 1.0e-10_wp, error)
         if (allocated(error)) return
         call check(error, s%n_analyses == 1 .and. s%n_factorisations == 2 .and. s%n_solves == 4, &
            s%name()//' counters: 1 analysis, 2 factorisations, 4 solves')
         if (allocated(error)) return
         call s%free()
      end do
   end subroutine test_reuse

   subroutine test_nonsymmetric(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a
      class(linear_solver_t), allocatable :: s
      call convection_diffusion(25, 3.0_wp, 1.5_wp, a, error)
      if (allocated(error)) return
      call check(error, .not. a%is_symmetric(1.0e-12_wp), 'matrix is non-symmetric')
      if (allocated(error)) return
      call setup('umfpack', a, s, error)
      if (allocated(error)) return
      ! diagonally dominant M-matrix, modest condition number: 1e-10 is generous
      call check_solves(s, a, 1.0e-10_wp, error)
   end subroutine test_nonsymmetric

   !> Both solvers must fail with ERR_SINGULAR and a bad equation for which `ok` holds.
   subroutine expect_singular(a, ok, what, error)
      type(csc_t), intent(in) :: a
      logical, intent(in) :: ok(:)
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: s
      type(error_t), allocatable :: e
      real(wp) :: x(a%n), b(a%n)
      integer :: k
      character(len=16) :: buf
      b = 1.0_wp
      do k = 1, 2
         call setup(BOTH(k), a, s, e)
         call check(error, allocated(e), trim(BOTH(k))//' must reject '//what)
         if (allocated(error)) return
         call check(error, e%kind == ERR_SINGULAR, trim(BOTH(k))//' error kind singular: '//e%text())
         if (allocated(error)) return
         write (buf, '(i0)') s%bad_equation
         call check(error, s%bad_equation >= 1 .and. s%bad_equation <= a%n, &
            trim(BOTH(k))//' bad equation in range: '//trim(buf))
         if (allocated(error)) return
         call check(error, ok(s%bad_equation), trim(BOTH(k))//' bad equation '//trim(buf)// &
            ' belongs to the mechanism of '//what)
         if (allocated(error)) return
         call s%solve(b, x, e)
         call check(error, allocated(e), trim(BOTH(k))//' refuses to solve after a singular factorisation')
         if (allocated(error)) return
         call s%free()
      end do
   end subroutine expect_singular

   subroutine test_floating(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a
      logical, allocatable :: is_x(:)
      ! graph Laplacian: null vector = constant, every equation moves
      call laplacian(12, .false., a, error)
      if (allocated(error)) return
      call expect_singular(a, spread(.true., 1, a%n), 'a Neumann Laplacian', error)
      if (allocated(error)) return
      ! free elastic square: 3 rigid-body modes span every equation
      call elastic_square(8, SUPPORT_NONE, a, is_x, error)
      if (allocated(error)) return
      call expect_singular(a, spread(.true., 1, a%n), 'a floating elastic square', error)
      if (allocated(error)) return
      ! rollers on the bottom: only the horizontal translation is free (null vector = all
      ! x displacements), so the bad equation must be an x displacement
      call elastic_square(8, SUPPORT_ROLLER, a, is_x, error)
      if (allocated(error)) return
      call expect_singular(a, is_x, 'a square on rollers (x translation)', error)
   end subroutine test_floating

   subroutine test_partly_supported(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a, b, c
      integer :: na, k
      ! block diagonal [Dirichlet 10x10 grid, Neumann 7x7 grid]: only the second block is free
      call laplacian(10, .true., a, error)
      if (allocated(error)) return
      call laplacian(7, .false., b, error)
      if (allocated(error)) return
      na = a%n
      c%n = a%n + b%n
      c%colptr = [a%colptr, b%colptr(2:) + a%nnz()]
      c%rowind = [a%rowind, b%rowind + na]
      c%values = [a%values, b%values]
      call expect_singular(c, [(k > na, k = 1, c%n)], 'a free sub-body', error)
   end subroutine test_partly_supported

   !> Adds springs of `ratio` times the diagonal on equations first..last.
   subroutine add_springs(a, first, last, ratio)
      type(csc_t), intent(inout) :: a
      integer, intent(in) :: first, last
      real(wp), intent(in) :: ratio
      integer :: j, p
      do j = first, last
         p = a%locate(j, j)
         a%values(p) = a%values(p)*(1.0_wp + ratio)
      end do
   end subroutine add_springs

   !> A free sub-body held by springs of 1e-12 times its stiffness is positive definite, so
   !> LL' succeeds (checked below): the scaled pivot ratio (~ n * 1e-12) must catch it.
   subroutine test_tiny_springs(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a, b, c
      type(c_ptr) :: h
      integer(c_int) :: status
      integer :: na, k
      call laplacian(10, .true., a, error)
      if (allocated(error)) return
      call laplacian(7, .false., b, error)
      if (allocated(error)) return
      na = a%n
      c%n = a%n + b%n
      c%colptr = [a%colptr, b%colptr(2:) + a%nnz()]
      c%rowind = [a%rowind, b%rowind + na]
      c%values = [a%values, b%values]
      call add_springs(c, na + 1, c%n, 1.0e-12_wp)
      h = pecplas_cholmod_new(0_c_int)
      status = pecplas_cholmod_analyse(h, c%n, c%colptr, c%rowind)
      if (status == 0) status = pecplas_cholmod_factorise(h, c%n, c%colptr, c%rowind, c%values)
      call pecplas_cholmod_delete(h)
      call check(error, status == 0, 'bare CHOLMOD LL'' succeeds on the weakly held body')
      if (allocated(error)) return
      call expect_singular(c, [(k > na, k = 1, c%n)], 'a sub-body on 1e-12 springs', error)
   end subroutine test_tiny_springs

   subroutine test_unconnected(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a, c
      integer :: k
      ! a 6x6 Dirichlet grid plus equation 37 with an empty column (no element touches it)
      call laplacian(6, .true., a, error)
      if (allocated(error)) return
      c%n = 37
      c%colptr = [a%colptr, a%colptr(37)]
      c%rowind = a%rowind
      c%values = a%values
      call expect_singular(c, [(k == 37, k = 1, 37)], 'an unconnected dof', error)
   end subroutine test_unconnected

   subroutine test_well_posed(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a
      class(linear_solver_t), allocatable :: s
      logical, allocatable :: is_x(:)
      integer :: k, m
      do k = 1, 2
         do m = 1, 4
            select case (m)
            case (1) ! clamped elastic square, uniform
               call elastic_square(16, SUPPORT_FIXED, a, is_x, error)
            case (2) ! stiffness contrast 1e8 between the halves (pile in soft soil)
               call elastic_square(16, SUPPORT_FIXED, a, is_x, error, contrast=1.0e8_wp)
            case (3) ! Laplacian with conductivity contrast 1e10
               call laplacian(30, .true., a, error, contrast=1.0e10_wp)
            case (4) ! free body on soft springs (1e-6 of the diagonal): cond ~ 1e6, legitimate
               call laplacian(30, .false., a, error)
               call add_springs(a, 1, a%n, 1.0e-6_wp)
            end select
            if (allocated(error)) return
            call setup(BOTH(k), a, s, error)
            if (allocated(error)) return
            ! high contrast: cond up to ~1e12, so only a loose accuracy check (1e-3)
            call check_solves(s, a, 1.0e-3_wp, error)
            if (allocated(error)) return
            call check(error, s%bad_equation == 0, s%name()//' no bad equation when well posed')
            if (allocated(error)) return
            ! scaled pivot ratios are O(0.1) here: 3 decades of margin to the threshold at least
            call check(error, s%rcond > 1.0e3_wp*s%rcond_tol, s%name()//' rcond far from the threshold')
            if (allocated(error)) return
            call s%free()
         end do
      end do
   end subroutine test_well_posed

   subroutine test_indefinite(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a
      class(linear_solver_t), allocatable :: s
      type(error_t), allocatable :: e
      real(wp), parameter :: pi = acos(-1.0_wp)
      real(wp) :: shift
      integer :: j
      ! Dirichlet Laplacian minus a shift between its two lowest eigenvalues
      ! 4 - 2cos(pi/11) - 2cos(k pi/11), k = 1, 2: nonsingular, one negative eigenvalue
      call laplacian(10, .true., a, error)
      if (allocated(error)) return
      shift = 4.0_wp - 2.0_wp*cos(pi/11) - (cos(pi/11) + cos(2*pi/11))
      do j = 1, a%n
         a%values(a%locate(j, j)) = a%values(a%locate(j, j)) - shift
      end do
      call setup('CHOLMOD', a, s, e)
      call check(error, allocated(e), 'CHOLMOD rejects an indefinite matrix')
      if (allocated(error)) return
      call check(error, index(e%message, 'not singular') > 0 .and. index(e%message, 'UMFPACK') > 0, &
         'message says indefinite, not singular, and suggests UMFPACK: '//e%message)
      if (allocated(error)) return
      call setup('UMFPACK', a, s, error)
      if (allocated(error)) return
      ! eigenvalue gap to the shift ~0.1, cond ~ 1e2
      call check_solves(s, a, 1.0e-10_wp, error)
   end subroutine test_indefinite

   subroutine test_unknown(error)
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: s
      type(error_t), allocatable :: e
      call new_linear_solver('Pardiso', s, e)
      call check(error, allocated(e), 'unknown name is an error')
      if (allocated(error)) return
      call check(error, e%kind == ERR_INPUT .and. index(e%message, 'Pardiso') > 0 .and. &
         index(e%message, 'CHOLMOD UMFPACK') > 0, 'message names the input and lists: '//e%message)
      if (allocated(error)) return
      call new_linear_solver(' cholmod', s, error)
      if (allocated(error)) return
      call check(error, s%name() == 'CHOLMOD', 'names are case-insensitive')
      if (allocated(error)) return
      call new_linear_solver('Umfpack', s, error)
      if (allocated(error)) return
      call check(error, s%name() == 'UMFPACK', 'names are case-insensitive')
   end subroutine test_unknown

   subroutine test_dense(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      real(wp) :: a(3, 3), b(3), c(3, 3), w(2), s(2, 2), work(10), y(3), lu(3, 3), r(3, 1)
      integer :: info, ipiv(3)
      a = reshape([4, 1, 0, 1, 3, 1, 0, 1, 2]*1.0_wp, [3, 3])
      b = matmul(a, [1.0_wp, -2.0_wp, 3.0_wp])
      call solve_dense(a, b, error)
      if (allocated(error)) return
      ! exact solution (1, -2, 3) of a well-conditioned 3x3: to rounding
      call check(error, maxval(abs(b - [1.0_wp, -2.0_wp, 3.0_wp])) <= 1.0e-14_wp, 'dgesv solve')
      if (allocated(error)) return
      b = 1.0_wp
      call solve_dense(reshape([1, 2, 0, 2, 4, 0, 0, 0, 1]*1.0_wp, [3, 3]), b, e)
      call check(error, allocated(e), 'singular dense matrix is an error')
      if (allocated(error)) return
      call check(error, e%kind == ERR_SINGULAR, 'of kind singular')
      if (allocated(error)) return
      call dgemm('N', 'T', 3, 3, 3, 1.0_wp, a, 3, a, 3, 0.0_wp, c, 3)
      call check(error, maxval(abs(c - matmul(a, transpose(a)))) <= 1.0e-14_wp, 'dgemm = matmul')
      if (allocated(error)) return
      y = 0.0_wp
      call dgemv('T', 3, 3, 2.0_wp, a, 3, [1.0_wp, 2.0_wp, 3.0_wp], 1, 0.0_wp, y, 1)
      call check(error, maxval(abs(y - 2*matmul([1.0_wp, 2.0_wp, 3.0_wp], a))) <= 1.0e-14_wp, 'dgemv')
      if (allocated(error)) return
      s = reshape([2.0_wp, 1.0_wp, 1.0_wp, 2.0_wp], [2, 2])
      call dsyev('N', 'U', 2, s, 2, w, work, 10, info)
      ! eigenvalues of [[2,1],[1,2]] are 1 and 3
      call check(error, info == 0 .and. maxval(abs(w - [1.0_wp, 3.0_wp])) <= 1.0e-14_wp, 'dsyev')
      if (allocated(error)) return
      lu = a
      r(:, 1) = matmul(a, [1.0_wp, 1.0_wp, 1.0_wp])
      call dpotrf('U', 3, lu, 3, info)
      if (info == 0) call dpotrs('U', 3, 1, lu, 3, r, 3, info)
      call check(error, info == 0 .and. maxval(abs(r(:, 1) - 1.0_wp)) <= 1.0e-14_wp, 'dpotrf/dpotrs')
      if (allocated(error)) return
      lu = a
      r(:, 1) = matmul(a, [1.0_wp, 1.0_wp, 1.0_wp])
      call dgetrf(3, 3, lu, 3, ipiv, info)
      if (info == 0) call dgetrs('N', 3, 1, lu, 3, ipiv, r, 3, info)
      call check(error, info == 0 .and. maxval(abs(r(:, 1) - 1.0_wp)) <= 1.0e-14_wp, 'dgetrf/dgetrs')
   end subroutine test_dense

end module test_linalg_solvers
