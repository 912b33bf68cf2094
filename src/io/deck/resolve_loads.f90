!> Resolves *BOUNDARY, *LOAD and *STEP references once the mesh is built: node ids and
!> node sets become (node, dof) lists, edge sets become edges, element set names become
!> indices, pattern names in steps become pattern indices.
module pecplas_io_deck_resolve_loads
   use pecplas_base_error, only: error_t
   use pecplas_io_text_fields, only: parse_int, same_name, upper, add_name
   use pecplas_io_deck_state, only: deck_state_t, raw_item_t, raw_step_t, line_error
   use pecplas_model_type, only: model_t
   use pecplas_model_mesh, only: mesh_t
   use pecplas_io_deck_set_names, only: eset_names, nset_names, edge_set_names
   use pecplas_model_loads, only: load_pattern_t, step_t, load_kind, LOAD_DISPLACEMENT, &
      SUPPORT_NAME_LEN
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private

   public :: resolve_supports, resolve_patterns, resolve_steps

contains

   !> Internal node numbers of a target: a node id or a node-set name.
   subroutine target_nodes(state, mesh, item, nodes, error)
      type(deck_state_t), intent(in) :: state
      type(mesh_t), intent(in) :: mesh
      type(raw_item_t), intent(in) :: item
      integer, allocatable, intent(out) :: nodes(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: id, k
      logical :: is_id
      call parse_int(item%target, id, is_id)
      if (is_id) then
         k = state%node_lookup%index(id)
         if (k == 0) then
            call line_error(state, item%at, 'undefined node '//item%target// &
               ': no *NODES line defines it', error)
            return
         end if
         nodes = [k]
         return
      end if
      k = mesh%find_nset(item%target)
      if (k == 0) then
         call line_error(state, item%at, "undefined node set '"//item%target// &
            "'; known node sets:"//nset_names(mesh, ' (none)'), error)
         return
      end if
      nodes = mesh%nsets(k)%nodes
   end subroutine target_nodes

   !> Index in model%plates of the plate set `name`, 0 if none.
   integer function plate_index(model, name) result(k)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      integer :: i
      k = 0
      if (.not. allocated(model%plates)) return
      do i = 1, size(model%plates)
         if (same_name(model%plates(i)%name, name)) k = i
      end do
   end function plate_index

   function plate_names(model) result(list)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: list
      integer :: i
      list = ''
      if (allocated(model%plates)) then
         do i = 1, size(model%plates)
            call add_name(list, model%plates(i)%name)
         end do
      end if
      if (len(list) == 0) list = ' (none)'
   end function plate_names

   !> Fixed dofs, each (node, dof) once per group: the unnamed *BOUNDARY lines (group 0,
   !> always active) and each *BOUNDARY, NAME= (a support that phases switch; the lines of
   !> several blocks of one name add up); a rotation (dof 3) only where the node carries one (an
   !> error when a line names the rotation alone on a node without).
   subroutine resolve_supports(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: fixed(:, :, :)
      character(len=SUPPORT_NAME_LEN), allocatable :: names(:)
      integer, allocatable :: nodes(:)
      integer :: i, j, d, g, k
      allocate (names(0))
      do i = 1, state%nboundary
         associate (grp => state%boundary(i)%group)
            if (len(grp) == 0) cycle
            if (len(grp) > SUPPORT_NAME_LEN) then
               call line_error(state, state%boundary(i)%at, 'support name longer than '// &
                  itoa(SUPPORT_NAME_LEN)//' characters', error)
               return
            end if
            if (.not. any([(same_name(trim(names(k)), grp), k=1, size(names))])) &
               names = [character(len=SUPPORT_NAME_LEN) :: names, grp]
         end associate
      end do
      allocate (fixed(3, model%mesh%nnode(), 0:size(names)), source=.false.)
      do i = 1, state%nboundary
         call target_nodes(state, model%mesh, state%boundary(i), nodes, error)
         if (allocated(error)) return
         g = 0
         do k = 1, size(names)
            if (same_name(trim(names(k)), state%boundary(i)%group)) g = k
         end do
         do j = 1, size(nodes)
            do d = state%boundary(i)%dof(1), state%boundary(i)%dof(2)
               if (d == 3 .and. model%node_rotation(nodes(j)) == 0) then
                  if (state%boundary(i)%dof(1) < 3) cycle
                  call line_error(state, state%boundary(i)%at, 'node '// &
                     itoa(model%mesh%node_id(nodes(j)))//' carries no rotation (it is on '// &
                     'no *PLATE): ROT (dof 3) holds the rotation of plate nodes', error)
                  return
               end if
               fixed(d, nodes(j), g) = .true.
            end do
         end do
      end do
      allocate (model%supports%node(0), model%supports%dof(0), model%supports%group(0))
      do g = 0, size(names)
         associate (fx => fixed(:, :, g))
            model%supports%node = [model%supports%node, &
               ((j, d=1, count(fx(:, j))), j=1, size(fx, 2))]
            model%supports%dof = [model%supports%dof, pack(spread([1, 2, 3], 2, size(fx, 2)), fx)]
            model%supports%group = [model%supports%group, (g, k=1, count(fx))]
         end associate
      end do
      model%supports%names = names
   end subroutine resolve_supports

   !> model%patterns from the *LOAD blocks: node sets expanded to (node, dof) entries,
   !> edge sets to edges (3, n), element set names (or ALL) to indices.
   subroutine resolve_patterns(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      integer :: p, i
      allocate (model%patterns(0))
      if (.not. allocated(state%patterns)) return
      deallocate (model%patterns)
      allocate (model%patterns(size(state%patterns)))
      do p = 1, size(state%patterns)
         associate (raw => state%patterns(p), pat => model%patterns(p))
            pat%name = raw%name
            pat%kind = load_kind(raw%kind)
            allocate (pat%node(0), pat%dof(0), pat%value(0), pat%edge(3, 0), pat%pressure(0), &
               pat%pressure_gradient(0), pat%pressure_y_ref(0), pat%eset(0), pat%vector(2, 0))
            allocate (pat%plate(0), pat%plate_vector(2, 0))
            pat%floored = raw%floored
            pat%p_min = raw%p_min
            do i = 1, raw%n
               call add_item(state, model, raw%kind, raw%items(i), pat, error)
               if (allocated(error)) return
            end do
         end associate
      end do
   end subroutine resolve_patterns

   subroutine add_item(state, model, kind, item, pat, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in), target :: model
      character(len=*), intent(in) :: kind
      type(raw_item_t), intent(in) :: item
      type(load_pattern_t), intent(inout) :: pat
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: nodes(:), sets(:), edges(:, :)
      integer :: k, n
      type(mesh_t), pointer :: mesh
      mesh => model%mesh
      k = plate_index(model, item%target)
      if (kind == 'PLATE_LOAD' .or. (kind == 'GRAVITY' .and. k > 0)) then
         if (k == 0) then
            call line_error(state, item%at, "undefined plate set '"//item%target// &
               "'; known plate sets:"//plate_names(model), error)
            return
         end if
         pat%plate = [pat%plate, k]
         pat%plate_vector = reshape([pat%plate_vector, item%value], [2, size(pat%plate) ])
         return
      end if
      select case (kind)
      case ('FORCE', 'DISPLACEMENT')
         call target_nodes(state, mesh, item, nodes, error)
         if (allocated(error)) return
         n = size(nodes)
         if (item%dof(1) == 3) then
            do k = 1, n
               if (model%node_rotation(nodes(k)) == 0) then
                  call line_error(state, item%at, 'node '//itoa(mesh%node_id(nodes(k)))// &
                     ' carries no rotation (it is on no *PLATE): dof 3 (ROT) applies to '// &
                     'plate nodes', error)
                  return
               end if
            end do
         end if
         pat%node = [pat%node, nodes]
         pat%dof = [pat%dof, spread(item%dof(1), 1, n)]
         pat%value = [pat%value, spread(item%value(1), 1, n)]
      case ('PRESSURE')
         k = mesh%find_edge_set(item%target)
         if (k == 0) then
            call line_error(state, item%at, "undefined edge set '"//item%target// &
               "'; known edge sets:"//edge_set_names(mesh, ' (none)'), error)
            return
         end if
         ! pattern edges are (3, n), third node 0 on linear sides
         associate (en => mesh%edge_sets(k)%nodes)
            n = size(en, 2)
            allocate (edges(3, n))
            edges = 0
            edges(1:size(en, 1), :) = en
         end associate
         pat%edge = reshape([pat%edge, edges], [3, size(pat%edge, 2) + n])
         pat%pressure = [pat%pressure, spread(item%value(1), 1, n)]
         pat%pressure_gradient = [pat%pressure_gradient, spread(item%gradient, 1, n)]
         pat%pressure_y_ref = [pat%pressure_y_ref, spread(item%y_ref, 1, n)]
      case default
         if (upper(item%target) == 'ALL') then
            allocate (sets(size(mesh%esets)))
            sets = [(k, k=1, size(mesh%esets))]
         else
            ! a set, or every part of a Gmsh group of several element types
            sets = mesh%find_esets(item%target)
            if (size(sets) == 0) then
               call line_error(state, item%at, "undefined element set '"//item%target// &
                  "'; known element sets:"//eset_names(mesh)//' (or ALL)', error)
               return
            end if
         end if
         n = size(sets)
         pat%eset = [pat%eset, sets]
         pat%vector = reshape([pat%vector, spread(item%value, 2, n)], [2, size(pat%vector, 2) + n])
      end select
   end subroutine add_item

   !> model%steps from the *STEP blocks: pattern names to indices, each at most once.
   subroutine resolve_steps(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      integer :: s, i, k, p
      allocate (model%steps(size(state%steps)))
      do s = 1, size(state%steps)
         associate (raw => state%steps(s), step => model%steps(s))
            step%name = raw%name
            step%increments = raw%increments
            step%file = state%lines%file(raw%at)
            step%line = state%lines%line(raw%at)
            step%arc_length = raw%arc_length
            step%max_increments = raw%max_increments
            step%iterations_wanted = raw%iterations_wanted
            step%min_length = raw%min_length
            step%max_length = raw%max_length
            step%dof = raw%dof
            step%displacement = raw%displacement
            allocate (step%pattern(raw%n), step%target(raw%n))
            do i = 1, raw%n
               p = 0
               do k = 1, size(model%patterns)
                  if (same_name(model%patterns(k)%name, raw%items(i)%target)) p = k
               end do
               if (p == 0) then
                  call line_error(state, raw%items(i)%at, "undefined load pattern '"// &
                     raw%items(i)%target//"'; known patterns:"//pattern_names(model%patterns), &
                     error)
                  return
               end if
               if (any(step%pattern(1:i - 1) == p)) then
                  call line_error(state, raw%items(i)%at, "load pattern '"// &
                     raw%items(i)%target//"' is named twice in step '"//raw%name//"'", error)
                  return
               end if
               step%pattern(i) = p
               step%target(i) = raw%items(i)%value(1)
            end do
            if (raw%arc_length) then
               call resolve_arc_step(state, model, raw, step, error)
               if (allocated(error)) return
            end if
         end associate
      end do
   end subroutine resolve_steps

   !> An arc-length step scales force patterns only (imposed displacements have no limit
   !> point to pass: load control follows them) and at least one must change; its target node
   !> must exist.
   subroutine resolve_arc_step(state, model, raw, step, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(raw_step_t), intent(in) :: raw
      type(step_t), intent(inout) :: step
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      logical :: force
      character(len=:), allocatable :: msg
      force = .false.
      do i = 1, size(step%pattern)
         if (model%patterns(step%pattern(i))%kind == LOAD_DISPLACEMENT) then
            call line_error(state, raw%items(i)%at, "CONTROL=ARC_LENGTH scales force "// &
               "patterns only; '"//model%patterns(step%pattern(i))%name//"' is a displacement "// &
               'pattern (load control follows imposed displacements: give it a step of its own)', &
               error)
            return
         end if
         force = .true.
      end do
      if (.not. force) then
         call line_error(state, raw%at, "CONTROL=ARC_LENGTH needs a force pattern in step '"// &
            raw%name//"'", error)
         return
      end if
      if (len(raw%node) > 0) then
         call model%mesh%node_of(raw%node, step%node, msg)
         if (step%node == 0) then
            call line_error(state, raw%at, 'NODE='//raw%node//': '//msg, error)
            return
         end if
      end if
   end subroutine resolve_arc_step

   !> ' a b c': the names of the load patterns (' (none)' when there are none).
   function pattern_names(patterns) result(list)
      type(load_pattern_t), intent(in) :: patterns(:)
      character(len=:), allocatable :: list
      integer :: k
      list = ''
      do k = 1, size(patterns)
         call add_name(list, patterns(k)%name)
      end do
      if (len(list) == 0) list = ' (none)'
   end function pattern_names

end module pecplas_io_deck_resolve_loads
