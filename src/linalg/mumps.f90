!> MUMPS distributed multifrontal LDL^T / LU behind `linear_solver_t`, for MPI runs
!> (`mpirun -np N pecplas DECK` with *SOLVER, LINEAR=MUMPS; MPI build only, see doc/mpi.md).
!>
!> The matrix reaches MUMPS as distributed assembled input (ICNTL(18) = 3), in one of two
!> ways. Summed input (`mumps_summed_input`, the partitioned assembly of an MPI run): each
!> rank holds the part of the matrix assembled from its own elements and hands MUMPS all of
!> it; MUMPS adds the parts. Replicated input (the default): every rank holds the same whole
!> matrix and hands MUMPS only its share, a block of whole columns with about nnz/N entries. The analysis is done once per pattern and
!> reused by every factorisation, as with CHOLMOD. A symmetric matrix (its upper triangle
!> stored, or full storage found symmetric to 1e-13 of its largest entry) is factorised as
!> general symmetric (SYM = 2, LDL^T, also for the indefinite Katona bordered systems), from
!> its upper triangle; any other as unsymmetric (SYM = 0, LU). A matrix analysed as
!> symmetric whose values later are not (a tangent that loses symmetry when an interface
!> slips or a non-associated material yields) is analysed again as unsymmetric, for good.
!>
!> Singularity (method): MUMPS's null-pivot detection (ICNTL(24) = 1) with the threshold
!> CNTL(3) = rcond_tol, relative to the norm of the scaled matrix; a null pivot, or the
!> status -10 (numerically singular), is singular and bad_equation is the first null pivot.
module pecplas_linalg_mumps
   use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_int, c_double, c_associated
   use pecplas_base_kinds, only: wp, ik8
   use pecplas_base_error, only: error_t, fatal_error, singular_error
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_linalg_solver_type, only: linear_solver_t, solver_report
   use pecplas_base_parallel, only: parallel_rank, parallel_size, parallel_any
   implicit none (type, external)
   private

   public :: mumps_solver_t, mumps_available, mumps_summed_input

   !> Relative asymmetry (of the largest entry) below which a full matrix is symmetric.
   real(wp), parameter :: SYM_TOL = 1.0e-13_wp

   interface
      integer(c_int) function c_available() bind(C, name='pecplas_mumps_available')
         import :: c_int
      end function
      type(c_ptr) function c_new(sym, tol, status) bind(C, name='pecplas_mumps_new')
         import :: c_ptr, c_int, c_double
         integer(c_int), value :: sym
         real(c_double), value :: tol
         integer(c_int), intent(out) :: status
      end function
      integer(c_int) function c_analyse(h, n, nz, irn, jcn) bind(C, name='pecplas_mumps_analyse')
         import :: c_ptr, c_int
         type(c_ptr), value :: h
         integer(c_int), value :: n, nz
         integer(c_int), intent(in) :: irn(*), jcn(*)
      end function
      integer(c_int) function c_factorise(h, a) bind(C, name='pecplas_mumps_factorise')
         import :: c_ptr, c_int, c_double
         type(c_ptr), value :: h
         real(c_double), intent(in) :: a(*)
      end function
      integer(c_int) function c_solve(h, nrhs, b) bind(C, name='pecplas_mumps_solve')
         import :: c_ptr, c_int, c_double
         type(c_ptr), value :: h
         integer(c_int), value :: nrhs
         real(c_double), intent(inout) :: b(*)
      end function
      subroutine c_info(h, infog, rinfog, null_pivot) bind(C, name='pecplas_mumps_info')
         import :: c_ptr, c_int, c_double
         type(c_ptr), value :: h
         integer(c_int), intent(out) :: infog(80), null_pivot
         real(c_double), intent(out) :: rinfog(40)
      end subroutine
      subroutine c_start() bind(C, name='pecplas_mumps_start')
      end subroutine
      subroutine c_free(h) bind(C, name='pecplas_mumps_free')
         import :: c_ptr
         type(c_ptr), value :: h
      end subroutine
   end interface

   !> MUMPS with distributed assembled input. Do not copy a solver that holds a factor.
   type, extends(linear_solver_t) :: mumps_solver_t
      type(c_ptr), private :: handle = c_null_ptr
      !> This rank's entries: positions first+1 .. last of the CSC values, of which `pick`
      !> (1-based) go to MUMPS (all of them, or the upper triangle for SYM = 2).
      integer, private :: first = 0, last = 0
      integer, allocatable, private :: pick(:)
      logical, private :: upper = .false., symmetric = .false., force_lu = .false.
      !> Each rank gives its own part of the matrix, the sum over the ranks (else the whole
      !> matrix on every rank).
      logical :: summed = .false.
      integer(ik8), private :: nnz = 0
      !> MUMPS's global statistics of the last call (INFOG, RINFOG; 1-based as in its guide).
      integer :: infog(80) = 0
      real(wp) :: rinfog(40) = 0.0_wp
   contains
      procedure :: analyse => mumps_analyse
      procedure :: factorise => mumps_factorise
      procedure :: solve_raw => mumps_solve_raw
      procedure :: free => mumps_free
      procedure :: name => mumps_name
      procedure :: report => mumps_report
      final :: mumps_final
   end type mumps_solver_t

contains

   !> True when this build links MUMPS (the MPI build).
   logical function mumps_available()
      mumps_available = c_available() == 1
   end function mumps_available

   !> Marks `solver`, when it is MUMPS, as given each rank's part of a matrix summed over the
   !> ranks (`summed`), instead of the whole matrix on every rank. Other solvers: nothing.
   subroutine mumps_summed_input(solver, summed)
      class(linear_solver_t), intent(inout) :: solver
      logical, intent(in) :: summed
      select type (solver)
      type is (mumps_solver_t)
         solver%summed = summed
      end select
   end subroutine mumps_summed_input

   function mumps_name(this) result(name)
      class(mumps_solver_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = 'MUMPS'
   end function mumps_name

   !> The common statistics, then MUMPS's own: ranks, its analysis estimates of the factor
   !> entries (INFOG(3)), flops (RINFOG(1)) and megabytes on the largest rank and on all
   !> (INFOG(16), INFOG(17)), and the megabytes used on the largest rank and on all
   !> (INFOG(21), INFOG(22)).
   function mumps_report(this) result(line)
      class(mumps_solver_t), intent(in) :: this
      character(len=:), allocatable :: line
      character(len=256) :: buf
      integer(ik8) :: entries
      entries = merge(int(this%infog(3), ik8), -1000000_ik8*this%infog(3), this%infog(3) >= 0)
      write (buf, '(a,i0,a,i0,a,es10.3,a,i0,a,i0,a,i0,a,i0)') ' ranks=', parallel_size(), &
         ' est_factor_entries=', entries, ' est_flops=', this%rinfog(1), ' est_mb_rank=', &
         this%infog(16), ' est_mb_total=', this%infog(17), ' mb_rank=', this%infog(21), &
         ' mb_total=', this%infog(22)
      line = solver_report(this)//trim(buf)
   end function mumps_report

   subroutine mumps_analyse(this, a, error)
      class(mumps_solver_t), intent(inout) :: this
      type(csc_t), intent(in) :: a
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: status
      integer(c_int), allocatable :: irn(:), jcn(:)
      integer :: j, k, m, null_pivot
      call this%free()
      if (.not. mumps_available()) then
         call fatal_error(error, 'this build has no MUMPS (build it with make build-mpi)')
         return
      end if
      if (.not. allocated(a%colptr) .or. a%n < 1) then
         call fatal_error(error, 'MUMPS analyse: empty matrix')
         return
      end if
      call c_start()
      ! every rank must take the same decision (with summed input each sees its own part)
      this%symmetric = a%upper
      if (.not. this%force_lu .and. .not. a%upper) &
         this%symmetric = .not. parallel_any(.not. a%is_symmetric(SYM_TOL))
      this%handle = c_new(merge(2_c_int, 0_c_int, this%symmetric), this%rcond_tol, status)
      if (status < 0) then
         call fatal_error(error, 'MUMPS initialisation failed: '//status_text(int(status), 0))
         return
      end if
      if (this%summed) then
         this%first = 0
         this%last = a%nnz()
      else
         call share(a, parallel_rank(), parallel_size(), this%first, this%last)
      end if
      allocate (irn(this%last - this%first), jcn(this%last - this%first), &
         this%pick(this%last - this%first))
      m = 0
      do j = 1, a%n
         do k = max(a%colptr(j), this%first), min(a%colptr(j + 1), this%last) - 1
            if (this%symmetric .and. a%rowind(k + 1) + 1 > j) cycle ! lower: not given
            m = m + 1
            irn(m) = a%rowind(k + 1) + 1
            jcn(m) = j
            this%pick(m) = k + 1
         end do
      end do
      this%pick = this%pick(:m)
      status = c_analyse(this%handle, a%n, m, irn, jcn)
      call c_info(this%handle, this%infog, this%rinfog, null_pivot)
      if (status < 0) then
         call fatal_error(error, 'MUMPS analysis failed: '//status_text(int(status), this%infog(2)))
         return
      end if
      this%n = a%n
      this%upper = a%upper
      this%nnz = a%nnz()
      this%ordering = ordering_name(this%infog(7))//trim(merge(' (LDL^T)', ' (LU)   ', &
         this%symmetric))
      this%n_analyses = this%n_analyses + 1
   end subroutine mumps_analyse

   !> Entries first+1 .. last (0-based CSC positions) of rank `rank` among `nranks`: whole
   !> columns, cut where the running count of entries passes rank*nnz/nranks.
   subroutine share(a, rank, nranks, first, last)
      type(csc_t), intent(in) :: a
      integer, intent(in) :: rank, nranks
      integer, intent(out) :: first, last
      first = cut(rank)
      last = cut(rank + 1)
   contains
      integer function cut(r)
         integer, intent(in) :: r
         integer(ik8) :: target
         integer :: j
         target = (int(a%nnz(), ik8)*r)/nranks
         cut = a%nnz()
         if (r >= nranks) return
         do j = 1, a%n + 1
            if (a%colptr(j) >= target) then
               cut = a%colptr(j)
               return
            end if
         end do
      end function cut
   end subroutine share

   subroutine mumps_factorise(this, a, error)
      class(mumps_solver_t), intent(inout) :: this
      type(csc_t), intent(in) :: a
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: status
      integer :: null_pivot
      character(len=160) :: buf
      this%factorised = .false.
      this%bad_equation = 0
      if (.not. c_associated(this%handle) .or. this%n == 0) then
         call fatal_error(error, 'MUMPS factorise: analyse the matrix first')
         return
      end if
      if (parallel_any(a%n /= this%n .or. a%nnz() /= this%nnz .or. &
                       (a%upper .neqv. this%upper))) then
         call fatal_error(error, 'MUMPS factorise: pattern differs from the analysed one')
         return
      end if
      if (this%symmetric .and. .not. a%upper) then
         if (parallel_any(.not. a%is_symmetric(SYM_TOL))) then
            this%force_lu = .true.
            call this%analyse(a, error)
            if (allocated(error)) return
         end if
      end if
      status = c_factorise(this%handle, a%values(this%pick))
      call c_info(this%handle, this%infog, this%rinfog, null_pivot)
      this%n_factorisations = this%n_factorisations + 1
      if (status < 0 .and. status /= -10) then
         call fatal_error(error, 'MUMPS factorisation failed: '//status_text(int(status), this%infog(2)))
         return
      end if
      this%nnz_factor = merge(int(this%infog(29), ik8), -1000000_ik8*this%infog(29), &
         this%infog(29) >= 0)
      this%flops = this%rinfog(3)
      ! INFOG(21): megabytes used on the rank that uses most, the peak per rank.
      this%peak_memory = max(this%peak_memory, 1.0e6_wp*this%infog(21))
      if (status == -10 .or. this%infog(28) > 0) then
         this%bad_equation = null_pivot
         write (buf, '(a,i0,a,i0)') 'null pivots ', this%infog(28), ', free equation ', null_pivot
         call singular_error(error, 'MUMPS: singular matrix (free mechanism or missing '// &
            'support), '//trim(buf))
         return
      end if
      this%factorised = .true.
   end subroutine mumps_factorise

   subroutine mumps_solve_raw(this, n, nrhs, b, x, error)
      class(mumps_solver_t), intent(inout) :: this
      integer, intent(in) :: n, nrhs
      real(wp), intent(in) :: b(n, nrhs)
      real(wp), intent(out) :: x(n, nrhs)
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: status
      x = b
      status = c_solve(this%handle, int(nrhs, c_int), x)
      if (status < 0) then
         call fatal_error(error, 'MUMPS solve failed: '//status_text(int(status), 0))
         return
      end if
      this%n_solves = this%n_solves + nrhs
   end subroutine mumps_solve_raw

   subroutine mumps_free(this)
      class(mumps_solver_t), intent(inout) :: this
      if (c_associated(this%handle)) call c_free(this%handle)
      this%handle = c_null_ptr
      this%factorised = .false.
      this%n = 0
      if (allocated(this%pick)) deallocate (this%pick)
   end subroutine mumps_free

   subroutine mumps_final(this)
      type(mumps_solver_t), intent(inout) :: this
      call this%free()
   end subroutine mumps_final

   pure function ordering_name(code) result(name)
      integer, intent(in) :: code
      character(len=:), allocatable :: name
      select case (code)
      case (0); name = 'AMD'
      case (2); name = 'AMF'
      case (3); name = 'SCOTCH'
      case (4); name = 'PORD'
      case (5); name = 'METIS'
      case (6); name = 'QAMD'
      case default; name = 'OTHER'
      end select
   end function ordering_name

   function status_text(status, detail) result(text)
      integer, intent(in) :: status, detail
      character(len=:), allocatable :: text
      character(len=40) :: buf
      select case (status)
      case (-8, -9, -11, -13, -14, -15, -17, -19, -20)
         text = 'out of memory (INFOG(1) = '
      case (-999)
         text = 'this build has no MUMPS (INFOG(1) = '
      case default
         text = 'MUMPS error (INFOG(1) = '
      end select
      write (buf, '(i0,a,i0,a)') status, ', INFOG(2) = ', detail, '; see the MUMPS users'' guide)'
      text = text//trim(buf)
   end function status_text

end module pecplas_linalg_mumps
