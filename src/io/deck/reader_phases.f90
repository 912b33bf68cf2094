!> Phase changes of the deck (doc/deck.md, Phases): *DEACTIVATE, *ACTIVATE [, STRESS=ZERO |
!> WISHED_IN_PLACE], *CHANGE_MATERIAL and *CHANGE_LAW after a *STEP line (before its
!> *END STEP) change the model at the start of that step. Read into the open step, then
!> resolved to the index of an element set, joint set, load pattern or named support (and
!> of a material or law) and checked phase by phase once the whole deck is read: a thing
!> activated while active or deactivated while inactive, a step that drives an inactive
!> pattern, a load or imposed displacement on a node that no active element or joint holds
!> in a phase, an unknown name, material or law are errors at the deck line.
module pecplas_io_deck_reader_phases
   use pecplas_base_error, only: error_t
   use pecplas_base_kinds, only: wp
   use pecplas_io_text_fields, only: field_t, split_fields, check_count, same_name, upper, &
      add_name, itoa, parse_real
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, raw_change_t, line_error
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_set_names, only: eset_names
   use pecplas_model_loads, only: LOAD_FORCE, LOAD_DISPLACEMENT, LOAD_PRESSURE
   use pecplas_model_phases, only: phase_change_t, CHANGE_DEACTIVATE, CHANGE_ACTIVATE, &
      CHANGE_MATERIAL, CHANGE_LAW, CHANGE_NAMES, TARGET_ELEMENTS, TARGET_JOINTS, START_ZERO, &
      START_WISHED, TARGET_PATTERNS, TARGET_SUPPORTS, TARGET_NAMES, TARGET_PLATES, &
      TARGET_ANCHORS, CHANGE_PRESTRESS
   use pecplas_model_phase_plan, only: initial_activity, step_activity, attached_nodes, &
      target_activity
   implicit none (type, external)
   private

   public :: read_change, resolve_phases

contains

   !> One change keyword block, appended to the open step's changes.
   subroutine read_change(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(raw_change_t) :: ch
      type(field_t), allocatable :: f(:)
      character(len=:), allocatable :: text
      logical :: found, ok
      integer :: kind, i, k
      real(wp) :: force
      kind = 0
      do i = 1, size(CHANGE_NAMES)
         if (trim(CHANGE_NAMES(i)) == block%kw%name) kind = i
      end do
      if (kind == CHANGE_ACTIVATE) then
         call block%kw%check_keys(state%lines%get(block%at), [character(len=6) :: 'STRESS'], &
            error)
      else
         call block%kw%check_keys(state%lines%get(block%at), [character(len=1) ::], error)
      end if
      if (allocated(error)) return
      if (state%open_step == 0) then
         call line_error(state, block%at, block%kw%name//' changes the model at the start '// &
            'of a step: put it after a *STEP line (and before that step''s *END STEP)', error)
         return
      end if
      ch%kind = kind
      ch%start = START_ZERO
      if (kind == CHANGE_ACTIVATE) then
         call block%kw%get('STRESS', text, found)
         if (found) then
            select case (upper(text))
            case ('ZERO')
               ch%start = START_ZERO
            case ('WISHED_IN_PLACE')
               ch%start = START_WISHED
            case default
               call line_error(state, block%at, "STRESS="//text//": expected ZERO or "// &
                  "WISHED_IN_PLACE", error)
               return
            end select
         end if
      end if
      if (block%last < block%first .and. kind == CHANGE_PRESTRESS) then
         call line_error(state, block%at, '*PRESTRESS needs data lines "anchor, force" (the '// &
            'prestress force of one anchor)', error)
         return
      end if
      if (block%last < block%first) then
         if (kind == CHANGE_MATERIAL .or. kind == CHANGE_LAW) then
            text = merge('element_set, material', 'joint_set, law       ', kind == CHANGE_MATERIAL)
            call line_error(state, block%at, block%kw%name//' needs data lines "'//trim(text)// &
               '"', error)
         else
            call line_error(state, block%at, block%kw%name//' needs data lines: the names '// &
               'of element sets or joint sets', error)
         end if
         return
      end if
      do i = block%first, block%last
         call split_fields(state%lines%text(i), f)
         ch%at = i
         if (kind == CHANGE_PRESTRESS) then
            call check_count(state%lines%get(i), f, 2, 2, 'anchor, force', error)
            if (allocated(error)) return
            call parse_real(f(2)%s, force, ok)
            if (.not. ok) then
               call line_error(state, i, "prestress force must be a number, found '"// &
                  f(2)%s//"'", error)
               return
            end if
            ch%set = f(1)%s
            ch%new = f(2)%s
            call push(state%steps(state%open_step)%changes, ch)
         else if (kind == CHANGE_MATERIAL .or. kind == CHANGE_LAW) then
            call check_count(state%lines%get(i), f, 2, 2, merge('element_set, material', &
               'joint_set, law       ', kind == CHANGE_MATERIAL), error)
            if (allocated(error)) return
            ch%set = f(1)%s
            ch%new = f(2)%s
            call push(state%steps(state%open_step)%changes, ch)
         else
            do k = 1, size(f)
               if (f(k)%s == '=') then
                  call line_error(state, i, "expected set names, found '='", error)
                  return
               end if
               ch%set = f(k)%s
               ch%new = ''
               call push(state%steps(state%open_step)%changes, ch)
            end do
         end if
      end do
   end subroutine read_change

   subroutine push(list, ch)
      type(raw_change_t), allocatable, intent(inout) :: list(:)
      type(raw_change_t), intent(in) :: ch
      type(raw_change_t), allocatable :: tmp(:)
      integer :: n
      if (.not. allocated(list)) allocate (list(0))
      n = size(list)
      allocate (tmp(n + 1))
      tmp(1:n) = list
      tmp(n + 1) = ch
      call move_alloc(tmp, list)
   end subroutine push

   !> model%steps(:)%changes from the raw changes (names to indices), then the phases
   !> checked in order.
   subroutine resolve_phases(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: parts(:)
      integer :: s, c, i, n, nraw
      do s = 1, size(state%steps)
         associate (raw => state%steps(s), step => model%steps(s))
            step%reset_displacements = raw%reset_displacements
            ! a Gmsh group of several element types (mesh_t%find_esets) changes each part
            n = 0
            if (allocated(raw%changes)) then
               do c = 1, size(raw%changes)
                  n = n + max(1, size(model%mesh%find_esets(raw%changes(c)%set)))
               end do
            end if
            allocate (step%changes(n))
            n = 0
            nraw = 0
            if (allocated(raw%changes)) nraw = size(raw%changes)
            do c = 1, nraw
               parts = model%mesh%find_esets(raw%changes(c)%set)
               if (size(parts) <= 1) then
                  n = n + 1
                  call resolve_change(state, model, raw%changes(c), step%changes(n), error)
                  if (allocated(error)) return
                  cycle
               end if
               do i = 1, size(parts)
                  n = n + 1
                  call resolve_change(state, model, raw%changes(c), step%changes(n), error, &
                     parts(i))
                  if (allocated(error)) return
               end do
            end do
            if (step%reset_displacements .and. has_katona(model)) then
               call line_error(state, raw%at, 'RESET_DISPLACEMENTS is not available with '// &
                  'Katona contact joint sets (TYPE=KATONA) yet (their gaps are measured from '// &
                  'the displacements)', error)
               return
            end if
         end associate
      end do
      call check_phases(state, model, error)
   end subroutine resolve_phases

   logical function has_katona(model)
      type(model_t), intent(in) :: model
      integer :: j
      has_katona = .false.
      if (.not. allocated(model%joint_sets)) return
      do j = 1, size(model%joint_sets)
         if (model%joint_sets(j)%is_katona()) has_katona = .true.
      end do
   end function has_katona

   !> One change; `part`: the element set of a Gmsh group's part that `raw` names with the
   !> group's name.
   subroutine resolve_change(state, model, raw, ch, error, part)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      type(raw_change_t), intent(in) :: raw
      type(phase_change_t), intent(out) :: ch
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: part
      integer :: j, k
      character(len=:), allocatable :: list
      ch%kind = raw%kind
      ch%start = raw%start
      ch%set_name = raw%set
      ch%file = state%lines%file(raw%at)
      ch%line = state%lines%line(raw%at)
      ch%set = model%mesh%find_eset(raw%set)
      if (present(part)) then
         ch%set = part
         ch%set_name = model%mesh%esets(part)%name
      end if
      ch%target = TARGET_ELEMENTS
      ! the kinds of thing a phase switches, looked up in this order (doc/deck.md, Phases)
      if (ch%set == 0) call find_target(model, raw%set, ch%target, ch%set)
      if (ch%set == 0 .and. ch%kind == CHANGE_PRESTRESS) then
         list = ''
         if (allocated(model%anchors)) then
            do k = 1, size(model%anchors)
               call add_name(list, model%anchors(k)%name)
            end do
         end if
         call line_error(state, raw%at, "no anchor '"//raw%set//"'; known anchors:"//list, &
            error)
         return
      end if
      if (ch%set == 0) then
         list = eset_names(model%mesh)
         if (allocated(model%joint_sets)) then
            do k = 1, size(model%joint_sets)
               call add_name(list, model%joint_sets(k)%name)
            end do
         end if
         if (ch%kind == CHANGE_ACTIVATE .or. ch%kind == CHANGE_DEACTIVATE) then
            if (allocated(model%plates)) then
               do k = 1, size(model%plates)
                  call add_name(list, model%plates(k)%name)
               end do
            end if
            if (allocated(model%patterns)) then
               do k = 1, size(model%patterns)
                  call add_name(list, model%patterns(k)%name)
               end do
            end if
            if (allocated(model%supports%names)) then
               do k = 1, size(model%supports%names)
                  call add_name(list, trim(model%supports%names(k)))
               end do
            end if
            if (allocated(model%anchors)) then
               do k = 1, size(model%anchors)
                  call add_name(list, model%anchors(k)%name)
               end do
            end if
            call line_error(state, raw%at, "no plate set, anchor, element set, joint set, "// &
               "load pattern or named support '"//raw%set//"'; known:"//list, error)
         else
            call line_error(state, raw%at, "no element set or joint set '"//raw%set// &
               "'; known sets:"//list, error)
         end if
         return
      end if
      if (ch%target == TARGET_ANCHORS .or. ch%kind == CHANGE_PRESTRESS) then
         call resolve_anchor_change(state, model, raw, ch, error)
         return
      end if
      if (ch%target == TARGET_PLATES) then
         if (ch%kind /= CHANGE_ACTIVATE .and. ch%kind /= CHANGE_DEACTIVATE) then
            call line_error(state, raw%at, "'"//raw%set//"' is a plate set: a phase "// &
               'activates or deactivates it (its section does not change)', error)
         else if (ch%start == START_WISHED) then
            call line_error(state, raw%at, "STRESS=WISHED_IN_PLACE is for element sets "// &
               "and Katona contact sets; plate set '"//raw%set//"' starts free of forces", &
               error)
         end if
         return
      end if
      if (ch%target == TARGET_PATTERNS .or. ch%target == TARGET_SUPPORTS) then
         select case (ch%kind)
         case (CHANGE_MATERIAL, CHANGE_LAW)
            call line_error(state, raw%at, "'"//raw%set//"' is a "// &
               trim(TARGET_NAMES(ch%target))//': '//trim(CHANGE_NAMES(ch%kind))// &
               ' changes element sets or joint sets', error)
            return
         end select
         if (ch%kind == CHANGE_ACTIVATE .and. ch%start == START_WISHED) then
            call line_error(state, raw%at, "STRESS=WISHED_IN_PLACE is for element sets "// &
               "and Katona contact sets; '"//raw%set//"' is a "// &
               trim(TARGET_NAMES(ch%target)), error)
            return
         end if
         if (ch%target == TARGET_PATTERNS) then
            if (model%patterns(ch%set)%kind == LOAD_DISPLACEMENT) then
               call line_error(state, raw%at, "load pattern '"//raw%set//"' imposes "// &
                  'displacements: a phase cannot switch it (its factor drives it; a '// &
                  'support that a phase installs or removes is a *BOUNDARY, NAME=)', error)
               return
            end if
         end if
         return
      end if
      select case (ch%kind)
      case (CHANGE_ACTIVATE)
         if (ch%target == TARGET_JOINTS .and. ch%start == START_WISHED) then
            if (.not. model%joint_sets(ch%set)%is_katona()) then
               call line_error(state, raw%at, "STRESS=WISHED_IN_PLACE is for element sets "// &
                  "and Katona contact sets; joint set '"//raw%set//"' starts from the "// &
                  'stresses of the soil beside it anyway', error)
               return
            end if
         end if
      case (CHANGE_MATERIAL)
         if (ch%target /= TARGET_ELEMENTS) then
            call line_error(state, raw%at, "'"//raw%set//"' is a joint set: *CHANGE_LAW "// &
               'changes the law of a joint set', error)
            return
         end if
         ch%new_name = raw%new
         list = ''
         do k = 1, size(model%materials)
            if (same_name(model%materials(k)%m%name, raw%new)) ch%new = k
            call add_name(list, model%materials(k)%m%name)
         end do
         if (ch%new == 0) then
            call line_error(state, raw%at, "no material '"//raw%new//"'; known materials:"// &
               list, error)
            return
         end if
      case (CHANGE_LAW)
         if (ch%target /= TARGET_JOINTS) then
            call line_error(state, raw%at, "'"//raw%set//"' is an element set: "// &
               '*CHANGE_MATERIAL changes the material of an element set', error)
            return
         end if
         ch%new_name = raw%new
         list = ''
         if (allocated(model%laws)) then
            do k = 1, size(model%laws)
               if (same_name(model%laws(k)%law%name, raw%new)) ch%new = k
               call add_name(list, model%laws(k)%law%name)
            end do
         end if
         if (ch%new == 0) then
            call line_error(state, raw%at, "no interface law '"//raw%new//"' (Katona contact "// &
               "is no law a set can change to); known laws:"//list, error)
            return
         end if
         if (model%joint_sets(ch%set)%is_katona()) then
            call line_error(state, raw%at, "joint set '"//raw%set//"' is a Katona contact set: "// &
               'its law cannot change', error)
            return
         end if
      end select
   end subroutine resolve_change

   !> The thing a phase-change line names, looked up among the joint sets, the load patterns
   !> and the named supports, in this order (element sets come first, by the caller);
   !> set = 0 when none has that name.
   subroutine find_target(model, name, target, set)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      integer, intent(out) :: target, set
      integer :: k
      set = 0
      target = TARGET_ELEMENTS
      if (allocated(model%joint_sets)) then
         do k = size(model%joint_sets), 1, -1
            if (same_name(model%joint_sets(k)%name, name)) set = k
         end do
         target = TARGET_JOINTS
         if (set > 0) return
      end if
      if (allocated(model%plates)) then
         do k = size(model%plates), 1, -1
            if (same_name(model%plates(k)%name, name)) set = k
         end do
         target = TARGET_PLATES
         if (set > 0) return
      end if
      if (allocated(model%patterns)) then
         do k = size(model%patterns), 1, -1
            if (same_name(model%patterns(k)%name, name)) set = k
         end do
         target = TARGET_PATTERNS
         if (set > 0) return
      end if
      if (allocated(model%supports%names)) then
         do k = size(model%supports%names), 1, -1
            if (same_name(trim(model%supports%names(k)), name)) set = k
         end do
         target = TARGET_SUPPORTS
         if (set > 0) return
      end if
      if (allocated(model%anchors)) then
         do k = size(model%anchors), 1, -1
            if (same_name(model%anchors(k)%name, name)) set = k
         end do
         target = TARGET_ANCHORS
         if (set > 0) return
      end if
      target = TARGET_ELEMENTS
   end subroutine find_target

   !> A change naming an anchor set: *ACTIVATE (STRESS= does not apply), *DEACTIVATE, or
   !> *PRESTRESS with a force within the anchor's limits.
   subroutine resolve_anchor_change(state, model, raw, ch, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      type(raw_change_t), intent(in) :: raw
      type(phase_change_t), intent(inout) :: ch
      type(error_t), allocatable, intent(out) :: error
      logical :: ok
      if (ch%target /= TARGET_ANCHORS) then
         call line_error(state, raw%at, "'"//raw%set//"' is not an anchor: *PRESTRESS "// &
            'prestresses anchors (*ANCHOR)', error)
         return
      end if
      select case (ch%kind)
      case (CHANGE_ACTIVATE)
         if (ch%start == START_WISHED) call line_error(state, raw%at, 'STRESS= is for '// &
            "element sets; anchor '"//raw%set//"' starts without force (or with its "// &
            '*PRESTRESS)', error)
      case (CHANGE_MATERIAL, CHANGE_LAW)
         call line_error(state, raw%at, "'"//raw%set//"' is an anchor: it has no material "// &
            'or law to change (define another *ANCHOR and swap them with *DEACTIVATE and '// &
            '*ACTIVATE)', error)
      case (CHANGE_PRESTRESS)
         call parse_real(raw%new, ch%value, ok)
         associate (a => model%anchors(ch%set))
            if (ch%value > a%tension_limit .or. ch%value < -a%compression_limit) &
               call line_error(state, raw%at, "prestress "//raw%new//" of anchor '"// &
               raw%set//"' is beyond its TENSION_LIMIT or COMPRESSION_LIMIT", error)
         end associate
      end select
   end subroutine resolve_anchor_change

   !> Walks the phases: activation of an active set, deactivation of an inactive one, and a
   !> load or imposed displacement acting in a phase on a node that no active element or
   !> joint holds are errors.
   subroutine check_phases(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: eact(:), jact(:), dropped(:), held(:), pact(:), sact(:), plact(:), &
         aact(:)
      integer, allocatable :: emat(:), jlaw(:)
      real(wp), allocatable :: factors(:)
      integer :: s, c, p, k, npat
      logical :: on
      call initial_activity(model, eact, jact)
      pact = target_activity(model, TARGET_PATTERNS, 0)
      sact = target_activity(model, TARGET_SUPPORTS, 0)
      plact = target_activity(model, TARGET_PLATES, 0)
      aact = target_activity(model, TARGET_ANCHORS, 0)
      emat = [(model%mesh%esets(c)%material_index, c=1, size(model%mesh%esets))]
      allocate (jlaw(size(jact)))
      do c = 1, size(jact)
         jlaw(c) = model%joint_sets(c)%law_index
      end do
      npat = 0
      if (allocated(model%patterns)) npat = size(model%patterns)
      allocate (factors(npat), source=0.0_wp)
      do s = 1, size(model%steps)
         associate (step => model%steps(s))
            do c = 1, size(step%changes)
               associate (ch => step%changes(c))
                  if (ch%kind == CHANGE_ACTIVATE .or. ch%kind == CHANGE_DEACTIVATE) then
                     select case (ch%target)
                     case (TARGET_ELEMENTS)
                        on = eact(ch%set)
                     case (TARGET_JOINTS)
                        on = jact(ch%set)
                     case (TARGET_PATTERNS)
                        on = pact(ch%set)
                     case (TARGET_PLATES)
                        on = plact(ch%set)
                     case (TARGET_ANCHORS)
                        on = aact(ch%set)
                     case default
                        on = sact(ch%set)
                     end select
                     if (ch%kind == CHANGE_ACTIVATE .and. on) then
                        call line_error(state, state%steps(s)%changes(c)%at, &
                           trim(what(ch%target))//" '"//ch%set_name// &
                           "' is already active in step '"//step%name//"'", error)
                        return
                     end if
                     if (ch%kind == CHANGE_DEACTIVATE .and. .not. on) then
                        call line_error(state, state%steps(s)%changes(c)%at, &
                           trim(what(ch%target))//" '"//ch%set_name// &
                           "' is not active in step '"//step%name//"'", error)
                        return
                     end if
                     if (ch%target == TARGET_PATTERNS) pact(ch%set) = ch%kind == CHANGE_ACTIVATE
                     ! (--strict) a pattern activated at factor 0 that the step does not drive
                     if (ch%target == TARGET_PATTERNS .and. ch%kind == CHANGE_ACTIVATE) then
                        if (factors(ch%set) == 0.0_wp .and. .not. any(step%pattern == ch%set)) &
                           call model%warnings%add("load pattern '"//ch%set_name//"' is "// &
                           "activated at factor 0 and step '"//step%name//"' does not drive "// &
                           'it: it loads nothing', ch%file, ch%line)
                     end if
                     if (ch%target == TARGET_SUPPORTS) sact(ch%set) = ch%kind == CHANGE_ACTIVATE
                     if (ch%target == TARGET_ANCHORS) aact(ch%set) = ch%kind == CHANGE_ACTIVATE
                  end if
                  if (ch%kind == CHANGE_PRESTRESS) then
                     if (.not. aact(ch%set)) then
                        call line_error(state, state%steps(s)%changes(c)%at, "anchor '"// &
                           ch%set_name//"' is not active in step '"//step%name//"': "// &
                           '*ACTIVATE it in this step or before *PRESTRESS', error)
                        return
                     end if
                  end if
               end associate
               ! (--strict) a change to what the set already has changes nothing
               associate (ch => step%changes(c))
                  if (ch%kind == CHANGE_MATERIAL) then
                     if (emat(ch%set) == ch%new) call model%warnings%add("element set '"// &
                        ch%set_name//"' already has material '"//ch%new_name//"': the "// &
                        '*CHANGE_MATERIAL changes nothing', ch%file, ch%line)
                     emat(ch%set) = ch%new
                  else if (ch%kind == CHANGE_LAW) then
                     if (jlaw(ch%set) == ch%new) call model%warnings%add("joint set '"// &
                        ch%set_name//"' already has law '"//ch%new_name//"': the "// &
                        '*CHANGE_LAW changes nothing', ch%file, ch%line)
                     jlaw(ch%set) = ch%new
                  end if
               end associate
               ! each change applies before the next is checked (a set named twice)
               call step_activity_one(step%changes(c), eact, jact, plact)
            end do
            call step_activity(model, s, eact, jact, dropped)
            held = attached_nodes(model, eact, jact, plact, aact)
            do k = 1, size(step%pattern)
               if (.not. pact(step%pattern(k))) then
                  call line_error(state, state%steps(s)%at, "step '"//step%name// &
                     "' drives load pattern '"//model%patterns(step%pattern(k))%name// &
                     "', which is not active in it: *ACTIVATE it first", error)
                  return
               end if
               factors(step%pattern(k)) = step%target(k)
            end do
            do p = 1, npat
               if (.not. pact(p)) cycle
               if (factors(p) == 0.0_wp .and. .not. any(step%pattern == p)) cycle
               call check_pattern(state, model, s, p, held, error)
               if (allocated(error)) return
            end do
         end associate
      end do
   end subroutine check_phases

   !> 'set' for element and joint sets (as the messages have always said), else the kind.
   pure function what(target) result(text)
      integer, intent(in) :: target
      character(len=:), allocatable :: text
      text = 'set'
      if (target == TARGET_PATTERNS .or. target == TARGET_SUPPORTS .or. &
          target == TARGET_ANCHORS) text = TARGET_NAMES(target)
   end function what

   pure subroutine step_activity_one(ch, eact, jact, plact)
      type(phase_change_t), intent(in) :: ch
      logical, intent(inout) :: eact(:), jact(:), plact(:)
      if (ch%kind /= CHANGE_ACTIVATE .and. ch%kind /= CHANGE_DEACTIVATE) return
      if (ch%target == TARGET_PLATES) then
         plact(ch%set) = ch%kind == CHANGE_ACTIVATE
      else if (ch%target == TARGET_ELEMENTS) then
         eact(ch%set) = ch%kind == CHANGE_ACTIVATE
      else if (ch%target == TARGET_JOINTS) then
         jact(ch%set) = ch%kind == CHANGE_ACTIVATE
      end if
   end subroutine step_activity_one

   !> A pattern acting in step s must act on held nodes only.
   subroutine check_pattern(state, model, s, p, held, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      integer, intent(in) :: s, p
      logical, intent(in) :: held(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: k, node
      node = 0
      associate (pat => model%patterns(p))
         select case (pat%kind)
         case (LOAD_FORCE, LOAD_DISPLACEMENT)
            do k = 1, size(pat%node)
               if (pat%value(k) /= 0.0_wp .and. .not. held(pat%node(k))) then
                  node = pat%node(k)
                  exit
               end if
            end do
         case (LOAD_PRESSURE)
            do k = 1, size(pat%pressure)
               if (pat%pressure(k) == 0.0_wp) cycle
               if (.not. all(held(pack(pat%edge(:, k), pat%edge(:, k) > 0)))) then
                  node = pat%edge(1, k)
                  exit
               end if
            end do
         end select
         if (node == 0) return
         call line_error(state, state%steps(s)%at, "load pattern '"//pat%name//"' acts in "// &
            "step '"//model%steps(s)%name//"' on node "//itoa(model%mesh%node_id(node))// &
            ', which no active element or joint holds in that step (its sets are not '// &
            'active): deactivate the pattern (target factor 0) before, or keep an element '// &
            'at that node', error)
      end associate
   end subroutine check_pattern

end module pecplas_io_deck_reader_phases
