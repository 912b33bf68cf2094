!> Benchmark of the elastic massif path: `pecplas-bench ETYPE N [DIR]` builds an N x N
!> plane-strain square of ETYPE (Q4 or Q8) elements as a Gmsh file and a deck, runs it
!> through the whole program (read, setup, assembly, factorisation, solve, residual, output),
!> then factorises and solves the SAME matrix with bare CHOLMOD calls (analyse + factorise +
!> solve, no checks; after a sync of the results file) and prints one line: phase times, the
!> ratio total / bare, peak memory, nnz(L), and the user and system CPU times of the run and
!> of the bare solve (the system time is the kernel's work for the process: page faults on
!> fresh memory, file writes).
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
   real(wp) :: cpu0(2), cpu1(2), cpu2(2)
   real(wp), allocatable :: b(:), x(:)
   integer(c_int) :: rc

   call square_case('usage: pecplas-bench Q4|Q8 N [DIR]', etype, n, base)

   cpu0 = cpu_times()
   t0 = wall_time()
   code = run_deck(base//'.inp', base//'.h5', .true., model, problem)
   total = wall_time() - t0
   cpu1 = cpu_times()
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
   cpu2 = cpu_times()
   call pecplas_cholmod_delete(h)

   write (*, '(a3,i9,i10,7f9.3,f9.3,f8.2,f9.1,es10.2,4f9.3)') etype, n, problem%dofs%neq, &
      tread, problem%time%assembly, problem%time%factorisation, problem%time%solve, &
      problem%time%residual, problem%time%output, total, t_an + t_fa + t_so, &
      total/(t_an + t_fa + t_so), peak_memory_mb(), lnz, cpu1 - cpu0, cpu2 - cpu1
contains
   !> User and system CPU time of this process so far [s] (utime and stime of
   !> /proc/self/stat, in the kernel's fixed 100 ticks per second); -1 when unreadable.
   function cpu_times() result(t)
      real(wp) :: t(2)
      character(len=4096) :: line
      character(len=32) :: field(13)
      integer :: u, ios, k
      t = -1.0_wp
      open (newunit=u, file='/proc/self/stat', status='old', action='read', iostat=ios)
      if (ios /= 0) return
      read (u, '(a)', iostat=ios) line
      close (u)
      if (ios /= 0) return
      ! the fields after the command name, which ends at the last ')': state is field 3,
      ! utime 14, stime 15
      k = index(line, ')', back=.true.)
      read (line(k + 1:), *, iostat=ios) field
      if (ios /= 0) return
      read (field(12), *, iostat=ios) t(1)
      if (ios == 0) read (field(13), *, iostat=ios) t(2)
      if (ios /= 0) then
         t = -1.0_wp
      else
         t = t/100.0_wp
      end if
   end function cpu_times

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
