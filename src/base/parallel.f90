!> The ranks of an MPI run (`mpirun -np N pecplas DECK`, MPI build only): every rank runs
!> the same program on the same deck; rank 0 alone prints and writes the results file; the
!> MUMPS solver shares the matrix among the ranks. In the default serial build there is one
!> rank and these procedures do nothing. MPI itself is called from parallel_shim.c.
module pecplas_base_parallel
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: parallel_built, parallel_init, parallel_finalize, parallel_rank, parallel_size
   public :: parallel_sum, parallel_min, parallel_max, parallel_max_int, parallel_any

   interface
      integer(c_int) function c_built() bind(C, name='pecplas_parallel_built')
         import :: c_int
      end function
      subroutine c_init() bind(C, name='pecplas_parallel_init')
      end subroutine
      subroutine c_finalize() bind(C, name='pecplas_parallel_finalize')
      end subroutine
      integer(c_int) function c_rank() bind(C, name='pecplas_parallel_rank')
         import :: c_int
      end function
      integer(c_int) function c_size() bind(C, name='pecplas_parallel_size')
         import :: c_int
      end function
      subroutine c_reduce(x, n, op) bind(C, name='pecplas_parallel_reduce')
         import :: c_int, c_double
         real(c_double), intent(inout) :: x(*)
         integer(c_int), value :: n, op
      end subroutine
      integer(c_int) function c_max_int(value) bind(C, name='pecplas_parallel_max_int')
         import :: c_int
         integer(c_int), value :: value
      end function
   end interface

contains

   !> True in the MPI build (which also has the MUMPS solver).
   logical function parallel_built()
      parallel_built = c_built() == 1
   end function parallel_built

   !> Starts MPI (MPI build; idempotent); ranks above 0 lose their standard output.
   subroutine parallel_init()
      call c_init()
   end subroutine parallel_init

   !> Ends MPI before the program exits (idempotent).
   subroutine parallel_finalize()
      call c_finalize()
   end subroutine parallel_finalize

   !> This process's rank, 0-based (0 in a serial build or before parallel_init).
   integer function parallel_rank()
      parallel_rank = int(c_rank())
   end function parallel_rank

   !> Number of ranks (1 in a serial build).
   integer function parallel_size()
      parallel_size = int(c_size())
   end function parallel_size

   !> x = its sum over the ranks, on every rank (nothing with one rank). Collective: every
   !> rank must call it, in the same order, as for the procedures below.
   subroutine parallel_sum(x)
      real(wp), intent(inout) :: x(:)
      call c_reduce(x, int(size(x), c_int), 0_c_int)
   end subroutine parallel_sum

   !> x = its smallest value over the ranks, element by element, on every rank.
   subroutine parallel_min(x)
      real(wp), intent(inout) :: x(:)
      call c_reduce(x, int(size(x), c_int), 1_c_int)
   end subroutine parallel_min

   !> x = its largest value over the ranks, element by element, on every rank.
   subroutine parallel_max(x)
      real(wp), intent(inout) :: x(:)
      call c_reduce(x, int(size(x), c_int), 2_c_int)
   end subroutine parallel_max

   !> The largest `value` over the ranks.
   integer function parallel_max_int(value)
      integer, intent(in) :: value
      parallel_max_int = int(c_max_int(int(value, c_int)))
   end function parallel_max_int

   !> True on every rank when `flag` is true on some rank.
   logical function parallel_any(flag)
      logical, intent(in) :: flag
      parallel_any = parallel_max_int(merge(1, 0, flag)) == 1
   end function parallel_any

end module pecplas_base_parallel
