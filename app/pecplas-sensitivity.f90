!> pecplas-sensitivity [DECK] [options] — see pecjoin_sensitivity_cli.
program pecplas_sensitivity
   use pecjoin_sensitivity_cli, only: sensitivity_main
   implicit none (type, external)
   character(len=:), allocatable :: args(:)
   integer :: i, n, length, code

   n = command_argument_count()
   length = 1
   do i = 1, n
      call get_command_argument(i, length=code)
      length = max(length, code)
   end do
   allocate (character(len=length) :: args(n))
   do i = 1, n
      call get_command_argument(i, args(i))
   end do
   code = sensitivity_main(args)
   if (code /= 0) call exit(code)
end program pecplas_sensitivity
