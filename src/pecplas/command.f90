!> What every command-line program (pecplas, pecplas-path, pecplas-identify,
!> pecplas-sensitivity) does with an error that ends it: one line on standard error,
!> "<program>: error: <text>", and the exit code to return. Standard error is flushed at
!> once: gfortran buffers it when it is redirected to a file.
module pecplas_command
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none (type, external)
   private

   public :: command_error

contains

   integer function command_error(program, code, text) result(exit_code)
      character(len=*), intent(in) :: program, text
      integer, intent(in) :: code
      flush (output_unit)
      write (0, '(a)') program//': error: '//text
      flush (0)
      exit_code = code
   end function command_error

end module pecplas_command
