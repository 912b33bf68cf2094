!> Cost of the two ways of solving the Katona saddle-point system on a deck's mesh:
!> `pecplas-bench-katona DECK` sets the deck up (the stiffness R, augmented when singular,
!> factorised by CHOLMOD) and prints, in seconds (wall):
!>   - CHOLMOD numeric factorisation of R, one solve;
!>   - the flexibility G = D R^-1 D^T (2 nd right-hand sides; the bordered path does this
!>     once per factorisation, then each state iteration is a dense LU of order 2 nd);
!>   - UMFPACK on the full saddle matrix [R D^T; D 0] with every doublet bonded: symbolic
!>     analysis, numeric factorisation, one solve (the saddle path would refactorise at each
!>     state iteration, the pattern kept by writing all rows).
!> doc/validation.md ("Katona contact") uses it to set the choice of the bordered path.
program bench_katona
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_model_mesh_tools, only: orient_edge_sets, check_elements
   use pecplas_problem_type, only: problem_t, setup_problem, initialise_stresses
   use pecplas_solve_stiffness, only: factorise_stiffness
   use pecplas_base_timers, only: wall_time
   use pecplas_linalg_sparse, only: coo_t, csc_t, coo_to_csc
   use pecplas_linalg_solver, only: umfpack_solver_t
   use pecplas_fe_joint_penalty, only: set_default_penalties
   use pecplas_joints_katona_operator, only: build_flexibility, doublet_rows
   implicit none (type, external)
   character(len=512) :: deck
   type(model_t) :: model
   type(problem_t) :: problem
   type(error_t), allocatable :: error
   type(coo_t) :: coo
   type(csc_t) :: saddle
   type(umfpack_solver_t) :: umf
   real(wp), allocatable :: b(:), x(:), g(:, :), bs(:), xs(:)
   real(wp) :: t0, t_fact, t_solve, t_g, t_an, t_fa, t_so, c(2, 2, 2)
   integer :: nflip, n, m, k, j, p, r, a, d, q

   if (command_argument_count() < 1) error stop 'usage: pecplas-bench-katona DECK'
   call get_command_argument(1, deck)
   call read_deck(trim(deck), model, error)
   if (.not. allocated(error)) call check_elements(model%mesh, nflip, error)
   if (.not. allocated(error)) call orient_edge_sets(model%mesh, error)
   if (.not. allocated(error)) call setup_problem(model, problem, error)
   ! the Katona doublets are set up with the initial stresses (as the program does)
   if (.not. allocated(error)) call initialise_stresses(model, problem, error)
   if (.not. allocated(error)) call set_default_penalties(model, problem%system%rules, &
      problem%state%joints, error)
   if (.not. allocated(error)) call factorise_stiffness(model, problem, .false., error)
   if (allocated(error)) then
      write (*, '(a)') 'set-up failed: '//error%message
      error stop 1
   end if
   if (.not. problem%katona%active) error stop 'the deck has no Katona joint set'
   n = problem%system%dofs%neq
   m = 2*problem%katona%nd
   t0 = wall_time()
   call problem%linear%solver%factorise(problem%linear%k, error)
   t_fact = wall_time() - t0
   allocate (b(n), x(n), source=1.0_wp)
   t0 = wall_time()
   call problem%linear%solver%solve(b, x, error)
   t_solve = wall_time() - t0
   t0 = wall_time()
   call build_flexibility(problem%katona, problem%system%dofs, problem%linear%solver, g, error)
   t_g = wall_time() - t0
   ! saddle matrix: R (full storage) and the doublet rows
   call coo%init(n + m, problem%linear%k%nnz() + 16*m)
   do j = 1, n
      do p = problem%linear%k%colptr(j) + 1, problem%linear%k%colptr(j + 1)
         call coo%add(problem%linear%k%rowind(p) + 1, j, problem%linear%k%values(p))
      end do
   end do
   do k = 1, problem%katona%nd
      c = doublet_rows(problem%katona, k)
      do r = 1, 2
         ! a row on supported dofs only is no constraint (the solver gives it lambda = 0)
         if (all(problem%system%dofs%eq(:, problem%katona%node(:, k)) == 0 .or. &
                 transpose(c(r, :, :)) == 0.0_wp)) call coo%add(n + 2*k - 2 + r, n + 2*k - 2 + r, 1.0_wp)
         do a = 1, 2
            do d = 1, 2
               q = problem%system%dofs%eq(d, problem%katona%node(a, k))
               if (q == 0 .or. c(r, a, d) == 0.0_wp) cycle
               call coo%add(n + 2*k - 2 + r, q, c(r, a, d))
               call coo%add(q, n + 2*k - 2 + r, c(r, a, d))
            end do
         end do
      end do
   end do
   call coo_to_csc(coo, saddle, error)
   if (allocated(error)) error stop 'saddle assembly failed'
   t0 = wall_time()
   call umf%analyse(saddle, error)
   t_an = wall_time() - t0
   t0 = wall_time()
   call umf%factorise(saddle, error)
   t_fa = wall_time() - t0
   if (allocated(error)) write (*, '(a)') ' UMFPACK: '//error%message
   allocate (bs(n + m), xs(n + m), source=1.0_wp)
   t0 = wall_time()
   if (.not. allocated(error)) call umf%solve(bs, xs, error)
   t_so = wall_time() - t0
   write (*, '(a,i0,a,i0,a,es9.2)') ' equations ', n, '  doublet rows 2nd ', m, &
      '  augmentation ', problem%katona%alpha
   write (*, '(a,f9.4,a,f9.5,a,f9.4,a,f9.5)') ' CHOLMOD factorise R ', t_fact, '  solve ', &
      t_solve, '  flexibility G (2nd solves) ', t_g, '  per column ', t_g/max(m, 1)
   write (*, '(a,f9.4,a,f9.4,a,f9.5)') ' UMFPACK saddle: analyse ', t_an, '  factorise ', t_fa, &
      '  solve ', t_so
end program bench_katona
