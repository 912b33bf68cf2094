!> pecplas-sensitivity [DECK] [options] — see pecplas_cmd_sensitivity.
program pecplas_sensitivity
   use pecplas_cmd_sensitivity, only: sensitivity_main
   use pecplas_cmd_command, only: command_arguments
   implicit none (type, external)
   integer :: code

   code = sensitivity_main(command_arguments())
   if (code /= 0) call exit(code)
end program pecplas_sensitivity
