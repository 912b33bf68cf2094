!> pecplas-identify [options] CURVE.csv ... — see pecjoin_identify_cli.
program pecplas_identify
   use pecjoin_identify_cli, only: identify_main
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
   code = identify_main(args)
   if (code /= 0) call exit(code)
end program pecplas_identify
