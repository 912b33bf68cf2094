!> Unique element edges of a model for its local refinement (pecplas_model_refine_local):
!> each edge once, with its ends, its mid node (quadratic elements), the number of massif
!> elements on it, a refinement mark and the nodes created on it when it is split
!> (at 1/4, 1/2, 3/4 from its first end; 1/2 is the existing mid node of a quadratic edge).
!> `close_marks` makes the marks admissible (conforming closure, no hanging node):
!> - a triangle with a marked edge has its longest edge marked (it is bisected there first,
!>   which bounds the angles of repeated refinements);
!> - a quadrilateral has no mark, all four, two opposite ones (split in two) or one (split
!>   into three triangles from the side's midpoint: the refinement stays local);
!> - the two faces of a joint are marked together (the joint is split with its neighbours),
!>   and so are the two edges between the doublets of springs.
module pecplas_model_refine_local_edges
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_model_mesh_sides, only: side_table_t, build_side_table, find_sides
   use pecplas_model_mesh_tools, only: corner_count
   implicit none (type, external)
   private

   public :: local_edges_t, build_local_edges, edge_of, element_edges, close_marks, longest

   type :: local_edges_t
      !> ends(2, e) as on the first side found; mid(e) (0: linear), nel(e) massif elements.
      integer, allocatable :: ends(:, :), mid(:), nel(:)
      !> Nodes on a split edge at 1/4, 1/2, 3/4 from ends(1, e) (0: not yet made).
      integer, allocatable :: node(:, :)
      logical, allocatable :: marked(:)
      !> Element sides (set, element, local side) and the unique edge of each side.
      type(side_table_t) :: table
      integer, allocatable :: of_side(:)
   end type local_edges_t

contains

   subroutine build_local_edges(model, le)
      type(model_t), intent(in) :: model
      type(local_edges_t), intent(out) :: le
      integer, allocatable :: same(:)
      integer :: k, ne, nside
      call build_side_table(model%mesh, le%table)
      nside = size(le%table%nodes, 2)
      allocate (le%of_side(nside), source=0)
      ne = 0
      do k = 1, nside
         if (le%of_side(k) /= 0) cycle
         same = find_sides(le%table, le%table%nodes(:, k))
         ne = ne + 1
         le%of_side(same) = ne
      end do
      allocate (le%ends(2, ne), le%mid(ne), le%nel(ne), source=0)
      allocate (le%node(3, ne), source=0)
      allocate (le%marked(ne), source=.false.)
      do k = nside, 1, -1
         le%ends(:, le%of_side(k)) = le%table%nodes(1:2, k)
         le%mid(le%of_side(k)) = le%table%nodes(3, k)
         le%nel(le%of_side(k)) = le%nel(le%of_side(k)) + 1
      end do
      le%node(2, :) = le%mid
   end subroutine build_local_edges

   !> Unique edge with ends a and b (either order), 0 when no element has it.
   integer function edge_of(le, a, b) result(e)
      type(local_edges_t), intent(in) :: le
      integer, intent(in) :: a, b
      integer, allocatable :: sides(:)
      integer :: k
      e = 0
      sides = find_sides(le%table, [a, b])
      if (size(sides) == 0) then
         ! a quadratic side: find_sides needs its mid node; look among the sides from a
         do k = le%table%head(min(a, b)), le%table%head(min(a, b) + 1) - 1
            associate (s => le%table%item(k))
               if (min(le%table%nodes(1, s), le%table%nodes(2, s)) == min(a, b) .and. &
                   max(le%table%nodes(1, s), le%table%nodes(2, s)) == max(a, b)) &
                  e = le%of_side(s)
            end associate
         end do
      else
         e = le%of_side(sides(1))
      end if
   end function edge_of

   !> Unique edges of element j of set s, in local side order (side i: corner i to i + 1).
   function element_edges(le, model, s, j) result(edges)
      type(local_edges_t), intent(in) :: le
      type(model_t), intent(in) :: model
      integer, intent(in) :: s, j
      integer, allocatable :: edges(:)
      integer :: nc, i
      nc = corner_count(model%mesh%esets(s)%etype)
      allocate (edges(nc))
      do i = 1, nc
         edges(i) = edge_of(le, model%mesh%esets(s)%conn(i, j), &
            model%mesh%esets(s)%conn(mod(i, nc) + 1, j))
      end do
   end function element_edges

   !> Marks more edges until every element, joint and spring pair admits its marks.
   subroutine close_marks(model, le)
      type(model_t), intent(in) :: model
      type(local_edges_t), intent(inout) :: le
      logical :: changed
      integer :: s, j, k
      integer, allocatable :: ed(:)
      changed = .true.
      do while (changed)
         changed = .false.
         do s = 1, size(model%mesh%esets)
            do j = 1, size(model%mesh%esets(s)%conn, 2)
               ed = element_edges(le, model, s, j)
               if (.not. any(le%marked(ed))) cycle
               if (size(ed) == 3) then
                  k = longest(model, ed, le)
                  if (.not. le%marked(ed(k))) call mark(le, ed(k), changed)
               else if (.not. quad_admissible(le%marked(ed))) then
                  do k = 1, 4
                     call mark(le, ed(k), changed)
                  end do
               end if
            end do
         end do
         do s = 1, size(model%joint_sets)
            associate (c => model%joint_sets(s)%conn)
               if (size(c, 1) == 2) then
                  call spring_pairs(c, le, changed)
                  cycle
               end if
               do j = 1, size(c, 2)
                  call mark_together(le, edge_of(le, c(1, j), c(2, j)), &
                     edge_of(le, c(3, j), c(4, j)), changed)
               end do
            end associate
         end do
      end do
   end subroutine close_marks

   !> Springs (face-1 node, face-2 node): an edge between two face-1 nodes and the edge
   !> between their partners are marked together.
   subroutine spring_pairs(c, le, changed)
      integer, intent(in) :: c(:, :)
      type(local_edges_t), intent(inout) :: le
      logical, intent(inout) :: changed
      integer :: i, j
      do i = 1, size(c, 2)
         do j = i + 1, size(c, 2)
            call mark_together(le, edge_of(le, c(1, i), c(1, j)), &
               edge_of(le, c(2, i), c(2, j)), changed)
         end do
      end do
   end subroutine spring_pairs

   !> The two faces' edges of a joint are split together: one marked marks both (0: no edge).
   subroutine mark_together(le, e1, e2, changed)
      type(local_edges_t), intent(inout) :: le
      integer, intent(in) :: e1, e2
      logical, intent(inout) :: changed
      if (e1 == 0 .or. e2 == 0) return
      if (le%marked(e1) .neqv. le%marked(e2)) then
         call mark(le, e1, changed)
         call mark(le, e2, changed)
      end if
   end subroutine mark_together

   !> No mark, all four, exactly two opposite sides, or one side (a transition into
   !> triangles).
   pure logical function quad_admissible(mk) result(ok)
      logical, intent(in) :: mk(4)
      ok = all(mk) .or. count(mk) <= 1 .or. &
         ((mk(1) .eqv. mk(3)) .and. (mk(2) .eqv. mk(4)) .and. (mk(1) .neqv. mk(2)))
   end function quad_admissible

   subroutine mark(le, e, changed)
      type(local_edges_t), intent(inout) :: le
      integer, intent(in) :: e
      logical, intent(inout) :: changed
      if (le%marked(e)) return
      le%marked(e) = .true.
      changed = .true.
   end subroutine mark

   !> Local index of the longest of a triangle's edges (the first one on a tie).
   integer function longest(model, ed, le) result(k)
      type(model_t), intent(in) :: model
      integer, intent(in) :: ed(:)
      type(local_edges_t), intent(in) :: le
      real(wp) :: l, lmax
      integer :: i
      k = 1
      lmax = -1.0_wp
      do i = 1, size(ed)
         l = norm2(model%mesh%x(:, le%ends(1, ed(i))) - model%mesh%x(:, le%ends(2, ed(i))))
         if (l > lmax*(1.0_wp + 1.0e-12_wp)) then
            lmax = l
            k = i
         end if
      end do
   end function longest

end module pecplas_model_refine_local_edges
