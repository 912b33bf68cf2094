!> CHOLMOD supernodal Cholesky (symmetric positive definite matrices) behind
!> `linear_solver_t`, through the C shim cholmod_shim.c (which owns cholmod_common).
!>
!> Singularity (method): the pivots d_k of P A P' = L L' are compared with the diagonal of A,
!> r = min_k d_k / a_(p(k),p(k)). This is cholmod_rcond of the Jacobi-scaled matrix
!> D^-1/2 A D^-1/2 (its largest pivot is 1), so stiffness contrasts between materials do not
!> change it, while a mechanism leaves a roundoff pivot (measured <= 3e-11 up to 1e6
!> equations; see RCOND_TOL_DEFAULT).
!> r < rcond_tol is singular, and bad_equation = p(k_min): the vector y with L' y = e_k is
!> then a near null vector of A whose entry at p(k_min) is 1, i.e. that equation moves freely.
!> When LL' stops on a non-positive pivot (roundoff may make a zero pivot slightly negative),
!> a simplicial LDL' without pivoting tells a singular matrix (a tiny |D| at the mechanism)
!> from an indefinite one (negative pivots of normal size), for which UMFPACK is suggested;
!> LDL' without any negative pivot means LL' tripped on roundoff: singular too.
module pecplas_linalg_cholmod
   use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_int, c_double, c_associated
   use pecplas_base_kinds, only: wp, ik4, ik8
   use pecplas_base_error, only: error_t, fatal_error, singular_error
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_linalg_solver_type, only: linear_solver_t
   implicit none (type, external)
   private

   public :: cholmod_solver_t
   ! Raw shim bindings, public for benchmarks that time a bare analyse + factorise + solve.
   public :: pecplas_cholmod_new, pecplas_cholmod_delete, pecplas_cholmod_analyse
   public :: pecplas_cholmod_factorise, pecplas_cholmod_solve, pecplas_cholmod_pivots
   public :: pecplas_cholmod_perm, pecplas_cholmod_rcond, pecplas_cholmod_status
   public :: pecplas_cholmod_minor, pecplas_cholmod_ordering, pecplas_cholmod_lnz
   public :: pecplas_cholmod_flops, pecplas_cholmod_peak_memory, pecplas_cholmod_set_ordering
   public :: ORDER_RULE, ORDER_CHOLMOD_DEFAULT, ORDER_METIS_NODES, ORDER_AMD, ORDER_METIS
   public :: ORDER_NESDIS
   ! The cap on the OpenMP regions of CHOLMOD's factorisation (omp_serial.c), for tests.
   public :: pecplas_omp_serial_begin, pecplas_omp_serial_end, pecplas_omp_cap_begin
   public :: pecplas_omp_cap_end

   !> Orderings pecplas_cholmod_set_ordering accepts: the project's rule (the default of every
   !> new handle), CHOLMOD's own default strategy, METIS on the graph of nodes (equations with
   !> the same column pattern merged), or one CHOLMOD ordering code.
   integer(c_int), parameter :: ORDER_RULE = -1, ORDER_CHOLMOD_DEFAULT = -2, &
      ORDER_METIS_NODES = -3, ORDER_AMD = 2, ORDER_METIS = 3, ORDER_NESDIS = 4

   integer(c_int), parameter :: CHOLMOD_OK = 0, CHOLMOD_NOT_POSDEF = 1

   interface
      !> Until pecplas_omp_serial_end, OpenMP regions of this thread run on it alone.
      subroutine pecplas_omp_serial_begin() bind(C)
      end subroutine
      subroutine pecplas_omp_serial_end() bind(C)
      end subroutine
      !> Until pecplas_omp_cap_end, OpenMP regions of this thread get at most n threads.
      subroutine pecplas_omp_cap_begin(n) bind(C)
         import :: c_int
         integer(c_int), value :: n
      end subroutine
      subroutine pecplas_omp_cap_end() bind(C)
      end subroutine
      type(c_ptr) function pecplas_cholmod_new(ldl) bind(C)
         import :: c_ptr, c_int
         integer(c_int), value :: ldl
      end function
      subroutine pecplas_cholmod_delete(h) bind(C)
         import :: c_ptr
         type(c_ptr), value :: h
      end subroutine
      subroutine pecplas_cholmod_set_ordering(h, ordering) bind(C)
         import :: c_ptr, c_int
         type(c_ptr), value :: h
         integer(c_int), value :: ordering
      end subroutine
      integer(c_int) function pecplas_cholmod_analyse(h, n, colptr, rowind) bind(C)
         import :: c_ptr, c_int
         type(c_ptr), value :: h
         integer(c_int), value :: n
         integer(c_int), intent(in) :: colptr(*), rowind(*)
      end function
      integer(c_int) function pecplas_cholmod_factorise(h, n, colptr, rowind, x) bind(C)
         import :: c_ptr, c_int, c_double
         type(c_ptr), value :: h
         integer(c_int), value :: n
         integer(c_int), intent(in) :: colptr(*), rowind(*)
         real(c_double), intent(in) :: x(*)
      end function
      integer(c_int) function pecplas_cholmod_solve(h, n, nrhs, b, x) bind(C)
         import :: c_ptr, c_int, c_double
         type(c_ptr), value :: h
         integer(c_int), value :: n, nrhs
         real(c_double), intent(in) :: b(*)
         real(c_double), intent(out) :: x(*)
      end function
      integer(c_int) function pecplas_cholmod_pivots(h, d) bind(C)
         import :: c_ptr, c_int, c_double
         type(c_ptr), value :: h
         real(c_double), intent(out) :: d(*)
      end function
      integer(c_int) function pecplas_cholmod_perm(h, perm) bind(C)
         import :: c_ptr, c_int
         type(c_ptr), value :: h
         integer(c_int), intent(out) :: perm(*)
      end function
      real(c_double) function pecplas_cholmod_rcond(h) bind(C)
         import :: c_ptr, c_double
         type(c_ptr), value :: h
      end function
      integer(c_int) function pecplas_cholmod_status(h) bind(C)
         import :: c_ptr, c_int
         type(c_ptr), value :: h
      end function
      integer(c_int) function pecplas_cholmod_minor(h) bind(C)
         import :: c_ptr, c_int
         type(c_ptr), value :: h
      end function
      integer(c_int) function pecplas_cholmod_ordering(h) bind(C)
         import :: c_ptr, c_int
         type(c_ptr), value :: h
      end function
      real(c_double) function pecplas_cholmod_lnz(h) bind(C)
         import :: c_ptr, c_double
         type(c_ptr), value :: h
      end function
      real(c_double) function pecplas_cholmod_flops(h) bind(C)
         import :: c_ptr, c_double
         type(c_ptr), value :: h
      end function
      real(c_double) function pecplas_cholmod_peak_memory(h) bind(C)
         import :: c_ptr, c_double
         type(c_ptr), value :: h
      end function
   end interface

   !> Supernodal LL', ordering by the shim's rule (cholmod_shim.c: AMD, and METIS on the graph
   !> of nodes when AMD leaves many flops per entry of L, at the analysis or at the second
   !> factorisation; doc/theory.md §5). Only the upper triangle of the CSC
   !> matrix is read. Do not copy a solver that holds a factor (the handle would be shared).
   type, extends(linear_solver_t) :: cholmod_solver_t
      type(c_ptr), private :: handle = c_null_ptr
      character(len=7), private :: label = 'CHOLMOD'
      !> Pattern fingerprint (nnz and index sums) checked by factorise.
      integer(ik8), private :: pattern(3) = -1
   contains
      procedure :: analyse => cholmod_analyse
      procedure :: factorise => cholmod_factorise
      procedure :: solve_raw => cholmod_solve_raw
      procedure :: free => cholmod_free
      procedure :: name => cholmod_name
      final :: cholmod_final
   end type cholmod_solver_t

contains

   function cholmod_name(this) result(name)
      class(cholmod_solver_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = this%label
   end function cholmod_name

   subroutine cholmod_analyse(this, a, error)
      class(cholmod_solver_t), intent(inout) :: this
      type(csc_t), intent(in) :: a
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: status
      call this%free()
      if (.not. allocated(a%colptr) .or. a%n < 1) then
         call fatal_error(error, 'CHOLMOD analyse: empty matrix')
         return
      end if
      this%handle = pecplas_cholmod_new(0_c_int)
      if (.not. c_associated(this%handle)) then
         call fatal_error(error, 'CHOLMOD: cannot allocate the solver')
         return
      end if
      status = pecplas_cholmod_analyse(this%handle, a%n, a%colptr, a%rowind)
      if (status /= CHOLMOD_OK) then
         call fatal_error(error, 'CHOLMOD analysis failed: '//status_text(status))
         return
      end if
      this%n = a%n
      this%pattern = fingerprint(a)
      this%n_analyses = this%n_analyses + 1
      this%ordering = ordering_name(pecplas_cholmod_ordering(this%handle))
      this%nnz_factor = int(pecplas_cholmod_lnz(this%handle), ik8)
      this%flops = pecplas_cholmod_flops(this%handle)
      this%peak_memory = pecplas_cholmod_peak_memory(this%handle)
   end subroutine cholmod_analyse

   subroutine cholmod_factorise(this, a, error)
      class(cholmod_solver_t), intent(inout) :: this
      type(csc_t), intent(in) :: a
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: diag(:), piv(:)
      integer(c_int), allocatable :: perm(:)
      integer(c_int) :: status
      integer :: k, kmin
      character(len=160) :: buf
      this%factorised = .false.
      this%bad_equation = 0
      if (.not. c_associated(this%handle)) then
         call fatal_error(error, 'CHOLMOD factorise: analyse the matrix first')
         return
      end if
      if (any(fingerprint(a) /= this%pattern) .or. a%n /= this%n) then
         call fatal_error(error, 'CHOLMOD factorise: pattern differs from the analysed one')
         return
      end if
      allocate (diag(a%n), piv(a%n), perm(a%n))
      call a%diagonal(diag)
      ! A zero or negative diagonal entry settles it before any factorisation.
      do k = 1, a%n
         if (diag(k) <= 0.0_wp) then
            this%bad_equation = k
            write (buf, '(a,i0,a,es10.3)') 'equation ', k, ' has diagonal ', diag(k)
            if (diag(k) < 0.0_wp) then
               call singular_error(error, 'CHOLMOD: matrix not positive definite, '//trim(buf)// &
                  '; use the UMFPACK solver for indefinite systems')
            else
               call singular_error(error, 'CHOLMOD: singular matrix, '//trim(buf)// &
                  ' (no stiffness: missing support or unconnected degree of freedom)')
            end if
            return
         end if
      end do
      status = pecplas_cholmod_factorise(this%handle, a%n, a%colptr, a%rowind, a%values)
      this%n_factorisations = this%n_factorisations + 1
      this%peak_memory = max(this%peak_memory, pecplas_cholmod_peak_memory(this%handle))
      ! the shim's rule may have ordered the pattern anew at this factorisation
      if (ordering_name(pecplas_cholmod_ordering(this%handle)) /= this%ordering) then
         this%n_analyses = this%n_analyses + 1
         this%ordering = ordering_name(pecplas_cholmod_ordering(this%handle))
         this%nnz_factor = int(pecplas_cholmod_lnz(this%handle), ik8)
         this%flops = pecplas_cholmod_flops(this%handle)
      end if
      if (status == CHOLMOD_NOT_POSDEF) then
         call diagnose_not_posdef(this, a, diag, error)
         return
      else if (status < CHOLMOD_OK) then ! positive codes other than NOT_POSDEF are warnings
         call fatal_error(error, 'CHOLMOD factorisation failed: '//status_text(status))
         return
      end if
      if (pecplas_cholmod_pivots(this%handle, piv) /= 0 .or. &
          pecplas_cholmod_perm(this%handle, perm) /= 0) then
         call fatal_error(error, 'CHOLMOD: cannot read the factor')
         return
      end if
      kmin = scaled_min_pivot(piv, perm, diag)
      this%rcond = piv(kmin)/diag(perm(kmin) + 1)
      if (this%rcond < this%rcond_tol) then
         this%bad_equation = perm(kmin) + 1
         write (buf, '(a,es9.2,a,i0)') 'pivot ratio ', this%rcond, ' at equation ', &
            this%bad_equation
         call singular_error(error, 'CHOLMOD: singular matrix (free mechanism or missing '// &
            'support), '//trim(buf))
         return
      end if
      this%factorised = .true.
   end subroutine cholmod_factorise

   !> LL' met a non-positive pivot: refactorise as simplicial LDL' (no pivoting) and look at
   !> D. A scaled |D| below rcond_tol, an exact zero, or no negative D at all (LL' stopped on
   !> a roundoff pivot) is a mechanism; otherwise some D is negative: indefinite.
   subroutine diagnose_not_posdef(this, a, diag, error)
      class(cholmod_solver_t), intent(inout) :: this
      type(csc_t), intent(in) :: a
      real(wp), intent(in) :: diag(:)
      type(error_t), allocatable, intent(out) :: error
      type(c_ptr) :: ldl
      real(wp), allocatable :: d(:)
      integer(c_int), allocatable :: perm(:)
      integer(c_int) :: status
      integer :: kmin, nneg
      character(len=160) :: buf
      allocate (d(a%n), perm(a%n))
      ldl = pecplas_cholmod_new(1_c_int)
      if (.not. c_associated(ldl)) then
         call fatal_error(error, 'CHOLMOD: matrix not positive definite (no memory to check why)')
         return
      end if
      status = pecplas_cholmod_analyse(ldl, a%n, a%colptr, a%rowind)
      if (status == CHOLMOD_OK) &
         status = pecplas_cholmod_factorise(ldl, a%n, a%colptr, a%rowind, a%values)
      if (status /= CHOLMOD_OK .and. status /= CHOLMOD_NOT_POSDEF) then
         call pecplas_cholmod_delete(ldl)
         call fatal_error(error, 'CHOLMOD: matrix not positive definite (LDL'' check failed: '// &
            status_text(status)//')')
         return
      end if
      if (pecplas_cholmod_pivots(ldl, d) /= 0 .or. pecplas_cholmod_perm(ldl, perm) /= 0) then
         call pecplas_cholmod_delete(ldl)
         call fatal_error(error, 'CHOLMOD: cannot read the LDL'' factor')
         return
      end if
      if (status == CHOLMOD_NOT_POSDEF) then
         kmin = pecplas_cholmod_minor(ldl) + 1 ! exact zero pivot: factorisation stopped here
      else
         kmin = scaled_min_pivot(abs(d), perm, diag)
      end if
      nneg = count(d < 0.0_wp)
      call pecplas_cholmod_delete(ldl)
      if (status == CHOLMOD_NOT_POSDEF .or. nneg == 0 .or. &
          abs(d(kmin))/diag(perm(kmin) + 1) < this%rcond_tol) then
         this%bad_equation = perm(kmin) + 1
         write (buf, '(a,es9.2,a,i0)') 'pivot ratio ', abs(d(kmin))/diag(perm(kmin) + 1), &
            ' at equation ', this%bad_equation
         call singular_error(error, 'CHOLMOD: singular matrix (free mechanism or missing '// &
            'support), '//trim(buf))
      else
         this%bad_equation = perm(minloc(d, 1)) + 1
         write (buf, '(i0,a,i0)') nneg, ' negative pivots, e.g. at equation ', this%bad_equation
         call singular_error(error, 'CHOLMOD: matrix is not positive definite but not singular ('// &
            trim(buf)//'); use the UMFPACK solver for indefinite systems')
      end if
   end subroutine diagnose_not_posdef

   !> Factor column k with the least pivot relative to the original diagonal.
   pure integer function scaled_min_pivot(piv, perm, diag) result(kmin)
      real(wp), intent(in) :: piv(:), diag(:)
      integer(c_int), intent(in) :: perm(:)
      kmin = minloc(piv/diag(perm + 1), 1)
   end function scaled_min_pivot

   subroutine cholmod_solve_raw(this, n, nrhs, b, x, error)
      class(cholmod_solver_t), intent(inout) :: this
      integer, intent(in) :: n, nrhs
      real(wp), intent(in) :: b(n, nrhs)
      real(wp), intent(out) :: x(n, nrhs)
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: status
      status = pecplas_cholmod_solve(this%handle, n, nrhs, b, x)
      if (status < CHOLMOD_OK) then
         call fatal_error(error, 'CHOLMOD solve failed: '//status_text(status))
         return
      end if
      this%n_solves = this%n_solves + nrhs
   end subroutine cholmod_solve_raw

   subroutine cholmod_free(this)
      class(cholmod_solver_t), intent(inout) :: this
      if (c_associated(this%handle)) call pecplas_cholmod_delete(this%handle)
      this%handle = c_null_ptr
      this%factorised = .false.
      this%pattern = -1
   end subroutine cholmod_free

   subroutine cholmod_final(this)
      type(cholmod_solver_t), intent(inout) :: this
      call this%free()
   end subroutine cholmod_final

   !> Cheap guard that factorise gets the analysed pattern (not a proof).
   pure function fingerprint(a) result(f)
      type(csc_t), intent(in) :: a
      integer(ik8) :: f(3)
      f = [int(a%nnz(), ik8), sum(int(a%colptr, ik8)), sum(int(a%rowind, ik8))]
   end function fingerprint

   pure function ordering_name(code) result(name)
      integer(c_int), intent(in) :: code
      character(len=:), allocatable :: name
      character(len=11), parameter :: NAMES(0:6) = [character(len=11) :: 'NATURAL', 'GIVEN', &
         'AMD', 'METIS', 'NESDIS', 'COLAMD', 'POSTORDERED']
      name = 'UNKNOWN'
      if (code >= 0 .and. code <= 6) name = trim(NAMES(code))
   end function ordering_name

   function status_text(status) result(text)
      integer(c_int), intent(in) :: status
      character(len=:), allocatable :: text
      character(len=12) :: buf
      select case (status)
      case (-2); text = 'out of memory'
      case (-3); text = 'problem too large (integer overflow)'
      case (-4); text = 'invalid input'
      case (-1); text = 'method not installed'
      case (CHOLMOD_NOT_POSDEF); text = 'not positive definite'
      case (2); text = 'tiny diagonal in the factor'
      case default
         write (buf, '(i0)') status
         text = 'status '//trim(buf)
      end select
   end function status_text

end module pecplas_linalg_cholmod
