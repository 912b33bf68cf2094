!> Fill-reducing orderings compared on the elastic block: `pecplas-bench-ordering ETYPE N
!> [DIR] [REPEATS]` builds the N x N square of ETYPE (Q4 or Q8) elements, runs it through the
!> whole program to get its stiffness matrix, then for AMD, CHOLMOD's default strategy, METIS,
!> NESDIS, METIS on the graph of nodes and the project's rule analyses and factorises that
!> matrix REPEATS times (default 3); RULE2 is the rule factorising the pattern a second time
!> (as a Newton run does): its factorisation time is that of the second factorisation, which
!> includes the METIS ordering the rule defers to it, and its statistics are those after it
!> and prints one line per ordering: the ordering CHOLMOD used, nnz(L) and the flop count of
!> the analysis (load-independent), median / min / max analysis and factorisation times, and
!> the largest difference of the solution of K x = 1 from the one with the first ordering
!> listed, relative to max|x|. ORDERINGS: a comma list of the labels AMD, DEFAULT, METIS,
!> NESDIS, M-NODES, RULE, RULE2 (default: all). Last two columns: median CPU time (user + system) of the
!> analysis and of the factorisation [s] (the process's, so a loaded machine does not count).
program bench_ordering
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_base_timers, only: wall_time
   use pecplas_linalg_cholmod, only: pecplas_cholmod_new, pecplas_cholmod_delete, &
      pecplas_cholmod_analyse, pecplas_cholmod_factorise, pecplas_cholmod_solve, &
      pecplas_cholmod_lnz, pecplas_cholmod_flops, pecplas_cholmod_ordering, &
      pecplas_cholmod_set_ordering, ORDER_RULE, ORDER_CHOLMOD_DEFAULT, ORDER_AMD, &
      ORDER_METIS, ORDER_NESDIS, ORDER_METIS_NODES
   use bench_mesh, only: square_case
   use bench_process, only: cpu_times
   use pecplas_linalg_blas_core, only: blas_core_start
   implicit none (type, external)
   integer(c_int), parameter :: METHODS(7) = [ORDER_AMD, ORDER_CHOLMOD_DEFAULT, ORDER_METIS, &
      ORDER_NESDIS, ORDER_METIS_NODES, ORDER_RULE, ORDER_RULE]
   character(len=7), parameter :: LABELS(7) = [character(len=7) :: 'AMD', 'DEFAULT', 'METIS', &
      'NESDIS', 'M-NODES', 'RULE', 'RULE2']
   character(len=11), parameter :: CODES(0:6) = [character(len=11) :: 'NATURAL', 'GIVEN', &
      'AMD', 'METIS', 'NESDIS', 'COLAMD', 'POSTORDERED']
   character(len=64) :: arg
   character(len=:), allocatable :: etype, base
   integer :: n, code, repeats, m, r, used
   logical :: wanted(7), first
   type(model_t) :: model
   type(problem_t) :: problem
   type(c_ptr) :: h
   real(wp) :: t0, lnz, fl, dx
   real(wp), allocatable :: b(:), x(:), xref(:), ta(:), tf(:), ca(:), cf(:)
   real(wp) :: cpu(2)
   integer(c_int) :: rc, neq

   call blas_core_start() ! OpenBLAS's kernels: may run this program again (doc/build.md)
   call square_case('usage: pecplas-bench-ordering Q4|Q8 N [DIR] [REPEATS] [ORDERINGS]', &
      etype, n, base)
   repeats = 3
   if (command_argument_count() >= 4) then
      call get_command_argument(4, arg); read (arg, *) repeats
   end if
   wanted = .true.
   if (command_argument_count() >= 5) then
      call get_command_argument(5, arg)
      wanted = .false.
      do m = 1, size(METHODS)
         wanted(m) = index(','//trim(arg)//',', ','//trim(LABELS(m))//',') > 0
      end do
   end if
   code = run_deck(base//'.inp', base//'.h5', .true., model, problem)
   if (code /= 0) error stop 'bench run failed'

   neq = int(problem%linear%k%n, c_int)
   allocate (b(neq), x(neq), xref(neq), ta(repeats), tf(repeats), ca(repeats), cf(repeats))
   b = 1.0_wp
   first = .true.
   do m = 1, size(METHODS)
      if (.not. wanted(m)) cycle
      do r = 1, repeats
         h = pecplas_cholmod_new(0_c_int)
         call pecplas_cholmod_set_ordering(h, METHODS(m))
         cpu = cpu_times()
         t0 = wall_time()
         rc = pecplas_cholmod_analyse(h, neq, problem%linear%k%colptr, problem%linear%k%rowind)
         ta(r) = wall_time() - t0
         ca(r) = sum(cpu_times() - cpu)
         if (rc /= 0) error stop 'analysis failed'
         cpu = cpu_times()
         t0 = wall_time()
         rc = pecplas_cholmod_factorise(h, neq, problem%linear%k%colptr, problem%linear%k%rowind, &
            problem%linear%k%values)
         tf(r) = wall_time() - t0
         cf(r) = sum(cpu_times() - cpu)
         if (rc /= 0) error stop 'factorisation failed'
         if (LABELS(m) == 'RULE2') then
            cpu = cpu_times()
            t0 = wall_time()
            rc = pecplas_cholmod_factorise(h, neq, problem%linear%k%colptr, problem%linear%k%rowind, &
               problem%linear%k%values)
            tf(r) = wall_time() - t0
            cf(r) = sum(cpu_times() - cpu)
            if (rc /= 0) error stop 'second factorisation failed'
         end if
         rc = pecplas_cholmod_solve(h, neq, 1_c_int, b, x)
         if (rc /= 0) error stop 'solve failed'
         lnz = pecplas_cholmod_lnz(h)
         fl = pecplas_cholmod_flops(h)
         used = pecplas_cholmod_ordering(h)
         call pecplas_cholmod_delete(h)
      end do
      if (first) xref = x
      first = .false.
      dx = maxval(abs(x - xref))/maxval(abs(xref))
      write (*, '(a3,i6,i9,1x,a7,1x,a7,2es11.3,6f9.3,es10.2,2f9.3)') etype, n, neq, LABELS(m), &
         CODES(max(0, min(6, used))), lnz, fl, median(ta), minval(ta), maxval(ta), median(tf), &
         minval(tf), maxval(tf), dx, median(ca), median(cf)
      flush (6)
   end do
contains
   pure real(wp) function median(t)
      real(wp), intent(in) :: t(:)
      real(wp) :: s(size(t)), v
      integer :: i, j
      s = t
      do i = 2, size(s) ! insertion sort: a handful of values
         v = s(i)
         j = i - 1
         do while (j >= 1)
            if (s(j) <= v) exit
            s(j + 1) = s(j)
            j = j - 1
         end do
         s(j + 1) = v
      end do
      median = 0.5_wp*(s((size(s) + 1)/2) + s(size(s)/2 + 1))
   end function median
end program bench_ordering
