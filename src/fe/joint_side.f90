!> The massif beside each joint element, whose initial stress the element's points start
!> from (pecplas_fe_initial). A Goodman or thin-layer joint lies along a side of the massif
!> element on its face 1: that element, whatever the order of the joints or the number of
!> layers; a spring stands at a face-1 node: the element sets around that node (at a node
!> where layers meet, each of them). Where nothing is attached to face 1 (a joint to a node
!> of no element), the massif on face 2.
module pecplas_fe_joint_side
   use pecplas_base_kinds, only: wp
   use pecplas_base_sort, only: sort_short
   use pecplas_model_type, only: model_t
   use pecplas_model_joints, only: joint_set_t
   use pecplas_model_mesh_sides, only: side_table_t, build_side_table, find_sides, &
      element_centroid
   implicit none (type, external)
   private

   public :: mesh_index_t, beside_sets

   !> Look-ups of a mesh built once: the element sides by their end nodes, and the massif
   !> elements using each node (CSR: node_set/node_elem(head(n):head(n + 1) - 1)).
   type :: mesh_index_t
      type(side_table_t) :: sides
      integer, allocatable :: head(:), node_set(:), node_elem(:)
   contains
      procedure :: build => index_build
   end type mesh_index_t

contains

   !> The look-ups of the massif elements of `model`.
   subroutine index_build(this, model)
      class(mesh_index_t), intent(out) :: this
      type(model_t), intent(in) :: model
      integer, allocatable :: next(:)
      integer :: nn, s, j, i, n, k
      call build_side_table(model%mesh, this%sides)
      nn = model%mesh%nnode()
      allocate (this%head(nn + 1), source=0)
      do s = 1, size(model%mesh%esets)
         associate (conn => model%mesh%esets(s)%conn)
            do j = 1, size(conn, 2)
               do i = 1, size(conn, 1)
                  this%head(conn(i, j) + 1) = this%head(conn(i, j) + 1) + 1
               end do
            end do
         end associate
      end do
      this%head(1) = 1
      do n = 1, nn
         this%head(n + 1) = this%head(n + 1) + this%head(n)
      end do
      allocate (this%node_set(this%head(nn + 1) - 1), this%node_elem(this%head(nn + 1) - 1))
      next = this%head(1:nn)
      do s = 1, size(model%mesh%esets)
         associate (conn => model%mesh%esets(s)%conn)
            do j = 1, size(conn, 2)
               do i = 1, size(conn, 1)
                  k = next(conn(i, j))
                  this%node_set(k) = s
                  this%node_elem(k) = j
                  next(conn(i, j)) = k + 1
               end do
            end do
         end associate
      end do
   end subroutine index_build

   !> The element sets (distinct, in mesh order) of the massif beside element e of joint
   !> set `jset`: one set for a Goodman or thin-layer joint (the element whose side is the
   !> joint's face 1, on the face-1 side of the joint where two elements share that side),
   !> the sets around the face-1 node of a spring; the same on face 2 when face 1 touches
   !> no massif element; none when neither face does.
   subroutine beside_sets(model, index, jset, e, sets)
      type(model_t), intent(in) :: model
      type(mesh_index_t), intent(in) :: index
      type(joint_set_t), intent(in) :: jset
      integer, intent(in) :: e
      integer, allocatable, intent(out) :: sets(:)
      integer :: face1(3), face2(3)
      associate (c => jset%conn(:, e))
         if (jset%is_spring()) then
            sets = node_sets(index, c(1:1))
            if (size(sets) == 0) sets = node_sets(index, c(2:2))
            return
         end if
         ! face 1: n1 -> n2 (mid n5); face 2 along the same tangent: n4 -> n3 (mid n6)
         face1 = [c(1), c(2), 0]
         face2 = [c(4), c(3), 0]
         if (size(c) >= 6) then
            face1(3) = c(5)
            face2(3) = c(6)
         end if
         sets = side_set(model, index, face1, -1.0_wp)
         if (size(sets) == 0) sets = node_sets(index, face1(1:2))
         if (size(sets) == 0) sets = side_set(model, index, face2, 1.0_wp)
         if (size(sets) == 0) sets = node_sets(index, face2(1:2))
      end associate
   end subroutine beside_sets

   !> The set of the element that has the side `edge` (end, end, mid or 0): of several, the
   !> first whose centroid lies on the side `side` (-1: behind the joint normal, face 1;
   !> +1: ahead, face 2) of the edge; none when no element has that side.
   function side_set(model, index, edge, side) result(sets)
      type(model_t), intent(in) :: model
      type(mesh_index_t), intent(in) :: index
      integer, intent(in) :: edge(3)
      real(wp), intent(in) :: side
      integer, allocatable :: sets(:)
      integer, allocatable :: found(:)
      real(wp) :: t(2), n(2), xm(2)
      integer :: k, pick
      allocate (sets(0))
      if (edge(3) > 0) then
         found = find_sides(index%sides, edge)
      else
         found = find_sides(index%sides, edge(1:2))
      end if
      if (size(found) == 0) return
      pick = found(1)
      t = model%mesh%x(:, edge(2)) - model%mesh%x(:, edge(1))
      n = [-t(2), t(1)]
      xm = 0.5_wp*(model%mesh%x(:, edge(1)) + model%mesh%x(:, edge(2)))
      do k = size(found), 1, -1
         associate (s => index%sides%set(found(k)), j => index%sides%elem(found(k)))
            if (side*dot_product(n, element_centroid(model%mesh, s, j) - xm) > 0.0_wp) &
               pick = found(k)
         end associate
      end do
      sets = [index%sides%set(pick)]
   end function side_set

   !> The distinct sets (in mesh order) of the elements using any of `nodes`.
   pure function node_sets(index, nodes) result(sets)
      type(mesh_index_t), intent(in) :: index
      integer, intent(in) :: nodes(:)
      integer, allocatable :: sets(:)
      integer :: i, k
      allocate (sets(0))
      do i = 1, size(nodes)
         if (nodes(i) < 1 .or. nodes(i) > size(index%head) - 1) cycle
         do k = index%head(nodes(i)), index%head(nodes(i) + 1) - 1
            if (.not. any(sets == index%node_set(k))) sets = [sets, index%node_set(k)]
         end do
      end do
      call sort_short(sets)
   end function node_sets

end module pecplas_fe_joint_side
