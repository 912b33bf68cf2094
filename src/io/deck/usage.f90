!> Warnings about parts of a read deck that do nothing: a load pattern no step uses, a
!> material no section uses, a node or edge set nothing refers to, a step that leaves every
!> load factor where it was; and initial stresses that are tensile (a geostatic surface
!> below the top of its set, a homogeneous state with a tensile principal stress) or zero (a
!> geostatic state of a material without unit weight).
!> Each warning names the defining line (pecplas_base_warnings); none changes the run.
module pecplas_io_deck_usage
   use pecplas_base_kinds, only: wp
   use pecplas_io_text_fields, only: same_name, upper
   use pecplas_io_deck_state, only: deck_state_t
   use pecplas_model_type, only: model_t
   use pecplas_model_adapt_request, only: goal_spec_t, parse_goal_spec
   use pecplas_model_phases, only: CHANGE_MATERIAL
   use pecplas_io_text_fields, only: field_t, split_fields
   implicit none (type, external)
   private

   public :: check_usage

contains

   subroutine check_usage(state, model)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      call unused_patterns(state, model)
      call unused_materials(state, model)
      call unused_sets(state, model)
      call idle_steps(model)
      call tensile_initial(model)
   end subroutine check_usage

   subroutine unused_patterns(state, model)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      integer :: p, s
      logical :: used
      if (.not. allocated(state%patterns)) return
      do p = 1, size(state%patterns)
         used = .false.
         do s = 1, size(model%steps)
            if (any(model%steps(s)%pattern == p)) used = .true.
         end do
         if (.not. used) call warn_at(state, model, state%patterns(p)%at, "load pattern '"// &
            state%patterns(p)%name//"' is used by no *STEP: it is never applied")
      end do
   end subroutine unused_patterns

   subroutine unused_materials(state, model)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      integer :: m, k
      logical :: used
      if (.not. allocated(model%materials) .or. .not. allocated(state%material_at)) return
      do m = 1, min(size(model%materials), size(state%material_at))
         used = .false.
         if (allocated(state%sections)) then
            do k = 1, size(state%sections)
               if (same_name(state%sections(k)%material, model%materials(m)%m%name)) &
                  used = .true.
            end do
         end if
         ! or by a phase's *CHANGE_MATERIAL
         if (allocated(model%steps)) then
            do k = 1, size(model%steps)
               if (.not. allocated(model%steps(k)%changes)) cycle
               if (any(model%steps(k)%changes%new == m .and. &
                       model%steps(k)%changes%kind == CHANGE_MATERIAL)) used = .true.
            end do
         end if
         if (.not. used) call warn_at(state, model, state%material_at(m), "material '"// &
            model%materials(m)%m%name//"' is used by no *SECTION nor *CHANGE_MATERIAL")
      end do
   end subroutine unused_materials

   !> Node sets are used by *BOUNDARY and *LOAD lines, by *STEP's NODE= and by *ADAPT's GOAL;
   !> edge sets by *LOAD and *JOINTS.
   subroutine unused_sets(state, model)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      integer :: k
      if (allocated(state%nsets)) then
         do k = 1, size(state%nsets)
            if (.not. named(state, state%nsets(k)%name, .false.) .and. &
                .not. named_by_option(state, model, state%nsets(k)%name) .and. &
                .not. named_by_anchor(state, state%nsets(k)%name)) &
               call warn_at(state, model, state%nsets(k)%at, "node set '"// &
               state%nsets(k)%name//"' is used by no *BOUNDARY, *LOAD, *STEP (NODE=), "// &
               '*ANCHOR or *ADAPT (GOAL=) line')
         end do
      end if
      if (allocated(state%edge_sets)) then
         do k = 1, size(state%edge_sets)
            if (.not. named(state, state%edge_sets(k)%name, .true.)) call warn_at(state, &
               model, state%edge_sets(k)%at, "edge set '"//state%edge_sets(k)%name// &
               "' is used by no *LOAD or *JOINTS line")
         end do
      end if
   end subroutine unused_sets

   !> True when a *BOUNDARY or *LOAD item (or, for edges, a *JOINTS EDGES=) names `name`.
   logical function named(state, name, edges) result(used)
      type(deck_state_t), intent(in) :: state
      character(len=*), intent(in) :: name
      logical, intent(in) :: edges
      integer :: i, p
      used = .false.
      if (allocated(state%boundary)) then
         do i = 1, state%nboundary
            if (same_name(state%boundary(i)%target, name)) used = .true.
         end do
      end if
      if (allocated(state%patterns)) then
         do p = 1, size(state%patterns)
            do i = 1, state%patterns(p)%n
               if (same_name(state%patterns(p)%items(i)%target, name)) used = .true.
            end do
         end do
      end if
      ! a *PLATE's NODES= or EDGES=
      if (allocated(state%plate_sets)) then
         do i = 1, size(state%plate_sets)
            if (edges .and. allocated(state%plate_sets(i)%edges)) then
               if (same_name(state%plate_sets(i)%edges, name)) used = .true.
            end if
            if (.not. edges .and. allocated(state%plate_sets(i)%nodes)) then
               if (same_name(state%plate_sets(i)%nodes, name)) used = .true.
            end if
         end do
      end if
      if (edges .and. allocated(state%joint_sets)) then
         do i = 1, size(state%joint_sets)
            if (allocated(state%joint_sets(i)%edges)) then
               if (same_name(state%joint_sets(i)%edges, name)) used = .true.
            end if
         end do
      end if
   end function named

   !> True when a data line of an *ANCHOR names `name`.
   logical function named_by_anchor(state, name) result(used)
      type(deck_state_t), intent(in) :: state
      character(len=*), intent(in) :: name
      type(field_t), allocatable :: f(:)
      integer :: a, i, k
      used = .false.
      if (.not. allocated(state%anchors)) return
      do a = 1, size(state%anchors)
         do i = 1, size(state%anchors(a)%where)
            call split_fields(state%lines%text(state%anchors(a)%where(i)), f)
            do k = 1, size(f)
               if (same_name(f(k)%s, name)) used = .true.
            end do
         end do
      end do
   end function named_by_anchor

   !> True when a *STEP's NODE= or *ADAPT's GOAL= (node:SET:d, reaction:SET) names `name`.
   logical function named_by_option(state, model, name) result(used)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      type(goal_spec_t) :: goal
      character(len=:), allocatable :: msg
      integer :: s
      used = .false.
      if (allocated(state%steps)) then
         do s = 1, size(state%steps)
            if (allocated(state%steps(s)%node)) then
               if (same_name(state%steps(s)%node, name)) used = .true.
            end if
         end do
      end if
      if (model%adapt%given) then
         call parse_goal_spec(model%adapt%goal, goal, msg)
         if (allocated(goal%set)) then
            if (same_name(goal%set, name)) used = .true.
         end if
      end if
   end function named_by_option

   !> Factors start at 0; a step sets those it names. A step that names only patterns at
   !> the factor they already have applies nothing.
   subroutine idle_steps(model)
      type(model_t), intent(inout) :: model
      real(wp), allocatable :: factor(:)
      integer :: s
      logical :: changes
      if (.not. allocated(model%patterns) .or. .not. allocated(model%steps)) return
      allocate (factor(size(model%patterns)))
      factor = 0.0_wp
      do s = 1, size(model%steps)
         associate (st => model%steps(s))
            changes = any(factor(st%pattern) /= st%target)
            factor(st%pattern) = st%target
            ! a phase (doc/deck.md, Phases) changes the model; a nil step restores equilibrium
            if (size(st%pattern) == 0 .or. st%reset_displacements) changes = .true.
            if (allocated(st%changes)) then
               if (size(st%changes) > 0) changes = .true.
            end if
            if (.not. changes) call model%warnings%add("step '"//st%name//"' changes no "// &
               'load factor (every pattern it names is already at its target): it applies '// &
               'nothing', st%file, st%line)
         end associate
      end do
   end subroutine idle_steps

   subroutine tensile_initial(model)
      type(model_t), intent(inout) :: model
      real(wp) :: top, smax, centre, radius
      integer :: i
      character(len=32) :: b1, b2
      if (.not. allocated(model%initial_stresses)) return
      do i = 1, size(model%initial_stresses)
         associate (init => model%initial_stresses(i))
            if (init%kind == 'GEOSTATIC') then
               if (init%surcharge == 0.0_wp .and. weightless(model, init%eset)) &
                  call model%warnings%add("geostatic initial stress of set '"//init%set// &
                  "' is zero everywhere: its material has no unit weight (GAMMA, or "// &
                  'GAMMA_UNSAT/GAMMA_SAT, is 0) and q_surface is 0, so a frictional soil '// &
                  'starts without strength (give GAMMA on *MATERIAL)', init%file, init%line)
               top = set_top(model, init%eset)
               if (init%surface < top .and. init%surcharge <= 0.0_wp) then
                  write (b1, '(g0.6)') init%surface
                  write (b2, '(g0.6)') top
                  call model%warnings%add('geostatic y_surface = '//trim(b1)//' is below '// &
                     "the top of set '"//init%set//"' (y = "//trim(b2)//'): the initial '// &
                     'stress above y_surface is tensile (sigma_v = q + gamma (y_surface - y) '// &
                     '< 0)', init%file, init%line)
               end if
            else if (upper(init%kind) == 'HOMOGENEOUS') then
               centre = 0.5_wp*(init%stress(1) + init%stress(2))
               radius = hypot(0.5_wp*(init%stress(1) - init%stress(2)), init%stress(4))
               smax = max(centre + radius, init%stress(3))
               if (smax > 0.0_wp) then
                  write (b1, '(g0.6)') smax
                  call model%warnings%add('initial stress is tensile: largest principal '// &
                     'stress '//trim(b1)//' > 0 (tension is positive; soil is usually '// &
                     'compressed)', init%file, init%line)
               end if
            end if
         end associate
      end do
   end subroutine tensile_initial

   !> True when no element set covered by `s` (0: every set) has a unit weight: neither its
   !> material's GAMMA nor, with groundwater, its saturated unit weight.
   logical function weightless(model, s)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      integer :: k, m
      weightless = .true.
      if (.not. allocated(model%materials)) return
      do k = 1, size(model%mesh%esets)
         if (s /= 0 .and. k /= s) cycle
         m = model%mesh%esets(k)%material_index
         if (m < 1 .or. m > size(model%materials)) then
            weightless = .false.
            return
         end if
         if (model%materials(m)%m%unit_weight /= 0.0_wp) weightless = .false.
         if (allocated(model%water%mats)) then
            if (m <= size(model%water%mats)) then
               if (model%water%mats(m)%gamma_sat /= 0.0_wp) weightless = .false.
            end if
         end if
         if (.not. weightless) return
      end do
   end function weightless

   !> Highest y of the nodes of element set `s` (0: every set).
   real(wp) function set_top(model, s) result(top)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      integer :: k
      top = -huge(1.0_wp)
      do k = 1, size(model%mesh%esets)
         if (s /= 0 .and. k /= s) cycle
         if (size(model%mesh%esets(k)%conn) == 0) cycle
         top = max(top, maxval(model%mesh%x(2, pack(model%mesh%esets(k)%conn, .true.))))
      end do
   end function set_top

   subroutine warn_at(state, model, at, text)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      integer, intent(in) :: at
      character(len=*), intent(in) :: text
      if (at < 1 .or. at > state%lines%n) then
         call model%warnings%add(text)
      else
         call model%warnings%add(text, state%lines%file(at), state%lines%line(at))
      end if
   end subroutine warn_at

end module pecplas_io_deck_usage
