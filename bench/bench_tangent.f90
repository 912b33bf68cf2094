!> `pecplas-bench-tangent DECK OUT.h5`: runs DECK through the whole program (quiet, results
!> in OUT.h5.run.h5) and writes the matrix of the run's last factorisation (for a Newton run:
!> the consistent tangent of the last iteration) to OUT.h5, so that another linear solver can
!> be tried on the very matrices the program factorises (tools/pecplas_py/bench/amg.py):
!>   colptr, rowind,  the matrix (bench_matrix: 0-based CSC, attribute `upper`)
!>   values
!>   eq_node, eq_dir  node (1-based) and direction (1 = x, 2 = y) of each equation
!>   coordinates      (2, nnode) node coordinates
!>   u_free, k_u      the last displacements on the equations and the product of the stored
!>                    matrix with them, computed here: a reader that rebuilds K from the
!>                    pattern checks its own layout against k_u
!>   attributes       factorisations, factorisation_s (the run's factorisation wall time in
!>                    all, analyses included)
program bench_tangent
   use hdf5, only: hid_t, h5fclose_f
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_residual, only: free_part
   use pecplas_io_results_h5, only: h5_write, h5_attr
   use bench_matrix, only: create_matrix_file
   use pecplas_linalg_blas_core, only: blas_core_start
   implicit none (type, external)
   character(len=4096) :: arg
   character(len=:), allocatable :: deck, out
   integer :: code, err
   type(model_t) :: model
   type(problem_t) :: problem
   type(error_t), allocatable :: error
   integer(hid_t) :: f
   real(wp), allocatable :: u(:), ku(:)

   call blas_core_start() ! OpenBLAS's kernels: may run this program again (doc/build.md)
   if (command_argument_count() /= 2) error stop 'usage: pecplas-bench-tangent DECK OUT.h5'
   call get_command_argument(1, arg); deck = trim(arg)
   call get_command_argument(2, arg); out = trim(arg)
   code = run_deck(deck, out//'.run.h5', .true., model, problem)
   if (code /= 0 .or. .not. allocated(problem%linear%k%values)) error stop 'bench run failed'
   ! the values in k must be those a solver factorised last (not a later assembly)
   if (problem%linear%k_owner == 0) error stop 'the matrix held at the end was not factorised'

   u = free_part(problem, problem%state%u)
   allocate (ku(problem%linear%k%n))
   call problem%linear%k%matvec(u, ku)
   call create_matrix_file(out, problem%linear%k, f, error)
   if (.not. allocated(error)) call h5_attr(f, 'factorisations', problem%stats%factorisations, error)
   if (.not. allocated(error)) call h5_attr(f, 'factorisation_s', problem%stats%time%factorisation, &
      error)
   if (.not. allocated(error)) call h5_write(f, 'eq_node', problem%system%dofs%eq_node, error)
   if (.not. allocated(error)) call h5_write(f, 'eq_dir', problem%system%dofs%eq_dir, error)
   if (.not. allocated(error)) call h5_write(f, 'coordinates', model%mesh%x, error)
   if (.not. allocated(error)) call h5_write(f, 'u_free', u, error)
   if (.not. allocated(error)) call h5_write(f, 'k_u', ku, error)
   call h5fclose_f(f, err)
   if (allocated(error)) then
      write (0, '(a)') 'pecplas-bench-tangent: '//error%text()
      error stop 1
   end if
end program bench_tangent
