!> Analysis, solver and output options of a model, with their defaults.
module pecplas_model_options
   use pecplas_base_kinds, only: wp
   use pecplas_linalg_threads, only: thread_setting_t
   implicit none (type, external)
   private

   public :: analysis_t, solver_options_t, output_options_t

   !> output_options_t%exact_restart values.
   integer, parameter, public :: EXACT_NO = 0, EXACT_ON_STOP = 1, EXACT_ALWAYS = 2
   public :: PLANE_STRAIN, AXISYMMETRIC, LINEAR_SOLVERS, NONLINEAR_METHODS, method_name, method_kind

   integer, parameter :: PLANE_STRAIN = 1, AXISYMMETRIC = 2

   !> Linear solver names: AUTO picks CHOLMOD for symmetric positive definite systems.
   !> MUMPS: the distributed solver of the MPI build (`mpirun -np N pecplas DECK`).
   character(len=*), parameter :: LINEAR_SOLVERS(4) = [character(len=8) :: 'AUTO', 'CHOLMOD', &
      'UMFPACK', 'MUMPS']
   !> MODIFIED_NEWTON: the run's stiffness factorised once (the thesis's method); QUASI_NEWTON:
   !> the same with BFGS updates; NEWTON (the default): the consistent tangent every iteration.
   !> NONLINEAR_METHODS(m) is the deck and results name of method m.
   character(len=*), parameter :: NONLINEAR_METHODS(3) = [character(len=16) :: &
      'MODIFIED_NEWTON', 'QUASI_NEWTON', 'NEWTON']
   enum, bind(c)
      enumerator :: METHOD_MODIFIED = 1, METHOD_QUASI, METHOD_NEWTON
   end enum
   public :: METHOD_MODIFIED, METHOD_QUASI, METHOD_NEWTON

   type :: analysis_t
      !> PLANE_STRAIN or AXISYMMETRIC.
      integer :: kind = PLANE_STRAIN
      !> Out-of-plane thickness in plane strain.
      real(wp) :: thickness = 1.0_wp
   end type analysis_t

   type :: solver_options_t
      character(len=:), allocatable :: linear
      !> METHOD_MODIFIED, METHOD_QUASI or METHOD_NEWTON (*SOLVER METHOD=). Default full
      !> Newton: every soil model and joint law returns the consistent tangent of its update
      !> (doc/theory.md §4); the thesis's modified Newton is chosen by name.
      integer :: method = METHOD_NEWTON
      !> Residual-force criterion ||FR|| <= tol ||F|| (thesis default 1e-4).
      real(wp) :: tolerance = 1.0e-4_wp
      integer :: max_iterations = 50
      !> Number of times an increment may be halved before the run stops.
      integer :: max_cuts = 5
      !> An increment the method cannot converge is tried by the next methods of its chain
      !> (NEWTON -> QUASI_NEWTON; MODIFIED_NEWTON -> QUASI_NEWTON -> NEWTON) before it is cut.
      logical :: fallback = .true.
      !> Line search for full Newton and quasi-Newton iterations.
      logical :: line_search = .true.
      !> Arc-length increments tried from the last converged state when a force-controlled
      !> increment cannot be converged at any cut (0: none; the run then says 'diverged').
      integer :: limit_probe = 30
      !> Threads (OpenMP, CHOLMOD, BLAS): *SOLVER THREADS=; 0 = not given (then
      !> OMP_NUM_THREADS, else 1). After start-up, the number the run used.
      integer :: threads = 0
      !> After start-up, the threads each part of the run got (pecplas_linalg_threads).
      type(thread_setting_t) :: threads_used
   end type solver_options_t

   type :: output_options_t
      !> Results file; empty means output/<deck>.h5.
      character(len=:), allocatable :: file
      !> Write fields every `every` increments (and always the last of each step).
      integer :: every = 1
      logical :: stresses = .true., strains = .true., reactions = .true.
      !> Zienkiewicz–Zhu error estimate with the fields (*OUTPUT, ERROR_ESTIMATE=YES).
      logical :: error_estimate = .false.
      !> When the restart data carry what makes a restarted run repeat the uninterrupted
      !> one's arithmetic (the last factorised matrix, the points' tangents before an
      !> arc-length path): 'ON_STOP' with the increment after which the run stops on a
      !> signal or --stop-after-increments, 'ALWAYS' with every increment (also a run
      !> killed outright), 'NO' never (*OUTPUT, EXACT_RESTART=).
      integer :: exact_restart = EXACT_ON_STOP
   end type output_options_t

contains

   !> The deck and results name of nonlinear method `method` (NONLINEAR_METHODS).
   pure function method_name(method) result(name)
      integer, intent(in) :: method
      character(len=:), allocatable :: name
      name = trim(NONLINEAR_METHODS(max(1, min(size(NONLINEAR_METHODS), method))))
   end function method_name

   !> The method named `name` (one of NONLINEAR_METHODS, upper case), 0 if none.
   pure integer function method_kind(name) result(method)
      character(len=*), intent(in) :: name
      integer :: m
      method = 0
      do m = 1, size(NONLINEAR_METHODS)
         if (trim(name) == trim(NONLINEAR_METHODS(m))) method = m
      end do
   end function method_kind

end module pecplas_model_options
