!> Everything a run needs besides the model: element objects, equation numbering,
!> integration-point state, pattern vectors, the linear solver and its matrix, counters.
module pecplas_problem_type
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_fe_dofs, only: dofs_t, new_dofs
   use pecplas_fe_state, only: fe_state_t
   use pecplas_fe_loads, only: pattern_vectors
   use pecplas_massif_elements_type, only: massif_element_box_t
   use pecplas_massif_elements_factory, only: new_massif_element
   use pecplas_massif_kinematics, only: massif_rule_t, new_massif_rule
   use pecplas_fe_initial, only: apply_initial_stresses
   use pecplas_fe_assembly, only: internal_forces
   use pecplas_massif_materials_type, only: NCOMP
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_linalg_sparse_reuse, only: csc_builder_t
   use pecplas_linalg_solver_type, only: linear_solver_t
   use pecplas_base_timers, only: timers_t
   use pecplas_problem_position, only: run_position_t
   use pecplas_fe_joint_assembly, only: setup_joint_state
   use pecplas_joints_katona_type, only: katona_t
   use pecplas_joints_katona_doublets, only: setup_katona
   implicit none (type, external)
   private

   public :: problem_t, setup_problem, initialise_stresses

   !> problem_t%k_owner values.
   integer, parameter, public :: K_SOLVER = 1, K_TSOLVER = 2

   type :: problem_t
      type(massif_element_box_t), allocatable :: elems(:)
      !> Integration rule with tabulated shape functions, per element set.
      type(massif_rule_t), allocatable :: rules(:)
      type(dofs_t) :: dofs
      !> Integration-point state, the joints' in state%joints.
      type(fe_state_t) :: state
      !> Pattern vectors at factor 1: forces and imposed displacements (2, nnode, npattern).
      real(wp), allocatable :: pattern_force(:, :, :), pattern_disp(:, :, :)
      !> Nodal forces of the initial stresses, held as a constant load so that the initial
      !> state is in equilibrium (2, nnode); zero without *INITIAL_STRESS.
      real(wp), allocatable :: initial_force(:, :)
      class(linear_solver_t), allocatable :: solver
      !> Full-Newton fallback of a modified/quasi-Newton run: the consistent tangent is
      !> factorised by its own solver so that the run's stiffness factorisation stays.
      class(linear_solver_t), allocatable :: tsolver
      logical :: separate_tangent = .false., tangent_factorised = .false.
      type(csc_t) :: k
      !> The solver whose factorisation holds the values now in k (K_SOLVER, K_TSOLVER, or
      !> 0: an assembly not, or not yet, factorised), and whether the solver's factorisation
      !> is still that of the set-up stiffness: the restart data carries the matrices
      !> factorised during the run (pecplas_solve_restart).
      integer :: k_owner = 0
      logical :: solver_moved = .false.
      !> Triplet storage and scatter map of the stiffness re-assembly (pecplas_linalg_sparse_reuse).
      type(csc_builder_t) :: kbuild
      !> Katona contact doublets (inactive when no joint set has a KATONA law).
      type(katona_t) :: katona
      !> Counters for the summary.
      integer :: increments = 0, iterations = 0, cuts = 0, factorisations = 0, solves = 0
      !> Line-search residual evaluations; tangents found singular (elastic used instead);
      !> increments converged by each method (modified, quasi-, full Newton) and under
      !> arc-length control.
      integer :: line_searches = 0, singular_tangents = 0, arc_increments = 0
      integer :: by_method(3) = 0
      type(timers_t) :: time
      !> Position of the step loop after the last converged increment (restart).
      type(run_position_t) :: position
   end type problem_t

contains

   !> Builds elements, equations, zero initial state (massif and joints) and pattern vectors.
   subroutine setup_problem(model, problem, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(out) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: d(NCOMP, NCOMP)
      integer :: s, nel, ng, nst, nnode, npat, e, g

      nnode = model%mesh%nnode()
      allocate (problem%elems(size(model%mesh%esets)), problem%rules(size(model%mesh%esets)))
      allocate (problem%state%sets(size(model%mesh%esets)))
      do s = 1, size(model%mesh%esets)
         call new_massif_element(model%mesh%esets(s)%etype, problem%elems(s)%e, error)
         if (allocated(error)) return
         associate (st => problem%state%sets(s))
            call new_massif_rule(problem%rules(s), problem%elems(s)%e)
            st%xi = problem%rules(s)%xi
            st%w = problem%rules(s)%w
            ng = size(st%w)
            st%ngauss = ng
            nel = size(model%mesh%esets(s)%conn, 2)
            nst = model%materials(model%mesh%esets(s)%material_index)%m%nstate()
            allocate (st%stress(NCOMP, ng, nel), st%strain(NCOMP, ng, nel), source=0.0_wp)
            allocate (st%hist(nst, ng, nel), source=0.0_wp)
            allocate (st%stress_trial, st%strain_trial, source=st%stress)
            allocate (st%hist_trial, source=st%hist)
            associate (mat => model%materials(model%mesh%esets(s)%material_index)%m)
               if (.not. mat%constant_tangent()) then
                  call mat%elastic_tangent(d)
                  allocate (st%tangent(NCOMP, NCOMP, ng, nel))
                  do e = 1, nel
                     do g = 1, ng
                        st%tangent(:, :, g, e) = d
                     end do
                  end do
               end if
            end associate
         end associate
      end do
      problem%separate_tangent = model%solver%method /= 'NEWTON'
      call setup_joint_state(model, problem%state%joints, error)
      if (allocated(error)) return
      npat = 0
      if (allocated(model%patterns)) npat = size(model%patterns)
      allocate (problem%state%u(2, nnode), source=0.0_wp)
      allocate (problem%state%factors(npat), source=0.0_wp)
      call new_dofs(model, problem%dofs, error)
      if (allocated(error)) return
      allocate (problem%initial_force(2, nnode), source=0.0_wp)
      call pattern_vectors(model, problem%rules, problem%pattern_force, &
         problem%pattern_disp, error)
   end subroutine setup_problem

   !> Puts the *INITIAL_STRESS state into the integration points and computes its nodal
   !> forces, held as a constant load (the initial state is in equilibrium), and sets up the
   !> Katona doublets. Call after setup_problem and after the default penalties are set
   !> (joint laws are evaluated).
   subroutine initialise_stresses(model, problem, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      if (allocated(model%initial_stresses)) then
         call apply_initial_stresses(model, problem%rules, problem%state, error)
         if (allocated(error)) return
         call internal_forces(model, problem%rules, problem%state%u, problem%state, &
            problem%initial_force, error)
         if (allocated(error)) return
         call problem%state%commit()
      end if
      ! Katona doublets start from the projected joint stresses; their forces join the
      ! initial load so that the start is in equilibrium
      call setup_katona(model, problem%state%joints, problem%katona, problem%initial_force, &
         error)
   end subroutine initialise_stresses

end module pecplas_problem_type
