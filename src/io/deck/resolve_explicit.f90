!> Explicit joints of a *JOINTS block (data lines `id, n1, ...`): node ids resolved,
!> doublets distinct and coincident (closer than 1e-9 of the model size), line joints
!> oriented so that face 2 lies on the left of face 1 (checked against the elements having
!> the faces as sides), and for springs the joint edges (element sides along face 1) that
!> give their tributary measure and direction.
module pecplas_io_deck_resolve_explicit
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_text_fields, only: itoa
   use pecplas_io_deck_state, only: deck_state_t, line_error
   use pecplas_io_deck_raw_joints, only: raw_joint_set_t
   use pecplas_model_type, only: model_t
   use pecplas_model_joints, only: joint_set_t
   use pecplas_model_mesh_sides, only: side_table_t, build_side_table, find_sides, &
      element_centroid
   implicit none (type, external)
   private

   public :: explicit_joints

contains

   !> Explicit joints: node ids, distinct and coincident doublets, orientation.
   !> `allow_gap`: doublets may be apart (Katona node-to-node contact with an initial gap,
   !> checked by pecplas_joints_katona_doublets).
   subroutine explicit_joints(state, model, raw, set, edges, error, allow_gap)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      type(raw_joint_set_t), intent(in) :: raw
      type(joint_set_t), intent(inout) :: set
      integer, allocatable, intent(out) :: edges(:, :)
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: allow_gap
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
            if (dist > tol .and. .not. optval(allow_gap)) then
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
   end subroutine explicit_joints

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
   !> springs of the set, oriented with that element on the right (face 2 on the left), and
   !> the plate elements all of whose nodes are face-1 nodes (as written).
   subroutine spring_edges(model, table, face1, edges)
      type(model_t), intent(in) :: model
      type(side_table_t), intent(in) :: table
      integer, intent(in) :: face1(:)
      integer, allocatable, intent(out) :: edges(:, :)
      logical, allocatable :: is_face1(:)
      integer, allocatable :: found(:, :)
      real(wp) :: t(2), c(2)
      integer :: s, m, k, c1
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
      ! the elements of plates along face-1 nodes (springs under a plate on no massif
      ! element: a beam on a Winkler foundation)
      if (allocated(model%plates)) then
         do s = 1, size(model%plates)
            do k = 1, size(model%plates(s)%conn, 2)
               associate (pc => model%plates(s)%conn(:, k))
                  if (.not. all(is_face1(pc))) cycle
                  m = 0
                  do c1 = 1, size(found, 2)
                     if (min(found(1, c1), found(2, c1)) == min(pc(1), pc(2)) .and. &
                         max(found(1, c1), found(2, c1)) == max(pc(1), pc(2))) m = c1
                  end do
                  if (m > 0) cycle
                  if (size(pc) == 3) then
                     found = reshape([found, pc], [3, size(found, 2) + 1])
                  else
                     found = reshape([found, pc, 0], [3, size(found, 2) + 1])
                  end if
               end associate
            end do
         end do
      end if
      call move_alloc(found, edges)
   end subroutine spring_edges

   pure logical function optval(flag)
      logical, intent(in), optional :: flag
      optval = .false.
      if (present(flag)) optval = flag
   end function optval

end module pecplas_io_deck_resolve_explicit
