!> What every command-line program (pecplas, pecplas-path, pecplas-identify,
!> pecplas-sensitivity) does with an error that ends it: one line on standard error,
!> "<program>: error: <text>", and the exit code to return.
module pecplas_command
   implicit none (type, external)
   private

   public :: command_error

contains

   integer function command_error(program, code, text) result(exit_code)
      character(len=*), intent(in) :: program, text
      integer, intent(in) :: code
      write (0, '(a)') program//': error: '//text
      exit_code = code
   end function command_error

end module pecplas_command
