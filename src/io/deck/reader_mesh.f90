!> Deck handlers for the mesh keywords: *NODES, *ELEMENTS, *NSET, *EDGES. They only
!> collect user ids; references are resolved by pecplas_io_deck_resolve_mesh.
module pecplas_io_deck_reader_mesh
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_io_deck_element_aliases, only: element_alias_hint
   use pecplas_io_text_fields, only: deck_line_t, field_t, split_fields, field_int, field_real, &
      check_count, parse_int, same_name, upper, itoa, add_name
   use pecplas_io_deck_mesh_lines, only: quick_node, quick_ids
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, raw_eset_t, raw_nset_t, &
      raw_edge_set_t, line_error, where_text, grow_int, grow_int2, grow_real2
   implicit none (type, external)
   private

   public :: read_nodes, read_elements, read_nset, read_edges, check_name, no_data_error
   public :: ELEMENT_TYPES, element_nodes

   !> Massif element types and their node counts.
   character(len=*), parameter :: ELEMENT_TYPES(5) = [character(len=3) :: 'T3', 'T6', 'Q4', 'Q8', &
      'Q8R']
   integer, parameter :: NODES_PER_TYPE(5) = [3, 6, 4, 8, 8]

contains

   !> Number of nodes of element type `etype`, 0 if unknown.
   pure integer function element_nodes(etype) result(nen)
      character(len=*), intent(in) :: etype
      integer :: i
      nen = 0
      do i = 1, size(ELEMENT_TYPES)
         if (upper(etype) == ELEMENT_TYPES(i)) nen = NODES_PER_TYPE(i)
      end do
   end function element_nodes

   !> *NODES -- data: id, x, y
   subroutine read_nodes(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(field_t), allocatable :: f(:)
      type(deck_line_t) :: ln
      integer :: i, id, n
      real(wp) :: x, y
      call block%kw%check_keys(state%lines%get(block%at), [character(len=1) ::], error)
      if (allocated(error)) return
      call no_data_error(state, block, 'id, x, y', error)
      if (allocated(error)) return
      ! room for the whole block at once
      n = state%nnode + block%last - block%first + 1
      call grow_int(state%node_ids, n)
      call grow_int(state%node_at, n)
      call grow_real2(state%x, 2, n)
      do i = block%first, block%last
         ! the line read in place in the deck's buffer
         if (.not. quick_node(state%lines%buf(state%lines%i1(i):state%lines%i2(i)), id, x, &
               y)) then
            ! the general path: its checks say what is wrong with the line
            ln = state%lines%get(i)
            call split_fields(ln%text, f)
            call check_count(ln, f, 3, 3, 'id, x, y', error)
            if (allocated(error)) return
            call positive_id(ln, f, 1, 'node id', id, error)
            if (allocated(error)) return
            call field_real(ln, f, 2, 'x', x, error)
            if (allocated(error)) return
            call field_real(ln, f, 3, 'y', y, error)
            if (allocated(error)) return
         end if
         n = state%nnode + 1
         state%node_ids(n) = id
         state%node_at(n) = i
         state%x(:, n) = [x, y]
         state%nnode = n
      end do
   end subroutine read_nodes

   !> *ELEMENTS, TYPE=T3|T6|Q4|Q8|Q8R, SET=name -- data: id, n1, ..., nN
   subroutine read_elements(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      type(field_t), allocatable :: f(:)
      type(deck_line_t) :: ln
      character(len=:), allocatable :: etype, name, form, list
      type(raw_eset_t), allocatable :: tmp(:)
      integer :: i, j, k, nen, id, node, ids(9)
      kwline = state%lines%get(block%at)
      call block%kw%check_keys(kwline, [character(len=4) :: 'TYPE', 'SET'], error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'TYPE', etype, error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'SET', name, error)
      if (allocated(error)) return
      etype = upper(etype)
      nen = element_nodes(etype)
      if (nen == 0) then
         list = ''
         do i = 1, size(ELEMENT_TYPES)
            call add_name(list, trim(ELEMENT_TYPES(i)))
         end do
         call line_error(state, block%at, "unknown element type '"//etype//"'"// &
            element_alias_hint(etype)//'; known types:'//list, error)
         return
      end if
      call check_name(state, block%at, name, error)
      if (allocated(error)) return
      form = 'id'
      do j = 1, nen
         form = form//', n'//itoa(j)
      end do
      call no_data_error(state, block, form, error)
      if (allocated(error)) return

      if (.not. allocated(state%esets)) allocate (state%esets(0))
      k = 0
      do i = 1, size(state%esets)
         if (same_name(state%esets(i)%name, name)) k = i
      end do
      if (k == 0) then
         allocate (tmp(size(state%esets) + 1))
         tmp(1:size(state%esets)) = state%esets
         call move_alloc(tmp, state%esets)
         k = size(state%esets)
         state%esets(k)%name = name
         state%esets(k)%etype = etype
         state%esets(k)%at = block%at
         allocate (state%esets(k)%ids(0), state%esets(k)%where(0), state%esets(k)%conn(nen, 0))
      else if (state%esets(k)%etype /= etype) then
         call line_error(state, block%at, "element set '"//name//"' already holds "// &
            state%esets(k)%etype//' elements (from '//where_text(state, state%esets(k)%at)// &
            '); cannot add '//etype//' elements: one type per set, use another SET name', error)
         return
      end if

      associate (es => state%esets(k))
         ! room for the whole block at once
         call grow_int(es%ids, es%n + block%last - block%first + 1)
         call grow_int(es%where, es%n + block%last - block%first + 1)
         call grow_int2(es%conn, nen, es%n + block%last - block%first + 1)
         do i = block%first, block%last
            ! the line read in place in the deck's buffer
            if (quick_ids(state%lines%buf(state%lines%i1(i):state%lines%i2(i)), &
                  ids(1:nen + 1))) then
               es%n = es%n + 1
               es%ids(es%n) = ids(1)
               es%where(es%n) = i
               es%conn(:, es%n) = ids(2:nen + 1)
               cycle
            end if
            ! the general path: its checks say what is wrong with the line
            ln = state%lines%get(i)
            call split_fields(ln%text, f)
            if (size(f) /= nen + 1) then
               call line_error(state, i, 'wrong number of nodes for a '//etype// &
                  ' element: expected "'//form//'" ('//itoa(nen)//' nodes), found '// &
                  itoa(size(f) - 1)//' node(s)', error)
               return
            end if
            call positive_id(ln, f, 1, 'element id', id, error)
            if (allocated(error)) return
            es%n = es%n + 1
            es%ids(es%n) = id
            es%where(es%n) = i
            do j = 1, nen
               call positive_id(ln, f, j + 1, 'node id', node, error)
               if (allocated(error)) return
               es%conn(j, es%n) = node
            end do
         end do
      end associate
   end subroutine read_elements

   !> *NSET, NAME=name [, GENERATE] -- data: node ids, or first, last[, step]
   subroutine read_nset(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      type(field_t), allocatable :: f(:)
      type(deck_line_t) :: ln
      character(len=:), allocatable :: name, flag
      type(raw_nset_t), allocatable :: tmp(:)
      logical :: generate
      integer :: i, j, k, first, last, step, id
      kwline = state%lines%get(block%at)
      call block%kw%check_keys(kwline, [character(len=8) :: 'NAME', 'GENERATE'], error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'NAME', name, error)
      if (allocated(error)) return
      call block%kw%get('GENERATE', flag, generate)
      if (generate .and. len(flag) > 0) then
         call line_error(state, block%at, "GENERATE takes no value, found 'GENERATE="//flag// &
            "'", error)
         return
      end if
      call check_name(state, block%at, name, error)
      if (allocated(error)) return
      if (generate) then
         call no_data_error(state, block, 'first, last, step', error)
      else
         call no_data_error(state, block, 'node ids', error)
      end if
      if (allocated(error)) return

      if (.not. allocated(state%nsets)) allocate (state%nsets(0))
      k = 0
      do i = 1, size(state%nsets)
         if (same_name(state%nsets(i)%name, name)) k = i
      end do
      if (k == 0) then
         allocate (tmp(size(state%nsets) + 1))
         tmp(1:size(state%nsets)) = state%nsets
         call move_alloc(tmp, state%nsets)
         k = size(state%nsets)
         state%nsets(k)%name = name
         state%nsets(k)%at = block%at
         allocate (state%nsets(k)%ids(0), state%nsets(k)%upto(0), state%nsets(k)%step(0), &
            state%nsets(k)%where(0))
      end if

      associate (ns => state%nsets(k))
         do i = block%first, block%last
            ln = state%lines%get(i)
            call split_fields(ln%text, f)
            if (generate) then
               call check_count(ln, f, 2, 3, 'first, last, step', error)
               if (allocated(error)) return
               call positive_id(ln, f, 1, 'first node id', first, error)
               if (allocated(error)) return
               call positive_id(ln, f, 2, 'last node id', last, error)
               if (allocated(error)) return
               step = 1
               if (size(f) == 3) call positive_id(ln, f, 3, 'step', step, error)
               if (allocated(error)) return
               if (last < first) then
                  call line_error(state, i, 'GENERATE needs first <= last, found first = '// &
                     itoa(first)//', last = '//itoa(last), error)
                  return
               end if
               call add_id(ns, first, i, last, step)
            else
               do j = 1, size(f)
                  call positive_id(ln, f, j, 'node id', id, error)
                  if (allocated(error)) return
                  call add_id(ns, id, i)
               end do
            end if
         end do
      end associate
   end subroutine read_nset

   !> *EDGES, NAME=name -- data: n1, n2 [, n3] (end, end, mid)
   subroutine read_edges(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      type(field_t), allocatable :: f(:)
      type(deck_line_t) :: ln
      character(len=:), allocatable :: name
      type(raw_edge_set_t), allocatable :: tmp(:)
      integer :: i, j, k, id
      kwline = state%lines%get(block%at)
      call block%kw%check_keys(kwline, [character(len=4) :: 'NAME'], error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'NAME', name, error)
      if (allocated(error)) return
      call check_name(state, block%at, name, error)
      if (allocated(error)) return
      call no_data_error(state, block, 'n1, n2[, n3]', error)
      if (allocated(error)) return
      if (.not. allocated(state%edge_sets)) allocate (state%edge_sets(0))
      k = 0
      do i = 1, size(state%edge_sets)
         if (same_name(state%edge_sets(i)%name, name)) k = i
      end do
      if (k == 0) then
         allocate (tmp(size(state%edge_sets) + 1))
         tmp(1:size(state%edge_sets)) = state%edge_sets
         call move_alloc(tmp, state%edge_sets)
         k = size(state%edge_sets)
         state%edge_sets(k)%name = name
         state%edge_sets(k)%at = block%at
         allocate (state%edge_sets(k)%nodes(3, 0), state%edge_sets(k)%where(0))
      end if
      associate (es => state%edge_sets(k))
         do i = block%first, block%last
            ln = state%lines%get(i)
            call split_fields(ln%text, f)
            call check_count(ln, f, 2, 3, 'n1, n2[, n3] (end, end, mid)', error)
            if (allocated(error)) return
            if (es%nen == 0) es%nen = size(f)
            if (size(f) /= es%nen) then
               call line_error(state, i, "edge set '"//es%name//"' mixes "//itoa(es%nen)// &
                  '-node and '//itoa(size(f))//'-node edges: one kind per set (linear or '// &
                  'quadratic element sides)', error)
               return
            end if
            es%n = es%n + 1
            call grow_int2(es%nodes, 3, es%n)
            call grow_int(es%where, es%n)
            es%nodes(:, es%n) = 0
            es%where(es%n) = i
            do j = 1, size(f)
               call positive_id(ln, f, j, 'node id', id, error)
               if (allocated(error)) return
               es%nodes(j, es%n) = id
            end do
         end do
      end associate
   end subroutine read_edges

   !> Error for a keyword that needs data lines and has none.
   subroutine no_data_error(state, block, form, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      character(len=*), intent(in) :: form
      type(error_t), allocatable, intent(out) :: error
      if (block%last >= block%first) return
      call line_error(state, block%at, 'no data lines: expected lines "'//form//'" after '// &
         block%kw%name, error)
   end subroutine no_data_error

   !> Set names are referenced in data lines, so they cannot hold blanks or be a number.
   subroutine check_name(state, at, name, error)
      type(deck_state_t), intent(in) :: state
      integer, intent(in) :: at
      character(len=*), intent(in) :: name
      type(error_t), allocatable, intent(out) :: error
      integer :: id
      logical :: is_number
      call parse_int(name, id, is_number)
      if (is_number .or. scan(trim(name), ' =') > 0 .or. upper(name) == 'ALL') &
         call line_error(state, at, "bad name '"//name//"': a name must not be a number, "// &
         "contain blanks or '=', or be ALL", error)
   end subroutine check_name

   !> Field k of line `ln` as a positive integer.
   subroutine positive_id(ln, f, k, what, id, error)
      type(deck_line_t), intent(in) :: ln
      integer, intent(in) :: k
      type(field_t), intent(in) :: f(:)
      character(len=*), intent(in) :: what
      integer, intent(out) :: id
      type(error_t), allocatable, intent(out) :: error
      call field_int(ln, f, k, what, id, error)
      if (allocated(error)) return
      if (id <= 0) call deck_error(error, ln%file, ln%line, ln%keyword, what// &
         ' must be a positive integer, found '//itoa(id))
   end subroutine positive_id

   !> Appends id (or the range id, id + step, ..., upto) read at line `at`.
   pure subroutine add_id(ns, id, at, upto, step)
      type(raw_nset_t), intent(inout) :: ns
      integer, intent(in) :: id, at
      integer, intent(in), optional :: upto, step
      ns%n = ns%n + 1
      call grow_int(ns%ids, ns%n)
      call grow_int(ns%upto, ns%n)
      call grow_int(ns%step, ns%n)
      call grow_int(ns%where, ns%n)
      ns%ids(ns%n) = id
      ns%upto(ns%n) = id
      ns%step(ns%n) = 1
      if (present(upto)) ns%upto(ns%n) = upto
      if (present(step)) ns%step(ns%n) = step
      ns%where(ns%n) = at
   end subroutine add_id

end module pecplas_io_deck_reader_mesh
