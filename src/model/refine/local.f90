!> Local refinement of a model in memory: the marked massif elements are refined (their
!> sides split at mid-length) and the marks are closed so that the mesh stays conforming,
!> without hanging nodes (pecplas_model_refine_local_edges); T3, T6, Q4, Q8 and Q8R.
!> Conforming closure keeps the dof and constraint machinery unchanged: a quadrilateral next
!> to a refined one is split in two, so the refinement runs along quadrilateral strips to the
!> boundary or a joint; triangles are bisected.
!> New nodes are placed by the parent's isoparametric map (curved quadratic sides stay on
!> their curve) and numbered after the original ones, with ids above the largest; a refined
!> element's first child keeps its id. What refers to nodes is carried over:
!> - joints (GOODMAN4/6, THIN_LAYER) are split with their neighbours, springs gain doublets
!>   at the new nodes of their faces (tributary measures recomputed), Katona doublets follow;
!> - edge sets and pressure edges are split; the new nodes of a boundary side join a node set,
!>   a support or an imposed displacement (interpolated along the side) held by both ends.
!> Point forces on both ends of a split side, and supports or imposed displacements on both
!> ends of a split interior side, are refused with a one-line reason (their share on the new
!> nodes is not knowable from the resolved lists).
module pecplas_model_refine_local
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_model_mesh, only: element_set_t
   use pecplas_model_mesh_tools, only: corner_count
   use pecplas_model_refine_local_edges, only: local_edges_t, build_local_edges, edge_of, &
      element_edges, close_marks, longest
   use pecplas_model_refine_local_children, only: quad_children, quad_transition, &
      triangle_children, parent_map
   use pecplas_model_refine_local_carry, only: node_store_t, add_node, carry_sets, &
      carry_loads, split_joints
   use pecplas_model_refine_local_springs, only: spring_measures
   implicit none (type, external)
   private

   public :: refine_marked

contains

   !> `fine` = `model` with the elements `marked` (one per massif element, sets in order)
   !> refined; `reason` is allocated (and `fine` undefined) when refused.
   subroutine refine_marked(model, marked, fine, reason)
      type(model_t), intent(in) :: model
      logical, intent(in) :: marked(:)
      type(model_t), intent(out) :: fine
      character(len=:), allocatable, intent(out) :: reason
      type(local_edges_t) :: le
      type(node_store_t) :: store
      type(element_set_t), allocatable :: trans(:)
      integer :: s, j, g, next_eid, nn0
      if (size(marked) /= model%mesh%nelem()) then
         reason = 'marks do not match the elements'
         return
      end if
      call build_local_edges(model, le)
      g = 0
      do s = 1, size(model%mesh%esets)
         do j = 1, size(model%mesh%esets(s)%conn, 2)
            g = g + 1
            if (marked(g)) le%marked(element_edges(le, model, s, j)) = .true.
         end do
      end do
      call close_marks(model, le)
      fine = model
      nn0 = model%mesh%nnode()
      store%x = model%mesh%x
      store%n = nn0
      next_eid = 0
      do s = 1, size(model%mesh%esets)
         if (size(model%mesh%esets(s)%ids) > 0) next_eid = max(next_eid, &
            maxval(model%mesh%esets(s)%ids))
      end do
      do s = 1, size(model%joint_sets)
         if (size(model%joint_sets(s)%ids) > 0) next_eid = max(next_eid, &
            maxval(model%joint_sets(s)%ids))
      end do
      allocate (trans(size(model%mesh%esets)))
      do s = 1, size(model%mesh%esets)
         call refine_set(model, s, le, store, next_eid, fine%mesh%esets(s)%conn, &
            fine%mesh%esets(s)%ids, trans(s)%conn, trans(s)%ids)
      end do
      ! after all sets: a companion set made at an earlier level is itself refined above
      do s = 1, size(model%mesh%esets)
         if (size(trans(s)%ids) > 0) call add_to_companion(fine, s, trans(s)%conn, &
            trans(s)%ids)
      end do
      call split_joints(model, le, next_eid, fine, reason)
      if (allocated(reason)) return
      deallocate (fine%mesh%x, fine%mesh%node_id)
      fine%mesh%x = store%x(:, 1:store%n)
      fine%mesh%node_id = [model%mesh%node_id, &
         (maxval(model%mesh%node_id) + j, j=1, store%n - nn0)]
      call carry_sets(model, le, fine)
      call carry_loads(model, le, fine, reason)
      if (allocated(reason)) return
      call respring(model, fine, reason)
   end subroutine refine_marked

   !> Children of every element of set s (unmarked elements are copied).
   subroutine refine_set(model, s, le, store, next_eid, conn, ids, tconn, tids)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      type(local_edges_t), intent(inout) :: le
      type(node_store_t), intent(inout) :: store
      integer, intent(inout) :: next_eid
      integer, allocatable, intent(inout) :: conn(:, :), ids(:)
      !> Transition triangles of the set's quadrilaterals (T3, or T6 under Q8).
      integer, allocatable, intent(out) :: tconn(:, :), tids(:)
      integer, allocatable :: ed(:), c(:, :), id(:), inner(:)
      real(wp), allocatable :: ref(:, :, :), inner_ref(:, :), xe(:, :)
      integer :: j, k, nc, npe, n, i
      nc = corner_count(model%mesh%esets(s)%etype)
      npe = size(model%mesh%esets(s)%conn, 1)
      allocate (c(npe, 0), id(0), tconn(merge(6, 3, npe > nc), 0), tids(0))
      do j = 1, size(model%mesh%esets(s)%conn, 2)
         ed = element_edges(le, model, s, j)
         if (.not. any(le%marked(ed))) then
            c = reshape([reshape(c, [size(c)]), model%mesh%esets(s)%conn(:, j)], &
               [npe, size(c, 2) + 1])
            id = [id, model%mesh%esets(s)%ids(j)]
            cycle
         end if
         if (nc == 4 .and. count(le%marked(ed)) == 1) then
            call quad_transition(findloc(le%marked(ed), .true., 1), ref)
            xe = model%mesh%x(:, model%mesh%esets(s)%conn(:, j))
            allocate (inner(0), inner_ref(2, 0))
            do k = 1, 3
               block
                  integer :: cc(size(tconn, 1))
                  do i = 1, 3
                     cc(i) = node_at(ref(:, i, k))
                     if (size(cc) == 6) cc(3 + i) = node_at(0.5_wp*(ref(:, i, k) + &
                        ref(:, mod(i, 3) + 1, k)))
                  end do
                  tconn = reshape([reshape(tconn, [size(tconn)]), cc], &
                     [size(cc), size(tconn, 2) + 1])
               end block
            end do
            deallocate (inner, inner_ref)
            ! the first triangle keeps the quadrilateral's id (in the companion set)
            tids = [tids, model%mesh%esets(s)%ids(j), next_eid + 1, next_eid + 2]
            next_eid = next_eid + 2
            cycle
         else if (nc == 4) then
            call quad_children(le%marked(ed), ref)
         else
            call triangle_children(le%marked(ed), longest(model, ed, le), ref)
         end if
         xe = model%mesh%x(:, model%mesh%esets(s)%conn(:, j))
         allocate (inner(0), inner_ref(2, 0))
         n = size(ref, 3)
         do k = 1, n
            block
               integer :: cc(npe)
               do i = 1, nc
                  cc(i) = node_at(ref(:, i, k))
                  if (npe > nc) cc(nc + i) = node_at(0.5_wp*(ref(:, i, k) + &
                     ref(:, mod(i, nc) + 1, k)))
               end do
               c = reshape([reshape(c, [size(c)]), cc], [npe, size(c, 2) + 1])
            end block
         end do
         deallocate (inner, inner_ref)
         id = [id, model%mesh%esets(s)%ids(j), (next_eid + k, k=1, n - 1)]
         next_eid = next_eid + n - 1
      end do
      call move_alloc(c, conn)
      call move_alloc(id, ids)
   contains
      !> The node of the parent element at reference point r: a corner, a node on a side
      !> (made once per side), or an interior node (made once per element).
      integer function node_at(r) result(node)
         real(wp), intent(in) :: r(2)
         integer :: side, slot, e, q
         real(wp) :: t
         call locate(nc, r, side, t)
         if (side > 0) then
            if (t == 0.0_wp) then
               node = model%mesh%esets(s)%conn(side, j)
               return
            else if (t == 1.0_wp) then
               node = model%mesh%esets(s)%conn(mod(side, nc) + 1, j)
               return
            end if
            e = ed(side)
            if (le%ends(1, e) /= model%mesh%esets(s)%conn(side, j)) t = 1.0_wp - t
            slot = nint(4.0_wp*t)
            if (le%node(slot, e) == 0) then
               call add_node(store, parent_map(xe, r), le%node(slot, e))
            end if
            node = le%node(slot, e)
            return
         end if
         do q = 1, size(inner)
            if (all(inner_ref(:, q) == r)) then
               node = inner(q)
               return
            end if
         end do
         call add_node(store, parent_map(xe, r), node)
         inner = [inner, node]
         inner_ref = reshape([reshape(inner_ref, [size(inner_ref)]), r], [2, size(inner) ])
      end function node_at
   end subroutine refine_set

   !> Appends the transition triangles of quadrilateral set s to its companion set
   !> (name_T3 or name_T6: same material), made at the first transition with the set's
   !> initial stresses and body loads.
   subroutine add_to_companion(fine, s, tconn, tids)
      type(model_t), intent(inout) :: fine
      integer, intent(in) :: s
      integer, intent(in) :: tconn(:, :), tids(:)
      type(element_set_t) :: comp
      character(len=:), allocatable :: name
      integer :: c, k
      name = fine%mesh%esets(s)%name//merge('_T6', '_T3', size(tconn, 1) == 6)
      c = fine%mesh%find_eset(name)
      if (c > 0) then
         fine%mesh%esets(c)%conn = reshape([reshape(fine%mesh%esets(c)%conn, &
            [size(fine%mesh%esets(c)%conn)]), reshape(tconn, [size(tconn)])], &
            [size(tconn, 1), size(fine%mesh%esets(c)%ids) + size(tids)])
         fine%mesh%esets(c)%ids = [fine%mesh%esets(c)%ids, tids]
         return
      end if
      comp = fine%mesh%esets(s)
      comp%name = name
      comp%etype = merge('T6', 'T3', size(tconn, 1) == 6)
      comp%conn = tconn
      comp%ids = tids
      fine%mesh%esets = [fine%mesh%esets, comp]
      c = size(fine%mesh%esets)
      if (allocated(fine%initial_stresses)) then
         do k = 1, size(fine%initial_stresses)
            if (fine%initial_stresses(k)%eset /= s) cycle
            fine%initial_stresses = [fine%initial_stresses, fine%initial_stresses(k)]
            fine%initial_stresses(size(fine%initial_stresses))%eset = c
            fine%initial_stresses(size(fine%initial_stresses))%set = name
         end do
      end if
      do k = 1, size(fine%patterns)
         if (.not. allocated(fine%patterns(k)%eset)) cycle
         if (.not. any(fine%patterns(k)%eset == s)) cycle
         associate (p => fine%patterns(k))
            p%vector = reshape([reshape(p%vector, [size(p%vector)]), &
               p%vector(:, findloc(p%eset, s, 1))], [2, size(p%eset) + 1])
            p%eset = [p%eset, c]
         end associate
      end do
   end subroutine add_to_companion

   !> Side (0: interior) and position t along it (from its first corner) of reference point
   !> r; the children's points are dyadic fractions, so the tests are exact.
   pure subroutine locate(nc, r, side, t)
      integer, intent(in) :: nc
      real(wp), intent(in) :: r(2)
      integer, intent(out) :: side
      real(wp), intent(out) :: t
      side = 0
      t = 0.0_wp
      if (nc == 4) then
         if (r(2) == -1.0_wp) then
            side = 1
            t = 0.5_wp*(r(1) + 1.0_wp)
         else if (r(1) == 1.0_wp) then
            side = 2
            t = 0.5_wp*(r(2) + 1.0_wp)
         else if (r(2) == 1.0_wp) then
            side = 3
            t = 0.5_wp*(1.0_wp - r(1))
         else if (r(1) == -1.0_wp) then
            side = 4
            t = 0.5_wp*(1.0_wp - r(2))
         end if
      else
         if (r(2) == 0.0_wp) then
            side = 1
            t = r(1)
         else if (r(1) + r(2) == 1.0_wp) then
            side = 2
            t = r(2)
         else if (r(1) == 0.0_wp) then
            side = 3
            t = 1.0_wp - r(2)
         end if
      end if
   end subroutine locate

   !> Spring sets: tributary measures of all doublets recomputed on the refined faces.
   subroutine respring(model, fine, reason)
      type(model_t), intent(in) :: model
      type(model_t), intent(inout) :: fine
      character(len=:), allocatable, intent(out) :: reason
      integer :: s
      do s = 1, size(fine%joint_sets)
         if (.not. fine%joint_sets(s)%is_spring()) cycle
         if (size(fine%joint_sets(s)%conn, 2) == size(model%joint_sets(s)%conn, 2)) cycle
         call spring_measures(fine, s, reason)
         if (allocated(reason)) return
      end do
   end subroutine respring

end module pecplas_model_refine_local
