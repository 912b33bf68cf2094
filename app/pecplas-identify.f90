!> pecplas-identify [options] CURVE.csv ... — see pecplas_cmd_identify.
program pecplas_identify
   use pecplas_cmd_identify, only: identify_main
   use pecplas_cmd_command, only: command_arguments
   use pecplas_linalg_blas_core, only: blas_core_start
   implicit none (type, external)
   integer :: code

   call blas_core_start() ! OpenBLAS's kernels: may run this program again (doc/build.md)
   code = identify_main(command_arguments())
   if (code /= 0) call exit(code)
end program pecplas_identify
