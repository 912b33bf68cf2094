!> Builds model%mesh from what the deck reader collected: nodes (deck and *MESH), the
!> user id -> internal number lookup, element sets with internal connectivity, node sets
!> and edge sets. Every unknown or repeated id is reported at the line that wrote it.
module pecplas_io_deck_resolve_mesh
   use iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_io_text_fields, only: itoa, same_name
   use pecplas_io_deck_state, only: deck_state_t, line_error, where_text
   use pecplas_io_deck_repeats, only: first_repeat
   use pecplas_io_deck_reader_mesh, only: element_nodes
   use pecplas_io_deck_mesh_import, only: append_imported
   use pecplas_model_type, only: model_t
   use pecplas_model_mesh, only: mesh_t, element_set_t, node_set_t, edge_set_t
   use pecplas_model_options, only: AXISYMMETRIC
   use pecplas_model_mesh_tools, only: orient_edge_sets
   use pecplas_model_node_lookup, only: node_lookup_t
   implicit none (type, external)
   private

   public :: build_mesh

contains

   !> Fills model%mesh; afterwards state%node_lookup maps user node ids to internal numbers.
   subroutine build_mesh(state, model, error)
      type(deck_state_t), intent(inout) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      integer :: dup(2)

      associate (mesh => model%mesh, n => state%nnode)
         allocate (mesh%x(2, n), mesh%node_id(n), mesh%esets(0), mesh%nsets(0), &
            mesh%edge_sets(0), state%mesh_eset_at(0), state%mesh_edge_set_at(0))
         if (n > 0) then
            mesh%x = state%x(:, 1:n)
            mesh%node_id = state%node_ids(1:n)
            state%mesh_node_at = state%node_at(1:n)
         else
            allocate (state%mesh_node_at(0))
         end if
         call append_imported(state, mesh, error)
         if (allocated(error)) return
         if (mesh%nnode() == 0) then
            if (state%lines%n == 0) then
               ! an empty file (or only comments): say so, and where to start
               call deck_error(error, model%deck_file, 0, '*NODES', 'no nodes: the deck '// &
                  'is empty (no keyword line, only blanks or comments); a deck is keyword '// &
                  'blocks *NODES, *ELEMENTS (or *MESH), *MATERIAL, *SECTION, *BOUNDARY, '// &
                  '*LOAD, *STEP: see the complete example of doc/deck.md')
            else
               call deck_error(error, model%deck_file, 0, '*NODES', &
                  'no nodes: the deck defines no *NODES (and no *MESH)')
            end if
            return
         end if
         ! the lookup finds a repeated id in O(n); the message names the first repeat
         ! and both its lines
         call state%node_lookup%build(mesh, error)
         if (allocated(error)) then
            dup = first_repeat(mesh%node_id)
            if (dup(2) > 0) call line_error(state, state%mesh_node_at(dup(2)), &
               'duplicate node id '//itoa(mesh%node_id(dup(2)))//' (first defined at '// &
               where_text(state, state%mesh_node_at(dup(1)))//')', error)
            return
         end if
      end associate
      if (model%analysis%kind == AXISYMMETRIC) then
         call check_radius(state, model%mesh, error)
         if (allocated(error)) return
      end if
      call add_element_sets(state, model, error)
      if (allocated(error)) return
      call check_element_ids(state, model%mesh, error)
      if (allocated(error)) return
      call add_node_sets(state, model%mesh, error)
      if (allocated(error)) return
      call add_edge_sets(state, model%mesh, error)
      if (allocated(error)) return
      call orient_edges(state, model%mesh, error)
   end subroutine build_mesh

   !> Orders every edge so that the body lies on its left (pressures are copied from the
   !> edge sets into the load patterns, so this must happen before). An edge that is no
   !> element side is reported at the line that defined its set.
   subroutine orient_edges(state, mesh, error)
      type(deck_state_t), intent(in) :: state
      type(mesh_t), intent(inout) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(mesh_t) :: one
      character(len=:), allocatable :: message
      integer :: k
      call orient_edge_sets(mesh, error)
      if (.not. allocated(error)) return
      message = error%message
      ! find the set at fault (error path only: one set at a time)
      do k = 1, size(mesh%edge_sets)
         one%x = mesh%x
         one%node_id = mesh%node_id
         one%esets = mesh%esets
         if (allocated(one%edge_sets)) deallocate (one%edge_sets)
         allocate (one%edge_sets(1))
         one%edge_sets(1) = mesh%edge_sets(k)
         call orient_edge_sets(one, e)
         if (allocated(e)) then
            call line_error(state, state%mesh_edge_set_at(k), message, error)
            return
         end if
      end do
   end subroutine orient_edges

   !> Axisymmetric: x is the radius and must not be negative (rounding from a mesher
   !> tolerated up to 1e-9 of the model size).
   subroutine check_radius(state, mesh, error)
      type(deck_state_t), intent(in) :: state
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: tol
      character(len=24) :: buf
      integer :: i
      tol = 1.0e-9_wp*max(1.0_wp, maxval(abs(mesh%x)))
      do i = 1, mesh%nnode()
         if (mesh%x(1, i) >= -tol) cycle
         write (buf, '(es12.4)') mesh%x(1, i)
         call line_error(state, state%mesh_node_at(i), 'AXISYMMETRIC analysis: node '// &
            itoa(mesh%node_id(i))//' has a negative radius x = '//trim(adjustl(buf)), error)
         return
      end do
   end subroutine check_radius

   subroutine add_element_sets(state, model, error)
      type(deck_state_t), intent(inout) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      type(element_set_t) :: es
      integer :: i, k, e, j, nen, c(9)
      ! a deck of plates alone (a frame, a beam) needs no massif element
      if (.not. allocated(state%esets) .and. size(model%mesh%esets) == 0 .and. &
          .not. allocated(state%plate_sets)) then
         call deck_error(error, model%deck_file, 0, '*ELEMENTS', &
            'no elements: the deck defines no *ELEMENTS (and no *MESH, no *PLATE)')
         return
      end if
      if (.not. allocated(state%esets)) return
      do i = 1, size(state%esets)
         associate (raw => state%esets(i))
            k = model%mesh%find_eset(raw%name)
            if (k > 0) then
               call line_error(state, raw%at, "element set '"//raw%name// &
                  "' is already defined by *MESH at "// &
                  where_text(state, state%mesh_eset_at(k)), error)
               return
            end if
            nen = element_nodes(raw%etype)
            es%name = raw%name
            es%etype = raw%etype
            if (allocated(es%conn)) deallocate (es%conn, es%ids)
            allocate (es%conn(nen, raw%n), es%ids(raw%n))
            es%ids = raw%ids(1:raw%n)
            do e = 1, raw%n
               ! a local copy of the element's nodes: no reload of es%conn at every step
               do j = 1, nen
                  c(j) = state%node_lookup%index(raw%conn(j, e))
                  if (c(j) == 0) then
                     call line_error(state, raw%where(e), 'undefined node '// &
                        itoa(raw%conn(j, e))//' in element '//itoa(raw%ids(e))// &
                        ': no *NODES line defines it', error)
                     return
                  end if
                  if (any(c(1:j - 1) == c(j))) then
                     call line_error(state, raw%where(e), 'element '//itoa(raw%ids(e))// &
                        ' lists node '//itoa(raw%conn(j, e))//' twice', error)
                     return
                  end if
               end do
               es%conn(:, e) = c(1:nen)
               if (degenerate(model%mesh%x, c(1:nen))) then
                  call line_error(state, raw%where(e), 'element '//itoa(raw%ids(e))// &
                     ' is degenerate (zero area): its corner nodes are on one line', error)
                  return
               end if
            end do
            call append_eset(model%mesh, es)
            state%mesh_eset_at = [state%mesh_eset_at, raw%at]
         end associate
      end do
   end subroutine add_element_sets

   !> Zero area of the corner polygon (the first 3 or 4 nodes), relative to its size.
   !> Clockwise elements are not an error: check_elements (mesh tools) renumbers them.
   pure logical function degenerate(x, conn)
      real(wp), intent(in) :: x(:, :)
      integer, intent(in) :: conn(:)
      real(wp) :: area, size2
      integer :: nc, i, j
      nc = 3
      if (size(conn) == 4 .or. size(conn) == 8) nc = 4
      area = 0.0_wp
      size2 = 0.0_wp
      do i = 1, nc
         j = mod(i, nc) + 1
         area = area + x(1, conn(i))*x(2, conn(j)) - x(1, conn(j))*x(2, conn(i))
         size2 = max(size2, sum((x(:, conn(j)) - x(:, conn(i)))**2))
      end do
      degenerate = abs(0.5_wp*area) <= 1.0e-12_wp*size2
   end function degenerate

   !> Element ids are unique over the model (all sets, deck and *MESH).
   subroutine check_element_ids(state, mesh, error)
      type(deck_state_t), intent(in) :: state
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(node_lookup_t) :: unique
      integer, allocatable :: ids(:), at(:)
      integer :: i, k, n, dup(2)
      n = 0
      do i = 1, size(mesh%esets)
         n = n + size(mesh%esets(i)%ids)
      end do
      allocate (ids(n), at(n))
      n = 0
      do i = 1, size(mesh%esets)
         ids(n + 1:n + size(mesh%esets(i)%ids)) = mesh%esets(i)%ids
         n = n + size(mesh%esets(i)%ids)
      end do
      ! a lookup of the ids is built in O(n) when they are all different (the usual case)
      call unique%build_ids(ids, 'element id', error)
      if (.not. allocated(error)) return
      deallocate (error)
      ! a repeat: the line of every element, to name the first repeat and both its lines
      n = 0
      do i = 1, size(mesh%esets)
         k = 0
         if (allocated(state%esets)) then
            do k = size(state%esets), 1, -1
               if (same_name(state%esets(k)%name, mesh%esets(i)%name)) exit
            end do
         end if
         if (k > 0) then
            at(n + 1:n + size(mesh%esets(i)%ids)) = state%esets(k)%where(1:state%esets(k)%n)
         else
            at(n + 1:n + size(mesh%esets(i)%ids)) = state%mesh_eset_at(i)
         end if
         n = n + size(mesh%esets(i)%ids)
      end do
      dup = first_repeat(ids)
      if (dup(2) > 0) call line_error(state, at(dup(2)), 'duplicate element id '// &
         itoa(ids(dup(2)))//' (first defined at '//where_text(state, at(dup(1)))//')', error)
   end subroutine check_element_ids

   subroutine add_node_sets(state, mesh, error)
      type(deck_state_t), intent(in) :: state
      type(mesh_t), intent(inout) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(node_set_t) :: ns
      logical, allocatable :: seen(:)
      integer :: i, j, n, node, id
      integer(int64) :: count
      if (.not. allocated(state%nsets)) return
      allocate (seen(mesh%nnode()))
      do i = 1, size(state%nsets)
         associate (raw => state%nsets(i))
            if (mesh%find_nset(raw%name) > 0) then
               call line_error(state, raw%at, "node set '"//raw%name// &
                  "' is already defined by *MESH", error)
               return
            end if
            ns%name = raw%name
            if (allocated(ns%nodes)) deallocate (ns%nodes)
            ! a set holds each node once, so no range can list more ids than there are nodes
            do j = 1, raw%n
               count = (int(raw%upto(j), int64) - raw%ids(j))/raw%step(j) + 1
               if (count > mesh%nnode()) then
                  call line_error(state, raw%where(j), 'GENERATE range '//itoa(raw%ids(j))// &
                     ', '//itoa(raw%upto(j))//', '//itoa(raw%step(j))//' lists '// &
                     itoa(int(count))//" ids, more than the "//itoa(mesh%nnode())// &
                     ' nodes of the mesh (every id of a node set must be a node)', error)
                  return
               end if
            end do
            allocate (ns%nodes(mesh%nnode()))
            n = 0
            seen = .false.
            do j = 1, raw%n
               do id = raw%ids(j), raw%upto(j), raw%step(j)
                  node = state%node_lookup%index(id)
                  if (node == 0) then
                     call line_error(state, raw%where(j), 'undefined node '//itoa(id)// &
                        " in node set '"//raw%name//"': no *NODES line defines it", error)
                     return
                  end if
                  if (seen(node)) cycle
                  seen(node) = .true.
                  n = n + 1
                  ns%nodes(n) = node
               end do
            end do
            ns%nodes = ns%nodes(1:n)
            call append_nset(mesh, ns)
         end associate
      end do
   end subroutine add_node_sets

   subroutine add_edge_sets(state, mesh, error)
      type(deck_state_t), intent(inout) :: state
      type(mesh_t), intent(inout) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(edge_set_t) :: es
      integer :: i, j, k
      if (.not. allocated(state%edge_sets)) return
      do i = 1, size(state%edge_sets)
         associate (raw => state%edge_sets(i))
            if (mesh%find_edge_set(raw%name) > 0) then
               call line_error(state, raw%at, "edge set '"//raw%name// &
                  "' is already defined by *MESH", error)
               return
            end if
            es%name = raw%name
            if (allocated(es%nodes)) deallocate (es%nodes)
            allocate (es%nodes(raw%nen, raw%n))
            do j = 1, raw%n
               do k = 1, raw%nen
                  es%nodes(k, j) = state%node_lookup%index(raw%nodes(k, j))
                  if (es%nodes(k, j) == 0) then
                     call line_error(state, raw%where(j), 'undefined node '// &
                        itoa(raw%nodes(k, j))//" in edge set '"//raw%name// &
                        "': no *NODES line defines it", error)
                     return
                  end if
                  if (any(es%nodes(1:k - 1, j) == es%nodes(k, j))) then
                     call line_error(state, raw%where(j), 'edge lists node '// &
                        itoa(raw%nodes(k, j))//' twice', error)
                     return
                  end if
               end do
            end do
            call append_edge_set(mesh, es)
            state%mesh_edge_set_at = [state%mesh_edge_set_at, raw%at]
         end associate
      end do
   end subroutine add_edge_sets

   !> Appends a set (explicit copies: gfortran 12 loses deferred-length components of
   !> derived types in array constructors).
   subroutine append_eset(mesh, es)
      type(mesh_t), intent(inout) :: mesh
      type(element_set_t), intent(in) :: es
      type(element_set_t), allocatable :: tmp(:)
      integer :: n
      n = size(mesh%esets)
      allocate (tmp(n + 1))
      tmp(1:n) = mesh%esets
      tmp(n + 1) = es
      call move_alloc(tmp, mesh%esets)
   end subroutine append_eset

   subroutine append_nset(mesh, ns)
      type(mesh_t), intent(inout) :: mesh
      type(node_set_t), intent(in) :: ns
      type(node_set_t), allocatable :: tmp(:)
      integer :: n
      n = size(mesh%nsets)
      allocate (tmp(n + 1))
      tmp(1:n) = mesh%nsets
      tmp(n + 1) = ns
      call move_alloc(tmp, mesh%nsets)
   end subroutine append_nset

   subroutine append_edge_set(mesh, es)
      type(mesh_t), intent(inout) :: mesh
      type(edge_set_t), intent(in) :: es
      type(edge_set_t), allocatable :: tmp(:)
      integer :: n
      n = size(mesh%edge_sets)
      allocate (tmp(n + 1))
      tmp(1:n) = mesh%edge_sets
      tmp(n + 1) = es
      call move_alloc(tmp, mesh%edge_sets)
   end subroutine append_edge_set

end module pecplas_io_deck_resolve_mesh
