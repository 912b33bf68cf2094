!> The ranks of an MPI run (`mpirun -np N pecplas DECK`, MPI build only): every rank runs
!> the same program on the same deck; rank 0 alone prints and writes the results file; the
!> MUMPS solver shares the matrix among the ranks. In the default serial build there is one
!> rank and these procedures do nothing. MPI itself is called from parallel_shim.c.
module pecplas_parallel
   use, intrinsic :: iso_c_binding, only: c_int
   implicit none (type, external)
   private

   public :: parallel_built, parallel_init, parallel_finalize, parallel_rank, parallel_size

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

end module pecplas_parallel
