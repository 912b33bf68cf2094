!> pecplas-identify [options] CURVE.csv ... — see pecjoin_identify_cli.
program pecplas_identify
   use pecjoin_identify_cli, only: identify_main
   use pecplas_command, only: command_arguments
   implicit none (type, external)
   integer :: code

   code = identify_main(command_arguments())
   if (code /= 0) call exit(code)
end program pecplas_identify
