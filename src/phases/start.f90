!> The start of a phase (doc/theory.md, Phases): the changes of a step are applied to the
!> run's state from the converged state of the step before, and the out-of-balance they
!> create becomes a carried load that the step takes to zero along its load path.
!>
!>   *DEACTIVATE     an element set or joint set stops adding stiffness and forces; a joint
!>                   set one of whose nodes loses its last active element goes with it;
!>   *ACTIVATE       an element set starts stress-free (or with its *INITIAL_STRESS stress:
!>                   STRESS=WISHED_IN_PLACE), strains measured from the current displacement,
!>                   no history; a joint set starts from the initial stresses of the soil
!>                   beside it, relative displacements measured from the current ones;
!>   *CHANGE_MATERIAL the set's points keep their stresses; the history restarts (zero, the
!>                   new material's size); *CHANGE_LAW: the joint points keep their stresses,
!>                   the history restarts from them (the law's init_state);
!>   RESET_DISPLACEMENTS the displacements (and the strains and joint relative displacements
!>                   measured from them) restart at zero; stresses and histories are kept.
!>
!> Then: the free equations of nodes that no active element or joint holds (taken out of the
!> system by a diagonal entry, pecplas_fe_assembly), the pattern vectors over the active sets,
!> the held load (the weight of the active sets under the K0 procedure), and the carried
!> out-of-balance c = F_int - F_ext at the step start on the free equations.
module pecplas_phases_start
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_columns, only: nodal_columns
   use pecplas_model_loads, only: LOAD_GRAVITY
   use pecplas_model_phases, only: CHANGE_DEACTIVATE, CHANGE_ACTIVATE, CHANGE_MATERIAL, &
      CHANGE_LAW, TARGET_ELEMENTS, TARGET_JOINTS, TARGET_PATTERNS, TARGET_SUPPORTS, &
      TARGET_NAMES, START_WISHED, TARGET_PLATES, TARGET_ANCHORS
   use pecplas_model_phase_plan, only: step_activity, attached_nodes, target_activity
   use pecplas_fe_dofs, only: dofs_t, new_dofs
   use pecplas_fe_plate_assembly, only: activate_plate
   use pecplas_problem_type, only: problem_t, set_orphans
   use pecplas_phases_anchors, only: start_anchors
   use pecplas_problem_phase, only: PROCEDURE_NONE, PROCEDURE_K0, PROCEDURE_GRAVITY, &
      PROCEDURE_NAMES, HOLD_NONE, HOLD_WEIGHT
   use pecplas_fe_state, only: set_state_t, set_material
   use pecplas_fe_assembly, only: internal_forces
   use pecplas_fe_loads, only: pattern_vectors, add_body_force
   use pecplas_fe_initial, only: initial_set_stress, initial_joint_set_stress, mesh_index_t
   use pecplas_fe_joint_initial, only: set_joint_stress
   use pecplas_massif_kinematics, only: MAX_NODES, massif_gauss_derivs
   use pecplas_massif_point_kernels, only: point_strain
   use pecplas_massif_materials_type, only: NCOMP
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t, joint_strain
   use pecplas_joints_points, only: joint_set_element, joint_element_points
   use pecplas_joints_laws_type, only: MODE_STICK, MODE_OPEN
   use pecplas_joints_katona_operator, only: relative_displacements, add_contact_forces
   use pecplas_fe_pore, only: set_steady_pressures, reset_excess
   use pecplas_fe_water_faces, only: add_water_faces, add_plate_water
   use pecplas_model_plate_water_sides, only: plate_water_sides
   use pecplas_water_type, only: PLATE_FREE
   use pecplas_base_strings, only: decimal_text, itoa
   implicit none (type, external)
   private

   public :: start_phase, replay_phases, LINE_LEN

   !> Length of a line of the change list (results file).
   integer, parameter :: LINE_LEN = 160

   !> A copy of a steady pore pressure array (pore_forces).
   type :: steady_copy_t
      real(wp), allocatable :: v(:, :)
   end type steady_copy_t

contains

   !> Applies the phase of step `istep` (module header) to a phased run. On exit `fint`
   !> holds the internal forces of the state after the changes (the converged forces the
   !> step starts from), `refactorise` says whether the stiffness changed, `lines` says what
   !> changed, one line per change.
   subroutine start_phase(model, problem, istep, fint, refactorise, lines, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      integer, intent(in) :: istep
      real(wp), allocatable, intent(out) :: fint(:, :)
      logical, intent(out) :: refactorise
      character(len=LINE_LEN), allocatable, intent(out) :: lines(:)
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: eactive(:), jactive(:), dropped(:), held(:), pactive(:), &
         aactive(:)
      type(mesh_index_t) :: index
      integer :: c, j, p
      logical :: indexed, anchors_changed
      real(wp), allocatable :: reaction0(:, :)

      allocate (lines(0))
      refactorise = .false.
      ! the reactions the step starts from (after the first phase): the changes' share on the
      ! supported dofs is carried too, so that the reactions go from these linearly
      if (problem%phase%index > 0) then
         call phase_reactions(model, problem, reaction0, error)
         if (allocated(error)) return
      end if
      if (problem%phase%index == 0) then
         call first_phase(model, problem, error)
         if (allocated(error)) return
         lines = [character(len=LINE_LEN) :: 'initial procedure: '// &
            trim(PROCEDURE_NAMES(problem%phase%procedure))]
      end if
      indexed = .false.
      problem%phase%renumbered = .false.
      ! anchors: the prestress of the phase before ends, the step's anchor changes apply
      call start_anchors(model, problem%state, istep, anchors_changed, lines)
      if (anchors_changed) refactorise = .true.
      associate (step => model%steps(istep), st => problem%state)
         call water_changes(model, problem, istep, lines, error)
         if (allocated(error)) return
         do c = 1, size(step%changes)
            if (step%changes(c)%target == TARGET_ANCHORS) cycle
            associate (ch => step%changes(c))
               ! load patterns and supports: their activity (below) says what they do
               if (ch%target == TARGET_PATTERNS .or. ch%target == TARGET_SUPPORTS) then
                  call add_line(lines, trim(merge('activate  ', 'deactivate', &
                     ch%kind == CHANGE_ACTIVATE))//' '//trim(TARGET_NAMES(ch%target))//' '// &
                     ch%set_name)
                  cycle
               end if
               refactorise = .true.
               select case (ch%kind)
               case (CHANGE_DEACTIVATE)
                  if (ch%target == TARGET_PLATES) then
                     st%plates%sets(ch%set)%active = .false.
                     call add_line(lines, 'deactivate plate set '//ch%set_name)
                  else if (ch%target == TARGET_ELEMENTS) then
                     st%sets(ch%set)%active = .false.
                     call add_line(lines, 'deactivate element set '//ch%set_name)
                  else
                     st%joints%sets(ch%set)%active = .false.
                     call katona_off(problem, ch%set)
                     call add_line(lines, 'deactivate joint set '//ch%set_name)
                  end if
               case (CHANGE_ACTIVATE)
                  if (ch%target == TARGET_PLATES) then
                     call activate_plate(model, st%u, st%plates, ch%set, error)
                     if (allocated(error)) return
                     call add_line(lines, 'activate plate set '//ch%set_name// &
                        ' (free of forces, its strains counted from the current displacements)')
                  else if (ch%target == TARGET_ELEMENTS) then
                     call activate_set(model, problem, ch%set, ch%start == START_WISHED, error)
                     if (allocated(error)) return
                     if (ch%start == START_WISHED) then
                        call add_line(lines, 'activate element set '//ch%set_name// &
                           ' (wished in place: its initial stress)')
                     else
                        call add_line(lines, 'activate element set '//ch%set_name// &
                           ' (stress-free)')
                     end if
                  else
                     if (.not. indexed) call index%build(model)
                     indexed = .true.
                     if (model%joint_sets(ch%set)%is_katona()) then
                        call katona_on(problem, ch%set, ch%start == START_WISHED)
                        if (ch%start == START_WISHED) then
                           call add_line(lines, 'activate Katona contact set '//ch%set_name// &
                              ' (wished in place: the contact forces of the initial stresses, '// &
                              'in stick, its gaps and slips measured from the current '// &
                              'displacements)')
                        else
                           call add_line(lines, 'activate Katona contact set '//ch%set_name// &
                              ' (no contact force, in stick, its gaps and slips measured from '// &
                              'the current displacements)')
                        end if
                     else
                        call activate_joints(model, problem, index, ch%set, error)
                        if (allocated(error)) return
                        call add_line(lines, 'activate joint set '//ch%set_name// &
                           ' (from the initial stresses of the soil beside it)')
                     end if
                  end if
               case (CHANGE_MATERIAL)
                  call swap_material(model, st%sets(ch%set), ch%new)
                  call add_line(lines, 'change the material of element set '//ch%set_name// &
                     ' to '//ch%new_name)
               case (CHANGE_LAW)
                  st%joints%sets(ch%set)%law = ch%new
                  associate (js => st%joints%sets(ch%set))
                     deallocate (js%hist, js%hist_trial)
                     js%nstate = model%laws(ch%new)%law%nstate()
                     allocate (js%hist(js%nstate, js%npoint, size(js%sigma, 3)), source=0.0_wp)
                     allocate (js%hist_trial, source=js%hist)
                  end associate
                  call set_joint_stress(model, st%joints, ch%set, st%joints%sets(ch%set)%sigma, &
                     error)
                  if (allocated(error)) return
                  call add_line(lines, 'change the law of joint set '//ch%set_name//' to '// &
                     ch%new_name)
               end select
            end associate
         end do
         if (step%reset_displacements) then
            call reset_displacements(problem)
            call add_line(lines, 'reset displacements')
         end if
         ! supports installed or released: the equations follow
         if (allocated(problem%phase%supports_on)) then
            if (any(target_activity(model, TARGET_SUPPORTS, istep) .neqv. &
                    problem%phase%supports_on)) then
               call renumber(model, problem, target_activity(model, TARGET_SUPPORTS, istep), &
                  error)
               if (allocated(error)) return
               refactorise = .true.
            end if
         end if
         ! joint sets left hanging by a deactivation go with it
         eactive = st%sets%active
         allocate (jactive(0))
         if (allocated(st%joints%sets)) jactive = st%joints%sets%active
         call step_activity(model, istep, eactive, jactive, dropped)
         do j = 1, size(dropped)
            if (.not. dropped(j)) cycle
            st%joints%sets(j)%active = .false.
            call katona_off(problem, j)
            call add_line(lines, 'deactivate joint set '//model%joint_sets(j)%name// &
               ' (a node of it lost its last active element)')
         end do
         ! nodes no active element or joint holds: out of the system
         call set_orphans(model, problem, eactive, jactive)
         allocate (pactive(0))
         if (allocated(st%plates%sets)) pactive = st%plates%sets%active
         aactive = st%anchors%sets%active
         held = attached_nodes(model, eactive, jactive, pactive, aactive)
         ! the loads of the active sets
         call pattern_vectors(model, problem%system%rules, problem%system%pattern_force, &
            problem%system%pattern_disp, error, eactive, pactive, &
            level=model%water%level_at(istep))
         if (allocated(error)) return
         ! an inactive pattern loads nothing: a deactivated one's load is released below
         if (allocated(problem%phase%patterns_on)) then
            problem%phase%patterns_on = target_activity(model, TARGET_PATTERNS, istep)
            do p = 1, size(problem%phase%patterns_on)
               if (problem%phase%patterns_on(p)) cycle
               problem%system%pattern_force(:, :, p) = 0.0_wp
               problem%system%pattern_disp(:, :, p) = 0.0_wp
            end do
         end if
         call held_load(model, problem, eactive, model%water%level_at(istep), istep, error)
         if (allocated(error)) return
         call gravity_water(model, problem, eactive, model%water%level_at(istep), istep, error)
         if (allocated(error)) return
         ! the K0 state's own out-of-balance: held until the first nil step
         if (.not. problem%phase%released) then
            if (size(step%pattern) == 0 .and. size(step%changes) == 0) then
               problem%phase%released = .true.
               if (any(problem%phase%unbalanced /= 0.0_wp)) call add_line(lines, &
                  'release the out-of-balance of the initial (K0) state')
            else
               problem%system%initial_force = problem%system%initial_force + &
                  problem%phase%unbalanced
               ! a node no active element holds any more carries none of it: its own share of
               ! the K0 out-of-balance (not zero where the K0 stress is not linear across an
               ! element, e.g. one that a phreatic level crosses) would stay in its residual,
               ! which no internal force of its can balance
               do p = 1, size(held)
                  if (.not. held(p)) problem%system%initial_force(:, p) = 0.0_wp
               end do
            end if
         end if
         ! the out-of-balance of the changes, carried along the step
         allocate (fint, mold=problem%system%initial_force)
         call internal_forces(model, problem%system%rules, st%u, st, fint, error)
         if (allocated(error)) return
         call st%rollback()
         if (refactorise) problem%linear%tangent_factorised = .false.
         problem%phase%carried = fint - problem%system%initial_force
         ! the contact forces of Katona doublets act as internal forces
         if (problem%katona%active) call add_contact_forces(problem%katona, problem%katona%f, &
            problem%phase%carried)
         do p = 1, size(st%factors)
            problem%phase%carried = problem%phase%carried - &
               st%factors(p)*problem%system%pattern_force(:, :, p)
         end do
         ! on a supported dof the reaction is balanced (no out-of-balance there) but leaves
         ! its value at the step start over the step: what changed there is carried
         if (allocated(reaction0)) then
            where (problem%system%dofs%eq == 0) problem%phase%carried = &
               problem%phase%carried - reaction0
         else
            where (problem%system%dofs%eq == 0) problem%phase%carried = 0.0_wp
         end if
         do p = 1, size(held)
            if (.not. held(p)) problem%phase%carried(:, p) = 0.0_wp
         end do
      end associate
      problem%phase%index = istep
   end subroutine start_phase

   !> The reactions of the converged state before a phase's changes, F_int - F_ext on the
   !> supported dofs (zero on the free ones), F_ext the held load and the patterns at their
   !> factors (the carried out-of-balance of the step before is released at its end).
   subroutine phase_reactions(model, problem, reaction, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      real(wp), allocatable, intent(out) :: reaction(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: p
      allocate (reaction, mold=problem%system%initial_force)
      call internal_forces(model, problem%system%rules, problem%state%u, problem%state, &
         reaction, error)
      if (allocated(error)) return
      call problem%state%rollback()
      reaction = reaction - problem%system%initial_force
      if (problem%katona%active) call add_contact_forces(problem%katona, problem%katona%f, &
         reaction)
      do p = 1, size(problem%state%factors)
         reaction = reaction - problem%state%factors(p)*problem%system%pattern_force(:, :, p)
      end do
      where (problem%system%dofs%eq > 0) reaction = 0.0_wp
   end subroutine phase_reactions

   !> The phases of steps 1 to k applied again to a problem just set up (a restart: its
   !> state is then read over the one they leave).
   subroutine replay_phases(model, problem, k, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      integer, intent(in) :: k
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: fint(:, :)
      character(len=LINE_LEN), allocatable :: lines(:)
      logical :: refactorise
      integer :: i
      do i = 1, k
         call start_phase(model, problem, i, fint, refactorise, lines, error)
         if (allocated(error)) return
      end do
   end subroutine replay_phases

   !> Before the first step: what each set holds, and how the initial state came about.
   subroutine first_phase(model, problem, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: f(:, :)
      integer :: s, i, kind, nset, nh
      nset = size(model%mesh%esets)
      allocate (problem%phase%hold(nset), source=HOLD_NONE)
      allocate (problem%phase%homogeneous(2, nodal_columns(model), 0))
      allocate (problem%phase%unbalanced(2, nodal_columns(model)), source=0.0_wp)
      problem%phase%procedure = PROCEDURE_NONE
      if (allocated(model%patterns)) then
         do i = 1, size(model%patterns)
            if (model%patterns(i)%kind == LOAD_GRAVITY) problem%phase%procedure = PROCEDURE_GRAVITY
         end do
      end if
      if (.not. allocated(model%initial_stresses)) then
         problem%phase%water_pattern = gravity_pattern(model)
         call k0_unbalance(model, problem, error)
         return
      end if
      if (size(model%initial_stresses) == 0) then
         problem%phase%water_pattern = gravity_pattern(model)
         call k0_unbalance(model, problem, error)
         return
      end if
      problem%phase%procedure = PROCEDURE_K0
      nh = 0
      do s = 1, nset
         ! the last entry that covers the set says how it was made
         kind = 0
         do i = 1, size(model%initial_stresses)
            associate (init => model%initial_stresses(i))
               if (init%eset /= 0 .and. init%eset /= s) cycle
               kind = merge(1, 2, init%kind == 'GEOSTATIC')
            end associate
         end do
         select case (kind)
         case (1)
            ! geostatic: the set's weight (y up)
            problem%phase%hold(s) = HOLD_WEIGHT
         case (2)
            ! homogeneous: the nodal forces of its own stress
            allocate (f(2, nodal_columns(model)))
            call own_forces(model, problem, s, f, error)
            if (allocated(error)) return
            nh = nh + 1
            problem%phase%homogeneous = reshape([problem%phase%homogeneous, f], &
               [2, nodal_columns(model), nh])
            problem%phase%hold(s) = nh
            deallocate (f)
         end select
      end do
      call k0_unbalance(model, problem, error)
   end subroutine first_phase

   !> The out-of-balance of the K0 state (phase_state_t%unbalanced): the internal and
   !> contact forces of the initial state with every set and joint active, less what the
   !> sets hold; then the Katona doublets of the joint sets not active at the start go off.
   subroutine k0_unbalance(model, problem, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: jkeep(:), all_on(:)
      real(wp), allocatable :: f(:, :), u(:, :)
      integer :: j
      allocate (jkeep(0))
      if (allocated(problem%state%joints%sets)) jkeep = problem%state%joints%sets%active
      allocate (all_on(size(problem%state%sets)), source=.true.)
      allocate (f, mold=problem%system%initial_force)
      call forces_at_start(model, problem, all_on, .true., f, error)
      if (allocated(error)) return
      if (problem%katona%active) call add_contact_forces(problem%katona, problem%katona%f, f)
      ! (at the initial displacements, zero, as forces_at_start: a restart replays this with
      ! its restored displacements in place, and the forces of the pore pressures held under
      ! gravity loading are computed from a state at them, to roundoff)
      u = problem%state%u
      problem%state%u = 0.0_wp
      call held_load(model, problem, all_on, model%water%level_at(1), 0, error, &
         all_joints=.true.)
      problem%state%u = u
      if (allocated(error)) return
      ! on the free equations: at a support it is the support's reaction to the K0 state
      problem%phase%unbalanced = f - problem%system%initial_force
      problem%phase%base_reaction = problem%phase%unbalanced
      if (problem%katona%active) problem%phase%katona_f0 = problem%katona%f
      where (problem%system%dofs%eq == 0) problem%phase%unbalanced = 0.0_wp
      where (problem%system%dofs%eq > 0) problem%phase%base_reaction = 0.0_wp
      ! the scale of the out-of-balance (pecplas_solve_held_warning): the held load's forces
      associate (n => model%mesh%nnode())
         problem%phase%held0_norm = norm2(pack(problem%system%initial_force(:, 1:n), &
            problem%system%dofs%eq(:, 1:n) > 0))
      end associate
      do j = 1, size(jkeep)
         if (.not. jkeep(j)) call katona_off(problem, j)
      end do
   end subroutine k0_unbalance

   !> The held load (problem%system%initial_force): what the active sets hold.
   !> `level`: the phreatic level in force (the weights below it are gamma_sat); `istep`:
   !> the step whose *PLATE_WATER sides are in force (0: those before the first step).
   !> Under gravity loading with water (phase_state_t%water_pattern > 0) it holds the
   !> forces of the steady pore pressures instead of the water on the faces, with the joint
   !> sets active now or, `all_joints`, all (the K0 state's out-of-balance is measured so).
   subroutine held_load(model, problem, eactive, level, istep, error, all_joints)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      logical, intent(in) :: eactive(:)
      integer, intent(in) :: level, istep
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: all_joints
      logical, allocatable :: jon(:), pon(:)
      real(wp), allocatable :: f(:, :)
      integer :: s
      problem%system%initial_force = 0.0_wp
      do s = 1, size(eactive)
         if (.not. eactive(s)) cycle
         if (problem%phase%hold(s) == HOLD_WEIGHT) then
            call add_body_force(model, problem%system%rules, s, [0.0_wp, -1.0_wp], .true., &
               problem%system%initial_force, error, level)
            if (allocated(error)) return
         else if (problem%phase%hold(s) > 0) then
            problem%system%initial_force = problem%system%initial_force + &
               problem%phase%homogeneous(:, :, problem%phase%hold(s))
         end if
      end do
      ! gravity loading: the forces of the steady pore pressures are held (they cancel the
      ! pore pressures in the internal forces) and the water comes in with the gravity
      ! pattern (gravity_water)
      if (problem%phase%water_pattern > 0) then
         if (level > 0) then
            allocate (f, mold=problem%system%initial_force)
            call pore_forces(model, problem, eactive, all_joints, f, error)
            if (allocated(error)) return
            problem%system%initial_force = problem%system%initial_force + f
         end if
         return
      end if
      ! the water standing on the free faces and on the plates (by their *PLATE_WATER modes)
      if (model%water%used() .and. level > 0) then
         allocate (jon(0), pon(0))
         if (allocated(problem%state%joints%sets)) jon = problem%state%joints%sets%active
         if (allocated(problem%state%plates%sets)) pon = problem%state%plates%sets%active
         call add_water_faces(model, eactive, jon, level, problem%system%initial_force, error, &
            pon)
         if (allocated(error)) return
         call add_plate_water(model, pon, eactive, jon, level, istep, &
            problem%system%initial_force)
      end if
   end subroutine held_load

   !> Nodal forces of the converged stresses of set s alone.
   subroutine own_forces(model, problem, s, f, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      integer, intent(in) :: s
      real(wp), intent(out) :: f(:, :)
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: eon(:)
      allocate (eon(size(problem%state%sets)), source=.false.)
      eon(s) = .true.
      call forces_at_start(model, problem, eon, .false., f, error)
   end subroutine own_forces

   !> The GRAVITY pattern the water comes in with under gravity loading: the first one in a
   !> model with groundwater and no *INITIAL_STRESS (0: none).
   integer function gravity_pattern(model) result(k)
      type(model_t), intent(in) :: model
      integer :: i
      k = 0
      if (.not. model%water%used() .or. .not. allocated(model%patterns)) return
      do i = 1, size(model%patterns)
         if (model%patterns(i)%kind == LOAD_GRAVITY) then
            k = i
            return
         end if
      end do
   end function gravity_pattern

   !> Gravity loading with groundwater (doc/theory.md, Groundwater): the water comes in with
   !> the weight. The held load holds the forces F_p of the steady pore pressures (held_load),
   !> and the gravity pattern's vector gets the water on the free faces and on the plates
   !> less F_p, so that at pattern factor lambda the effective stresses carry lambda times
   !> the effective weight and the total stresses (sigma' - lambda p m) lambda times the
   !> total weight and the water on the faces, as if the pore pressures rose with the weight.
   !> A phase whose gravity pattern is off holds the water on the faces as under K0.
   subroutine gravity_water(model, problem, eactive, level, istep, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      logical, intent(in) :: eactive(:)
      integer, intent(in) :: level, istep
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: jon(:), pon(:)
      real(wp), allocatable :: w(:, :)
      integer :: k
      k = problem%phase%water_pattern
      if (k <= 0 .or. level <= 0) return
      allocate (w, mold=problem%system%initial_force)
      w = 0.0_wp
      allocate (jon(0), pon(0))
      if (allocated(problem%state%joints%sets)) jon = problem%state%joints%sets%active
      if (allocated(problem%state%plates%sets)) pon = problem%state%plates%sets%active
      call add_water_faces(model, eactive, jon, level, w, error, pon)
      if (allocated(error)) return
      call add_plate_water(model, pon, eactive, jon, level, istep, w)
      if (allocated(problem%phase%patterns_on)) then
         if (.not. problem%phase%patterns_on(k)) then
            ! no weight coming in: the water on the faces held, F_p's hold released
            problem%system%initial_force = w
            return
         end if
      end if
      problem%system%pattern_force(:, :, k) = problem%system%pattern_force(:, :, k) + w - &
         problem%system%initial_force
   end subroutine gravity_water

   !> The internal forces f of the steady pore pressures alone (the total-stress part -p m
   !> of the massif points and p of the joint points) at the current displacements, with
   !> the element sets `eon` active and the joint sets active now or, `all_joints`, all:
   !> the forces of the state less those of the same state without steady pore pressures.
   subroutine pore_forces(model, problem, eon, all_joints, f, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      logical, intent(in) :: eon(:)
      logical, intent(in), optional :: all_joints
      real(wp), intent(out) :: f(:, :)
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: ekeep(:), jkeep(:)
      real(wp), allocatable :: f0(:, :)
      type(steady_copy_t), allocatable :: keep(:), jpore(:), jfix(:)
      integer :: s
      ekeep = problem%state%sets%active
      allocate (jkeep(0))
      if (allocated(problem%state%joints%sets)) then
         jkeep = problem%state%joints%sets%active
         if (present(all_joints)) then
            if (all_joints) problem%state%joints%sets%active = .true.
         end if
      end if
      problem%state%sets%active = eon
      call internal_forces(model, problem%system%rules, problem%state%u, problem%state, f, &
         error)
      if (allocated(error)) return
      call problem%state%rollback()
      ! the same without the steady pore pressures
      allocate (keep(size(problem%state%sets)), jpore(size(jkeep)), jfix(size(jkeep)))
      do s = 1, size(problem%state%sets)
         if (.not. problem%state%sets(s)%pore%on()) cycle
         keep(s)%v = problem%state%sets(s)%pore%steady
         problem%state%sets(s)%pore%steady = 0.0_wp
      end do
      do s = 1, size(jkeep)
         if (.not. allocated(problem%state%joints%sets(s)%pore)) cycle
         jpore(s)%v = problem%state%joints%sets(s)%pore
         problem%state%joints%sets(s)%pore = 0.0_wp
         if (.not. allocated(problem%state%joints%sets(s)%pore_fix)) cycle
         jfix(s)%v = problem%state%joints%sets(s)%pore_fix
         problem%state%joints%sets(s)%pore_fix = 0.0_wp
      end do
      allocate (f0, mold=f)
      call internal_forces(model, problem%system%rules, problem%state%u, problem%state, f0, &
         error)
      do s = 1, size(problem%state%sets)
         if (allocated(keep(s)%v)) problem%state%sets(s)%pore%steady = keep(s)%v
      end do
      do s = 1, size(jkeep)
         if (allocated(jpore(s)%v)) problem%state%joints%sets(s)%pore = jpore(s)%v
         if (allocated(jfix(s)%v)) problem%state%joints%sets(s)%pore_fix = jfix(s)%v
      end do
      problem%state%sets%active = ekeep
      if (size(jkeep) > 0) problem%state%joints%sets%active = jkeep
      call problem%state%rollback()
      if (allocated(error)) return
      f = f - f0
   end subroutine pore_forces

   !> Internal forces of the stresses held in the state at zero displacement, with the element
   !> sets `eon` and every joint set (`joints_on`) or none active; the activity and the
   !> trial state are put back as they were.
   subroutine forces_at_start(model, problem, eon, joints_on, f, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      logical, intent(in) :: eon(:), joints_on
      real(wp), intent(out) :: f(:, :)
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: ekeep(:), jkeep(:)
      real(wp), allocatable :: u0(:, :)
      ekeep = problem%state%sets%active
      allocate (jkeep(0))
      if (allocated(problem%state%joints%sets)) then
         jkeep = problem%state%joints%sets%active
         problem%state%joints%sets%active = joints_on
      end if
      problem%state%sets%active = eon
      allocate (u0, mold=problem%state%u)
      u0 = 0.0_wp
      call internal_forces(model, problem%system%rules, u0, problem%state, f, error)
      problem%state%sets%active = ekeep
      if (size(jkeep) > 0) problem%state%joints%sets%active = jkeep
      call problem%state%rollback()
   end subroutine forces_at_start

   !> Element set s becomes active: stress-free or with its initial stress, no history, its
   !> strains those of the current displacements.
   subroutine activate_set(model, problem, s, wished, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      integer, intent(in) :: s
      logical, intent(in) :: wished
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: d(NCOMP, NCOMP)
      integer :: e, g
      associate (st => problem%state%sets(s))
         st%active = .true.
         st%stress = 0.0_wp
         if (wished) call initial_set_stress(model, problem%system%rules, s, st%stress)
         st%hist = 0.0_wp
         call set_strains(model, problem, s, st%strain, error)
         if (allocated(error)) return
         st%stress_trial = st%stress
         st%strain_trial = st%strain
         st%hist_trial = st%hist
         if (allocated(st%tangent)) then
            call model%materials(set_material(model, s, st))%m%elastic_tangent(d)
            do e = 1, size(st%tangent, 4)
               do g = 1, size(st%tangent, 3)
                  st%tangent(:, :, g, e) = d
               end do
            end do
         end if
      end associate
   end subroutine activate_set

   !> Strains (4, ngauss, nel) of massif set s at the converged displacements.
   subroutine set_strains(model, problem, s, strain, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      integer, intent(in) :: s
      real(wp), intent(out) :: strain(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: xe(2, MAX_NODES), ue(2*MAX_NODES), dndx(2, MAX_NODES), hr(MAX_NODES), dvol
      integer :: e, g, k, nn
      associate (set => model%mesh%esets(s), rule => problem%system%rules(s))
         nn = rule%nnode
         do e = 1, size(set%conn, 2)
            do k = 1, nn
               xe(:, k) = model%mesh%x(:, set%conn(k, e))
               ue(2*k - 1:2*k) = problem%state%u(:, set%conn(k, e))
            end do
            do g = 1, size(strain, 2)
               call massif_gauss_derivs(rule, g, model%analysis%kind, model%analysis%thickness, &
                  xe(:, 1:nn), dndx(:, 1:nn), hr(1:nn), dvol, error)
               if (allocated(error)) return
               call point_strain(nn, dndx(:, 1:nn), hr(1:nn), ue(1:2*nn), strain(:, g, e))
            end do
         end do
      end associate
   end subroutine set_strains

   !> Joint set js becomes active: stresses from the soil beside it, relative displacements
   !> from the current displacements.
   subroutine activate_joints(model, problem, index, js, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(mesh_index_t), intent(in) :: index
      integer, intent(in) :: js
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t), allocatable :: pts(:)
      real(wp), allocatable :: ue(:)
      integer :: e, ip
      associate (set => model%joint_sets(js), st => problem%state%joints%sets(js))
         st%active = .true.
         st%sigma = 0.0_wp
         call initial_joint_set_stress(model, index, problem%state, js, error)
         if (allocated(error)) return
         call joint_set_element(set, elem, error)
         if (allocated(error)) return
         allocate (pts(elem%npoint()), ue(2*size(set%conn, 1)))
         do e = 1, size(set%conn, 2)
            call joint_element_points(model, set, elem, e, pts, error)
            if (allocated(error)) return
            ue = reshape(problem%state%u(:, set%conn(:, e)), [size(ue)])
            do ip = 1, size(pts)
               st%eps(:, ip, e) = joint_strain(pts(ip), ue)
            end do
         end do
         st%eps_trial = st%eps
         st%sigma_trial = st%sigma
         st%hist_trial = st%hist
      end associate
   end subroutine activate_joints

   !> The Katona doublets of joint set js (if any) go open, without force, and stay so.
   subroutine katona_off(problem, js)
      type(problem_t), intent(inout) :: problem
      integer, intent(in) :: js
      associate (kt => problem%katona)
         if (.not. kt%active) return
         where (kt%set_of == js)
            kt%off = .true.
            kt%mode = MODE_OPEN
            kt%sgn = 0
         end where
         where (spread(kt%set_of == js, 1, 2)) kt%f = 0.0_wp
         call kt%begin_increment()
      end associate
   end subroutine katona_off

   !> The Katona doublets of joint set js come back: in stick, bond intact, their gap and
   !> slip measured from the current relative displacements; without force, or (`wished`)
   !> with the contact forces of the initial stresses (the normal and shear stress of the
   !> soil beside them, as at the start of a run).
   subroutine katona_on(problem, js, wished)
      type(problem_t), intent(inout) :: problem
      integer, intent(in) :: js
      logical, intent(in) :: wished
      real(wp), allocatable :: z(:, :)
      associate (kt => problem%katona)
         if (.not. kt%active) return
         allocate (z(2, kt%nd))
         call relative_displacements(kt, problem%state%u, z)
         where (kt%set_of == js)
            kt%off = .false.
            kt%mode = MODE_STICK
            kt%sgn = 0
            kt%broken = .false.
            kt%gap0 = z(1, :)
            kt%anchor = z(2, :)
         end where
         where (spread(kt%set_of == js, 1, 2))
            kt%f = 0.0_wp
            kt%z = z
         end where
         if (wished .and. allocated(problem%phase%katona_f0)) then
            where (spread(kt%set_of == js, 1, 2)) kt%f = problem%phase%katona_f0
         end if
         call kt%begin_increment()
      end associate
   end subroutine katona_on

   !> Element set state st takes material m: stresses kept, history restarted (zero, of
   !> the new size), tangents stored when m has no constant tangent (its elastic one).
   subroutine swap_material(model, st, m)
      type(model_t), intent(in) :: model
      type(set_state_t), intent(inout) :: st
      integer, intent(in) :: m
      real(wp) :: d(NCOMP, NCOMP)
      integer :: nel, e, g
      associate (mat => model%materials(m)%m)
         st%material = m
         nel = size(st%stress, 3)
         deallocate (st%hist, st%hist_trial)
         allocate (st%hist(mat%nstate(), st%ngauss, nel), source=0.0_wp)
         allocate (st%hist_trial, source=st%hist)
         if (allocated(st%tangent)) deallocate (st%tangent)
         if (.not. mat%constant_tangent()) then
            call mat%elastic_tangent(d)
            allocate (st%tangent(NCOMP, NCOMP, st%ngauss, nel))
            do e = 1, nel
               do g = 1, st%ngauss
                  st%tangent(:, :, g, e) = d
               end do
            end do
         end if
      end associate
   end subroutine swap_material

   !> The equations numbered again with the named supports `son` active (pecplas_fe_dofs):
   !> a dof a support now holds stays where it is (phase_state_t%held_u); a released dof
   !> becomes an equation, and the reaction the support exerted there is part of the
   !> phase's carried out-of-balance (start_phase), released over the step. The solvers
   !> start afresh on the new system (analysis and factorisation).
   subroutine renumber(model, problem, son, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      logical, intent(in) :: son(:)
      type(error_t), allocatable, intent(out) :: error
      type(dofs_t) :: old
      old = problem%system%dofs
      call new_dofs(model, problem%system%dofs, error, son)
      if (allocated(error)) return
      associate (eq => problem%system%dofs%eq, ph => problem%phase)
         where (eq == 0 .and. old%eq > 0) ph%held_u = problem%state%u
         where (eq > 0) ph%held_u = 0.0_wp
         ! the K0 reactions and out-of-balance keep to their kind of equation
         if (allocated(ph%base_reaction)) then
            where (eq > 0) ph%base_reaction = 0.0_wp
         end if
         if (allocated(ph%unbalanced)) then
            where (eq == 0) ph%unbalanced = 0.0_wp
         end if
         ph%supports_on = son
         ph%renumbered = .true.
      end associate
      associate (lin => problem%linear)
         if (allocated(lin%solver)) then
            call lin%solver%free()
            deallocate (lin%solver)
         end if
         if (allocated(lin%tsolver)) then
            call lin%tsolver%free()
            deallocate (lin%tsolver)
         end if
         call lin%kbuild%forget()
         lin%k_owner = 0
         lin%tangent_factorised = .false.
      end associate
   end subroutine renumber

   !> Displacements back to zero; the strains and joint relative displacements measured
   !> from them too. Stresses and histories stay.
   subroutine reset_displacements(problem)
      type(problem_t), intent(inout) :: problem
      integer :: s
      problem%state%u = 0.0_wp
      if (allocated(problem%phase%held_u)) problem%phase%held_u = 0.0_wp
      do s = 1, size(problem%state%sets)
         problem%state%sets(s)%strain = 0.0_wp
         problem%state%sets(s)%strain_trial = 0.0_wp
      end do
      if (.not. allocated(problem%state%joints%sets)) return
      do s = 1, size(problem%state%joints%sets)
         problem%state%joints%sets(s)%eps = 0.0_wp
         problem%state%joints%sets(s)%eps_trial = 0.0_wp
      end do
   end subroutine reset_displacements

   !> Groundwater at the start of step istep: the steady pore pressures under the level in
   !> force, and the excess pore pressures set to zero when the step says so (*CHANGE_WATER).
   subroutine water_changes(model, problem, istep, lines, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      integer, intent(in) :: istep
      character(len=LINE_LEN), allocatable, intent(inout) :: lines(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: k, s, side
      if (.not. model%water%used()) return
      k = model%water%level_at(istep)
      call set_steady_pressures(model, problem%system%rules, problem%state, k, error)
      if (allocated(error)) return
      if (k /= model%water%level_at(istep - 1) .or. istep == 1) then
         if (k > 0) then
            call add_line(lines, 'phreatic level '//model%water%levels(k)%name// &
               ' (gamma_w = '//decimal_text(model%water%levels(k)%gamma_w, 6)//')')
         else
            call add_line(lines, 'no phreatic level (no steady pore pressure)')
         end if
      end if
      if (allocated(model%water%step_reset)) then
         if (model%water%step_reset(istep)) then
            call reset_excess(problem%state)
            call add_line(lines, 'excess pore pressures set to zero')
         end if
      end if
      ! *PLATE_WATER of the step: the water's pressure on a plate face comes or goes
      if (allocated(model%water%plate_side)) then
         do s = 1, size(model%water%plate_side)
            side = model%water%plate_side_at(s, istep)
            if (side == PLATE_FREE) then
               ! on the free faces: they change with the sets the step activates or removes
               call free_water_line(model, s, istep, lines)
               cycle
            end if
            if (side == model%water%plate_side_at(s, istep - 1)) cycle
            if (side == 0) then
               call add_line(lines, 'no water on plate set '//model%plates(s)%name)
            else
               call add_line(lines, 'water on the '//trim(merge('left ', 'right', side > 0))// &
                  ' face of plate set '//model%plates(s)%name)
            end if
         end do
      end if
   end subroutine water_changes

   !> The progress line of plate set s whose water stands on its free faces (*PLATE_WATER
   !> FREE) in the first step and when those faces in step istep differ from the step
   !> before's: how many of its elements have the water on the left face only, how many on
   !> the right only.
   subroutine free_water_line(model, s, istep, lines)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s, istep
      character(len=LINE_LEN), allocatable, intent(inout) :: lines(:)
      integer, allocatable :: now(:), before(:)
      logical :: changed
      now = plate_water_sides(model, s, istep)
      before = plate_water_sides(model, s, istep - 1)
      changed = any(now /= before) .or. istep == 1 .or. &
         model%water%plate_side_at(s, istep - 1) /= PLATE_FREE
      if (.not. changed) return
      call add_line(lines, 'free faces of plate set '//model%plates(s)%name// &
         ' (no soil against them; water acts below the level): '// &
         itoa(count(now > 0))//' of its '//itoa(size(now))//' elements on the left, '// &
         itoa(count(now < 0))//' on the right')
   end subroutine free_water_line

   subroutine add_line(lines, text)
      character(len=LINE_LEN), allocatable, intent(inout) :: lines(:)
      character(len=*), intent(in) :: text
      lines = [character(len=LINE_LEN) :: lines, text]
   end subroutine add_line

end module pecplas_phases_start
