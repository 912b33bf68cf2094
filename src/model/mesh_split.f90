!> Node doublets along an interface: `split_along_edges` duplicates every node of an edge
!> set, gives the duplicates to the elements of one element set (the SIDE body, face 2 of
!> the joints) and returns the joint connectivity along the edges (face 1 = the original
!> nodes, used by the body on the other side).
!>
!> Rules for what else touches a split node (the deck reader applies the same ones to
!> supports and load patterns):
!> - node sets that hold a split node also hold its duplicate;
!> - an edge (of any edge set or pressure pattern) that is a side of a SIDE element and of
!>   no other element moves to the duplicates; the interface edges themselves, sides of both
!>   bodies, keep the original nodes.
!> A node already split for the same SIDE body by an earlier call (e.g. the corner where a
!> pile's shaft and tip joints meet) is reused, not split again: `origin` remembers which
!> node each duplicate came from.
module pecplas_model_mesh_split
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error
   use pecplas_model_mesh, only: mesh_t
   use pecplas_model_mesh_sides, only: side_table_t, build_side_table, find_sides, &
      element_centroid
   implicit none (type, external)
   private

   public :: split_result_t, split_along_edges, remap_side_edges

   type :: split_result_t
      !> Joint connectivity (2 nen, nedge) in (B.8)/(B.10) order: face-1 ends 1, 2, face-2
      !> ends 3 (facing 2), 4 (facing 1), then mid nodes 5 (face 1), 6 (face 2). Oriented so
      !> that the SIDE body lies on the left of 1 -> 2 (the joint normal points into it).
      integer, allocatable :: conn(:, :)
      !> Node doublets (face-1 node, face-2 node), each once, in order of first appearance.
      integer, allocatable :: doublets(:, :)
      !> Nodes created (original, duplicate).
      integer, allocatable :: created(:, :)
   end type split_result_t

contains

   !> Splits `mesh` along edge set `ke`, the duplicates going to element set `ks`.
   !> origin(node) is the node a duplicate was made from (itself otherwise); it is
   !> extended to the new nodes. Errors: an edge that is not a side of a SIDE element, or
   !> with no element of another set on its other side, or already split.
   subroutine split_along_edges(mesh, ke, ks, origin, result, error)
      type(mesh_t), intent(inout) :: mesh
      integer, intent(in) :: ke, ks
      integer, allocatable, intent(inout) :: origin(:)
      type(split_result_t), intent(out) :: result
      type(error_t), allocatable, intent(out) :: error
      type(side_table_t) :: table
      integer, allocatable :: face1(:, :), face2(:, :), sidel(:), dupof(:), tmp(:)
      real(wp), allocatable :: x(:, :)
      integer :: nn, nen, ne, f, k, i, j, nnew, maxid, m, v
      real(wp) :: c(2), t(2)

      nn = mesh%nnode()
      if (.not. allocated(origin)) allocate (origin(0))
      if (size(origin) < nn) origin = [origin, [(i, i=size(origin) + 1, nn)]]
      associate (en => mesh%edge_sets(ke)%nodes, side_name => mesh%esets(ks)%name, &
                 edge_name => mesh%edge_sets(ke)%name)
         nen = size(en, 1)
         ne = size(en, 2)
         if (ne == 0) then
            call input_error(error, "edge set '"//edge_name//"' has no edges to split")
            return
         end if
         call build_side_table(mesh, table, origin)
         allocate (face1(nen, ne), face2(nen, ne), sidel(ne))
         do f = 1, ne
            call match_edge(table, en(:, f), ks, face1(:, f), face2(:, f), &
               sidel(f), error)
            if (allocated(error)) then
               error%message = "edge "//id_list(mesh, en(:, f))//" of edge set '"// &
                  edge_name//"' "//error%message//" (SIDE='"//side_name//"')"
               return
            end if
            if (all(face1(:, f) /= face2(:, f))) then
               call input_error(error, "edge "//id_list(mesh, en(:, f))//" of edge set '"// &
                  edge_name//"' is already split: joints were generated along it before")
               return
            end if
         end do
      end associate

      ! one duplicate per node that both bodies still share, numbered in node order
      allocate (dupof(nn), source=0)
      maxid = maxval(mesh%node_id)
      do f = 1, ne
         do k = 1, nen
            if (face2(k, f) == face1(k, f)) dupof(face1(k, f)) = 1
         end do
      end do
      nnew = 0
      do v = 1, nn
         if (dupof(v) == 0) cycle
         nnew = nnew + 1
         dupof(v) = nn + nnew
      end do
      allocate (x(2, nn + nnew))
      x(:, 1:nn) = mesh%x
      allocate (result%created(2, nnew))
      mesh%node_id = [mesh%node_id, (maxid + i, i=1, nnew)]
      origin = [origin, (0, i=1, nnew)]
      do v = 1, nn
         if (dupof(v) == 0) cycle
         x(:, dupof(v)) = mesh%x(:, v)
         origin(dupof(v)) = origin(v)
         result%created(:, dupof(v) - nn) = [v, dupof(v)]
      end do
      call move_alloc(x, mesh%x)

      ! the SIDE body takes the duplicates
      associate (conn => mesh%esets(ks)%conn)
         do j = 1, size(conn, 2)
            do i = 1, size(conn, 1)
               if (dupof(conn(i, j)) > 0) conn(i, j) = dupof(conn(i, j))
            end do
         end do
      end associate
      do f = 1, ne
         do k = 1, nen
            if (face2(k, f) == face1(k, f)) face2(k, f) = dupof(face1(k, f))
         end do
      end do

      ! node sets gain the duplicates; edge sets on the SIDE body move to them
      do i = 1, size(mesh%nsets)
         associate (nodes => mesh%nsets(i)%nodes)
            m = size(nodes)
            allocate (tmp(0))
            do j = 1, m
               if (dupof(nodes(j)) > 0) tmp = [tmp, dupof(nodes(j))]
            end do
         end associate
         if (size(tmp) > 0) mesh%nsets(i)%nodes = [mesh%nsets(i)%nodes, tmp]
         deallocate (tmp)
      end do
      do i = 1, size(mesh%edge_sets)
         call remap_side_edges(mesh, ks, dupof, mesh%edge_sets(i)%nodes)
      end do

      ! joint connectivity, oriented with the SIDE body on the left of face-1 1 -> 2
      allocate (result%conn(2*nen, ne), result%doublets(2, 0))
      do f = 1, ne
         c = element_centroid(mesh, ks, sidel(f))
         t = mesh%x(:, face1(2, f)) - mesh%x(:, face1(1, f))
         if (-t(2)*(c(1) - mesh%x(1, face1(1, f))) + t(1)*(c(2) - mesh%x(2, face1(1, f))) &
             < 0.0_wp) then
            face1(1:2, f) = face1([2, 1], f)
            face2(1:2, f) = face2([2, 1], f)
         end if
         result%conn(1:4, f) = [face1(1, f), face1(2, f), face2(2, f), face2(1, f)]
         if (nen == 3) result%conn(5:6, f) = [face1(3, f), face2(3, f)]
         do k = 1, nen
            if (any(result%doublets(1, :) == face1(k, f))) cycle
            result%doublets = reshape([result%doublets, face1(k, f), face2(k, f)], &
               [2, size(result%doublets, 2) + 1])
         end do
      end do
   end subroutine split_along_edges

   !> Moves to the duplicates (dupof(node) > 0) every edge of `edges` (nen, n; a 0 is an
   !> absent mid node) that is a side of an element of set ks and of no other element.
   !> Call after the elements of ks were renumbered.
   subroutine remap_side_edges(mesh, ks, dupof, edges)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: ks, dupof(:)
      integer, intent(inout) :: edges(:, :)
      type(side_table_t) :: table
      integer :: f, k, mapped(3), nen
      logical :: other, side
      if (size(edges, 2) == 0) return
      call build_side_table(mesh, table)
      nen = size(edges, 1)
      do f = 1, size(edges, 2)
         mapped = 0
         mapped(1:nen) = edges(:, f)
         do k = 1, nen
            if (edges(k, f) < 1 .or. edges(k, f) > size(dupof)) cycle
            if (dupof(edges(k, f)) > 0) mapped(k) = dupof(edges(k, f))
         end do
         if (all(mapped(1:nen) == edges(:, f))) cycle
         other = any(table%set(find_sides(table, edges(:, f))) /= ks)
         side = any(table%set(find_sides(table, mapped(1:nen))) == ks)
         if (side .and. .not. other) edges(:, f) = mapped(1:nen)
      end do
   end subroutine remap_side_edges

   !> Finds the sides matching edge `en` through the table keys (origins): face1 = nodes of
   !> the element outside set ks, face2 = nodes of the element of ks (in the order of en),
   !> sidel = that element. On failure error%message completes "edge (...) of edge set 'x'".
   subroutine match_edge(table, en, ks, face1, face2, sidel, error)
      type(side_table_t), intent(in) :: table
      integer, intent(in) :: en(:), ks
      integer, intent(out) :: face1(:), face2(:), sidel
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: sides(:)
      integer :: k, s, n1, n2, j, i
      n1 = 0; n2 = 0; sidel = 0
      face1 = 0; face2 = 0
      allocate (sides(0)) ! gives the descriptor bounds (silences a gfortran 12 false warning)
      sides = find_sides(table, en)
      do k = 1, size(sides)
         s = sides(k)
         ! nodes of this side in the order of the edge
         do j = 1, size(en)
            do i = 1, 3
               if (table%nodes(i, s) == 0) cycle
               if (table%key(table%nodes(i, s)) /= table%key(en(j))) cycle
               if (table%set(s) == ks) then
                  face2(j) = table%nodes(i, s)
               else
                  face1(j) = table%nodes(i, s)
               end if
            end do
         end do
         if (table%set(s) == ks) then
            n2 = n2 + 1
            sidel = table%elem(s)
         else
            n1 = n1 + 1
         end if
      end do
      if (n2 == 0) then
         call input_error(error, 'is not a side of an element of the SIDE body')
      else if (n2 > 1) then
         call input_error(error, 'lies inside the SIDE body (two of its elements share it)')
      else if (n1 == 0) then
         call input_error(error, 'has no element of another set on its other side: '// &
            'nothing to join')
      else if (n1 > 1) then
         call input_error(error, 'is a side of more than two elements')
      end if
   end subroutine match_edge

   !> "(id id [id])": user ids of internal node numbers.
   function id_list(mesh, nodes) result(s)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: nodes(:)
      character(len=:), allocatable :: s
      character(len=16) :: buf
      integer :: i
      s = '('
      do i = 1, size(nodes)
         if (nodes(i) < 1) cycle
         write (buf, '(i0)') mesh%node_id(nodes(i))
         if (i > 1) s = s//' '
         s = s//trim(buf)
      end do
      s = s//')'
   end function id_list

end module pecplas_model_mesh_split
