!> UMFPACK sparse LU (any nonsingular matrix, e.g. non-symmetric tangents) behind
!> `linear_solver_t`, through direct bind(C) interfaces to the umfpack_di_* routines
!> (int indices, real values; Control and Info sizes from umfpack.h: 20 and 90).
!>
!> Singularity (method): UMFPACK factorises R A (R: row scaling by the row sums, its
!> default), so Info[UMFPACK_RCOND] = min|U(k,k)| / max|U(k,k)| is a scaled pivot ratio.
!> rcond < rcond_tol (1e-8 by default, see RCOND_TOL_DEFAULT), or an exact zero pivot (status UMFPACK_WARNING_singular_matrix), is
!> singular. The mechanism is then found with a probe: solve A x = r for a fixed positive
!> pseudo-random r; x is dominated by the near-null vector, so bad_equation = argmax |x|
!> (a non-finite x_i, which only the unknowns hanging on an exact zero pivot get, wins).
module pecplas_linalg_umfpack
   use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_int, c_double, c_associated
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use, intrinsic :: ieee_exceptions, only: ieee_set_flag, ieee_divide_by_zero, ieee_invalid, &
      ieee_overflow, ieee_get_halting_mode, ieee_set_halting_mode
   use pecplas_base_kinds, only: wp, ik8
   use pecplas_base_error, only: error_t, fatal_error, singular_error
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_linalg_solver_type, only: linear_solver_t
   implicit none (type, external)
   private

   public :: umfpack_solver_t

   integer, parameter :: UMFPACK_CONTROL = 20, UMFPACK_INFO = 90
   ! Status codes and Info/Control positions (0-based C indices, as in umfpack.h).
   integer(c_int), parameter :: UMFPACK_OK = 0, UMFPACK_WARNING_SINGULAR = 1, UMFPACK_A = 0
   integer, parameter :: I_SIZE_OF_UNIT = 3, I_STRATEGY_USED = 18, I_ORDERING_USED = 19, &
      I_PEAK_MEMORY = 41, I_FLOPS = 42, I_LNZ = 43, I_UNZ = 44, I_RCOND = 67
   integer, parameter :: C_PRL = 0

   interface
      subroutine umfpack_di_defaults(control) bind(C, name='umfpack_di_defaults')
         import :: c_double
         real(c_double), intent(out) :: control(*)
      end subroutine
      integer(c_int) function umfpack_di_symbolic(n_row, n_col, ap, ai, ax, symbolic, control, &
         info) bind(C, name='umfpack_di_symbolic')
         import :: c_int, c_double, c_ptr
         integer(c_int), value :: n_row, n_col
         integer(c_int), intent(in) :: ap(*), ai(*)
         real(c_double), intent(in) :: ax(*), control(*)
         type(c_ptr), intent(inout) :: symbolic
         real(c_double), intent(inout) :: info(*)
      end function
      integer(c_int) function umfpack_di_numeric(ap, ai, ax, symbolic, numeric, control, info) &
         bind(C, name='umfpack_di_numeric')
         import :: c_int, c_double, c_ptr
         integer(c_int), intent(in) :: ap(*), ai(*)
         real(c_double), intent(in) :: ax(*), control(*)
         type(c_ptr), value :: symbolic
         type(c_ptr), intent(inout) :: numeric
         real(c_double), intent(inout) :: info(*)
      end function
      integer(c_int) function umfpack_di_solve(sys, ap, ai, ax, x, b, numeric, control, info) &
         bind(C, name='umfpack_di_solve')
         import :: c_int, c_double, c_ptr
         integer(c_int), value :: sys
         integer(c_int), intent(in) :: ap(*), ai(*)
         real(c_double), intent(in) :: ax(*), b(*), control(*)
         real(c_double), intent(out) :: x(*)
         type(c_ptr), value :: numeric
         real(c_double), intent(inout) :: info(*)
      end function
      subroutine umfpack_di_free_symbolic(symbolic) bind(C, name='umfpack_di_free_symbolic')
         import :: c_ptr
         type(c_ptr), intent(inout) :: symbolic
      end subroutine
      subroutine umfpack_di_free_numeric(numeric) bind(C, name='umfpack_di_free_numeric')
         import :: c_ptr
         type(c_ptr), intent(inout) :: numeric
      end subroutine
   end interface

   !> Sparse LU with UMFPACK's defaults (automatic strategy, AMD/COLAMD, row scaling, two
   !> steps of iterative refinement). Needs the full matrix, not only its upper triangle.
   !> Do not copy a solver that holds a factor (the C objects would be shared).
   type, extends(linear_solver_t) :: umfpack_solver_t
      type(c_ptr), private :: symbolic = c_null_ptr, numeric = c_null_ptr
      character(len=7), private :: label = 'UMFPACK'
      real(c_double) :: control(UMFPACK_CONTROL) = 0.0_wp
      real(c_double) :: info(UMFPACK_INFO) = 0.0_wp
      !> Copy of the factorised matrix, which iterative refinement in the solve needs.
      type(csc_t), private :: a
   contains
      procedure :: analyse => umfpack_analyse
      procedure :: factorise => umfpack_factorise
      procedure :: solve_raw => umfpack_solve_raw
      procedure :: free => umfpack_free
      procedure :: name => umfpack_name
      final :: umfpack_final
   end type umfpack_solver_t

contains

   function umfpack_name(this) result(name)
      class(umfpack_solver_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = this%label
   end function umfpack_name

   subroutine umfpack_analyse(this, a, error)
      class(umfpack_solver_t), intent(inout) :: this
      type(csc_t), intent(in) :: a
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: status
      call this%free()
      if (a%upper) then
         call fatal_error(error, 'UMFPACK needs the full matrix, not only its upper triangle')
         return
      end if
      if (.not. allocated(a%colptr) .or. a%n < 1) then
         call fatal_error(error, 'UMFPACK analyse: empty matrix')
         return
      end if
      call umfpack_di_defaults(this%control)
      this%control(C_PRL + 1) = 0.0_wp ! UMFPACK prints nothing; errors come back as values
      status = umfpack_di_symbolic(a%n, a%n, a%colptr, a%rowind, a%values, this%symbolic, &
         this%control, this%info)
      if (status /= UMFPACK_OK) then
         call fatal_error(error, 'UMFPACK symbolic analysis failed: '//status_text(status))
         return
      end if
      this%n = a%n
      this%a%n = a%n
      this%a%colptr = a%colptr
      this%a%rowind = a%rowind
      this%n_analyses = this%n_analyses + 1
   end subroutine umfpack_analyse

   subroutine umfpack_factorise(this, a, error)
      class(umfpack_solver_t), intent(inout) :: this
      type(csc_t), intent(in) :: a
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: status
      character(len=160) :: buf
      this%factorised = .false.
      this%bad_equation = 0
      if (.not. c_associated(this%symbolic)) then
         call fatal_error(error, 'UMFPACK factorise: analyse the matrix first')
         return
      end if
      if (a%n /= this%n .or. a%nnz() /= this%a%nnz()) then
         call fatal_error(error, 'UMFPACK factorise: pattern differs from the analysed one')
         return
      end if
      if (any(a%rowind /= this%a%rowind) .or. any(a%colptr /= this%a%colptr)) then
         call fatal_error(error, 'UMFPACK factorise: pattern differs from the analysed one')
         return
      end if
      if (c_associated(this%numeric)) call umfpack_di_free_numeric(this%numeric)
      this%a%values = a%values
      status = umfpack_di_numeric(a%colptr, a%rowind, a%values, this%symbolic, this%numeric, &
         this%control, this%info)
      this%n_factorisations = this%n_factorisations + 1
      if (status /= UMFPACK_OK .and. status /= UMFPACK_WARNING_SINGULAR) then
         call fatal_error(error, 'UMFPACK factorisation failed: '//status_text(status))
         return
      end if
      this%rcond = this%info(I_RCOND + 1)
      this%nnz_factor = int(this%info(I_LNZ + 1) + this%info(I_UNZ + 1), ik8)
      this%flops = this%info(I_FLOPS + 1)
      this%peak_memory = max(this%peak_memory, this%info(I_PEAK_MEMORY + 1)*this%info(I_SIZE_OF_UNIT + 1))
      this%ordering = ordering_name(nint(this%info(I_ORDERING_USED + 1)), &
         nint(this%info(I_STRATEGY_USED + 1)))
      if (status == UMFPACK_WARNING_SINGULAR .or. .not. (this%rcond >= this%rcond_tol)) then
         this%bad_equation = probe_mechanism(this)
         write (buf, '(a,es9.2,a,i0)') 'rcond ', this%rcond, ', free equation ', this%bad_equation
         call singular_error(error, 'UMFPACK: singular matrix (free mechanism or missing '// &
            'support), '//trim(buf))
         return
      end if
      this%factorised = .true.
   end subroutine umfpack_factorise

   !> Equation with the largest |x| for A x = r, r a fixed positive pseudo-random vector
   !> (not orthogonal to any null vector that has entries of one sign).
   integer function probe_mechanism(this) result(k)
      class(umfpack_solver_t), intent(inout) :: this
      real(wp), allocatable :: r(:), x(:)
      integer(c_int) :: status
      integer :: i
      logical :: halt(3)
      allocate (r(this%n), x(this%n))
      do i = 1, this%n
         r(i) = 0.5_wp + modulo(0.6180339887498949_wp*i, 1.0_wp)
      end do
      ! a build that traps floating-point exceptions (doc/build.md, Uninitialised reads) must
      ! not stop in this solve: its divisions by a zero pivot are the probe
      call ieee_get_halting_mode(ieee_divide_by_zero, halt(1))
      call ieee_get_halting_mode(ieee_invalid, halt(2))
      call ieee_get_halting_mode(ieee_overflow, halt(3))
      if (any(halt)) call ieee_set_halting_mode([ieee_divide_by_zero, ieee_invalid, &
         ieee_overflow], .false.)
      status = umfpack_di_solve(UMFPACK_A, this%a%colptr, this%a%rowind, this%a%values, x, r, &
         this%numeric, this%control, this%info)
      ! An exact zero pivot divides by zero on purpose here: those flags are expected, and
      ! flags raised before this procedure are kept by the Fortran runtime.
      call ieee_set_flag([ieee_divide_by_zero, ieee_invalid, ieee_overflow], .false.)
      call ieee_set_halting_mode(ieee_divide_by_zero, halt(1))
      call ieee_set_halting_mode(ieee_invalid, halt(2))
      call ieee_set_halting_mode(ieee_overflow, halt(3))
      do i = 1, this%n
         if (.not. ieee_is_finite(x(i))) then
            k = i
            return
         end if
      end do
      k = maxloc(abs(x), 1)
   end function probe_mechanism

   subroutine umfpack_solve_raw(this, n, nrhs, b, x, error)
      class(umfpack_solver_t), intent(inout) :: this
      integer, intent(in) :: n, nrhs
      real(wp), intent(in) :: b(n, nrhs)
      real(wp), intent(out) :: x(n, nrhs)
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: status
      integer :: j
      do j = 1, nrhs
         status = umfpack_di_solve(UMFPACK_A, this%a%colptr, this%a%rowind, this%a%values, &
            x(:, j), b(:, j), this%numeric, this%control, this%info)
         if (status /= UMFPACK_OK) then
            call fatal_error(error, 'UMFPACK solve failed: '//status_text(status))
            return
         end if
         this%n_solves = this%n_solves + 1
      end do
   end subroutine umfpack_solve_raw

   subroutine umfpack_free(this)
      class(umfpack_solver_t), intent(inout) :: this
      if (c_associated(this%numeric)) call umfpack_di_free_numeric(this%numeric)
      if (c_associated(this%symbolic)) call umfpack_di_free_symbolic(this%symbolic)
      this%numeric = c_null_ptr
      this%symbolic = c_null_ptr
      this%factorised = .false.
      if (allocated(this%a%colptr)) deallocate (this%a%colptr)
      if (allocated(this%a%rowind)) deallocate (this%a%rowind)
      if (allocated(this%a%values)) deallocate (this%a%values)
   end subroutine umfpack_free

   subroutine umfpack_final(this)
      type(umfpack_solver_t), intent(inout) :: this
      call this%free()
   end subroutine umfpack_final

   pure function ordering_name(ordering, strategy) result(name)
      integer, intent(in) :: ordering, strategy
      character(len=:), allocatable :: name
      select case (ordering)
      case (1); name = 'AMD'
      case (2); name = 'GIVEN'
      case (3); name = 'METIS'
      case (5); name = 'NONE'
      case default; name = 'OTHER'
      end select
      if (strategy == 3) then
         name = name//' (symmetric strategy)'
      else
         name = name//' (unsymmetric strategy)'
      end if
   end function ordering_name

   function status_text(status) result(text)
      integer(c_int), intent(in) :: status
      character(len=:), allocatable :: text
      character(len=12) :: buf
      select case (status)
      case (-1); text = 'out of memory'
      case (-8); text = 'invalid matrix (rows must be sorted and unique within columns)'
      case (-11); text = 'pattern differs from the analysed one'
      case (-18); text = 'ordering failed'
      case default
         write (buf, '(i0)') status
         text = 'status '//trim(buf)
      end select
   end function status_text

end module pecplas_linalg_umfpack
