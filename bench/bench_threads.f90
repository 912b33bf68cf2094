!> `pecplas-bench-threads FILE.matrix.h5 R,B,W ...`: the thread configurations of CHOLMOD's
!> factorisation side by side on one matrix (written by pecplas-bench, bench_matrix): reads it
!> and analyses it once (the program's ordering rule), then for each configuration R,B,W
!> (threads of CHOLMOD's parallel regions, most BLAS threads of a call, flops per BLAS
!> thread, 0 = every call gets B; see pecplas_linalg_threads) factorises it once and solves
!> once, and prints one line: R, B, W, factorisation and solve wall time [s], user and system
!> CPU time of both [s], BLAS calls, the share of them given more than one thread and the
!> share of the flops in those, and the largest |x - x1| / |x1| against the first
!> configuration's solution x1.
program bench_threads
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_double
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_base_timers, only: wall_time
   use pecplas_linalg_cholmod, only: pecplas_cholmod_new, pecplas_cholmod_delete, &
      pecplas_cholmod_analyse, pecplas_cholmod_factorise, pecplas_cholmod_solve
   use bench_matrix, only: read_matrix_file
   use bench_process, only: cpu_times
   use pecplas_linalg_threads, only: thread_setting_t, resolve_threads, apply_threads
   use pecplas_linalg_blas_core, only: blas_core_start
   implicit none (type, external)
   interface
      integer(c_int) function pecplas_threads_configure(loops, regions, blas, work) bind(C)
         import :: c_int, c_double
         integer(c_int), value :: loops, regions, blas
         real(c_double), value :: work
      end function
      subroutine pecplas_threads_calls_stats(out, reset) bind(C)
         import :: c_int, c_double
         real(c_double), intent(out) :: out(4)
         integer(c_int), value :: reset
      end subroutine
   end interface
   character(len=4096) :: arg
   type(csc_t) :: k
   type(error_t), allocatable :: error
   type(c_ptr) :: h
   integer(c_int) :: rc, r, b
   real(c_double) :: w, stats(4)
   real(wp) :: t0, t_fa, t_so, cpu0(2), cpu1(2), dev
   real(wp), allocatable :: rhs(:), x(:), x1(:)
   integer :: i, ios
   type(thread_setting_t) :: setting

   call blas_core_start() ! OpenBLAS's kernels: may run this program again (doc/build.md)
   if (command_argument_count() < 2) error stop 'usage: pecplas-bench-threads FILE.matrix.h5 R,B,W ...'
   call get_command_argument(1, arg)
   call read_matrix_file(trim(arg), k, error)
   if (allocated(error)) then
      write (0, '(a)') 'pecplas-bench-threads: '//error%text()
      error stop 1
   end if
   allocate (rhs(k%n), x(k%n))
   rhs = 1.0_wp
   h = pecplas_cholmod_new(0_c_int)
   t0 = wall_time()
   rc = pecplas_cholmod_analyse(h, int(k%n, c_int), k%colptr, k%rowind)
   if (rc /= 0) error stop 'CHOLMOD analysis failed'
   setting = resolve_threads(0)
   call apply_threads(setting)
   write (*, '(a,f8.3,a,i0,a)') '# analysis ', wall_time() - t0, ' s; BLAS '//setting%blas// &
      ' ('//setting%blas_threading//'), OMP_NUM_THREADS ', setting%n, ' ('//setting%source//')'
   write (*, '(a)') '# regions blas work factor_s solve_s user_s sys_s calls threaded_calls '// &
      'threaded_flops dev'
   do i = 2, command_argument_count()
      call get_command_argument(i, arg)
      read (arg, *, iostat=ios) r, b, w
      if (ios /= 0) error stop 'configuration R,B,W expected'
      rc = pecplas_threads_configure(b, r, b, w)
      call pecplas_threads_calls_stats(stats, 1_c_int)
      cpu0 = cpu_times()
      t0 = wall_time()
      rc = pecplas_cholmod_factorise(h, int(k%n, c_int), k%colptr, k%rowind, k%values)
      t_fa = wall_time() - t0
      if (rc /= 0) error stop 'CHOLMOD factorisation failed'
      t0 = wall_time()
      rc = pecplas_cholmod_solve(h, int(k%n, c_int), 1_c_int, rhs, x)
      t_so = wall_time() - t0
      cpu1 = cpu_times()
      if (rc /= 0) error stop 'CHOLMOD solve failed'
      call pecplas_threads_calls_stats(stats, 1_c_int)
      if (.not. allocated(x1)) x1 = x
      dev = maxval(abs(x - x1))/maxval(abs(x1))
      write (*, '(2i4,es10.2,2f9.3,2f9.2,es11.3,2f8.4,es10.2)') r, b, w, t_fa, t_so, &
         cpu1 - cpu0, stats(1), stats(2)/max(stats(1), 1.0_c_double), &
         stats(4)/max(stats(3), 1.0_c_double), dev
      flush (6)
   end do
   call pecplas_cholmod_delete(h)
end program bench_threads
