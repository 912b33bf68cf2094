!> `pecplas-bench-bare FILE.matrix.h5`: the bare CHOLMOD solve of pecplas-bench's baseline,
!> in a process of its own: reads the matrix a run assembled (bench_matrix; not timed), then
!> analyse + factorise + one solve through the program's CHOLMOD calls (same ordering rule and
!> thread configuration for OMP_NUM_THREADS, no checks) and prints one line: analyse,
!> factorise, solve and their sum [s, wall], nnz(L), user and system CPU times of the three
!> calls [s].
program bench_bare
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_base_timers, only: wall_time
   use pecplas_linalg_cholmod, only: pecplas_cholmod_new, pecplas_cholmod_delete, &
      pecplas_cholmod_analyse, pecplas_cholmod_factorise, pecplas_cholmod_solve, &
      pecplas_cholmod_lnz
   use bench_matrix, only: read_matrix_file
   use bench_process, only: cpu_times
   use pecplas_linalg_threads, only: thread_setting_t, resolve_threads, apply_threads
   use pecplas_linalg_blas_core, only: blas_core_start
   implicit none (type, external)
   character(len=4096) :: arg
   type(csc_t) :: k
   type(error_t), allocatable :: error
   type(c_ptr) :: h
   integer(c_int) :: rc
   real(wp) :: t0, t_an, t_fa, t_so, lnz, cpu0(2), cpu1(2)
   real(wp), allocatable :: b(:), x(:)
   type(thread_setting_t) :: threads

   call blas_core_start() ! OpenBLAS's kernels: may run this program again (doc/build.md)
   if (command_argument_count() /= 1) error stop 'usage: pecplas-bench-bare FILE.matrix.h5'
   call get_command_argument(1, arg)
   call read_matrix_file(trim(arg), k, error)
   if (allocated(error)) then
      write (0, '(a)') 'pecplas-bench-bare: '//error%text()
      error stop 1
   end if
   allocate (b(k%n), x(k%n))
   b = 1.0_wp
   ! the threads of each part as the program gives them (OMP_NUM_THREADS)
   threads = resolve_threads(0)
   call apply_threads(threads)
   cpu0 = cpu_times()
   h = pecplas_cholmod_new(0_c_int)
   t0 = wall_time()
   rc = pecplas_cholmod_analyse(h, int(k%n, c_int), k%colptr, k%rowind)
   t_an = wall_time() - t0
   if (rc /= 0) error stop 'bare CHOLMOD analysis failed'
   t0 = wall_time()
   rc = pecplas_cholmod_factorise(h, int(k%n, c_int), k%colptr, k%rowind, k%values)
   t_fa = wall_time() - t0
   if (rc /= 0) error stop 'bare CHOLMOD factorisation failed'
   t0 = wall_time()
   rc = pecplas_cholmod_solve(h, int(k%n, c_int), 1_c_int, b, x)
   t_so = wall_time() - t0
   cpu1 = cpu_times()
   if (rc /= 0) error stop 'bare CHOLMOD solve failed'
   lnz = pecplas_cholmod_lnz(h)
   call pecplas_cholmod_delete(h)
   write (*, '(4f9.3,es10.2,2f9.3)') t_an, t_fa, t_so, t_an + t_fa + t_so, lnz, cpu1 - cpu0
end program bench_bare
