!> pecplas DECK [-o FILE.h5] [--quiet] — see pecplas_cli.
program main
   use pecplas_cli, only: pecplas_main
   use pecplas_parallel, only: parallel_init, parallel_finalize
   implicit none (type, external)
   character(len=:), allocatable :: args(:)
   integer :: i, n, length, code

   call parallel_init() ! MPI build: one of the ranks of `mpirun -np N pecplas DECK`
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
   code = pecplas_main(args)
   call parallel_finalize()
   if (code /= 0) call exit(code)
end program main
