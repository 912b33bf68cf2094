!> A run's problem besides the model: the discretised system, the linear system, the run
!> state and the run statistics, each a type of its own (problem/system, linear, stats).
module pecplas_problem_type
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: METHOD_NEWTON
   use pecplas_fe_dofs, only: new_dofs
   use pecplas_fe_state, only: fe_state_t, set_state_allocate
   use pecplas_linalg_threads, only: PARALLEL_MIN_ELEMENTS
   use pecplas_fe_loads, only: pattern_vectors
   use pecplas_fe_pore, only: setup_pore
   use pecplas_massif_elements_factory, only: new_massif_element
   use pecplas_massif_kinematics, only: new_massif_rule
   use pecplas_fe_initial, only: apply_initial_stresses
   use pecplas_fe_assembly, only: internal_forces
   use pecplas_massif_materials_type, only: NCOMP
   use pecplas_problem_system, only: discrete_system_t
   use pecplas_problem_linear, only: linear_system_t
   use pecplas_problem_stats, only: run_stats_t
   use pecplas_problem_position, only: run_position_t
   use pecplas_problem_phase, only: phase_state_t
   use pecplas_problem_safety, only: safety_result_t
   use pecplas_model_phase_plan, only: is_phased, initial_activity, attached_nodes, &
      target_activity, plate_activity
   use pecplas_model_phases, only: TARGET_SUPPORTS, TARGET_PATTERNS
   use pecplas_fe_joint_assembly, only: setup_joint_state
   use pecplas_fe_plate_assembly, only: setup_plate_state
   use pecplas_fe_anchor_assembly, only: setup_anchor_state
   use pecplas_model_columns, only: nodal_columns, rotation_column
   use pecplas_joints_katona_type, only: katona_t
   use pecplas_joints_katona_doublets, only: setup_katona
   implicit none (type, external)
   private

   public :: problem_t, setup_problem, initialise_stresses, set_orphans

   !> A run's problem, in the parts it is made of: the discretised system (built once from
   !> the model), the linear system (matrix, solvers, factorisations), the run state (fields
   !> and histories of the integration points, Katona contact, where the step loop stands)
   !> and the run statistics. A new kind of unknown or state gets a component of its own.
   type :: problem_t
      type(discrete_system_t) :: system
      type(linear_system_t) :: linear
      !> Integration-point state and nodal fields, the joints' in state%joints.
      type(fe_state_t) :: state
      !> Katona contact doublets (inactive when no joint set has a KATONA law).
      type(katona_t) :: katona
      !> Position of the step loop after the last converged increment (restart).
      type(run_position_t) :: position
      type(run_stats_t) :: stats
      !> Phases: the phase in force and its carried out-of-balance (pecplas_phases_start).
      type(phase_state_t) :: phase
      !> What a safety step found (pecplas_solve_safety).
      type(safety_result_t) :: safety
   end type problem_t

contains

   !> Builds elements, equations, zero initial state (massif and joints) and pattern vectors.
   subroutine setup_problem(model, problem, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(out) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: d(NCOMP, NCOMP)
      integer :: s, nel, ng, nst, nnode, npat, e, g
      logical, allocatable :: eactive(:), jactive(:)

      ! the nodal arrays: a column per node, then per plate rotation
      nnode = nodal_columns(model)
      allocate (problem%system%elems(size(model%mesh%esets)), problem%system%rules(size(model%mesh%esets)))
      allocate (problem%state%sets(size(model%mesh%esets)))
      do s = 1, size(model%mesh%esets)
         call new_massif_element(model%mesh%esets(s)%etype, problem%system%elems(s)%e, error)
         if (allocated(error)) return
         associate (st => problem%state%sets(s))
            call new_massif_rule(problem%system%rules(s), problem%system%elems(s)%e)
            st%xi = problem%system%rules(s)%xi
            st%w = problem%system%rules(s)%w
            ng = size(st%w)
            st%ngauss = ng
            nel = size(model%mesh%esets(s)%conn, 2)
            nst = model%materials(model%mesh%esets(s)%material_index)%m%nstate()
            call set_state_allocate(st, NCOMP, nst, ng, nel)
            associate (mat => model%materials(model%mesh%esets(s)%material_index)%m)
               if (.not. mat%constant_tangent()) then
                  call mat%elastic_tangent(d)
                  allocate (st%tangent(NCOMP, NCOMP, ng, nel))
                  ! first touch on the element loops' threads (as set_state_allocate)
                  !$omp parallel do default(shared) private(e, g) schedule(static) &
                  !$omp if (nel >= PARALLEL_MIN_ELEMENTS)
                  do e = 1, nel
                     do g = 1, ng
                        st%tangent(:, :, g, e) = d
                     end do
                  end do
                  !$omp end parallel do
               end if
            end associate
         end associate
      end do
      problem%linear%separate_tangent = model%solver%method /= METHOD_NEWTON
      call setup_joint_state(model, problem%state%joints, error)
      if (allocated(error)) return
      call setup_pore(model, problem%system%rules, problem%state, error)
      if (allocated(error)) return
      call setup_plate_state(model, problem%state%plates)
      call setup_anchor_state(model, problem%state%anchors)
      ! phases: the sets first activated by a step are inactive until then
      problem%phase%phased = is_phased(model)
      if (problem%phase%phased) then
         call initial_activity(model, eactive, jactive)
         problem%state%sets%active = eactive
         if (allocated(problem%state%joints%sets)) problem%state%joints%sets%active = jactive
         problem%state%plates%sets%active = plate_activity(model, 0)
      end if
      npat = 0
      if (allocated(model%patterns)) npat = size(model%patterns)
      allocate (problem%state%u(2, nnode), source=0.0_wp)
      allocate (problem%state%factors(npat), source=0.0_wp)
      if (problem%phase%phased) then
         ! the named supports and patterns a step first activates are off until then
         problem%phase%supports_on = target_activity(model, TARGET_SUPPORTS, 0)
         problem%phase%patterns_on = target_activity(model, TARGET_PATTERNS, 0)
         allocate (problem%phase%held_u(2, nnode), source=0.0_wp)
         call new_dofs(model, problem%system%dofs, error, problem%phase%supports_on)
      else
         call new_dofs(model, problem%system%dofs, error)
      end if
      if (allocated(error)) return
      if (problem%phase%phased) call set_orphans(model, problem, eactive, jactive)
      allocate (problem%system%initial_force(2, nnode), source=0.0_wp)
      call pattern_vectors(model, problem%system%rules, problem%system%pattern_force, &
         problem%system%pattern_disp, error)
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
         call apply_initial_stresses(model, problem%system%rules, problem%state, error)
         if (allocated(error)) return
         call internal_forces(model, problem%system%rules, problem%state%u, problem%state, &
            problem%system%initial_force, error)
         if (allocated(error)) return
         call problem%state%commit()
      end if
      ! Katona doublets start from the projected joint stresses; their forces join the
      ! initial load so that the start is in equilibrium
      call setup_katona(model, problem%state%joints, problem%katona, problem%system%initial_force, &
         error)
   end subroutine initialise_stresses

   !> The free equations of the nodes that no active element or joint holds
   !> (problem%state%orphan_eq: pecplas_fe_assembly keeps the stiffness regular there).
   subroutine set_orphans(model, problem, eactive, jactive)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      logical, intent(in) :: eactive(:), jactive(:)
      logical, allocatable :: held(:), pactive(:), aactive(:)
      integer, allocatable :: eq(:, :)
      integer :: s, e, k, node
      allocate (pactive(0), aactive(0))
      if (allocated(problem%state%plates%sets)) pactive = problem%state%plates%sets%active
      if (allocated(problem%state%anchors%sets)) aactive = problem%state%anchors%sets%active
      allocate (held(nodal_columns(model)), source=.false.)
      held(1:model%mesh%nnode()) = attached_nodes(model, eactive, jactive, pactive, aactive)
      ! an active plate holds its nodes and their rotations
      if (allocated(problem%state%plates%sets)) then
         do s = 1, size(problem%state%plates%sets)
            if (.not. problem%state%plates%sets(s)%active) cycle
            do e = 1, size(model%plates(s)%conn, 2)
               do k = 1, size(model%plates(s)%conn, 1)
                  node = model%plates(s)%conn(k, e)
                  held(node) = .true.
                  held(rotation_column(model, node)) = .true.
               end do
            end do
         end do
      end if
      eq = problem%system%dofs%eq
      problem%state%orphan_eq = pack(eq, eq > 0 .and. spread(.not. held, 1, 2))
   end subroutine set_orphans

end module pecplas_problem_type
