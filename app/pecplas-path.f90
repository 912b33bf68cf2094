!> pecplas-path DECK [-o BASE] [--quiet] — see pecjoin_path_cli.
program pecplas_path
   use pecjoin_path_cli, only: path_main
   use pecplas_command, only: command_arguments
   implicit none (type, external)
   integer :: code

   code = path_main(command_arguments())
   if (code /= 0) call exit(code)
end program pecplas_path
