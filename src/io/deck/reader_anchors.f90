!> *ANCHOR (doc/deck.md, Anchors and struts):
!>   *ANCHOR, NAME=a, TYPE=NODE_TO_NODE, EA=EA [, SPACING=Ls] [, TENSION_LIMIT=Ft]
!>            [, COMPRESSION_LIMIT=Fc]            -- data: n1, n2 (one bar per line)
!>   *ANCHOR, NAME=s, TYPE=FIXED_END, EA=EA, LENGTH=L, ANGLE=deg [, SPACING=Ls] [, ...]
!>                                                -- data: nodes or node sets (one bar each)
!> A node is a node id or a node set (of one node for NODE_TO_NODE). The section is read
!> with the block; nodes are resolved once the mesh is built (before generated joints
!> split it: the bars keep the original nodes of a split line, those of a plate).
module pecplas_io_deck_reader_anchors
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_text_fields, only: deck_line_t, field_t, split_fields, parse_real, &
      parse_int, same_name, upper, add_name, itoa
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, line_error, where_text
   use pecplas_io_deck_raw_anchors, only: raw_anchor_t
   use pecplas_io_deck_reader_mesh, only: check_name
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: AXISYMMETRIC
   use pecplas_model_anchors, only: anchor_set_t, anchor_kind, ANCHOR_TYPES, &
      ANCHOR_FIXED_END, ANCHOR_NODE_TO_NODE
   implicit none (type, external)
   private

   public :: read_anchor, resolve_anchors

   real(wp), parameter :: PI = acos(-1.0_wp)

contains

   !> One *ANCHOR block: its section checked at the keyword line, its data lines kept.
   subroutine read_anchor(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      type(raw_anchor_t) :: raw
      character(len=:), allocatable :: text, list
      logical :: found
      integer :: i
      kwline = state%lines%get(block%at)
      associate (kw => block%kw, set => raw%set)
         call kw%check_keys(kwline, [character(len=17) :: 'NAME', 'TYPE', 'EA', 'SPACING', &
            'TENSION_LIMIT', 'COMPRESSION_LIMIT', 'LENGTH', 'ANGLE'], error)
         if (allocated(error)) return
         call kw%require(kwline, 'NAME', set%name, error)
         if (allocated(error)) return
         call check_name(state, block%at, set%name, error)
         if (allocated(error)) return
         call kw%require(kwline, 'TYPE', text, error)
         if (allocated(error)) return
         set%kind = anchor_kind(upper(text))
         if (set%kind == 0) then
            list = ''
            do i = 1, size(ANCHOR_TYPES)
               call add_name(list, trim(ANCHOR_TYPES(i)))
            end do
            call line_error(state, block%at, "unknown anchor type '"//upper(text)// &
               "'; known types:"//list, error)
            return
         end if
         call kw%require(kwline, 'EA', text, error)
         if (allocated(error)) return
         call positive(state, block%at, 'EA', text, set%ea, error)
         if (allocated(error)) return
         call optional_positive(state, block, 'SPACING', set%spacing, error)
         if (allocated(error)) return
         call optional_positive(state, block, 'TENSION_LIMIT', set%tension_limit, error)
         if (allocated(error)) return
         call optional_positive(state, block, 'COMPRESSION_LIMIT', set%compression_limit, error)
         if (allocated(error)) return
         if (set%kind == ANCHOR_FIXED_END) then
            allocate (set%length(1))
            call kw%require(kwline, 'LENGTH', text, error)
            if (allocated(error)) return
            call positive(state, block%at, 'LENGTH', text, set%length(1), error)
            if (allocated(error)) return
            call kw%require(kwline, 'ANGLE', text, error)
            if (allocated(error)) return
            call number(state, block%at, 'ANGLE', text, raw%angle, error)
            if (allocated(error)) return
         else
            call kw%get('LENGTH', text, found)
            if (.not. found) call kw%get('ANGLE', text, found)
            if (found) then
               call line_error(state, block%at, 'LENGTH= and ANGLE= are for FIXED_END '// &
                  'anchors; a NODE_TO_NODE anchor has the length and direction of its nodes', &
                  error)
               return
            end if
         end if
      end associate
      if (block%last < block%first) then
         if (raw%set%kind == ANCHOR_NODE_TO_NODE) then
            call line_error(state, block%at, '*ANCHOR needs data lines: "n1, n2" (the two '// &
               'nodes of a bar)', error)
         else
            call line_error(state, block%at, '*ANCHOR needs data lines: nodes or node sets '// &
               '(one bar per node)', error)
         end if
         return
      end if
      raw%at = block%at
      raw%where = [(i, i=block%first, block%last)]
      if (.not. allocated(state%anchors)) allocate (state%anchors(0))
      do i = 1, size(state%anchors)
         if (same_name(state%anchors(i)%set%name, raw%set%name)) then
            call line_error(state, block%at, "anchor '"//raw%set%name//"' is defined twice "// &
               '(first at '//where_text(state, state%anchors(i)%at)//')', error)
            return
         end if
      end do
      state%anchors = [state%anchors, raw]
   end subroutine read_anchor

   !> model%anchors from the raw blocks: nodes, lengths, directions; errors at the line.
   subroutine resolve_anchors(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      integer :: r
      allocate (model%anchors(0))
      if (.not. allocated(state%anchors)) return
      if (size(state%anchors) > 0 .and. model%analysis%kind == AXISYMMETRIC) then
         call line_error(state, state%anchors(1)%at, 'anchors are available in plane '// &
            'strain only (*ANALYSIS, TYPE=PLANE_STRAIN)', error)
         return
      end if
      deallocate (model%anchors)
      allocate (model%anchors(size(state%anchors)))
      do r = 1, size(state%anchors)
         call one_anchor(state, model, state%anchors(r), model%anchors(r), error)
         if (allocated(error)) return
      end do
   end subroutine resolve_anchors

   subroutine one_anchor(state, model, raw, set, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      type(raw_anchor_t), intent(in) :: raw
      type(anchor_set_t), intent(out) :: set
      type(error_t), allocatable, intent(out) :: error
      type(field_t), allocatable :: f(:)
      integer, allocatable :: nodes(:), conn(:, :), lines(:)
      real(wp) :: dx(2), len0
      integer :: i, k, a, b
      logical :: taken
      set = raw%set
      taken = same_name(set%name, 'ALL') .or. model%mesh%find_eset(set%name) > 0 .or. &
         model%mesh%find_nset(set%name) > 0
      if (allocated(state%joint_sets)) then
         do i = 1, size(state%joint_sets)
            if (same_name(state%joint_sets(i)%name, set%name)) taken = .true.
         end do
      end if
      if (allocated(model%plates)) then
         do i = 1, size(model%plates)
            if (same_name(model%plates(i)%name, set%name)) taken = .true.
         end do
      end if
      if (allocated(model%patterns)) then
         do i = 1, size(model%patterns)
            if (same_name(model%patterns(i)%name, set%name)) taken = .true.
         end do
      end if
      if (taken) then
         call line_error(state, raw%at, "anchor name '"//set%name//"' is the name of a set, "// &
            'plate or load pattern already: phases name them alike, give it another name', error)
         return
      end if
      set%file = state%lines%file(raw%at)
      set%line = state%lines%line(raw%at)
      allocate (conn(2, 0), lines(0))
      do i = 1, size(raw%where)
         call split_fields(state%lines%text(raw%where(i)), f)
         if (set%kind == ANCHOR_NODE_TO_NODE) then
            if (size(f) /= 2) then
               call line_error(state, raw%where(i), 'expected "n1, n2" (the two nodes of a '// &
                  'bar), found '//itoa(size(f))//' field(s)', error)
               return
            end if
            call one_node(state, model, raw%where(i), f(1)%s, a, error)
            if (allocated(error)) return
            call one_node(state, model, raw%where(i), f(2)%s, b, error)
            if (allocated(error)) return
            conn = reshape([conn, a, b], [2, size(conn, 2) + 1])
            lines = [lines, raw%where(i)]
         else
            do k = 1, size(f)
               call node_list(state, model, raw%where(i), f(k)%s, nodes, error)
               if (allocated(error)) return
               do a = 1, size(nodes)
                  conn = reshape([conn, nodes(a), 0], [2, size(conn, 2) + 1])
                  lines = [lines, raw%where(i)]
               end do
            end do
         end if
      end do
      set%conn = conn
      if (allocated(set%length)) deallocate (set%length)
      allocate (set%length(size(conn, 2)), set%direction(2, size(conn, 2)))
      do i = 1, size(conn, 2)
         if (set%kind == ANCHOR_FIXED_END) then
            set%length(i) = raw%set%length(1)
            set%direction(:, i) = [cos(raw%angle*PI/180.0_wp), sin(raw%angle*PI/180.0_wp)]
            cycle
         end if
         dx = model%mesh%x(:, conn(2, i)) - model%mesh%x(:, conn(1, i))
         len0 = norm2(dx)
         if (.not. len0 > 0.0_wp) then
            call line_error(state, lines(i), "anchor '"//set%name//"': nodes "// &
               itoa(model%mesh%node_id(conn(1, i)))//' and '// &
               itoa(model%mesh%node_id(conn(2, i)))//' are at the same point: a bar of '// &
               'zero length (a FIXED_END anchor takes a LENGTH= and an ANGLE=)', error)
            return
         end if
         set%length(i) = len0
         set%direction(:, i) = dx/len0
      end do
   end subroutine one_anchor

   !> The node that `ref` names (a node id or a node set of one node).
   subroutine one_node(state, model, at, ref, node, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      integer, intent(in) :: at
      character(len=*), intent(in) :: ref
      integer, intent(out) :: node
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: msg
      call model%mesh%node_of(ref, node, msg)
      if (node == 0) call line_error(state, at, 'anchor node: '//msg, error)
   end subroutine one_node

   !> The nodes that `ref` names: a node id or every node of a node set.
   subroutine node_list(state, model, at, ref, nodes, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      integer, intent(in) :: at
      character(len=*), intent(in) :: ref
      integer, allocatable, intent(out) :: nodes(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: id, k
      logical :: is_id
      call parse_int(ref, id, is_id)
      if (is_id) then
         k = state%node_lookup%index(id)
         if (k == 0) then
            call line_error(state, at, 'undefined node '//ref//': no *NODES line defines it', &
               error)
            return
         end if
         nodes = [k]
         return
      end if
      k = model%mesh%find_nset(ref)
      if (k == 0) then
         call line_error(state, at, "undefined node set '"//ref//"' (expected a node id "// &
            'or a node set)', error)
         return
      end if
      nodes = model%mesh%nsets(k)%nodes
   end subroutine node_list

   subroutine positive(state, at, key, text, value, error)
      type(deck_state_t), intent(in) :: state
      integer, intent(in) :: at
      character(len=*), intent(in) :: key, text
      real(wp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      call number(state, at, key, text, value, error)
      if (allocated(error)) return
      if (.not. value > 0.0_wp) call line_error(state, at, key//' must be positive, found '// &
         text, error)
   end subroutine positive

   subroutine optional_positive(state, block, key, value, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      character(len=*), intent(in) :: key
      real(wp), intent(inout) :: value
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      logical :: found
      call block%kw%get(key, text, found)
      if (found) call positive(state, block%at, key, text, value, error)
   end subroutine optional_positive

   subroutine number(state, at, key, text, value, error)
      type(deck_state_t), intent(in) :: state
      integer, intent(in) :: at
      character(len=*), intent(in) :: key, text
      real(wp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      logical :: ok
      call parse_real(text, value, ok)
      if (.not. ok) call line_error(state, at, key//" must be a number, found '"//text//"'", &
         error)
   end subroutine number

end module pecplas_io_deck_reader_anchors
