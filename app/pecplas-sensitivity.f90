!> pecplas-sensitivity [DECK] [options] — see pecjoin_sensitivity_cli.
program pecplas_sensitivity
   use pecjoin_sensitivity_cli, only: sensitivity_main
   use pecplas_command, only: command_arguments
   implicit none (type, external)
   integer :: code

   code = sensitivity_main(command_arguments())
   if (code /= 0) call exit(code)
end program pecplas_sensitivity
