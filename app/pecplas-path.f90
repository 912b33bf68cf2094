!> pecplas-path DECK [-o BASE] [--quiet] — see pecplas_cmd_path.
program pecplas_path
   use pecplas_cmd_path, only: path_main
   use pecplas_cmd_command, only: command_arguments
   implicit none (type, external)
   integer :: code

   code = path_main(command_arguments())
   if (code /= 0) call exit(code)
end program pecplas_path
