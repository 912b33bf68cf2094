!> The MUMPS solver and LINEAR=MUMPS. Each test checks what holds in the build at hand: in
!> the default serial build, that MUMPS is refused as an input error naming the deck line and
!> how to build with it; in the MPI build (one rank here; `make test-mpi` runs whole decks
!> on 1 and 2 ranks), that MUMPS solves and flags mechanisms like CHOLMOD and UMFPACK.
!> `make test-mpi` also runs this suite under `mpirun -np 1` and `-np 2`: every rank runs
!> the same tests, so the collective MUMPS calls match.
module test_linalg_mumps
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, ERR_SINGULAR, ERR_INPUT
   use pecplas_linalg_sparse, only: csc_t, coo_t, coo_to_csc
   use pecplas_linalg_mumps, only: mumps_summed_input
   use pecplas_base_parallel, only: parallel_rank, parallel_size
   use pecplas_linalg_solver, only: linear_solver_t, new_linear_solver, mumps_available
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_base_files, only: make_directories, process_id, remove_file
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_linalg, only: convection_diffusion, elastic_square, det_vector, &
      SUPPORT_NONE, SUPPORT_FIXED
   implicit none (type, external)
   private
   public :: collect_linalg_mumps

   !> Where the test writes its deck (the default deck with LINEAR=MUMPS), one per MPI rank.
   character(len=*), parameter :: DECK_STEM = 'build/test-data/mumps_default'

contains

   subroutine collect_linalg_mumps(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('deck_linear_mumps', test_deck), &
               new_unittest('factory', test_factory), &
               new_unittest('symmetric_and_unsymmetric', test_solves), &
               new_unittest('mechanism_flagged', test_singular), &
               new_unittest('symmetry_lost', test_symmetry_lost), &
               new_unittest('summed_parts', test_summed_parts)]
   end subroutine collect_linalg_mumps

   !> This process's copy of the deck (ranks of `mpirun -np 2` would otherwise write one
   !> file). Named by process id, not rank: this test may run before MUMPS has started MPI,
   !> when every rank is still rank 0.
   function deck() result(path)
      character(len=:), allocatable :: path
      character(len=16) :: buf
      write (buf, '(a,i0)') '_p', process_id()
      path = DECK_STEM//trim(buf)//'.inp'
   end function deck

   !> input/default.inp with LINEAR=MUMPS on its *SOLVER line; `at`: that line's number.
   subroutine write_deck(at, error)
      integer, intent(out) :: at
      type(error_t), allocatable, intent(out) :: error
      character(len=512) :: line
      integer :: in, out, ios, n
      call make_directories('build/test-data')
      open (newunit=in, file='input/default.inp', status='old', action='read', iostat=ios)
      call check(error, ios == 0, 'input/default.inp readable')
      if (allocated(error)) return
      open (newunit=out, file=deck(), status='replace', action='write')
      at = 0
      n = 0
      do
         read (in, '(a)', iostat=ios) line
         if (ios /= 0) exit
         n = n + 1
         if (index(line, '*SOLVER,') == 1) then
            line = '*SOLVER, LINEAR=MUMPS,'//line(9:)
            at = n
         end if
         write (out, '(a)') trim(line)
      end do
      close (in)
      close (out)
      call check(error, at > 0, 'input/default.inp has a *SOLVER line')
   end subroutine write_deck

   !> Serial build: exit 2 with "deck:line: [*SOLVER] ... make build-mpi"; MPI build: read.
   subroutine test_deck(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(model_t) :: model
      character(len=16) :: where
      integer :: at
      call write_deck(at, error)
      if (allocated(error)) return
      call read_deck(deck(), model, e)
      call remove_file(deck()) ! one file per process id: not left behind
      if (mumps_available()) then
         if (allocated(e)) then
            call check(error, .false., 'MPI build reads LINEAR=MUMPS, got: '//e%text())
            return
         end if
         if (allocated(error)) return
         call check(error, model%solver%linear == 'MUMPS', 'LINEAR=MUMPS kept')
         return
      end if
      call check(error, allocated(e), 'serial build refuses LINEAR=MUMPS')
      if (allocated(error)) return
      write (where, '(a,i0,a)') ':', at, ':'
      call check(error, e%exit_code() == 2, 'an input error: exit 2')
      if (allocated(error)) return
      call check(error, index(e%text(), deck()//trim(where)) == 1, 'message starts with '// &
         'deck:line, got: '//e%text())
      if (allocated(error)) return
      call check(error, index(e%text(), 'make build-mpi') > 0, 'message says how to build '// &
         'with MUMPS, got: '//e%text())
   end subroutine test_deck

   subroutine test_factory(error)
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: s
      type(error_t), allocatable :: e
      call new_linear_solver('mumps', s, e)
      if (mumps_available()) then
         call check(error, .not. allocated(e), 'MUMPS made in the MPI build')
         if (allocated(error)) return
         call check(error, s%name() == 'MUMPS', 'solver named MUMPS')
      else
         call check(error, allocated(e), 'no MUMPS in the serial build')
         if (allocated(error)) return
         call check(error, e%kind == ERR_INPUT .and. index(e%text(), 'build-mpi') > 0, &
            'input error saying how to build with MUMPS, got: '//e%text())
      end if
   end subroutine test_factory

   !> A x = A x_ref for a symmetric (upper triangle, LDL^T) and an unsymmetric (LU) matrix:
   !> x = x_ref within 1e-10 relative (both well conditioned; backward-stable factorisations).
   subroutine test_solves(error)
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: s
      type(error_t), allocatable :: e
      type(csc_t) :: a
      logical, allocatable :: is_x(:)
      integer :: k
      if (.not. mumps_available()) then
         call new_linear_solver('MUMPS', s, e)
         call check(error, allocated(e) .and. .not. allocated(s), 'serial build: no solver')
         return
      end if
      do k = 1, 2
         if (k == 1) call elastic_square(8, SUPPORT_FIXED, a, is_x, error)
         if (k == 2) call convection_diffusion(12, 3.0_wp, -2.0_wp, a, error)
         if (allocated(error)) return
         call new_linear_solver('MUMPS', s, error)
         if (allocated(error)) return
         call s%analyse(a, error)
         if (.not. allocated(error)) call s%factorise(a, error)
         ! a second factorisation on the same analysis (the Newton loop's reuse)
         if (.not. allocated(error)) call s%factorise(a, error)
         if (allocated(error)) return
         call check_solution(s, a, 11, 'MUMPS error in x', error)
         if (allocated(error)) return
         call check(error, s%n_analyses == 1 .and. s%n_factorisations == 2, &
            'one analysis reused by two factorisations')
         if (allocated(error)) return
         deallocate (s)
      end do
   end subroutine test_solves

   !> A floating elastic square (rigid-body modes) is reported singular, with a free equation.
   subroutine test_singular(error)
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: s
      type(error_t), allocatable :: e
      type(csc_t) :: a
      logical, allocatable :: is_x(:)
      if (.not. mumps_available()) then
         call new_linear_solver('MUMPS', s, e)
         call check(error, allocated(e), 'serial build: MUMPS refused')
         return
      end if
      call elastic_square(8, SUPPORT_NONE, a, is_x, error)
      if (allocated(error)) return
      call new_linear_solver('MUMPS', s, error)
      if (allocated(error)) return
      call s%analyse(a, error)
      if (allocated(error)) return
      call s%factorise(a, e)
      call check(error, allocated(e), 'floating square flagged')
      if (allocated(error)) return
      call check(error, e%kind == ERR_SINGULAR, 'as a singular matrix: '//e%text())
      if (allocated(error)) return
      call check(error, s%bad_equation >= 1 .and. s%bad_equation <= a%n .and. &
         .not. s%factorised, 'a free equation named, no factor kept')
   end subroutine test_singular

   !> Analysed symmetric (LDL^T), then factorised with unsymmetric values on the same
   !> pattern (convection added): analysed again as LU, and x = x_ref within 1e-10.
   subroutine test_symmetry_lost(error)
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: s
      type(error_t), allocatable :: e
      type(csc_t) :: a0, a1
      if (.not. mumps_available()) then
         call new_linear_solver('MUMPS', s, e)
         call check(error, allocated(e), 'serial build: MUMPS refused')
         return
      end if
      call convection_diffusion(10, 0.0_wp, 0.0_wp, a0, error)
      if (.not. allocated(error)) call convection_diffusion(10, 3.0_wp, -2.0_wp, a1, error)
      if (allocated(error)) return
      call check(error, a0%is_symmetric(1.0e-13_wp) .and. .not. a1%is_symmetric(1.0e-13_wp) &
         .and. all(a0%rowind == a1%rowind), 'fixtures: symmetric then not, same pattern')
      if (allocated(error)) return
      call new_linear_solver('MUMPS', s, error)
      if (allocated(error)) return
      call s%analyse(a0, error)
      if (.not. allocated(error)) call s%factorise(a0, error)
      if (.not. allocated(error)) call s%factorise(a1, error)
      if (allocated(error)) return
      call check_solution(s, a1, 5, 'MUMPS x after LU', error)
      if (allocated(error)) return
      call check(error, s%n_analyses == 2 .and. index(s%ordering, 'LU') > 0, &
         'analysed again as LU, got ordering '//s%ordering)
   end subroutine test_symmetry_lost

   !> Summed input (the partitioned assembly of an MPI run): rank r gives MUMPS only the
   !> entries (i, j) of A with mod(i + j, N) = r, N ranks (the whole A on one rank); MUMPS
   !> adds the parts, so A x = A x_ref gives x = x_ref within 1e-10 (well-conditioned
   !> fixtures, backward-stable factorisations). The split is symmetric in (i, j): the
   !> symmetric fixture is still factorised as LDL^T, the convection one as LU.
   subroutine test_summed_parts(error)
      type(error_t), allocatable, intent(out) :: error
      class(linear_solver_t), allocatable :: s
      type(error_t), allocatable :: e
      type(csc_t) :: a, part
      type(coo_t) :: coo
      logical, allocatable :: is_x(:)
      integer :: k, j, p, i
      if (.not. mumps_available()) then
         call new_linear_solver('MUMPS', s, e)
         call check(error, allocated(e), 'serial build: MUMPS refused')
         return
      end if
      do k = 1, 2
         if (k == 1) call elastic_square(8, SUPPORT_FIXED, a, is_x, error)
         if (k == 2) call convection_diffusion(12, 3.0_wp, -2.0_wp, a, error)
         if (allocated(error)) return
         call coo%init(a%n, a%nnz(), a%upper)
         do j = 1, a%n
            do p = a%colptr(j) + 1, a%colptr(j + 1)
               i = a%rowind(p) + 1
               if (a%upper .and. i > j) cycle
               if (modulo(i + j, parallel_size()) == parallel_rank()) &
                  call coo%add(i, j, a%values(p))
            end do
         end do
         call coo_to_csc(coo, part, error)
         if (allocated(error)) return
         call new_linear_solver('MUMPS', s, error)
         if (allocated(error)) return
         call mumps_summed_input(s, .true.)
         call s%analyse(part, error)
         if (.not. allocated(error)) call s%factorise(part, error)
         if (allocated(error)) return
         call check_solution(s, a, 7, 'MUMPS x from summed parts', error)
         if (allocated(error)) return
         call check(error, index(s%ordering, trim(merge('LDL^T', 'LU   ', k == 1))) > 0, &
            'factorisation kind agreed by the ranks, got '//s%ordering)
         if (allocated(error)) return
         deallocate (s)
      end do
   end subroutine test_summed_parts

   !> Solves A x = A x_ref with the factorised `s` (x_ref = det_vector(n, seed)): x = x_ref
   !> within 1e-10 of max|x_ref| (well-conditioned fixtures, backward-stable factorisations).
   subroutine check_solution(s, a, seed, what, error)
      class(linear_solver_t), intent(inout) :: s
      type(csc_t), intent(in) :: a
      integer, intent(in) :: seed
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: xref(:), b(:), x(:)
      xref = det_vector(a%n, seed)
      allocate (b(a%n), x(a%n))
      call a%matvec(xref, b)
      call s%solve(b, x, error)
      if (allocated(error)) return
      call check_close(error, maxval(abs(x - xref)), 0.0_wp, 0.0_wp, what, &
         atol=1.0e-10_wp*maxval(abs(xref)))
   end subroutine check_solution

end module test_linalg_mumps
