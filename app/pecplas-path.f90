!> pecplas-path DECK [-o BASE] [--quiet] — see pecplas_cmd_path.
program pecplas_path
   use pecplas_cmd_path, only: path_main
   use pecplas_cmd_command, only: command_arguments
   use pecplas_linalg_blas_core, only: blas_core_start
   implicit none (type, external)
   integer :: code

   call blas_core_start() ! OpenBLAS's kernels: may run this program again (doc/build.md)
   code = path_main(command_arguments())
   if (code /= 0) call exit(code)
end program pecplas_path
