!> Benchmark of the elastic massif path: `pecplas-bench ETYPE N [DIR]` builds an N x N
!> plane-strain square of ETYPE (Q4 or Q8) elements as a Gmsh file and a deck, runs it
!> through the whole program (read, setup, assembly, factorisation, solve, residual, output),
!> then factorises and solves the SAME matrix with bare CHOLMOD calls (analyse + factorise +
!> solve, no checks; after a sync of the results file) and prints one line: phase times, the
!> ratio total / bare, peak memory.
!> One case per process so that the peak resident memory belongs to that case.
program bench_massif
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_double
   use pecplas_kinds, only: wp
   use pecplas_model, only: model_t
   use pecplas_cli, only: run_deck
   use pecplas_driver_problem, only: problem_t
   use pecplas_driver_timers, only: wall_time
   use pecplas_linalg_cholmod, only: pecplas_cholmod_new, pecplas_cholmod_delete, &
      pecplas_cholmod_analyse, pecplas_cholmod_factorise, pecplas_cholmod_solve, &
      pecplas_cholmod_lnz
   use bench_mesh, only: square_case
   implicit none (type, external)
   character(len=:), allocatable :: etype, base
   integer :: n, code
   type(model_t) :: model
   type(problem_t) :: problem
   type(c_ptr) :: h
   real(wp) :: t0, total, tread, t_an, t_fa, t_so, lnz
   real(wp), allocatable :: b(:), x(:)
   integer(c_int) :: rc

   call square_case('usage: pecplas-bench Q4|Q8 N [DIR]', etype, n, base)

   t0 = wall_time()
   code = run_deck(base//'.inp', base//'.h5', .true., model, problem)
   total = wall_time() - t0
   if (code /= 0) error stop 'bench run failed'
   tread = problem%time%setup

   ! Bare CHOLMOD on the same matrix: analyse + factorise + one solve. The results file is
   ! first written back to the disk (sync), so that the kernel's write-back of the run's
   ! output does not run during, and slow down, the bare factorisation.
   call execute_command_line('sync')
   allocate (b(problem%k%n), x(problem%k%n))
   b = 1.0_wp
   h = pecplas_cholmod_new(0_c_int)
   t0 = wall_time()
   rc = pecplas_cholmod_analyse(h, int(problem%k%n, c_int), problem%k%colptr, problem%k%rowind)
   t_an = wall_time() - t0
   t0 = wall_time()
   rc = pecplas_cholmod_factorise(h, int(problem%k%n, c_int), problem%k%colptr, &
      problem%k%rowind, problem%k%values)
   t_fa = wall_time() - t0
   t0 = wall_time()
   rc = pecplas_cholmod_solve(h, int(problem%k%n, c_int), 1_c_int, b, x)
   t_so = wall_time() - t0
   lnz = pecplas_cholmod_lnz(h)
   call pecplas_cholmod_delete(h)

   write (*, '(a3,i9,i10,7f9.3,f9.3,f8.2,f9.1,es10.2)') etype, n, problem%dofs%neq, tread, &
      problem%time%assembly, problem%time%factorisation, problem%time%solve, &
      problem%time%residual, problem%time%output, total, t_an + t_fa + t_so, &
      total/(t_an + t_fa + t_so), peak_memory_mb(), lnz
contains
   !> Peak resident memory of this process (VmHWM of /proc/self/status), MB.
   real(wp) function peak_memory_mb()
      character(len=256) :: line
      integer :: u, ios, kb
      peak_memory_mb = -1.0_wp
      open (newunit=u, file='/proc/self/status', status='old', action='read', iostat=ios)
      if (ios /= 0) return
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:6) == 'VmHWM:') then
            read (line(7:), *) kb
            peak_memory_mb = kb/1024.0_wp
         end if
      end do
      close (u)
   end function peak_memory_mb
end program bench_massif
