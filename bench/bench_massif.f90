!> Benchmark of the elastic massif path: `pecplas-bench ETYPE N [DIR]` builds an N x N
!> plane-strain square of ETYPE (Q4 or Q8) elements as a Gmsh file and a deck, runs it
!> through the whole program (read, setup, assembly, factorisation, solve, residual, output),
!> writes the matrix it assembled to DIR/square_ETYPE_N.matrix.h5 (bench_matrix) for the bare
!> CHOLMOD solve of pecplas-bench-bare, which runs in a process of its own, and prints one
!> line: phase times, the run's wall time, peak memory, and its user and system CPU times
!> (the system time is the kernel's work for the process: page faults on fresh memory, file
!> writes). PECPLAS_BENCH_MATRIX=0 skips the matrix file (repeated runs of tools/bench_threads.sh).
!> One case per process so that the peak resident memory belongs to that case.
program bench_massif
   use hdf5, only: hid_t, h5fclose_f
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_base_timers, only: wall_time
   use bench_mesh, only: square_case
   use bench_matrix, only: create_matrix_file
   use bench_process, only: cpu_times, peak_memory_mb
   use pecplas_linalg_blas_core, only: blas_core_start
   implicit none (type, external)
   character(len=:), allocatable :: etype, base
   integer :: n, code, err, length
   character(len=8) :: value
   type(model_t) :: model
   type(problem_t) :: problem
   type(error_t), allocatable :: error
   integer(hid_t) :: f
   real(wp) :: t0, total, cpu0(2), cpu1(2), peak

   call blas_core_start() ! OpenBLAS's kernels: may run this program again (doc/build.md)
   call square_case('usage: pecplas-bench Q4|Q8 N [DIR]', etype, n, base)

   cpu0 = cpu_times()
   t0 = wall_time()
   code = run_deck(base//'.inp', base//'.h5', .true., model, problem)
   total = wall_time() - t0
   cpu1 = cpu_times()
   peak = peak_memory_mb()
   if (code /= 0) error stop 'bench run failed'

   call get_environment_variable('PECPLAS_BENCH_MATRIX', value, length)
   if (length /= 1 .or. value(1:1) /= '0') then
      call create_matrix_file(base//'.matrix.h5', problem%linear%k, f, error)
      call h5fclose_f(f, err)
      if (allocated(error)) then
         write (0, '(a)') 'pecplas-bench: '//error%text()
         error stop 1
      end if
   end if

   write (*, '(a3,i9,i10,7f9.3,f9.1,2f9.3)') etype, n, problem%system%dofs%neq, problem%stats%time%setup, &
      problem%stats%time%assembly, problem%stats%time%factorisation, problem%stats%time%solve, &
      problem%stats%time%residual, problem%stats%time%output, total, peak, cpu1 - cpu0
end program bench_massif
