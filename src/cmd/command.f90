!> What every command-line program (pecplas, pecplas-path, pecplas-identify,
!> pecplas-sensitivity) does with an error that ends it: one line on standard error,
!> "<program>: error: <text>" (a word of it over 256 characters cut, as in deck errors),
!> and the exit code to return. Standard error is flushed at
!> once: gfortran buffers it when it is redirected to a file. Also the command-line
!> arguments as one array, which every program's main hands to its entry function.
module pecplas_cmd_command
   use, intrinsic :: iso_fortran_env, only: output_unit
   use pecplas_base_error, only: shortened
   implicit none (type, external)
   private

   public :: command_error, command_arguments

contains

   integer function command_error(program, code, text) result(exit_code)
      character(len=*), intent(in) :: program, text
      integer, intent(in) :: code
      flush (output_unit)
      write (0, '(a)') program//': error: '//shortened(text)
      flush (0)
      exit_code = code
   end function command_error

   !> The command-line arguments, padded to the longest one (an empty array when there are none).
   function command_arguments() result(args)
      character(len=:), allocatable :: args(:)
      integer :: i, n, length, arg_length
      n = command_argument_count()
      length = 1
      do i = 1, n
         call get_command_argument(i, length=arg_length)
         length = max(length, arg_length)
      end do
      allocate (character(len=length) :: args(n))
      do i = 1, n
         call get_command_argument(i, args(i))
      end do
   end function command_arguments

end module pecplas_cmd_command
