!> Deck handler for plates (beams with rotations):
!>   *PLATE, SET=name, EA=, EI= [, NU=0] [, W=0] [, NP=] [, MP=] [, NODES=node_set | EDGES=edge_set]
!>      data (explicit elements, without NODES/EDGES): n1, n2[, n3] (end, end[, mid]) node ids.
!> Resolved once the mesh is built (resolve_plates): a node set becomes the element sides all
!> of whose nodes it holds (or, for nodes of no massif element, the line through its nodes in
!> the order written), an edge set its edges; the nodes of every plate get a rotation.
module pecplas_io_deck_reader_plates
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_text_fields, only: deck_line_t, field_t, split_fields, field_int, parse_real, &
      same_name, upper, itoa
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, line_error, where_text, &
      grow_int, grow_int2
   use pecplas_io_deck_raw_plates, only: raw_plate_set_t
   use pecplas_io_deck_reader_mesh, only: check_name
   use pecplas_model_type, only: model_t
   use pecplas_model_plates, only: plate_set_t
   implicit none (type, external)
   private

   public :: read_plate, resolve_plates, extend_rotations

contains

   !> *PLATE, SET=name, EA=, EI= [, NU=] [, W=] [, NP=] [, MP=] [, NODES= | EDGES=].
   subroutine read_plate(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      type(raw_plate_set_t) :: ps
      type(raw_plate_set_t), allocatable :: tmp(:)
      logical :: has_nodes, has_edges
      integer :: i, n
      kwline = state%lines%get(block%at)
      associate (kw => block%kw)
         call kw%check_keys(kwline, [character(len=5) :: 'SET', 'EA', 'EI', 'NU', 'W', 'NP', &
            'MP', 'NODES', 'EDGES'], error)
         if (allocated(error)) return
         call kw%require(kwline, 'SET', ps%name, error)
         if (allocated(error)) return
         call check_name(state, block%at, ps%name, error)
         if (allocated(error)) return
         call section_value(state, block, 'EA', .true., ps%section%ea, error)
         if (allocated(error)) return
         call section_value(state, block, 'EI', .true., ps%section%ei, error)
         if (allocated(error)) return
         call section_value(state, block, 'NU', .false., ps%section%nu, error)
         if (allocated(error)) return
         if (.not. (ps%section%nu > -1.0_wp .and. ps%section%nu < 0.5_wp)) then
            call line_error(state, block%at, 'NU must lie in (-1, 0.5), found '// &
               trim(real_text(ps%section%nu)), error)
            return
         end if
         call section_value(state, block, 'W', .false., ps%section%w, error)
         if (allocated(error)) return
         call section_value(state, block, 'NP', .false., ps%section%np, error)
         if (allocated(error)) return
         call section_value(state, block, 'MP', .false., ps%section%mp, error)
         if (allocated(error)) return
         call kw%get('NODES', ps%nodes, has_nodes)
         call kw%get('EDGES', ps%edges, has_edges)
         if (has_nodes .and. has_edges) then
            call line_error(state, block%at, 'NODES=node_set and EDGES=edge_set exclude '// &
               'each other (the plate lies along one of them)', error)
            return
         end if
      end associate
      if (.not. allocated(state%plate_sets)) allocate (state%plate_sets(0))
      n = size(state%plate_sets)
      do i = 1, n
         if (same_name(state%plate_sets(i)%name, ps%name)) then
            call line_error(state, block%at, "plate set '"//ps%name//"' is defined twice "// &
               '(first at '//where_text(state, state%plate_sets(i)%at)//')', error)
            return
         end if
      end do
      ps%at = block%at
      if (has_nodes .or. has_edges) then
         if (block%last >= block%first) then
            call line_error(state, block%first, '*PLATE with NODES= or EDGES= generates its '// &
               "elements and takes no data lines, found '"//state%lines%text(block%first)// &
               "'", error)
            return
         end if
      else
         call read_explicit(state, block, ps, error)
         if (allocated(error)) return
      end if
      allocate (tmp(n + 1))
      tmp(1:n) = state%plate_sets
      tmp(n + 1) = ps
      call move_alloc(tmp, state%plate_sets)
   end subroutine read_plate

   !> Value of section parameter `key` (0 when optional and absent): a number, positive for
   !> EA and EI, not negative for the others.
   subroutine section_value(state, block, key, required, value, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      character(len=*), intent(in) :: key
      logical, intent(in) :: required
      real(wp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      logical :: found, ok
      value = 0.0_wp
      call block%kw%get(key, text, found)
      if (.not. found) then
         if (required) call line_error(state, block%at, 'missing required parameter '//key// &
            '= (the plate section: *PLATE, SET=name, EA=normal stiffness, EI=bending '// &
            'stiffness, per unit width)', error)
         return
      end if
      call parse_real(text, value, ok)
      if (.not. ok) then
         call line_error(state, block%at, key//" must be a number, found '"//text//"'", error)
         return
      end if
      if (key == 'NU') return
      if (required .and. .not. value > 0.0_wp) then
         call line_error(state, block%at, key//' must be positive, found '//text, error)
      else if (value < 0.0_wp) then
         call line_error(state, block%at, key//' must not be negative, found '//text, error)
      end if
   end subroutine section_value

   !> Data lines n1, n2[, n3] of explicit plate elements (one kind per set).
   subroutine read_explicit(state, block, ps, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      type(raw_plate_set_t), intent(inout) :: ps
      type(error_t), allocatable, intent(out) :: error
      type(field_t), allocatable :: f(:)
      integer :: i, j, id, nen
      if (block%last < block%first) then
         call line_error(state, block%at, 'no data lines: expected "n1, n2[, n3]" plate '// &
            'elements after *PLATE, or NODES=node_set or EDGES=edge_set to generate them', &
            error)
         return
      end if
      allocate (ps%where(0))
      do i = block%first, block%last
         allocate (f(0))
         call split_fields(state%lines%text(i), f)
         nen = size(f)
         if (nen /= 2 .and. nen /= 3) then
            call line_error(state, i, 'a plate element has 2 or 3 nodes "n1, n2[, n3]" '// &
               '(end, end[, mid]), found '//itoa(nen)//' field(s)', error)
            return
         end if
         if (ps%nen == 0) then
            ps%nen = nen
            allocate (ps%conn(nen, 0))
         else if (nen /= ps%nen) then
            call line_error(state, i, "plate set '"//ps%name//"' mixes 2-node and 3-node "// &
               'elements: one kind per set', error)
            return
         end if
         ps%n = ps%n + 1
         call grow_int(ps%where, ps%n)
         call grow_int2(ps%conn, nen, ps%n)
         do j = 1, nen
            call field_int(state%lines%get(i), f, j, 'node id', id, error)
            if (allocated(error)) return
            ps%conn(j, ps%n) = id
         end do
         ps%where(ps%n) = i
         deallocate (f)
      end do
      ps%where = ps%where(1:ps%n)
      ps%conn = ps%conn(:, 1:ps%n)
   end subroutine read_explicit

   !> model%plates from the *PLATE blocks, and the rotation of every plate node
   !> (model%node_rotation, numbered in node order). Call once the mesh is built.
   subroutine resolve_plates(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      integer :: p, i, j, k
      allocate (model%plates(0))
      allocate (model%node_rotation(model%mesh%nnode()), source=0)
      if (.not. allocated(state%plate_sets)) return
      deallocate (model%plates)
      allocate (model%plates(size(state%plate_sets)))
      do p = 1, size(state%plate_sets)
         associate (raw => state%plate_sets(p), pl => model%plates(p))
            pl%name = raw%name
            pl%section = raw%section
            pl%file = state%lines%file(raw%at)
            pl%line = state%lines%line(raw%at)
            if (model%analysis%kind == 2 .and. raw%section%plastic()) then
               call line_error(state, raw%at, 'NP= and MP= (plastic plates) are for plane '// &
                  'strain; an axisymmetric plate is elastic', error)
               return
            end if
            if (allocated(raw%nodes)) then
               if (len(raw%nodes) > 0) then
                  call plate_on_nodes(state, model, raw, pl, error)
                  if (allocated(error)) return
                  cycle
               end if
            end if
            if (allocated(raw%edges)) then
               if (len(raw%edges) > 0) then
                  k = model%mesh%find_edge_set(raw%edges)
                  if (k == 0) then
                     call line_error(state, raw%at, "undefined edge set '"//raw%edges// &
                        "' (EDGES= of *PLATE)", error)
                     return
                  end if
                  pl%conn = model%mesh%edge_sets(k)%nodes
                  pl%nen = size(pl%conn, 1)
                  cycle
               end if
            end if
            pl%nen = raw%nen
            allocate (pl%conn(raw%nen, raw%n))
            do i = 1, raw%n
               do j = 1, raw%nen
                  pl%conn(j, i) = state%node_lookup%index(raw%conn(j, i))
                  if (pl%conn(j, i) == 0) then
                     call line_error(state, raw%where(i), 'undefined node '// &
                        itoa(raw%conn(j, i))//': no *NODES line defines it', error)
                     return
                  end if
                  if (any(pl%conn(1:j - 1, i) == pl%conn(j, i))) then
                     call line_error(state, raw%where(i), 'plate element lists node '// &
                        itoa(raw%conn(j, i))//' twice', error)
                     return
                  end if
               end do
            end do
         end associate
      end do
      call check_lengths(state, model, error)
      if (allocated(error)) return
      do p = 1, size(model%plates)
         do i = 1, size(model%plates(p)%conn, 2)
            model%node_rotation(model%plates(p)%conn(:, i)) = 1
         end do
      end do
      k = 0
      do i = 1, size(model%node_rotation)
         if (model%node_rotation(i) == 0) cycle
         k = k + 1
         model%node_rotation(i) = k
      end do
   end subroutine resolve_plates

   !> Every plate element must have a length (its end nodes apart).
   subroutine check_lengths(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: size_model, h
      integer :: p, e
      size_model = maxval(abs(model%mesh%x))
      do p = 1, size(model%plates)
         associate (pl => model%plates(p))
            if (size(pl%conn, 2) == 0) then
               call line_error(state, state%plate_sets(p)%at, "plate set '"//pl%name// &
                  "' has no element", error)
               return
            end if
            do e = 1, size(pl%conn, 2)
               h = norm2(model%mesh%x(:, pl%conn(2, e)) - model%mesh%x(:, pl%conn(1, e)))
               if (h <= 1.0e-9_wp*size_model) then
                  call line_error(state, state%plate_sets(p)%at, "plate set '"//pl%name// &
                     "': element of zero length between nodes "// &
                     itoa(model%mesh%node_id(pl%conn(1, e)))//' and '// &
                     itoa(model%mesh%node_id(pl%conn(2, e))), error)
                  return
               end if
            end do
         end associate
      end do
   end subroutine check_lengths

   !> A plate along node set raw%nodes: the sides of massif elements all of whose nodes are
   !> in the set (each side once), chained along the line; when no node of the set belongs to
   !> a massif element, the line through its nodes in the order written. A node of the set
   !> on no such side is not on a line: an error at the *PLATE line.
   subroutine plate_on_nodes(state, model, raw, pl, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      type(raw_plate_set_t), intent(in) :: raw
      type(plate_set_t), intent(inout) :: pl
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: inset(:), used(:), onside(:)
      integer, allocatable :: nodes(:), sides(:, :)
      integer :: k, s, e, i, nc, nen, n, a, b, m
      k = model%mesh%find_nset(raw%nodes)
      if (k == 0) then
         call line_error(state, raw%at, "undefined node set '"//raw%nodes// &
            "' (NODES= of *PLATE)", error)
         return
      end if
      nodes = model%mesh%nsets(k)%nodes
      if (size(nodes) < 2) then
         call line_error(state, raw%at, "node set '"//raw%nodes//"' has "// &
            itoa(size(nodes))//' node(s): a plate needs a line of at least 2', error)
         return
      end if
      allocate (inset(model%mesh%nnode()), used(model%mesh%nnode()), source=.false.)
      inset(nodes) = .true.
      do s = 1, size(model%mesh%esets)
         used(pack(model%mesh%esets(s)%conn, .true.)) = .true.
      end do
      if (.not. any(used(nodes))) then
         ! nodes of no massif element: the line through them in the order written
         pl%nen = 2
         allocate (pl%conn(2, size(nodes) - 1))
         pl%conn(1, :) = nodes(1:size(nodes) - 1)
         pl%conn(2, :) = nodes(2:size(nodes))
         return
      end if
      allocate (sides(3, 0))
      nen = 0
      do s = 1, size(model%mesh%esets)
         associate (conn => model%mesh%esets(s)%conn)
            nc = merge(3, 4, size(conn, 1) == 3 .or. size(conn, 1) == 6)
            do e = 1, size(conn, 2)
               do i = 1, nc
                  a = conn(i, e)
                  b = conn(mod(i, nc) + 1, e)
                  m = 0
                  if (size(conn, 1) == 2*nc) m = conn(nc + i, e)
                  if (.not. (inset(a) .and. inset(b))) cycle
                  if (m > 0) then
                     if (.not. inset(m)) cycle
                  end if
                  if (seen_side(sides, a, b)) cycle
                  n = merge(3, 2, m > 0)
                  if (nen == 0) nen = n
                  if (n /= nen) then
                     call line_error(state, raw%at, "node set '"//raw%nodes//"' runs along "// &
                        'linear and quadratic element sides: one kind per plate set', error)
                     return
                  end if
                  sides = reshape([sides, a, b, m], [3, size(sides, 2) + 1])
               end do
            end do
         end associate
      end do
      allocate (onside(model%mesh%nnode()), source=.false.)
      do i = 1, size(sides, 2)
         onside(sides(1:2, i)) = .true.
         if (sides(3, i) > 0) onside(sides(3, i)) = .true.
      end do
      do i = 1, size(nodes)
         if (.not. onside(nodes(i))) then
            call line_error(state, raw%at, 'node '//itoa(model%mesh%node_id(nodes(i)))// &
               " of node set '"//raw%nodes//"' is not on a line of the plate (no element "// &
               'side joins it to another node of the set)', error)
            return
         end if
      end do
      pl%nen = nen
      pl%conn = chained(sides(1:nen, :), model%mesh%nnode())
   end subroutine plate_on_nodes

   !> True when the side a-b (either way) is already in `sides`.
   pure logical function seen_side(sides, a, b)
      integer, intent(in) :: sides(:, :), a, b
      integer :: i
      seen_side = .false.
      do i = 1, size(sides, 2)
         if ((sides(1, i) == a .and. sides(2, i) == b) .or. &
             (sides(1, i) == b .and. sides(2, i) == a)) seen_side = .true.
      end do
   end function seen_side

   !> The sides in the order of a walk along the lines they form, each turned so that its
   !> first node is the last node of the one before (a walk starts at a line's end).
   pure function chained(sides, nnode) result(conn)
      integer, intent(in) :: sides(:, :), nnode
      integer :: conn(size(sides, 1), size(sides, 2))
      integer :: degree(nnode), k, i, node, next
      logical :: done(size(sides, 2))
      degree = 0
      do i = 1, size(sides, 2)
         degree(sides(1:2, i)) = degree(sides(1:2, i)) + 1
      end do
      done = .false.
      k = 0
      do while (k < size(sides, 2))
         ! start at a free end of a line when there is one, else anywhere
         node = 0
         do i = 1, size(sides, 2)
            if (done(i)) cycle
            if (degree(sides(1, i)) == 1) node = sides(1, i)
            if (degree(sides(2, i)) == 1 .and. node == 0) node = sides(2, i)
            if (node > 0) exit
         end do
         if (node == 0) node = sides(1, findloc(done, .false., 1))
         do
            next = 0
            do i = 1, size(sides, 2)
               if (done(i)) cycle
               if (sides(1, i) == node) then
                  next = i
                  k = k + 1
                  conn(:, k) = sides(:, i)
               else if (sides(2, i) == node) then
                  next = i
                  k = k + 1
                  conn(:, k) = sides(:, i)
                  conn(1:2, k) = sides([2, 1], i)
               end if
               if (next > 0) exit
            end do
            if (next == 0) exit
            done(next) = .true.
            degree(sides(1:2, next)) = degree(sides(1:2, next)) - 1
            node = conn(2, k)
         end do
      end do
   end function chained

   !> Nodes added after the plates were resolved (duplicates of generated joints) carry no
   !> rotation.
   subroutine extend_rotations(model)
      type(model_t), intent(inout) :: model
      integer, allocatable :: tmp(:)
      if (.not. allocated(model%node_rotation)) allocate (model%node_rotation(0))
      if (size(model%node_rotation) >= model%mesh%nnode()) return
      allocate (tmp(model%mesh%nnode()), source=0)
      tmp(1:size(model%node_rotation)) = model%node_rotation
      call move_alloc(tmp, model%node_rotation)
   end subroutine extend_rotations

   pure function real_text(x) result(s)
      real(wp), intent(in) :: x
      character(len=32) :: s
      write (s, '(g0)') x
   end function real_text

end module pecplas_io_deck_reader_plates
