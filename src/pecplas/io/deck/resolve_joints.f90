!> Resolves the *JOINTS blocks once the mesh, supports and patterns are built: the law of
!> each set, explicit joints (node ids, coincident doublets, orientation against the bodies
!> they join) and generated joints (node doublets created along EDGES for the body SIDE,
!> pecplas_model_mesh_split). Splitting nodes also updates what referred to them:
!> - a support or an imposed displacement on a split node also holds its duplicate (the
!>   doublet sits at one point, both bodies are held there);
!> - point forces stay on the original node (a load is not doubled);
!> - pressures on sides of the SIDE body move to the duplicates; node sets gain them.
!> Springs get their tributary measure and tangent from the joint edges around them.
module pecplas_io_deck_resolve_joints
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t
   use pecplas_io_deck_fields, only: same_name, add_name, itoa
   use pecplas_io_deck_state, only: deck_state_t, line_error, where_text
   use pecplas_io_deck_raw_joints, only: raw_joint_set_t
   use pecplas_io_deck_repeats, only: first_repeat
   use pecplas_model, only: model_t
   use pecplas_model_joints, only: joint_set_t
   use pecplas_model_mesh_split, only: split_result_t, split_along_edges, remap_side_edges
   use pecplas_model_mesh_sides, only: side_table_t, build_side_table, find_sides, &
      element_centroid
   use pecjoin_tributary, only: spring_tributaries
   implicit none (type, external)
   private

   public :: resolve_joints

   real(wp), parameter :: PI = acos(-1.0_wp)

contains

   !> Fills model%joint_sets (deck order); model%laws is allocated even when empty.
   subroutine resolve_joints(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      type(joint_set_t), allocatable :: tmp(:)
      type(joint_set_t) :: set
      integer, allocatable :: origin(:), ids(:), at(:)
      integer :: r, n, i, next_id, dup(2)
      if (.not. allocated(model%laws)) allocate (model%laws(0))
      if (.not. allocated(model%joint_sets)) allocate (model%joint_sets(0))
      if (.not. allocated(state%joint_sets)) return
      origin = [(i, i=1, model%mesh%nnode())]
      allocate (ids(0), at(0))
      do i = 1, size(model%mesh%esets)
         ids = [ids, model%mesh%esets(i)%ids]
      end do
      at = [(0, i=1, size(ids))]
      next_id = 0
      if (size(ids) > 0) next_id = maxval(ids)
      do r = 1, size(state%joint_sets)
         associate (raw => state%joint_sets(r))
            do i = 1, raw%n
               next_id = max(next_id, raw%ids(i))
            end do
         end associate
      end do
      do r = 1, size(state%joint_sets)
         call one_set(state, model, state%joint_sets(r), origin, next_id, set, error)
         if (allocated(error)) return
         n = size(model%joint_sets)
         allocate (tmp(n + 1))
         tmp(1:n) = model%joint_sets
         tmp(n + 1) = set
         call move_alloc(tmp, model%joint_sets)
         ids = [ids, set%ids]
         if (state%joint_sets(r)%n > 0) then
            at = [at, state%joint_sets(r)%where]
         else
            at = [at, spread(state%joint_sets(r)%at, 1, size(set%ids))]
         end if
      end do
      dup = first_repeat(ids)
      if (dup(2) > 0) then
         if (at(dup(1)) > 0) then
            call line_error(state, at(dup(2)), 'duplicate element id '//itoa(ids(dup(2)))// &
               ' (first defined at '//where_text(state, at(dup(1)))//')', error)
         else
            call line_error(state, at(dup(2)), 'duplicate element id '//itoa(ids(dup(2)))// &
               ': a massif element has it already (ids are unique over the model)', error)
         end if
      end if
   end subroutine resolve_joints

   subroutine one_set(state, model, raw, origin, next_id, set, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(raw_joint_set_t), intent(in) :: raw
      integer, allocatable, intent(inout) :: origin(:)
      integer, intent(inout) :: next_id
      type(joint_set_t), intent(out) :: set
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: edges(:, :)
      integer :: i, bad
      set%name = raw%name
      set%etype = raw%etype
      set%law = raw%law
      set%integration = raw%integration
      set%thickness = raw%thickness
      do i = 1, size(model%laws)
         if (same_name(model%laws(i)%law%name, raw%law)) set%law_index = i
      end do
      if (set%law_index == 0) then
         call line_error(state, raw%at, "undefined interface law '"//raw%law// &
            "'; known laws:"//law_names(model), error)
         return
      end if
      if (len(raw%edges) > 0) then
         call generated(state, model, raw, origin, next_id, set, edges, error)
      else
         call explicit(state, model, raw, set, edges, error)
      end if
      if (allocated(error)) return
      if (set%etype /= 'SPRING') return
      allocate (set%tributary(size(set%conn, 2)), set%tangent(2, size(set%conn, 2)))
      call spring_tributaries(model%mesh%x, model%analysis%kind, model%analysis%thickness, &
         set%conn(1, :), edges, set%tributary, set%tangent, bad, error)
      if (allocated(error)) then
         call line_error(state, spring_line(raw, bad), "joint set '"//set%name// &
            "', spring "//itoa(set%ids(bad))//' at node '// &
            itoa(model%mesh%node_id(set%conn(1, bad)))//': '//error%message, error)
         return
      end if
      if (raw%has_angle) set%tangent = spread([cos(raw%angle*PI/180.0_wp), &
         sin(raw%angle*PI/180.0_wp)], 2, size(set%conn, 2))
   end subroutine one_set

   !> ' a b' names of the interface laws (for messages).
   function law_names(model) result(list)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: list
      integer :: i
      list = ''
      do i = 1, size(model%laws)
         call add_name(list, model%laws(i)%law%name)
      end do
      if (len(list) == 0) list = ' (none: define one with *INTERFACE_LAW, NAME=..., TYPE=...)'
   end function law_names

   !> ' a b' names of the edge sets (edges) or element sets (for messages).
   function set_names(model, edges) result(list)
      type(model_t), intent(in) :: model
      logical, intent(in) :: edges
      character(len=:), allocatable :: list
      integer :: i
      list = ''
      if (edges) then
         do i = 1, size(model%mesh%edge_sets)
            call add_name(list, model%mesh%edge_sets(i)%name)
         end do
      else
         do i = 1, size(model%mesh%esets)
            call add_name(list, model%mesh%esets(i)%name)
         end do
      end if
      if (len(list) == 0) list = ' (none)'
   end function set_names

   pure integer function spring_line(raw, k) result(at)
      type(raw_joint_set_t), intent(in) :: raw
      integer, intent(in) :: k
      at = raw%at
      if (raw%n >= k .and. k > 0) at = raw%where(k)
   end function spring_line

   !> EDGES=, SIDE=: splits the mesh and builds the set; edges(nen, m) = face-1 joint edges.
   subroutine generated(state, model, raw, origin, next_id, set, edges, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(raw_joint_set_t), intent(in) :: raw
      integer, allocatable, intent(inout) :: origin(:)
      integer, intent(inout) :: next_id
      type(joint_set_t), intent(inout) :: set
      integer, allocatable, intent(out) :: edges(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(split_result_t) :: res
      type(error_t), allocatable :: e
      integer, allocatable :: dupof(:)
      integer :: ke, ks, nen, nn0, i
      ke = model%mesh%find_edge_set(raw%edges)
      if (ke == 0) then
         call line_error(state, raw%at, "undefined edge set '"//raw%edges// &
            "' in EDGES=; known edge sets:"//set_names(model, .true.), error)
         return
      end if
      ks = model%mesh%find_eset(raw%side)
      if (ks == 0) then
         call line_error(state, raw%at, "undefined element set '"//raw%side// &
            "' in SIDE=; known element sets:"//set_names(model, .false.), error)
         return
      end if
      nen = size(model%mesh%edge_sets(ke)%nodes, 1)
      if ((set%etype == 'GOODMAN4' .and. nen /= 2) .or. (set%etype == 'GOODMAN6' .and. &
          nen /= 3)) then
         call line_error(state, raw%at, set%etype//" joints need "// &
            trim(merge('2-node (linear)   ', '3-node (quadratic)', nen == 3))//" edges; edge set '" &
            //raw%edges//"' has "//itoa(nen)//'-node edges: use '// &
            trim(merge('GOODMAN6', 'GOODMAN4', nen == 3))//' (or THIN_LAYER, SPRING)', error)
         return
      end if
      nn0 = model%mesh%nnode()
      call split_along_edges(model%mesh, ke, ks, origin, res, e)
      if (allocated(e)) then
         call line_error(state, raw%at, e%message, error)
         return
      end if
      allocate (dupof(nn0), source=0)
      do i = 1, size(res%created, 2)
         dupof(res%created(1, i)) = res%created(2, i)
      end do
      call extend_to_duplicates(model, ks, dupof)
      if (set%etype == 'SPRING') then
         set%conn = res%doublets
      else
         set%conn = res%conn
      end if
      edges = res%conn([1, 2], :)
      if (nen == 3) edges = res%conn([1, 2, 5], :)
      set%ids = [(next_id + i, i=1, size(set%conn, 2))]
      next_id = next_id + size(set%conn, 2)
   end subroutine generated

   !> Supports and imposed displacements on split nodes also hold the duplicates; pressure
   !> edges on SIDE-only sides move to them (point forces stay where they were given).
   subroutine extend_to_duplicates(model, ks, dupof)
      type(model_t), intent(inout) :: model
      integer, intent(in) :: ks, dupof(:)
      integer :: k, p, n
      associate (sup => model%supports)
         if (allocated(sup%node)) then
            n = size(sup%node)
            do k = 1, n
               if (dupof(sup%node(k)) == 0) cycle
               sup%node = [sup%node, dupof(sup%node(k))]
               sup%dof = [sup%dof, sup%dof(k)]
            end do
         end if
      end associate
      if (.not. allocated(model%patterns)) return
      do p = 1, size(model%patterns)
         associate (pat => model%patterns(p))
            select case (pat%kind)
            case ('DISPLACEMENT')
               n = size(pat%node)
               do k = 1, n
                  if (dupof(pat%node(k)) == 0) cycle
                  pat%node = [pat%node, dupof(pat%node(k))]
                  pat%dof = [pat%dof, pat%dof(k)]
                  pat%value = [pat%value, pat%value(k)]
               end do
            case ('PRESSURE')
               call remap_side_edges(model%mesh, ks, dupof, pat%edge)
            end select
         end associate
      end do
   end subroutine extend_to_duplicates

   !> Explicit joints: node ids, distinct and coincident doublets, orientation.
   subroutine explicit(state, model, raw, set, edges, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      type(raw_joint_set_t), intent(in) :: raw
      type(joint_set_t), intent(inout) :: set
      integer, allocatable, intent(out) :: edges(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(side_table_t) :: table
      integer :: e, j, nen, npair
      integer :: pairs(2, 3)
      real(wp) :: tol, dist
      character(len=24) :: b1, b2
      nen = raw%nen
      allocate (set%conn(nen, raw%n))
      set%ids = raw%ids
      tol = 1.0e-9_wp*max(norm2(maxval(model%mesh%x, dim=2) - minval(model%mesh%x, dim=2)), &
         tiny(1.0_wp))
      ! doublets: (1, 2) for springs; (1, 4), (2, 3) [, (5, 6)] for line joints
      pairs = reshape([1, 4, 2, 3, 5, 6], [2, 3])
      npair = nen/2
      if (nen == 2) pairs(:, 1) = [1, 2]
      do e = 1, raw%n
         do j = 1, nen
            set%conn(j, e) = state%node_lookup%index(raw%nodes(j, e))
            if (set%conn(j, e) == 0) then
               call line_error(state, raw%where(e), 'undefined node '//itoa(raw%nodes(j, e))// &
                  ' in joint '//itoa(raw%ids(e))//': no *NODES line defines it', error)
               return
            end if
            if (any(set%conn(1:j - 1, e) == set%conn(j, e))) then
               call line_error(state, raw%where(e), 'joint '//itoa(raw%ids(e))// &
                  ' lists node '//itoa(raw%nodes(j, e))//' twice', error)
               return
            end if
         end do
         do j = 1, npair
            dist = norm2(model%mesh%x(:, set%conn(pairs(1, j), e)) - &
               model%mesh%x(:, set%conn(pairs(2, j), e)))
            if (dist > tol) then
               write (b1, '(es10.3)') dist
               write (b2, '(es10.3)') tol
               call line_error(state, raw%where(e), 'joint on non-coincident nodes: joint '// &
                  itoa(raw%ids(e))//' of set '//raw%name//' joins nodes '// &
                  itoa(raw%nodes(pairs(1, j), e))//' and '//itoa(raw%nodes(pairs(2, j), e))// &
                  ' which are '//trim(adjustl(b1))//' apart (tolerance '//trim(adjustl(b2))// &
                  '): a doublet is two nodes at one point', error)
               return
            end if
         end do
      end do
      call build_side_table(model%mesh, table)
      if (nen == 2) then
         call spring_edges(model, table, set%conn(1, :), edges)
         return
      end if
      allocate (edges(0, 0))
      do e = 1, raw%n
         if (inverted(model, table, set%conn(:, e))) then
            call line_error(state, raw%where(e), 'joint '//itoa(raw%ids(e))//' is inverted: '// &
               'face 2 (n3, n4) must lie on the left of face 1 walked from n1 to n2, so that '// &
               'the joint normal points from face 1 into face 2; write it as "id, n2, n1, '// &
               'n4, n3'//trim(merge(', n5, n6', '        ', nen == 6))//'"', error)
            return
         end if
      end do
   end subroutine explicit

   !> True when an element having face 1 as a side lies on the left of 1 -> 2, or one having
   !> face 2 as a side on its right (faces attached to no element are not checked).
   logical function inverted(model, table, conn)
      type(model_t), intent(in) :: model
      type(side_table_t), intent(in) :: table
      integer, intent(in) :: conn(:)
      integer, allocatable :: sides(:)
      real(wp) :: x1(2), n(2), c(2)
      integer :: k
      allocate (sides(0)) ! gives the descriptor bounds (silences a gfortran 12 false warning)
      x1 = model%mesh%x(:, conn(1))
      n = model%mesh%x(:, conn(2)) - x1
      n = [-n(2), n(1)]
      inverted = .false.
      if (size(conn) == 6) then
         sides = find_sides(table, conn([1, 2, 5]))
      else
         sides = find_sides(table, conn([1, 2]))
      end if
      do k = 1, size(sides)
         c = element_centroid(model%mesh, table%set(sides(k)), table%elem(sides(k)))
         if (dot_product(n, c - x1) > 0.0_wp) inverted = .true.
      end do
      if (size(conn) == 6) then
         sides = find_sides(table, conn([4, 3, 6]))
      else
         sides = find_sides(table, conn([4, 3]))
      end if
      do k = 1, size(sides)
         c = element_centroid(model%mesh, table%set(sides(k)), table%elem(sides(k)))
         if (dot_product(n, c - x1) < 0.0_wp) inverted = .true.
      end do
   end function inverted

   !> Joint edges of explicit springs: element sides all of whose nodes are face-1 nodes of
   !> springs of the set, oriented with that element on the right (face 2 on the left).
   subroutine spring_edges(model, table, face1, edges)
      type(model_t), intent(in) :: model
      type(side_table_t), intent(in) :: table
      integer, intent(in) :: face1(:)
      integer, allocatable, intent(out) :: edges(:, :)
      logical, allocatable :: is_face1(:)
      integer, allocatable :: found(:, :)
      real(wp) :: t(2), c(2)
      integer :: s, m, k
      allocate (is_face1(model%mesh%nnode()), source=.false.)
      is_face1(face1) = .true.
      allocate (found(3, 0))
      do s = 1, size(table%set)
         associate (nd => table%nodes(:, s))
            if (.not. (is_face1(nd(1)) .and. is_face1(nd(2)))) cycle
            if (nd(3) > 0) then
               if (.not. is_face1(nd(3))) cycle
            end if
            ! the same side seen from two elements is one joint edge
            m = 0
            do k = 1, size(found, 2)
               if (min(found(1, k), found(2, k)) == min(nd(1), nd(2)) .and. &
                   max(found(1, k), found(2, k)) == max(nd(1), nd(2))) m = k
            end do
            if (m > 0) cycle
            c = element_centroid(model%mesh, table%set(s), table%elem(s))
            t = model%mesh%x(:, nd(2)) - model%mesh%x(:, nd(1))
            if (-t(2)*(c(1) - model%mesh%x(1, nd(1))) + t(1)*(c(2) - model%mesh%x(2, nd(1))) &
                > 0.0_wp) then
               found = reshape([found, nd(2), nd(1), nd(3)], [3, size(found, 2) + 1])
            else
               found = reshape([found, nd], [3, size(found, 2) + 1])
            end if
         end associate
      end do
      call move_alloc(found, edges)
   end subroutine spring_edges

end module pecplas_io_deck_resolve_joints
