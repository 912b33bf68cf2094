!> Assembles and factorises the global stiffness; picks the linear solver on first use
!> (AUTO: CHOLMOD for the symmetric positive definite stiffness, UMFPACK otherwise) and
!> turns a singular factorisation into a message naming the free node and direction.
module pecplas_solve_stiffness
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, ERR_SINGULAR, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: METHOD_NEWTON
   use pecplas_model_phases, only: CHANGE_MATERIAL, CHANGE_LAW
   use pecplas_model_provenance, only: place_t
   use pecplas_problem_type, only: problem_t
   use pecplas_problem_linear, only: K_SOLVER, K_TSOLVER
   use pecplas_fe_assembly, only: assemble_stiffness
   use pecplas_linalg_solver, only: new_linear_solver
   use pecplas_base_timers, only: wall_time
   use pecplas_joints_katona_operator, only: add_augmentation
   use pecplas_fe_share, only: share_of_run
   use pecplas_linalg_mumps, only: mumps_summed_input
   use pecplas_base_parallel, only: parallel_size, parallel_rank, parallel_sum, parallel_max, parallel_max_int
   implicit none (type, external)
   private

   public :: factorise_stiffness, factorise_values, linear_solver_name, partitioned, upper_storage

contains

   !> Name of the linear solver a run uses.
   !> `tangent_of_fallback`: the solver of the full-Newton fallback of a modified-Newton run.
   function linear_solver_name(model, tangent_of_fallback) result(name)
      type(model_t), intent(in) :: model
      logical, intent(in), optional :: tangent_of_fallback
      character(len=:), allocatable :: name
      integer :: i
      logical :: symmetric, tangent
      logical, allocatable :: used(:)
      name = model%solver%linear
      if (name /= 'AUTO') return
      tangent = model%solver%method == METHOD_NEWTON
      if (present(tangent_of_fallback)) tangent = tangent .or. tangent_of_fallback
      ! Katona contact has no separate fallback solver: its full-Newton iterations factorise
      ! the consistent tangent into the run's own solver (the bordered solves and the
      ! flexibility use that one), so a run whose chain reaches Newton needs LU there when
      ! the tangent is not symmetric (CHOLMOD would read its upper triangle alone: a
      ! symmetrised tangent, linear convergence, false failures)
      if (model%solver%fallback .and. has_katona(model)) tangent = .true.
      ! The elastic stiffness of modified Newton is symmetric positive definite: CHOLMOD.
      ! Full Newton with a non-symmetric consistent tangent (non-associated plasticity,
      ! frictional interfaces) needs LU: UMFPACK.
      ! Only the materials and laws the run uses count (a deck may keep spare ones).
      symmetric = .true.
      if (tangent) then
         used = used_materials(model)
         do i = 1, size(model%materials)
            if (used(i)) symmetric = symmetric .and. model%materials(i)%m%symmetric_tangent()
         end do
         if (allocated(model%laws)) then
            used = used_laws(model)
            do i = 1, size(model%laws)
               if (used(i)) symmetric = symmetric .and. model%laws(i)%law%symmetric_tangent()
            end do
         end if
      end if
      name = merge('CHOLMOD', 'UMFPACK', symmetric)
   end function linear_solver_name

   !> Materials an element set has at the start or gets in a phase (*CHANGE_MATERIAL).
   function used_materials(model) result(used)
      type(model_t), intent(in) :: model
      logical, allocatable :: used(:)
      integer :: s, c
      allocate (used(size(model%materials)), source=.false.)
      do s = 1, size(model%mesh%esets)
         c = model%mesh%esets(s)%material_index
         if (c >= 1 .and. c <= size(used)) used(c) = .true.
      end do
      call mark_changed(model, CHANGE_MATERIAL, used)
   end function used_materials

   !> Laws a joint set has at the start or gets in a phase (*CHANGE_LAW).
   function used_laws(model) result(used)
      type(model_t), intent(in) :: model
      logical, allocatable :: used(:)
      integer :: s, c
      allocate (used(size(model%laws)), source=.false.)
      if (allocated(model%joint_sets)) then
         do s = 1, size(model%joint_sets)
            c = model%joint_sets(s)%law_index
            if (c >= 1 .and. c <= size(used)) used(c) = .true.
         end do
      end if
      call mark_changed(model, CHANGE_LAW, used)
   end function used_laws

   !> Marks in `used` the new index of every phase change of kind `kind`.
   subroutine mark_changed(model, kind, used)
      type(model_t), intent(in) :: model
      integer, intent(in) :: kind
      logical, intent(inout) :: used(:)
      integer :: s, c, k
      if (.not. allocated(model%steps)) return
      do s = 1, size(model%steps)
         if (.not. allocated(model%steps(s)%changes)) cycle
         do c = 1, size(model%steps(s)%changes)
            associate (ch => model%steps(s)%changes(c))
               k = ch%new
               if (ch%kind == kind .and. k >= 1 .and. k <= size(used)) used(k) = .true.
            end associate
         end do
      end do
   end subroutine mark_changed

   !> True when a joint set of the model is held by Katona contact.
   logical function has_katona(model)
      type(model_t), intent(in) :: model
      integer :: s
      has_katona = .false.
      if (.not. allocated(model%joint_sets)) return
      do s = 1, size(model%joint_sets)
         if (model%joint_sets(s)%is_katona()) has_katona = .true.
      end do
   end function has_katona

   !> True when every matrix of the run goes to CHOLMOD (its own stiffness and, for a
   !> method other than full Newton, the tangent of its fallback): the stiffness is then
   !> stored as its upper triangle only, all that CHOLMOD reads. Half the memory and half
   !> the additions of the whole matrix that UMFPACK and MUMPS need.
   logical function upper_storage(model)
      type(model_t), intent(in) :: model
      upper_storage = linear_solver_name(model) == 'CHOLMOD' .and. &
         linear_solver_name(model, .true.) == 'CHOLMOD'
   end function upper_storage

   !> `tangent`: consistent tangents (full Newton) instead of elastic stiffness;
   !> `tangent_solver`: into the fallback's own solver when the run has one
   !> (problem%linear%separate_tangent), keeping the run's factorisation.
   subroutine factorise_stiffness(model, problem, tangent, error, tangent_solver)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      logical, intent(in) :: tangent
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: tangent_solver
      real(wp) :: t0
      type(place_t) :: p
      logical :: separate, parts, mumps
      real(wp) :: c0

      separate = .false.
      if (present(tangent_solver)) separate = tangent_solver .and. problem%linear%separate_tangent
      if (separate) then
         call factorise_tangent(model, problem, error)
         return
      end if

      parts = partitioned(model)
      mumps = model%solver%linear == 'MUMPS'
      t0 = wall_time()
      problem%linear%k_owner = 0
      if (mumps) call cpu_time(c0)
      call assemble_stiffness(model, problem%system%dofs, problem%system%rules, problem%state, tangent, &
         problem%linear%kbuild, problem%linear%k, error, share_of_run(parts), upper_storage(model))
      if (mumps) call rank_times(problem, wall_time() - t0, c0)
      if (parts) call agree_on_error(error)
      if (allocated(error)) return
      if (problem%katona%alpha > 0.0_wp .and. (.not. parts .or. parallel_rank() == 0)) then
         call add_augmentation(problem%katona, problem%system%dofs, problem%linear%k, error)
         if (allocated(error)) return
      end if
      problem%stats%time%assembly = problem%stats%time%assembly + (wall_time() - t0)
      t0 = wall_time()
      if (.not. allocated(problem%linear%solver)) then
         call new_linear_solver(linear_solver_name(model), problem%linear%solver, error)
         if (allocated(error)) return
         call mumps_summed_input(problem%linear%solver, parts)
         call problem%linear%solver%analyse(problem%linear%k, error)
         if (allocated(error)) return
      end if
      call problem%linear%solver%factorise(problem%linear%k, error)
      if (allocated(error)) call katona_augment(model, problem, error)
      if (allocated(error)) then
         if (error%kind == ERR_SINGULAR) then
            error%message = 'the stiffness matrix is singular: '// &
               problem%system%dofs%describe(model, problem%linear%solver%bad_equation)// &
               ' can move without resistance (a mechanism: missing supports in *BOUNDARY?). '// &
               'Solver said: '//error%message
            ! name the line that defines that node
            if (problem%linear%solver%bad_equation >= 1 .and. &
                problem%linear%solver%bad_equation <= problem%system%dofs%neq) then
               p = model%provenance%node(problem%system%dofs%eq_node(problem%linear%solver%bad_equation))
               call model%provenance%locate(error, p, trim(p%keyword))
            end if
         end if
         return
      end if
      ! the set-up's is the first factorisation
      if (problem%stats%factorisations > 0) problem%linear%solver_moved = .true.
      problem%linear%k_owner = K_SOLVER
      problem%stats%factorisations = problem%stats%factorisations + 1
      problem%stats%time%factorisation = problem%stats%time%factorisation + (wall_time() - t0)
   end subroutine factorise_stiffness

   !> The fallback tangent into problem%linear%tsolver (created and analysed on first use).
   subroutine factorise_tangent(model, problem, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: t0, c0
      logical :: parts, mumps
      parts = partitioned(model)
      mumps = model%solver%linear == 'MUMPS'
      t0 = wall_time()
      problem%linear%tangent_factorised = .false.
      problem%linear%k_owner = 0
      if (mumps) call cpu_time(c0)
      call assemble_stiffness(model, problem%system%dofs, problem%system%rules, problem%state, .true., &
         problem%linear%kbuild, problem%linear%k, error, share_of_run(parts), upper_storage(model))
      if (mumps) call rank_times(problem, wall_time() - t0, c0)
      if (parts) call agree_on_error(error)
      if (allocated(error)) return
      problem%stats%time%assembly = problem%stats%time%assembly + (wall_time() - t0)
      t0 = wall_time()
      if (.not. allocated(problem%linear%tsolver)) then
         call new_linear_solver(linear_solver_name(model, .true.), problem%linear%tsolver, error)
         if (allocated(error)) return
         call mumps_summed_input(problem%linear%tsolver, parts)
         call problem%linear%tsolver%analyse(problem%linear%k, error)
         if (allocated(error)) return
      end if
      call problem%linear%tsolver%factorise(problem%linear%k, error)
      problem%stats%time%factorisation = problem%stats%time%factorisation + (wall_time() - t0)
      if (allocated(error)) return
      problem%stats%factorisations = problem%stats%factorisations + 1
      problem%linear%tangent_factorised = .true.
      problem%linear%k_owner = K_TSOLVER
   end subroutine factorise_tangent

   !> A restarted run: factorises the matrix of `values` (a matrix of this run's stiffness
   !> pattern, factorised by the interrupted run: pecplas_solve_restart) into the run's
   !> solver, or into the full-Newton fallback's own solver (`tangent_solver`), so that the
   !> run goes on with the factorisation the interrupted run had.
   subroutine factorise_values(model, problem, values, tangent_solver, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      real(wp), intent(in) :: values(:)
      logical, intent(in) :: tangent_solver
      type(error_t), allocatable, intent(out) :: error
      if (size(values) /= problem%linear%k%nnz()) then
         call fatal_error(error, 'a factorised matrix of another pattern')
         return
      end if
      problem%linear%k%values = values
      problem%linear%k_owner = 0
      if (tangent_solver) then
         problem%linear%tangent_factorised = .false.
         if (.not. allocated(problem%linear%tsolver)) then
            call new_linear_solver(linear_solver_name(model, .true.), problem%linear%tsolver, error)
            if (allocated(error)) return
            call mumps_summed_input(problem%linear%tsolver, partitioned(model))
            call problem%linear%tsolver%analyse(problem%linear%k, error)
            if (allocated(error)) return
         end if
         call problem%linear%tsolver%factorise(problem%linear%k, error)
         if (allocated(error)) return
         problem%linear%tangent_factorised = .true.
         problem%linear%k_owner = K_TSOLVER
      else
         call problem%linear%solver%factorise(problem%linear%k, error)
         if (allocated(error)) return
         problem%linear%solver_moved = .true.
         problem%linear%k_owner = K_SOLVER
      end if
      problem%stats%factorisations = problem%stats%factorisations + 1
   end subroutine factorise_values

   !> A singular R with Katona contact (a body held only by its contacts): factorises
   !> R_a = R + alpha D^T D instead, alpha = largest diagonal term of R. The Katona solve is
   !> written in unknowns that make its solution independent of alpha (pecplas_joints_katona_states);
   !> from then on every factorisation of the run is augmented.
   subroutine katona_augment(model, problem, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(inout) :: error
      real(wp), allocatable :: diag(:)
      logical :: parts
      if (error%kind /= ERR_SINGULAR .or. .not. problem%katona%active) return
      if (problem%katona%alpha > 0.0_wp) return
      deallocate (error)
      parts = partitioned(model)
      allocate (diag(problem%linear%k%n))
      call problem%linear%k%diagonal(diag)
      if (parts) call parallel_sum(diag) ! each rank holds a part of R
      problem%katona%alpha = maxval(diag)
      if (.not. parts .or. parallel_rank() == 0) then
         call add_augmentation(problem%katona, problem%system%dofs, problem%linear%k, error)
      end if
      if (parts) call agree_on_error(error)
      if (allocated(error)) return
      call problem%linear%solver%factorise(problem%linear%k, error)
   end subroutine katona_augment

   !> True when each rank assembles only its share of the elements (pecplas_fe_share): an
   !> MPI run on several ranks with MUMPS, which adds the ranks' parts. The serial solvers
   !> need the whole matrix on every rank.
   logical function partitioned(model)
      type(model_t), intent(in) :: model
      partitioned = model%solver%linear == 'MUMPS' .and. parallel_size() > 1
   end function partitioned

   !> Adds this assembly's `wall` seconds and the CPU seconds since `cpu0` to the rank's
   !> times and updates their smallest and largest over the ranks (measured before any rank
   !> waits for another). The CPU time is the work done even when ranks share busy cores.
   subroutine rank_times(problem, wall, cpu0)
      type(problem_t), intent(inout) :: problem
      real(wp), intent(in) :: wall, cpu0
      real(wp) :: t(4), c1
      call cpu_time(c1)
      associate (tm => problem%stats%time)
         tm%rank_wall = tm%rank_wall + wall
         tm%rank_cpu = tm%rank_cpu + (c1 - cpu0)
         t = [tm%rank_wall, -tm%rank_wall, tm%rank_cpu, -tm%rank_cpu]
         call parallel_max(t)
         tm%rank_wall_max = t(1)
         tm%rank_wall_min = -t(2)
         tm%rank_cpu_max = t(3)
         tm%rank_cpu_min = -t(4)
      end associate
   end subroutine rank_times

   !> The same outcome on every rank after a partitioned assembly: a rank whose elements
   !> all passed takes the failure of another (its own message is on that rank's stderr).
   subroutine agree_on_error(error)
      type(error_t), allocatable, intent(inout) :: error
      integer :: kind
      kind = 0
      if (allocated(error)) kind = error%kind
      kind = parallel_max_int(kind)
      if (kind == 0 .or. allocated(error)) return
      call fatal_error(error, 'the assembly failed on another MPI rank (its message is '// &
         'on that rank''s standard error)')
      error%kind = kind
   end subroutine agree_on_error

end module pecplas_solve_stiffness
