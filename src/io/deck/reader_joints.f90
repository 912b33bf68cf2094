!> Deck handlers for the PECJOIN keywords:
!>   *INTERFACE_LAW, NAME=name, TYPE=type   -- data: KEY = value pairs (like *MATERIAL)
!>   *JOINTS, TYPE=t, SET=name, LAW=law [, INTEGRATION=GAUSS|LOBATTO] [, THICKNESS=e]
!>            [, ANGLE=deg] [, EDGES=edge_set, SIDE=element_set]
!>            [, EDGES=edge_set, FACES=BOTH [, EXTEND=length]]
!>      data (explicit joints): id, n1, n2[, n3, n4[, n5, n6]]; none with EDGES/SIDE.
!> Laws are built at once (parameter errors at their lines); TYPE=KATONA gives Katona contact
!> parameters (model%contacts), no law. Joints are resolved after the whole deck is read
!> (pecplas_io_deck_resolve_joints).
module pecplas_io_deck_reader_joints
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_text_fields, only: deck_line_t, &
      field_t, split_fields, field_int, parse_real, same_name, &
      upper, add_name, itoa
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, line_error, where_text, &
      grow_int, grow_int2
   use pecplas_io_deck_raw_joints, only: raw_joint_set_t
   use pecplas_io_deck_reader_mesh, only: check_name
   use pecplas_io_deck_reader_materials, only: read_pairs
   use pecplas_model_type, only: model_t
   use pecplas_base_params, only: params_t
   use pecplas_model_joints, only: JOINT_TYPES
   use pecplas_joints_laws_type, only: interface_law_t, interface_law_box_t
   use pecplas_model_contact, only: katona_contact_t, build_katona_contact, KATONA_TYPE
   use pecplas_joints_laws_checks, only: length_unit_metres, LENGTH_UNIT_KEYS
   implicit none (type, external)
   private

   public :: read_interface_law, read_joints

contains

   !> *INTERFACE_LAW, NAME=name, TYPE=type -- data: KEY = value pairs over any lines.
   !> Parameter errors are reported at the first data line (the keyword line if none).
   subroutine read_interface_law(state, model, block, error)
      type(deck_state_t), intent(inout) :: state
      type(model_t), intent(inout) :: model
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      character(len=:), allocatable :: name, ltype, text
      type(params_t) :: params
      class(interface_law_t), allocatable :: law
      type(interface_law_box_t), allocatable :: tmp(:)
      type(katona_contact_t) :: contact
      integer :: i, n, at
      real(wp) :: metres
      logical :: found, ok
      kwline = state%lines%get(block%at)
      ! groundwater (doc/deck.md): joints are drained, whatever the soil beside them
      if (block%kw%has('DRAINAGE')) then
         call line_error(state, block%at, 'DRAINAGE= is for *MATERIAL: joints are '// &
            'drained (their law works on the effective normal stress, the steady pore '// &
            'pressure of their position taken off); an undrained interface is not available', &
            error)
         return
      end if
      call block%kw%check_keys(kwline, [character(len=11) :: 'NAME', 'TYPE', &
         LENGTH_UNIT_KEYS], error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'NAME', name, error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'TYPE', ltype, error)
      if (allocated(error)) return
      call check_name(state, block%at, name, error)
      if (allocated(error)) return
      if (index(state%laws%names()//' '//KATONA_TYPE//' ', ' '//upper(ltype)//' ') == 0) then
         call line_error(state, block%at, "unknown interface law type '"//upper(ltype)// &
            "'; known types:"//state%laws%names()//' '//KATONA_TYPE, error)
         return
      end if
      if (.not. allocated(model%laws)) allocate (model%laws(0))
      if (.not. allocated(model%contacts)) allocate (model%contacts(0))
      if (.not. allocated(state%law_at)) allocate (state%law_at(0))
      if (.not. allocated(state%contact_at)) allocate (state%contact_at(0))
      n = size(model%laws)
      do i = 1, n
         if (same_name(model%laws(i)%law%name, name)) then
            call line_error(state, block%at, "interface law '"//name// &
               "' is defined twice (first at "//where_text(state, state%law_at(i))//')', error)
            return
         end if
      end do
      do i = 1, size(model%contacts)
         if (same_name(model%contacts(i)%name, name)) then
            call line_error(state, block%at, "interface law '"//name// &
               "' is defined twice (first at "//where_text(state, state%contact_at(i))//')', &
               error)
            return
         end if
      end do

      at = block%at
      if (block%last >= block%first) at = block%first
      params%file = state%lines%file(at)
      params%line = state%lines%line(at)
      params%keyword = '*INTERFACE_LAW'
      allocate (params%keys(0), params%values(0))
      ! LENGTH_UNIT=MM|M, MODEL_UNIT=MM|M: passed to the law as the unit's size in metres.
      ! In a model deck the mesh's length unit is never assumed: MODEL_UNIT must be stated.
      if (block%kw%has('LENGTH_UNIT') .and. .not. block%kw%has('MODEL_UNIT')) then
         call line_error(state, block%at, 'LENGTH_UNIT gives the unit of the law''s '// &
            'parameters; also state the length unit of the mesh with MODEL_UNIT=MM|M '// &
            '(e.g. LENGTH_UNIT=MM, MODEL_UNIT=M for thesis parameters in a model in metres)', &
            error)
         return
      end if
      do i = 1, size(LENGTH_UNIT_KEYS)
         call block%kw%get(trim(LENGTH_UNIT_KEYS(i)), text, found)
         if (.not. found) cycle
         call length_unit_metres(upper(text), metres, ok)
         if (.not. ok) then
            call line_error(state, block%at, trim(LENGTH_UNIT_KEYS(i))//"='"//text// &
               "' is not a length unit: use MM or M", error)
            return
         end if
         call params%add(trim(LENGTH_UNIT_KEYS(i)), metres)
      end do
      do i = block%first, block%last
         call read_pairs(state, i, params, error, model%warnings)
         if (allocated(error)) return
      end do
      if (upper(ltype) == KATONA_TYPE) then
         call build_katona_contact(name, params, contact, error)
         if (allocated(error)) return
         model%contacts = [model%contacts, contact]
         state%contact_at = [state%contact_at, block%at]
         return
      end if
      call state%laws%new_law(upper(ltype), name, params, law, error)
      if (allocated(error)) return
      if (.not. allocated(law%name)) law%name = name

      allocate (tmp(n + 1))
      do i = 1, n
         call move_alloc(model%laws(i)%law, tmp(i)%law)
      end do
      call move_alloc(law, tmp(n + 1)%law)
      call move_alloc(tmp, model%laws)
      state%law_at = [state%law_at, block%at]
   end subroutine read_interface_law

   !> *JOINTS: checks the keyword parameters and collects explicit elements.
   subroutine read_joints(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      type(raw_joint_set_t) :: js
      type(raw_joint_set_t), allocatable :: tmp(:)
      character(len=:), allocatable :: text, list
      logical :: found, has_edges, has_side, ok
      integer :: i, n

      kwline = state%lines%get(block%at)
      associate (kw => block%kw)
         call kw%check_keys(kwline, [character(len=11) :: 'TYPE', 'SET', 'LAW', 'INTEGRATION', &
            'THICKNESS', 'ANGLE', 'EDGES', 'SIDE', 'FACES', 'EXTEND'], error)
         if (allocated(error)) return
         call kw%require(kwline, 'TYPE', js%etype, error)
         if (allocated(error)) return
         call kw%require(kwline, 'SET', js%name, error)
         if (allocated(error)) return
         call kw%require(kwline, 'LAW', js%law, error)
         if (allocated(error)) return
         js%etype = upper(js%etype)
         if (.not. any(JOINT_TYPES == js%etype)) then
            list = ''
            do i = 1, size(JOINT_TYPES)
               call add_name(list, trim(JOINT_TYPES(i)))
            end do
            call line_error(state, block%at, "unknown joint type '"//js%etype// &
               "'; known types:"//list, error)
            return
         end if
         call check_name(state, block%at, js%name, error)
         if (allocated(error)) return
         call kw%get('INTEGRATION', text, found)
         js%integration = 'GAUSS'
         if (found) then
            js%integration = upper(text)
            if (js%integration /= 'GAUSS' .and. js%integration /= 'LOBATTO') then
               call line_error(state, block%at, "unknown INTEGRATION '"//text// &
                  "'; known: GAUSS LOBATTO (Newton-Cotes)", error)
               return
            end if
            if (js%etype == 'SPRING') then
               call line_error(state, block%at, 'INTEGRATION= applies to line joints '// &
                  '(GOODMAN4, GOODMAN6, THIN_LAYER), not to SPRING', error)
               return
            end if
         end if
         call kw%get('THICKNESS', text, found)
         if (found .neqv. js%etype == 'THIN_LAYER') then
            call line_error(state, block%at, 'THICKNESS=e is required for THIN_LAYER '// &
               'joints and applies to them only', error)
            return
         end if
         if (found) then
            call parse_real(text, js%thickness, ok)
            if (.not. ok .or. .not. js%thickness > 0.0_wp) then
               call line_error(state, block%at, "THICKNESS must be a positive number, found '" &
                  //text//"'", error)
               return
            end if
         end if
         call kw%get('ANGLE', text, js%has_angle)
         if (js%has_angle) then
            if (js%etype /= 'SPRING') then
               call line_error(state, block%at, 'ANGLE= (tangent direction) applies to '// &
                  'SPRING joints only', error)
               return
            end if
            call parse_real(text, js%angle, ok)
            if (.not. ok) then
               call line_error(state, block%at, "ANGLE must be a number of degrees, found '"// &
                  text//"'", error)
               return
            end if
         end if
         call kw%get('EDGES', js%edges, has_edges)
         call kw%get('SIDE', js%side, has_side)
         call both_faces(state, block, js, has_edges, has_side, error)
         if (allocated(error)) return
         if (js%both_faces) has_side = .true.
         if (has_edges .neqv. has_side) then
            call line_error(state, block%at, 'EDGES=edge_set and SIDE=element_set go '// &
               'together (joints generated along EDGES, duplicates given to SIDE)', error)
            return
         end if
      end associate

      if (.not. allocated(state%joint_sets)) allocate (state%joint_sets(0))
      n = size(state%joint_sets)
      do i = 1, n
         if (same_name(state%joint_sets(i)%name, js%name)) then
            call line_error(state, block%at, "joint set '"//js%name//"' is defined twice "// &
               '(first at '//where_text(state, state%joint_sets(i)%at)//')', error)
            return
         end if
      end do
      js%at = block%at
      if (has_edges) then
         if (block%last >= block%first) then
            call line_error(state, block%first, '*JOINTS with EDGES= and SIDE= generates '// &
               "its elements and takes no data lines, found '"// &
               state%lines%text(block%first)//"'", error)
            return
         end if
         allocate (js%ids(0), js%nodes(0, 0), js%where(0))
      else
         call read_explicit(state, block, js, error)
         if (allocated(error)) return
      end if
      allocate (tmp(n + 1))
      tmp(1:n) = state%joint_sets
      tmp(n + 1) = js
      call move_alloc(tmp, state%joint_sets)
   end subroutine read_joints

   !> FACES=BOTH [, EXTEND=length]: joints on both faces of the EDGES line (no SIDE=).
   subroutine both_faces(state, block, js, has_edges, has_side, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      type(raw_joint_set_t), intent(inout) :: js
      logical, intent(in) :: has_edges, has_side
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      logical :: found, ok
      call block%kw%get('FACES', text, found)
      if (found) then
         if (upper(text) /= 'BOTH') then
            call line_error(state, block%at, "FACES="//text//": expected FACES=BOTH (joints "// &
               'on both faces of the EDGES line); a joint on one face takes SIDE=', error)
            return
         end if
         if (.not. has_edges .or. has_side) then
            call line_error(state, block%at, 'FACES=BOTH takes EDGES=edge_set (the line) and '// &
               'no SIDE= (the bodies on both faces get their own nodes)', error)
            return
         end if
         js%both_faces = .true.
         js%side = ''
      end if
      call block%kw%get('EXTEND', text, found)
      if (.not. found) return
      if (.not. js%both_faces) then
         call line_error(state, block%at, 'EXTEND= goes with FACES=BOTH (the cut beyond the '// &
            "line's ends)", error)
         return
      end if
      call parse_real(text, js%extend, ok)
      if (.not. ok .or. js%extend < 0.0_wp) call line_error(state, block%at, 'EXTEND must be '// &
         "a length >= 0, found '"//text//"'", error)
   end subroutine both_faces

   !> Data lines id, n1, ..., nN of explicit joints (N = 2 springs, 4 GOODMAN4,
   !> 6 GOODMAN6, 4 or 6 THIN_LAYER, the same for the whole set).
   subroutine read_explicit(state, block, js, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      type(raw_joint_set_t), intent(inout) :: js
      type(error_t), allocatable, intent(out) :: error
      type(field_t), allocatable :: f(:)
      character(len=:), allocatable :: form
      integer :: i, j, id, nen
      if (block%last < block%first) then
         call line_error(state, block%at, 'no data lines: expected "id, n1, n2, ..." joint '// &
            'elements after *JOINTS, or EDGES=edge_set, SIDE=element_set to generate them', &
            error)
         return
      end if
      select case (js%etype)
      case ('SPRING')
         form = 'id, n1, n2 (face-1 node, face-2 node)'
      case ('GOODMAN4')
         form = 'id, n1, n2, n3, n4'
      case ('GOODMAN6')
         form = 'id, n1, n2, n3, n4, n5, n6'
      case default
         form = 'id, n1, n2, n3, n4[, n5, n6]'
      end select
      allocate (js%ids(0), js%where(0))
      do i = block%first, block%last
         allocate (f(0))
         call split_fields(state%lines%text(i), f)
         nen = size(f) - 1
         select case (js%etype)
         case ('SPRING')
            if (nen /= 2) nen = -1
         case ('GOODMAN4')
            if (nen /= 4) nen = -1
         case ('GOODMAN6')
            if (nen /= 6) nen = -1
         case default
            if (nen /= 4 .and. nen /= 6) nen = -1
            if (js%nen > 0 .and. nen > 0 .and. nen /= js%nen) then
               call line_error(state, i, "THIN_LAYER set '"//js%name//"' mixes 4-node and "// &
                  '6-node joints: one kind per set', error)
               return
            end if
         end select
         if (nen < 0) then
            call line_error(state, i, 'wrong number of nodes for a '//js%etype// &
               ' joint: expected "'//form//'", found '//itoa(size(f) - 1)//' node(s)', error)
            return
         end if
         if (js%nen == 0) then
            js%nen = nen
            allocate (js%nodes(nen, 0))
         end if
         js%n = js%n + 1
         call grow_int(js%ids, js%n)
         call grow_int(js%where, js%n)
         call grow_int2(js%nodes, nen, js%n)
         do j = 1, nen + 1
            call field_int(state%lines%get(i), f, j, trim(merge('joint id', 'node id ', j == 1)), &
               id, error)
            if (allocated(error)) return
            if (id <= 0) then
               call line_error(state, i, 'ids must be positive integers, found '//itoa(id), &
                  error)
               return
            end if
            if (j == 1) then
               js%ids(js%n) = id
            else
               js%nodes(j - 1, js%n) = id
            end if
         end do
         js%where(js%n) = i
         deallocate (f)
      end do
      js%ids = js%ids(1:js%n)
      js%where = js%where(1:js%n)
      js%nodes = js%nodes(:, 1:js%n)
   end subroutine read_explicit

end module pecplas_io_deck_reader_joints
