!> pecplas DECK [-o FILE.h5] [--quiet] — see pecplas_cmd_pecplas.
program main
   use pecplas_cmd_pecplas, only: pecplas_main
   use pecplas_cmd_command, only: command_arguments
   use pecplas_base_parallel, only: parallel_init, parallel_finalize
   use pecplas_linalg_blas_core, only: blas_core_start
   implicit none (type, external)
   integer :: code

   call blas_core_start() ! OpenBLAS's kernels: may run this program again (doc/build.md)
   call parallel_init() ! MPI build: one of the ranks of `mpirun -np N pecplas DECK`
   code = pecplas_main(command_arguments())
   call parallel_finalize()
   if (code /= 0) call exit(code)
end program main
