!> CHOLMOD's fill-reducing orderings through the shim: every ordering solves the same system
!> to round-off, the ordering asked for is the one reported, and the solver's rule is the
!> one doc/bench/ordering.md states.
module test_linalg_cholmod_ordering
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_associated
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_linalg_sparse, only: coo_t, csc_t, coo_to_csc
   use pecplas_linalg_solver, only: linear_solver_t, new_linear_solver
   use pecplas_linalg_cholmod, only: pecplas_cholmod_new, pecplas_cholmod_delete, &
      pecplas_cholmod_analyse, pecplas_cholmod_factorise, pecplas_cholmod_solve, &
      pecplas_cholmod_ordering, pecplas_cholmod_lnz, pecplas_cholmod_flops, &
      pecplas_cholmod_set_ordering, ORDER_RULE, ORDER_CHOLMOD_DEFAULT, ORDER_METIS_NODES, &
      ORDER_AMD, ORDER_METIS, ORDER_NESDIS
   use pecplas_testing, only: unittest_t, new_unittest, check
   use fixtures_linalg, only: elastic_square, det_vector, SUPPORT_ROLLER, SUPPORT_FIXED
   implicit none (type, external)
   private
   public :: collect_linalg_cholmod_ordering

   !> CHOLMOD's code of each ordering asked for (METIS on the graph of nodes reports METIS;
   !> CHOLMOD's default strategy keeps AMD on a matrix this small, see the test).
   integer(c_int), parameter :: ASKED(5) = [ORDER_AMD, ORDER_METIS, ORDER_NESDIS, &
      ORDER_METIS_NODES, ORDER_CHOLMOD_DEFAULT]
   integer(c_int), parameter :: REPORTED(5) = [ORDER_AMD, ORDER_METIS, ORDER_NESDIS, &
      ORDER_METIS, ORDER_AMD]

contains

   subroutine collect_linalg_cholmod_ordering(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('orderings_solve_alike', test_orderings), &
               new_unittest('rule_is_amd', test_rule), &
               new_unittest('nested_dissection_when_amd_fills', test_nested_dissection), &
               new_unittest('nested_dissection_at_second_factorisation', test_deferred)]
   end subroutine collect_linalg_cholmod_ordering

   !> Analyse + factorise + solve K x = b with ordering `ordering`; reports what CHOLMOD used.
   subroutine solve_with(a, ordering, b, x, used, lnz, fl, error)
      type(csc_t), intent(in) :: a
      integer(c_int), intent(in) :: ordering
      real(wp), intent(in) :: b(:)
      real(wp), intent(out) :: x(:), lnz, fl
      integer(c_int), intent(out) :: used
      type(error_t), allocatable, intent(out) :: error
      type(c_ptr) :: h
      integer(c_int) :: rc
      h = pecplas_cholmod_new(0_c_int)
      call check(error, c_associated(h), 'CHOLMOD handle')
      if (allocated(error)) return
      call pecplas_cholmod_set_ordering(h, ordering)
      rc = pecplas_cholmod_analyse(h, a%n, a%colptr, a%rowind)
      if (rc == 0) rc = pecplas_cholmod_factorise(h, a%n, a%colptr, a%rowind, a%values)
      if (rc == 0) rc = pecplas_cholmod_solve(h, a%n, 1_c_int, b, x)
      used = pecplas_cholmod_ordering(h)
      lnz = pecplas_cholmod_lnz(h)
      fl = pecplas_cholmod_flops(h)
      call pecplas_cholmod_delete(h)
      call check(error, rc == 0, 'CHOLMOD status 0 for every step')
   end subroutine solve_with

   !> Rollers on the base: nodes there keep one equation, the others two, so the graph of
   !> nodes METIS_NODES builds merges pairs and keeps singles; a unit spring on the first
   !> horizontal unknown takes the rigid horizontal motion. Every ordering solves the same
   !> SPD system: the solutions differ by round-off only.
   subroutine test_orderings(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a
      logical, allocatable :: is_x(:)
      real(wp), allocatable :: xref(:), b(:), x(:)
      real(wp) :: lnz, fl
      integer(c_int) :: used
      integer :: k
      character(len=80) :: msg
      call elastic_square(40, SUPPORT_ROLLER, a, is_x, error)
      if (allocated(error)) return
      k = findloc(is_x, .true., 1)
      a%values(a%locate(k, k)) = a%values(a%locate(k, k)) + 1.0_wp
      xref = det_vector(a%n, 7)
      allocate (b(a%n), x(a%n))
      call a%matvec(xref, b)
      do k = 1, size(ASKED)
         call solve_with(a, ASKED(k), b, x, used, lnz, fl, error)
         if (allocated(error)) return
         write (msg, '(a,i0,a,i0,a,i0)') 'ordering ', ASKED(k), ': CHOLMOD reports ', used, &
            ', expected ', REPORTED(k)
         call check(error, used == REPORTED(k), trim(msg))
         if (allocated(error)) return
         ! a fill-reducing ordering of a 3362-equation 2-D problem: nnz(L) well below the
         ! 5.7e6 of a dense factor, and at least the 1.5e4 of nnz(upper K) / 2
         call check(error, lnz > 1.5e4_wp .and. lnz < 5.0e5_wp .and. fl > lnz, &
            'nnz(L) and flops of a sparse factor')
         if (allocated(error)) return
         ! cond(K) of the 40x40 block held by one spring is ~1e6 at most: backward-stable
         ! Cholesky gives ~1e-10; the orderings differ only in rounding
         write (msg, '(a,i0,a,es9.2)') 'ordering ', ASKED(k), ': solution error ', &
            maxval(abs(x - xref))/maxval(abs(xref))
         call check(error, maxval(abs(x - xref)) <= 1.0e-8_wp*maxval(abs(xref)), trim(msg))
         if (allocated(error)) return
      end do
   end subroutine test_orderings

   !> The program's solver uses the shim's rule (AMD alone): its statistics equal those of an
   !> explicit AMD analysis of the same matrix (same deterministic algorithm: exact).
   subroutine test_rule(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a
      logical, allocatable :: is_x(:)
      class(linear_solver_t), allocatable :: s
      real(wp), allocatable :: b(:), x(:)
      real(wp) :: lnz, fl, lnz_rule, fl_rule
      integer(c_int) :: used, used_rule
      call elastic_square(30, SUPPORT_FIXED, a, is_x, error)
      if (allocated(error)) return
      allocate (b(a%n), x(a%n))
      b = 1.0_wp
      call new_linear_solver('CHOLMOD', s, error)
      if (allocated(error)) return
      call s%analyse(a, error)
      if (allocated(error)) return
      call check(error, s%ordering == 'AMD', 'solver ordering AMD, got '//s%ordering)
      if (allocated(error)) return
      call solve_with(a, ORDER_AMD, b, x, used, lnz, fl, error)
      if (allocated(error)) return
      call solve_with(a, ORDER_RULE, b, x, used_rule, lnz_rule, fl_rule, error)
      if (allocated(error)) return
      call check(error, used_rule == ORDER_AMD .and. lnz_rule == lnz .and. fl_rule == fl .and. &
         real(s%nnz_factor, wp) == lnz .and. s%flops == fl, 'rule = AMD: same nnz(L) and flops')
   end subroutine test_rule

   !> Two unknowns per node of an m x m x m grid, coupled by B = [2 1; 1 2] along each edge
   !> and B on the diagonal of every node (SPD): a 3-D pattern, where AMD leaves many flops per
   !> entry of L already at a few thousand nodes, with pairs of equations to merge.
   subroutine block_laplacian_3d(m, a, error)
      integer, intent(in) :: m
      type(csc_t), intent(out) :: a
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: B(2, 2) = reshape([2.0_wp, 1.0_wp, 1.0_wp, 2.0_wp], [2, 2])
      type(coo_t) :: coo
      real(wp) :: edge(4, 4)
      integer :: i, j, k, p, d, stride(3)
      stride = [1, m, m*m]
      edge(1:2, 1:2) = B; edge(3:4, 3:4) = B; edge(1:2, 3:4) = -B; edge(3:4, 1:2) = -B
      call coo%init(2*m**3, 4*16*m**3, .true.)
      do k = 1, m
         do j = 1, m
            do i = 1, m
               p = i + m*(j - 1) + m*m*(k - 1)
               call coo%add_block([2*p - 1, 2*p], B)
               do d = 1, 3
                  if (d == 1 .and. i == m .or. d == 2 .and. j == m .or. d == 3 .and. k == m) cycle
                  call coo%add_block([2*p - 1, 2*p, 2*(p + stride(d)) - 1, 2*(p + stride(d))], &
                     edge)
               end do
            end do
         end do
      end do
      call coo_to_csc(coo, a, error)
   end subroutine block_laplacian_3d

   !> The m x m x m block Laplacian a, a reference solution xref with b = a xref (x allocated),
   !> and AMD's flop count; an error unless AMD leaves lo <= flops per entry of L < hi (the
   !> range the calling test is about).
   subroutine grid_with_amd(m, lo, hi, a, xref, b, x, amd_flops, error)
      integer, intent(in) :: m
      real(wp), intent(in) :: lo, hi
      type(csc_t), intent(out) :: a
      real(wp), allocatable, intent(out) :: xref(:), b(:), x(:)
      real(wp), intent(out) :: amd_flops
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: amd_lnz
      integer(c_int) :: used
      character(len=80) :: msg
      call block_laplacian_3d(m, a, error)
      if (allocated(error)) return
      xref = det_vector(a%n, 3)
      allocate (b(a%n), x(a%n))
      call a%matvec(xref, b)
      call solve_with(a, ORDER_AMD, b, x, used, amd_lnz, amd_flops, error)
      if (allocated(error)) return
      write (msg, '(a,es10.3,a,es9.2,a,es9.2,a)') 'AMD flops per entry of L ', &
         amd_flops/amd_lnz, ' (in [', lo, ',', hi, ') for this test)'
      call check(error, amd_flops >= lo*amd_lnz .and. amd_flops < hi*amd_lnz, trim(msg))
   end subroutine grid_with_amd

   !> A pattern where AMD leaves >= 1000 flops per entry of L: the rule also orders it by METIS
   !> on the graph of nodes at the analysis and keeps that, as nested dissection has fewer
   !> flops than AMD on a 3-D grid (the check fails if it did not), and the system is solved.
   subroutine test_nested_dissection(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a
      class(linear_solver_t), allocatable :: s
      real(wp), allocatable :: xref(:), b(:), x(:)
      real(wp) :: amd_flops
      character(len=120) :: msg
      call grid_with_amd(24, 1000.0_wp, huge(1.0_wp), a, xref, b, x, amd_flops, error)
      if (allocated(error)) return
      call new_linear_solver('CHOLMOD', s, error)
      if (allocated(error)) return
      call s%analyse(a, error)
      if (allocated(error)) return
      write (msg, '(a,a,a,es10.3,a,es10.3)') 'rule: ', s%ordering, ', flops ', s%flops, &
         ' against AMD ', amd_flops
      call check(error, s%ordering == 'METIS' .and. s%flops < amd_flops .and. &
         s%n_analyses == 1, trim(msg))
      if (allocated(error)) return
      call s%factorise(a, error)
      if (allocated(error)) return
      call s%solve(b, x, error)
      if (allocated(error)) return
      ! K = (I + L) (x) B, L the grid's graph Laplacian (eigenvalues in [0, 12]), B's in
      ! [1, 3]: cond(K) <= 39, so Cholesky gives ~1e-14
      call check(error, maxval(abs(x - xref)) <= 1.0e-10_wp*maxval(abs(xref)), 'solution')
   end subroutine test_nested_dissection

   !> A pattern where AMD leaves between 500 and 1000 flops per entry of L (3-D grid, m = 20:
   !> 733): the analysis keeps AMD, and so does the first factorisation (a run that factorises
   !> once does not pay for METIS); the second orders it by METIS on the graph of nodes (fewer
   !> flops on a 3-D grid: 468 per entry), counted as a second analysis, and still solves.
   subroutine test_deferred(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_t) :: a
      class(linear_solver_t), allocatable :: s
      real(wp), allocatable :: xref(:), b(:), x(:)
      real(wp) :: amd_flops
      character(len=160) :: msg
      call grid_with_amd(20, 500.0_wp, 1000.0_wp, a, xref, b, x, amd_flops, error)
      if (allocated(error)) return
      call new_linear_solver('CHOLMOD', s, error)
      if (allocated(error)) return
      call s%analyse(a, error)
      if (.not. allocated(error)) call s%factorise(a, error)
      if (allocated(error)) return
      call check(error, s%ordering == 'AMD' .and. s%flops == amd_flops .and. &
         s%n_analyses == 1, 'first factorisation: AMD kept, got '//s%ordering)
      if (allocated(error)) return
      call s%factorise(a, error)
      if (allocated(error)) return
      write (msg, '(a,a,a,es10.3,a,es10.3,a,i0)') 'second factorisation: ', s%ordering, &
         ', flops ', s%flops, ' against AMD ', amd_flops, ', analyses ', s%n_analyses
      call check(error, s%ordering == 'METIS' .and. s%flops < amd_flops .and. &
         s%n_analyses == 2, trim(msg))
      if (allocated(error)) return
      call s%solve(b, x, error)
      if (allocated(error)) return
      ! cond(K) <= 39 as above
      call check(error, maxval(abs(x - xref)) <= 1.0e-10_wp*maxval(abs(xref)), 'solution')
   end subroutine test_deferred

end module test_linalg_cholmod_ordering
