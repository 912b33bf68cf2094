!> Uniform refinement (h/2) of a model read from a deck, in memory (the mesh level of
!> `pecplas --advise`). Q4 -> 4 Q4 (edge midpoints and centre), T3 -> 4 T3 (edge
!> midpoints). Original nodes keep their internal numbers and ids; new nodes come after them,
!> with ids above the largest. What refers to nodes is rebuilt:
!> - a midpoint of a boundary edge (one element) joins a node set, a support or an imposed
!>   displacement (mean of the two ends: exact for a linear one) when both ends hold it;
!> - pressure edges, edge sets and 4-node joints (GOODMAN4, THIN_LAYER) are cut in two at the
!>   midpoints of their edges (the midpoints of a joint's two faces form a new doublet).
!> Anything that cannot be refined without changing the problem is refused with a one-line
!> reason and no model: quadratic elements, springs and 6-node joints (tributary measures),
!> point forces on both ends of an edge (their total would grow), supports or imposed
!> displacements on both ends of an interior edge, a joint face that is no element edge.
module pecplas_model_refine
   use pecplas_kinds, only: wp
   use pecplas_model, only: model_t
   use pecplas_model_mesh, only: element_set_t
   use pecplas_model_refine_edges, only: edge_map_t, build_edges, mid, count_q4, &
      joint_faces_on_elements
   implicit none (type, external)
   private

   public :: refine_model

contains

   !> `fine` = `model` refined once; `reason` is allocated (and `fine` undefined) when refused.
   subroutine refine_model(model, fine, reason)
      type(model_t), intent(in) :: model
      type(model_t), intent(out) :: fine
      character(len=:), allocatable, intent(out) :: reason
      type(edge_map_t) :: em
      integer :: nn0, nn, s, k, next_eid, next_node

      call check_refinable(model, reason)
      if (allocated(reason)) return
      nn0 = model%mesh%nnode()
      call build_edges(model, em, nn0, nn)
      call joint_faces_on_elements(model, em, reason)
      if (allocated(reason)) return
      fine = model
      call add_nodes(model, em, nn0, nn, fine)
      next_eid = 0
      do s = 1, size(model%mesh%esets)
         if (size(model%mesh%esets(s)%ids) > 0) next_eid = max(next_eid, &
            maxval(model%mesh%esets(s)%ids))
      end do
      do s = 1, size(model%joint_sets)
         if (size(model%joint_sets(s)%ids) > 0) next_eid = max(next_eid, &
            maxval(model%joint_sets(s)%ids))
      end do
      next_node = nn - count_q4(model)
      do s = 1, size(model%mesh%esets)
         call refine_eset(model%mesh%esets(s), em, next_node, next_eid, fine%mesh%esets(s))
      end do
      do s = 1, size(model%joint_sets)
         associate (js => model%joint_sets(s), fs => fine%joint_sets(s))
            deallocate (fs%conn, fs%ids)
            allocate (fs%conn(4, 2*size(js%conn, 2)), fs%ids(2*size(js%conn, 2)))
            do k = 1, size(js%conn, 2)
               associate (c => js%conn(:, k))
                  fs%conn(:, 2*k - 1) = [c(1), mid(em, c(1), c(2)), mid(em, c(3), c(4)), c(4)]
                  fs%conn(:, 2*k) = [mid(em, c(1), c(2)), c(2), c(3), mid(em, c(3), c(4))]
               end associate
               fs%ids(2*k - 1) = js%ids(k)
               next_eid = next_eid + 1
               fs%ids(2*k) = next_eid
            end do
         end associate
      end do
      do s = 1, size(model%mesh%edge_sets)
         call split_edges(model%mesh%edge_sets(s)%nodes, em, fine%mesh%edge_sets(s)%nodes)
      end do
      call refine_loads(model, em, fine, reason)
   end subroutine refine_model

   !> Element and joint types, loads on quadratic edges.
   subroutine check_refinable(model, reason)
      type(model_t), intent(in) :: model
      character(len=:), allocatable, intent(out) :: reason
      integer :: s
      do s = 1, size(model%mesh%esets)
         associate (e => model%mesh%esets(s)%etype)
            if (e /= 'Q4' .and. e /= 'T3') then
               reason = 'element type '//e
               return
            end if
         end associate
      end do
      if (.not. allocated(model%joint_sets)) return
      do s = 1, size(model%joint_sets)
         associate (js => model%joint_sets(s))
            if (size(js%conn, 1) /= 4) then
               reason = 'joint type '//js%etype
               if (js%etype == 'THIN_LAYER') reason = reason//' (6 nodes)'
               return
            end if
         end associate
      end do
   end subroutine check_refinable

   !> Coordinates and ids of the new nodes (midpoints, then Q4 centres in set order); node sets
   !> gain the midpoints of boundary edges whose two ends they hold.
   subroutine add_nodes(model, em, nn0, nn, fine)
      type(model_t), intent(in) :: model
      type(edge_map_t), intent(in) :: em
      integer, intent(in) :: nn0, nn
      type(model_t), intent(inout) :: fine
      logical, allocatable :: inset(:)
      integer :: a, j, s, k, c, id0
      deallocate (fine%mesh%x, fine%mesh%node_id)
      allocate (fine%mesh%x(2, nn), fine%mesh%node_id(nn))
      fine%mesh%x(:, 1:nn0) = model%mesh%x
      fine%mesh%node_id(1:nn0) = model%mesh%node_id
      id0 = maxval(model%mesh%node_id) - nn0
      do a = 1, nn0
         do j = em%start(a), em%start(a) + em%cnt(a) - 1
            fine%mesh%x(:, em%mid(j)) = 0.5_wp*(model%mesh%x(:, a) + model%mesh%x(:, em%other(j)))
         end do
      end do
      c = nn - count_q4(model)
      do s = 1, size(model%mesh%esets)
         if (model%mesh%esets(s)%etype /= 'Q4') cycle
         do k = 1, size(model%mesh%esets(s)%conn, 2)
            c = c + 1
            fine%mesh%x(:, c) = 0.25_wp*sum(model%mesh%x(:, model%mesh%esets(s)%conn(:, k)), dim=2)
         end do
      end do
      fine%mesh%node_id(nn0 + 1:nn) = [(id0 + j, j=nn0 + 1, nn)]
      if (.not. allocated(model%mesh%nsets)) return
      allocate (inset(nn0))
      do s = 1, size(model%mesh%nsets)
         inset = .false.
         inset(model%mesh%nsets(s)%nodes) = .true.
         do a = 1, nn0
            do j = em%start(a), em%start(a) + em%cnt(a) - 1
               if (inset(a) .and. inset(em%other(j)) .and. em%nel(j) <= 1) &
                  fine%mesh%nsets(s)%nodes = [fine%mesh%nsets(s)%nodes, em%mid(j)]
            end do
         end do
      end do
   end subroutine add_nodes


   !> Four children per element, counter-clockwise like the parent; the first keeps its id.
   !> Q4 centres are numbered in the order add_nodes gave them (`next_node`: the last one used).
   subroutine refine_eset(es, em, next_node, next_eid, fs)
      type(element_set_t), intent(in) :: es
      type(edge_map_t), intent(in) :: em
      integer, intent(inout) :: next_node, next_eid
      type(element_set_t), intent(inout) :: fs
      integer :: k, j, m(4), ctr, ne
      ne = size(es%conn, 2)
      deallocate (fs%conn, fs%ids)
      allocate (fs%conn(size(es%conn, 1), 4*ne), fs%ids(4*ne))
      do k = 1, ne
         associate (c => es%conn(:, k))
            if (size(c) == 4) then
               do j = 1, 4
                  m(j) = mid(em, c(j), c(mod(j, 4) + 1))
               end do
               next_node = next_node + 1
               ctr = next_node
               fs%conn(:, 4*k - 3) = [c(1), m(1), ctr, m(4)]
               fs%conn(:, 4*k - 2) = [m(1), c(2), m(2), ctr]
               fs%conn(:, 4*k - 1) = [ctr, m(2), c(3), m(3)]
               fs%conn(:, 4*k) = [m(4), ctr, m(3), c(4)]
            else
               do j = 1, 3
                  m(j) = mid(em, c(j), c(mod(j, 3) + 1))
               end do
               fs%conn(:, 4*k - 3) = [c(1), m(1), m(3)]
               fs%conn(:, 4*k - 2) = [m(1), c(2), m(2)]
               fs%conn(:, 4*k - 1) = [m(3), m(2), c(3)]
               fs%conn(:, 4*k) = [m(1), m(2), m(3)]
            end if
         end associate
         fs%ids(4*k - 3) = es%ids(k)
         fs%ids(4*k - 2:4*k) = next_eid + [1, 2, 3]
         next_eid = next_eid + 3
      end do
   end subroutine refine_eset

   !> Each edge (2 or 3 rows, third 0) cut in two at its midpoint, in order.
   subroutine split_edges(e, em, f)
      integer, intent(in) :: e(:, :)
      type(edge_map_t), intent(in) :: em
      integer, allocatable, intent(inout) :: f(:, :)
      integer :: k, m
      deallocate (f)
      allocate (f(size(e, 1), 2*size(e, 2)), source=0)
      do k = 1, size(e, 2)
         m = mid(em, e(1, k), e(2, k))
         f(1:2, 2*k - 1) = [e(1, k), m]
         f(1:2, 2*k) = [m, e(2, k)]
      end do
   end subroutine split_edges

   !> Supports, imposed displacements, point forces and pressures on the refined mesh.
   subroutine refine_loads(model, em, fine, reason)
      type(model_t), intent(in) :: model
      type(edge_map_t), intent(in) :: em
      type(model_t), intent(inout) :: fine
      character(len=:), allocatable, intent(out) :: reason
      real(wp), allocatable :: val(:, :)
      logical, allocatable :: has(:, :)
      integer :: p, nn0, k
      nn0 = model%mesh%nnode()
      allocate (has(2, nn0), val(2, nn0))
      if (allocated(model%supports%node)) then
         call nodal_values(model%supports%node, model%supports%dof, &
            [(0.0_wp, k=1, size(model%supports%node))], has, val)
         call extend_nodal(em, has, val, fine%supports%node, fine%supports%dof, reason)
         if (allocated(reason)) return
      end if
      do p = 1, size(model%patterns)
         associate (pat => model%patterns(p), fp => fine%patterns(p))
            select case (pat%kind)
            case ('FORCE')
               call nodal_values(pat%node, pat%dof, pat%value, has, val)
               if (any_edge_both(em, has)) then
                  reason = 'nodal loads on a refined set ('//pat%name//')'
                  return
               end if
            case ('DISPLACEMENT')
               call nodal_values(pat%node, pat%dof, pat%value, has, val)
               call extend_nodal(em, has, val, fp%node, fp%dof, reason, fp%value)
               if (allocated(reason)) return
            case ('PRESSURE')
               call split_edges(pat%edge, em, fp%edge)
               fp%pressure = [(pat%pressure((k + 1)/2), k=1, 2*size(pat%pressure))]
            end select
         end associate
      end do
   end subroutine refine_loads

   subroutine nodal_values(node, dof, value, has, val)
      integer, intent(in) :: node(:), dof(:)
      real(wp), intent(in) :: value(:)
      logical, intent(out) :: has(:, :)
      real(wp), intent(out) :: val(:, :)
      integer :: k
      has = .false.
      val = 0.0_wp
      do k = 1, size(node)
         has(dof(k), node(k)) = .true.
         val(dof(k), node(k)) = value(k)
      end do
   end subroutine nodal_values

   !> Some edge has the same component at both ends.
   logical function any_edge_both(em, has) result(both)
      type(edge_map_t), intent(in) :: em
      logical, intent(in) :: has(:, :)
      integer :: a, j
      both = .false.
      do a = 1, size(has, 2)
         do j = em%start(a), em%start(a) + em%cnt(a) - 1
            if (any(has(:, a) .and. has(:, em%other(j)))) both = .true.
         end do
      end do
   end function any_edge_both

   !> Appends (midpoint, dof[, mean value]) for boundary edges holding dof at both ends;
   !> refuses the same on an interior edge (a node set across the body: its midpoint's share
   !> is not knowable from the resolved lists).
   subroutine extend_nodal(em, has, val, node, dof, reason, value)
      type(edge_map_t), intent(in) :: em
      logical, intent(in) :: has(:, :)
      real(wp), intent(in) :: val(:, :)
      integer, allocatable, intent(inout) :: node(:), dof(:)
      character(len=:), allocatable, intent(out) :: reason
      real(wp), allocatable, intent(inout), optional :: value(:)
      integer :: a, b, j, d
      do a = 1, size(has, 2)
         do j = em%start(a), em%start(a) + em%cnt(a) - 1
            b = em%other(j)
            do d = 1, 2
               if (.not. (has(d, a) .and. has(d, b))) cycle
               if (em%nel(j) > 1) then
                  reason = 'supports or imposed displacements on both ends of an interior edge'
                  return
               end if
               node = [node, em%mid(j)]
               dof = [dof, d]
               if (present(value)) value = [value, 0.5_wp*(val(d, a) + val(d, b))]
            end do
         end do
      end do
   end subroutine extend_nodal

end module pecplas_model_refine
