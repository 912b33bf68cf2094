!> Stiffness re-assembly through the scatter map (pecplas_linalg_sparse_reuse): the fast
!> path must give the matrix of the full COO -> CSC conversion of the same triplets, and any
!> change of the triplet sequence must take the full conversion again.
module test_linalg_sparse_reuse
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_fe_assembly, only: assemble_stiffness
   use pecplas_solve_stiffness, only: upper_storage
   use pecplas_linalg_cholmod, only: cholmod_solver_t
   use pecplas_linalg_sparse, only: csc_t, coo_to_csc
   use pecplas_linalg_sparse_reuse, only: csc_builder_t
   use pecplas_linalg_threads, only: thread_setting_t, apply_threads, openmp_threads
   use pecplas_testing, only: unittest_t, new_unittest, check
   use fixtures_linalg, only: det_vector
   implicit none (type, external)
   private
   public :: collect_linalg_sparse_reuse

   character(len=*), parameter :: DIR = 'build/test_out/sparse_reuse'

contains

   subroutine collect_linalg_sparse_reuse(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('fast_path_equals_full', test_fast_full), &
               new_unittest('fast_path_upper_only', test_fast_upper), &
               new_unittest('changed_sequence_falls_back', test_fallback), &
               new_unittest('joints_after_state_change', test_joints), &
               new_unittest('pattern_from_blocks_equals_full', test_pattern), &
               new_unittest('pattern_from_blocks_threads', test_pattern_threads), &
               new_unittest('block_positions_replay', test_block_replay), &
               new_unittest('pattern_node_groups', test_node_groups), &
               new_unittest('stiffness_storage_by_solver', test_storage)]
   end subroutine collect_linalg_sparse_reuse

   !> Fills `b` (after start) with nt pseudo-random triplets of an n x n matrix, many of them
   !> duplicates; `seed` changes the values only, `shift` moves triplet `shift` one column.
   subroutine fill(b, n, nt, seed, upper, shift)
      type(csc_builder_t), intent(inout) :: b
      integer, intent(in) :: n, nt, seed, shift
      logical, intent(in) :: upper
      real(wp) :: v(nt), r(nt), c(nt)
      integer :: k, i, j
      v = det_vector(nt, seed)
      r = det_vector(nt, 2)
      c = det_vector(nt, 3)
      call b%start(n, nt/4, upper)
      do k = 1, nt
         i = 1 + int((r(k) + 1.0_wp)/3.0_wp*n)
         j = 1 + int((c(k) + 1.0_wp)/3.0_wp*n)
         if (k == shift) j = 1 + mod(j, n)
         call b%coo%add(i, j, v(k))
      end do
   end subroutine fill

   !> True when a and b have the same pattern and equal values (== also equates -0 and +0,
   !> the one difference the fast path may make: it sums 0 + v where the sort copies v).
   logical function same_matrix(a, b)
      type(csc_t), intent(in) :: a, b
      same_matrix = a%n == b%n .and. (a%upper .eqv. b%upper) .and. a%nnz() == b%nnz()
      if (.not. same_matrix) return
      same_matrix = all(a%colptr == b%colptr) .and. all(a%rowind == b%rowind) .and. &
                    all(a%values == b%values)
   end function same_matrix

   !> Reference: the full conversion of the builder's current triplets.
   subroutine reference(b, a, error)
      type(csc_builder_t), intent(in) :: b
      type(csc_t), intent(out) :: a
      type(error_t), allocatable, intent(out) :: error
      call coo_to_csc(b%coo, a, error)
   end subroutine reference

   subroutine fast_vs_full(upper, error)
      logical, intent(in) :: upper
      type(error_t), allocatable, intent(out) :: error
      type(csc_builder_t) :: b
      type(csc_t) :: k, ref
      call fill(b, 40, 2000, 1, upper, 0)
      call b%finish(k, error)
      if (allocated(error)) return
      call fill(b, 40, 2000, 7, upper, 0)
      call b%finish(k, error)
      if (allocated(error)) return
      call reference(b, ref, error)
      if (allocated(error)) return
      call check(error, b%full == 1 .and. b%fast == 1, &
         'first call sorts, the repeated sequence scatters')
      if (allocated(error)) return
      call check(error, same_matrix(k, ref), &
         'fast path equals coo_to_csc exactly (pattern and values)')
      if (allocated(error)) return
      call check(error, maxval(abs(k%values)) > 0.1_wp, 'the matrix is not empty (values in -1..1)')
   end subroutine fast_vs_full

   subroutine test_fast_full(error)
      type(error_t), allocatable, intent(out) :: error
      call fast_vs_full(.false., error)
   end subroutine test_fast_full

   !> Element assembly without triplets (builder%pattern, csc%add_block, add_extra) on 30
   !> blocks of 6 pseudo-random equations of 40 (some eliminated, = 0) and 50 extra
   !> triplets: the same pattern and values as coo_to_csc of the triplet sequence, to the
   !> last bit (the same sums in the same order); the same lists again keep the pattern,
   !> one changed equation builds it anew.
   subroutine test_pattern(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: N = 40, NB = 30, ND = 6, NX = 50
      type(csc_builder_t) :: b, bref
      type(csc_t) :: k, ref
      real(wp) :: kb(ND, ND), x(NX)
      integer :: elist(ND*NB), eptr(NB + 1), i, pass
      elist = int((det_vector(ND*NB, 4) + 1.0_wp)/2.0_wp*(N + 3)) - 2 ! -2 .. N: some <= 0
      elist = max(0, min(N, elist))
      eptr = [(1 + ND*i, i=0, NB)]
      x = det_vector(NX, 5)
      do pass = 1, 3
         if (pass == 3) elist(7) = 1 + mod(elist(7), N)
         call bref%start(N, 16)
         call b%start(N, 16)
         do i = 1, NB
            kb = reshape(det_vector(ND*ND, 10 + i), [ND, ND])
            call bref%coo%add_block(elist(eptr(i):eptr(i + 1) - 1), kb)
         end do
         do i = 1, NX
            call bref%coo%add(1 + mod(7*i, N), 1 + mod(3*i, N), x(i))
            call b%coo%add(1 + mod(7*i, N), 1 + mod(3*i, N), x(i))
         end do
         call reference(bref, ref, error)
         if (allocated(error)) return
         call b%pattern(eptr, elist, k, error)
         do i = 1, NB
            if (allocated(error)) return
            kb = reshape(det_vector(ND*ND, 10 + i), [ND, ND])
            call k%add_block(elist(eptr(i):eptr(i + 1) - 1), kb, error)
         end do
         if (.not. allocated(error)) call b%add_extra(k, error)
         if (allocated(error)) return
         call check(error, same_matrix(k, ref), 'pattern assembly equals coo_to_csc exactly')
         if (allocated(error)) return
         call check(error, b%entries == bref%coo%nnz, 'entries counted as triplets')
         if (allocated(error)) return
      end do
      call check(error, b%full == 2 .and. b%fast == 1, &
         'the repeated lists keep the pattern, a changed one builds it again')
   end subroutine test_pattern

   !> Blocks added through the builder on a kept pattern: the second assembly records their
   !> positions, the next ones replay them; each result equals coo_to_csc of the same
   !> triplets exactly (one addition per entry and block, blocks in the same order), full
   !> and upper storage, values changing from one assembly to the next. Blocks added in
   !> another order than the pattern's lists drop the positions and still give the sum.
   subroutine test_block_replay(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: N = 40, NB = 30, ND = 6, NX = 20
      integer, parameter :: STATE_AFTER(5) = [0, 2, 2, 2, 0]
      type(csc_builder_t) :: b, bref
      type(csc_t) :: k, ref
      real(wp) :: kb(ND, ND)
      integer :: elist(ND*NB), eptr(NB + 1), order(NB), i, j, pass, iu
      logical :: upper
      character(len=60) :: msg
      elist = int((det_vector(ND*NB, 4) + 1.0_wp)/2.0_wp*(N + 3)) - 2 ! -2 .. N: some <= 0
      elist = max(0, min(N, elist))
      eptr = [(1 + ND*i, i=0, NB)]
      do iu = 1, 2
         upper = iu == 2
         do pass = 1, 5
            order = [(i, i=1, NB)]
            if (pass == 5) order([3, 17]) = [17, 3]
            call bref%start(N, 16, upper_only=upper)
            call b%start(N, 16, upper_only=upper)
            do j = 1, NB
               i = order(j)
               kb = reshape(det_vector(ND*ND, 10*pass + i), [ND, ND])
               call bref%coo%add_block(elist(eptr(i):eptr(i + 1) - 1), kb)
            end do
            do i = 1, NX
               call bref%coo%add(1 + mod(7*i, N), 1 + mod(3*i, N), real(i + pass, wp))
               call b%coo%add(1 + mod(7*i, N), 1 + mod(3*i, N), real(i + pass, wp))
            end do
            call reference(bref, ref, error)
            if (allocated(error)) return
            call b%pattern(eptr, elist, k, error)
            do j = 1, NB
               if (allocated(error)) return
               i = order(j)
               kb = reshape(det_vector(ND*ND, 10*pass + i), [ND, ND])
               call b%add_block(k, elist(eptr(i):eptr(i + 1) - 1), kb, error)
            end do
            if (.not. allocated(error)) call b%add_extra(k, error)
            if (allocated(error)) return
            write (msg, '(a,i0,a,l1)') 'block positions, assembly ', pass, ', upper ', upper
            call check(error, same_matrix(k, ref), trim(msg)//': equals coo_to_csc exactly')
            if (allocated(error)) return
            call check(error, b%bstate == STATE_AFTER(pass), trim(msg)//': recorded/replayed')
            if (allocated(error)) return
         end do
         call b%forget()
      end do
   end subroutine test_block_replay

   !> A pattern large enough for its columns to be shared among threads (30 000 equations,
   !> 20 000 blocks of 6, upper storage): built on 1 and on 2 threads, both equal the
   !> conversion of the same triplets entry for entry (each column is built by one thread, in
   !> the same way whichever it is).
   subroutine test_pattern_threads(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: N = 30000, NB = 20000, ND = 6
      type(csc_builder_t) :: b, bref
      type(csc_t) :: k, ref
      type(thread_setting_t) :: setting
      real(wp) :: zero(ND, ND)
      integer, allocatable :: elist(:), eptr(:)
      integer :: i, nthreads, before
      character(len=40) :: msg
      before = openmp_threads()
      zero = 0.0_wp
      elist = int((det_vector(ND*NB, 4) + 1.0_wp)/2.0_wp*(N + 3)) - 2
      elist = max(0, min(N, elist))
      eptr = [(1 + ND*i, i=0, NB)]
      call bref%start(N, 16, upper_only=.true.)
      do i = 1, NB
         call bref%coo%add_block(elist(eptr(i):eptr(i + 1) - 1), zero)
      end do
      call reference(bref, ref, error)
      if (allocated(error)) return
      do nthreads = 1, 2
         setting%n = nthreads
         call apply_threads(setting)
         call b%start(N, 16, upper_only=.true.)
         call b%pattern(eptr, elist, k, error)
         if (allocated(error)) exit
         write (msg, '(a,i0,a)') 'pattern on ', nthreads, ' thread(s) equals coo_to_csc'
         call check(error, k%upper .and. all(k%colptr == ref%colptr) .and. &
            all(k%rowind == ref%rowind), trim(msg))
         if (allocated(error)) exit
      end do
      setting%n = before
      call apply_threads(setting)
   end subroutine test_pattern_threads

   !> Upper-only storage: the lower triplets are dropped on entry, as coo_to_csc expects.
   subroutine test_fast_upper(error)
      type(error_t), allocatable, intent(out) :: error
      call fast_vs_full(.true., error)
   end subroutine test_fast_upper

   !> A moved triplet, a shorter and a longer sequence each take the full conversion, whose
   !> result is the new matrix; the unchanged sequence after them scatters again.
   subroutine test_fallback(error)
      type(error_t), allocatable, intent(out) :: error
      type(csc_builder_t) :: b
      type(csc_t) :: k, ref
      integer :: it
      call fill(b, 30, 900, 1, .false., 0)
      call b%finish(k, error)
      if (allocated(error)) return
      do it = 1, 4
         select case (it)
         case (1)
            call fill(b, 30, 900, 4, .false., 450)   ! one entry moved to another column
         case (2)
            call fill(b, 30, 899, 5, .false., 0)     ! one triplet fewer
         case (3)
            call fill(b, 30, 900, 6, .false., 0)     ! one more than last time
         case (4)
            call fill(b, 30, 900, 8, .false., 0)     ! repeated: fast again
         end select
         call b%finish(k, error)
         if (allocated(error)) return
         call reference(b, ref, error)
         if (allocated(error)) return
         call check(error, same_matrix(k, ref), 'builder result equals coo_to_csc after a change')
         if (allocated(error)) return
      end do
      call check(error, b%full == 4 .and. b%fast == 1, &
         '3 changed sequences fall back, 1 repeat scatters')
   end subroutine test_fallback

   !> Pad on a plane pressed and pushed beyond friction through Mohr-Coulomb joints, full
   !> Newton (the run stops at the limit load, exit 3): in the last state the joints slide,
   !> and the re-assembly of the consistent tangent through the map used during the run
   !> equals the full conversion by a fresh builder.
   subroutine test_joints(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(csc_builder_t) :: fresh
      type(csc_t) :: kfull, kel
      integer :: code
      call make_directories(DIR)
      code = run_deck('test/data/joints/pad_slip.inp', DIR//'/pad_slip.h5', .true., model, &
         problem)
      call check(error, code == 3, 'pad_slip stops when the pad slides away')
      if (allocated(error)) return
      call check(error, problem%linear%kbuild%fast > 0, 'the Newton iterations of the run used the map')
      if (allocated(error)) return
      associate (p => problem)
         call assemble_stiffness(model, p%system%dofs, p%system%rules, p%state, .false., p%linear%kbuild, p%linear%k, error)
         if (allocated(error)) return
         kel = p%linear%k
         call assemble_stiffness(model, p%system%dofs, p%system%rules, p%state, .true., p%linear%kbuild, p%linear%k, error)
         if (allocated(error)) return
         call assemble_stiffness(model, p%system%dofs, p%system%rules, p%state, .true., fresh, kfull, error)
         if (allocated(error)) return
      end associate
      call check(error, .not. upper_storage(model) .and. .not. problem%linear%k%upper, &
         'a run with a non-symmetric tangent (UMFPACK) stores the whole matrix')
      if (allocated(error)) return
      call check(error, fresh%full == 1 .and. fresh%fast == 0, 'a fresh builder sorts')
      if (allocated(error)) return
      call check(error, same_matrix(problem%linear%k, kfull), 'mapped tangent equals the full conversion')
      if (allocated(error)) return
      call check(error, &
         maxval(abs(kel%values - kfull%values)) > 1.0e-6_wp*maxval(abs(kfull%values)), &
         'the tangent differs from the elastic stiffness (the map rewrote the values)')
   end subroutine test_joints

   !> An elastic block (every matrix of the run goes to CHOLMOD) stores only the upper
   !> triangle of its stiffness: exactly the entries i <= j of the whole matrix assembled
   !> from the same state (and recovered from its values by upper_of_whole, as a restart from
   !> data holding the whole matrix does), and CHOLMOD, which reads only the upper triangle,
   !> gives the same solution from either (to 1e-14 relative; the same factor).
   subroutine test_storage(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(csc_builder_t) :: fresh
      type(csc_t) :: kfull
      type(cholmod_solver_t) :: s1, s2
      real(wp), allocatable :: b(:), x1(:), x2(:), taken(:)
      integer :: code, j, p, q, kept
      call make_directories(DIR)
      code = run_deck('test/data/decks/good_block_q4.inp', DIR//'/good_block_q4.h5', .true., &
         model, problem)
      call check(error, code == 0, 'the elastic block runs')
      if (allocated(error)) return
      call check(error, upper_storage(model) .and. problem%linear%k%upper, &
         'a run whose matrices all go to CHOLMOD stores the upper triangle')
      if (allocated(error)) return
      call assemble_stiffness(model, problem%system%dofs, problem%system%rules, problem%state, .false., &
         fresh, kfull, error)
      if (allocated(error)) return
      call check(error, .not. kfull%upper, 'assembled without `upper`: the whole matrix')
      if (allocated(error)) return
      kept = 0
      do j = 1, kfull%n
         do p = kfull%colptr(j) + 1, kfull%colptr(j + 1)
            if (kfull%rowind(p) + 1 > j) cycle
            kept = kept + 1
            q = problem%linear%k%locate(kfull%rowind(p) + 1, j)
            call check(error, q > 0, 'every upper entry of the whole matrix is stored')
            if (allocated(error)) return
            call check(error, problem%linear%k%values(q) == kfull%values(p), &
               'with the same value, to the last bit')
            if (allocated(error)) return
         end do
      end do
      call check(error, kept == problem%linear%k%nnz() .and. kept < kfull%nnz(), &
         'and nothing else (fewer entries than the whole matrix)')
      if (allocated(error)) return
      ! the values of the whole matrix, as restart data written before this storage hold it
      call check(error, problem%linear%k%whole_nnz() == kfull%nnz(), &
         'whole_nnz counts the entries of the whole matrix')
      if (allocated(error)) return
      call problem%linear%k%upper_of_whole(kfull%values, taken)
      call check(error, all(taken == problem%linear%k%values), &
         'upper_of_whole takes the upper triangle from the whole matrix, to the last bit')
      if (allocated(error)) return
      b = det_vector(kfull%n, 3)
      allocate (x1(kfull%n), x2(kfull%n))
      call s1%analyse(problem%linear%k, error)
      if (.not. allocated(error)) call s1%factorise(problem%linear%k, error)
      if (.not. allocated(error)) call s1%solve(b, x1, error)
      if (.not. allocated(error)) call s2%analyse(kfull, error)
      if (.not. allocated(error)) call s2%factorise(kfull, error)
      if (.not. allocated(error)) call s2%solve(b, x2, error)
      if (allocated(error)) return
      call check(error, maxval(abs(x1 - x2)) <= 1.0e-14_wp*maxval(abs(x2)), &
         'CHOLMOD solves the upper triangle and the whole matrix alike')
   end subroutine test_storage

   !> Blocks of a node grid (equations 2k-1, 2k of node k, as the massif assembly numbers
   !> them; some equations fixed, 0) with extra triplets on a few columns, one of them the
   !> second equation of a node: the columns of a node gather their rows once
   !> (pattern_from_blocks), and the pattern and the assembled values still equal coo_to_csc
   !> of the same triplets exactly, full and upper storage.
   subroutine test_node_groups(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: NXN = 7, NYN = 5, NB = (NXN - 1)*(NYN - 1), ND = 8
      integer, parameter :: NEQ = 2*NXN*NYN, XCOLS(3) = [8, 21, NEQ]
      type(csc_builder_t) :: b, bref
      type(csc_t) :: k, ref
      real(wp) :: kb(ND, ND)
      integer :: elist(ND*NB), eptr(NB + 1), eq(NEQ), nodes(4), e, i, ix, iy, iu, c
      logical :: upper
      eq = [(i, i=1, NEQ)]
      eq([1, 2, 15, 40]) = 0  ! a fixed node and two single fixed equations
      eptr = [(1 + ND*i, i=0, NB)]
      e = 0
      do iy = 1, NYN - 1
         do ix = 1, NXN - 1
            e = e + 1
            nodes = [ix + (iy - 1)*NXN, ix + 1 + (iy - 1)*NXN, ix + 1 + iy*NXN, ix + iy*NXN]
            do c = 1, 4
               elist(eptr(e) + 2*c - 2) = eq(2*nodes(c) - 1)
               elist(eptr(e) + 2*c - 1) = eq(2*nodes(c))
            end do
         end do
      end do
      do iu = 1, 2
         upper = iu == 2
         call bref%start(NEQ, 16, upper_only=upper)
         call b%start(NEQ, 16, upper_only=upper)
         do e = 1, NB
            kb = reshape(det_vector(ND*ND, 20 + e), [ND, ND])
            call bref%coo%add_block(elist(eptr(e):eptr(e + 1) - 1), kb)
         end do
         ! extra triplets in columns 8 (first equation of node 4), 21 (second of node 11)
         ! and 70 (last), rows far from the columns' own blocks
         do i = 1, 3
            call bref%coo%add(3*i, XCOLS(i), real(i, wp))
            call b%coo%add(3*i, XCOLS(i), real(i, wp))
         end do
         call reference(bref, ref, error)
         if (allocated(error)) return
         call b%pattern(eptr, elist, k, error)
         do e = 1, NB
            if (allocated(error)) return
            kb = reshape(det_vector(ND*ND, 20 + e), [ND, ND])
            call k%add_block(elist(eptr(e):eptr(e + 1) - 1), kb, error)
         end do
         if (.not. allocated(error)) call b%add_extra(k, error)
         if (allocated(error)) return
         call check(error, same_matrix(k, ref), 'node-grid pattern and values equal '// &
            'coo_to_csc exactly, upper = '//merge('T', 'F', upper))
         if (allocated(error)) return
      end do
   end subroutine test_node_groups

end module test_linalg_sparse_reuse
