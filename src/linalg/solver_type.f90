!> Abstract sparse direct solver: analyse a pattern once, factorise many times on it, solve
!> many right-hand sides per factorisation.
!>
!> Singular systems are reported, not solved: `factorise` returns an error of kind
!> ERR_SINGULAR and sets `bad_equation` (1-based) to an equation of the free mechanism.
!> The test is a pivot ratio compared with `rcond_tol` (see each solver for the details).
module pecplas_linalg_solver_type
   use pecplas_base_kinds, only: wp, ik8
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_linalg_sparse, only: csc_t
   implicit none (type, external)
   private

   public :: linear_solver_t, RCOND_TOL_DEFAULT, solver_report

   !> A scaled pivot ratio (rcond estimate) below this means numerically singular: 1e-8.
   !> Measured here (Q4 elastic squares and 5-point Laplacians): the roundoff pivot of a
   !> mechanism grows with the size, 1e-15 at 1e2 equations, 1e-11 at 2e5 and 2.5e-11 at
   !> 1e6, so 1e3*epsilon (2e-13) misses large floating bodies; well-posed matrices, also
   !> with 1e8 and 1e10 stiffness contrasts, stay at 0.05-0.5. A ratio of 1e-8 means 8 digits
   !> lost to cancellation, the same order as the MAXRATIO = 1e7 stop of structural codes.
   real(wp), parameter :: RCOND_TOL_DEFAULT = 1.0e-8_wp

   type, abstract :: linear_solver_t
      !> Equation (1-based) of a free mechanism after a singular factorisation; 0 otherwise.
      integer :: bad_equation = 0
      !> Singularity threshold on the pivot ratio (rcond estimate).
      real(wp) :: rcond_tol = RCOND_TOL_DEFAULT
      !> Order of the analysed matrix.
      integer :: n = 0
      !> Statistics for run reports.
      integer :: n_analyses = 0, n_factorisations = 0, n_solves = 0
      !> Nonzeros in the factor(s), flop count of one factorisation, peak memory in bytes.
      integer(ik8) :: nnz_factor = 0
      real(wp) :: flops = 0.0_wp, peak_memory = 0.0_wp
      !> Scaled pivot ratio of the last factorisation, the value compared with rcond_tol
      !> (CHOLMOD: min pivot / diagonal; UMFPACK: its Info[UMFPACK_RCOND]).
      real(wp) :: rcond = 0.0_wp
      !> Fill-reducing ordering used by the last analysis.
      character(len=:), allocatable :: ordering
      !> True after a successful factorisation (solves are allowed).
      logical :: factorised = .false.
   contains
      !> Symbolic analysis of the pattern of `a` (frees any earlier analysis).
      procedure(analyse_ifc), deferred :: analyse
      !> Numeric factorisation of `a`, whose pattern must be the analysed one.
      procedure(factorise_ifc), deferred :: factorise
      !> Solves with nrhs right-hand sides in b(n, nrhs).
      procedure(solve_raw_ifc), deferred :: solve_raw
      !> Releases all memory held by the library.
      procedure(free_ifc), deferred :: free
      !> Solver name as written in the deck.
      procedure(name_ifc), deferred :: name
      procedure, private :: solve_vec, solve_mat
      !> x = A^-1 b, for b(:) or b(:, nrhs).
      generic :: solve => solve_vec, solve_mat
      !> One line of statistics for the run report.
      procedure :: report => solver_report
   end type linear_solver_t

   abstract interface
      subroutine analyse_ifc(this, a, error)
         import :: linear_solver_t, csc_t, error_t
         class(linear_solver_t), intent(inout) :: this
         type(csc_t), intent(in) :: a
         type(error_t), allocatable, intent(out) :: error
      end subroutine analyse_ifc
      subroutine factorise_ifc(this, a, error)
         import :: linear_solver_t, csc_t, error_t
         class(linear_solver_t), intent(inout) :: this
         type(csc_t), intent(in) :: a
         type(error_t), allocatable, intent(out) :: error
      end subroutine factorise_ifc
      subroutine solve_raw_ifc(this, n, nrhs, b, x, error)
         import :: linear_solver_t, error_t, wp
         class(linear_solver_t), intent(inout) :: this
         integer, intent(in) :: n, nrhs
         real(wp), intent(in) :: b(n, nrhs)
         real(wp), intent(out) :: x(n, nrhs)
         type(error_t), allocatable, intent(out) :: error
      end subroutine solve_raw_ifc
      subroutine free_ifc(this)
         import :: linear_solver_t
         class(linear_solver_t), intent(inout) :: this
      end subroutine free_ifc
      function name_ifc(this) result(name)
         import :: linear_solver_t
         class(linear_solver_t), intent(in) :: this
         character(len=:), allocatable :: name
      end function name_ifc
   end interface

contains

   subroutine solve_vec(this, b, x, error)
      class(linear_solver_t), intent(inout) :: this
      real(wp), contiguous, intent(in) :: b(:)
      real(wp), contiguous, intent(out) :: x(:)
      type(error_t), allocatable, intent(out) :: error
      call check_ready(this, size(b), size(x), error)
      if (allocated(error)) return
      call this%solve_raw(this%n, 1, b, x, error)
   end subroutine solve_vec

   subroutine solve_mat(this, b, x, error)
      class(linear_solver_t), intent(inout) :: this
      real(wp), contiguous, intent(in) :: b(:, :)
      real(wp), contiguous, intent(out) :: x(:, :)
      type(error_t), allocatable, intent(out) :: error
      call check_ready(this, size(b, 1), size(x, 1), error)
      if (allocated(error)) return
      if (size(b, 2) /= size(x, 2)) then
         call fatal_error(error, this%name()//' solve: b and x have different column counts')
         return
      end if
      if (size(b, 2) == 0) return
      call this%solve_raw(this%n, size(b, 2), b, x, error)
   end subroutine solve_mat

   subroutine check_ready(this, nb, nx, error)
      class(linear_solver_t), intent(in) :: this
      integer, intent(in) :: nb, nx
      type(error_t), allocatable, intent(out) :: error
      if (.not. this%factorised) then
         call fatal_error(error, this%name()//' solve: no valid factorisation')
      else if (nb /= this%n .or. nx /= this%n) then
         call fatal_error(error, this%name()//' solve: vector length differs from the matrix order')
      end if
   end subroutine check_ready

   !> The statistics line of any solver (extensions append their own to it).
   function solver_report(this) result(line)
      class(linear_solver_t), intent(in) :: this
      character(len=:), allocatable :: line
      character(len=256) :: buf
      write (buf, '(a,i0,a,i0,a,es10.3,a,es10.3,a,i0,a,i0,a,i0)') ' n=', this%n, &
         ' nnz(factor)=', this%nnz_factor, ' flops=', this%flops, ' peak_bytes=', &
         this%peak_memory, ' analyses=', this%n_analyses, ' factorisations=', &
         this%n_factorisations, ' solves=', this%n_solves
      line = this%name()//trim(buf)
      if (allocated(this%ordering)) line = line//' ordering='//this%ordering
   end function solver_report

end module pecplas_linalg_solver_type
