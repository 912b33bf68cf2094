!> Unique edges of a model for its uniform refinement (pecplas_model_refine): every edge of
!> the massif elements, joint faces, edge sets and pressure edges once, with its midpoint node
!> and the number of massif elements on it (1: a boundary edge).
module pecplas_model_refine_edges
   use pecplas_model, only: model_t
   implicit none (type, external)
   private

   public :: edge_map_t, build_edges, mid, edge_elements, count_q4, joint_faces_on_elements

   !> Unique edges (a < b): CSR rows by a, the other end, the midpoint node, the number of
   !> massif elements on the edge.
   type :: edge_map_t
      integer, allocatable :: start(:), cnt(:), other(:), mid(:), nel(:)
   end type edge_map_t

contains

   !> Every unique edge of the massif elements, joint faces, pressure edges and edge sets, with
   !> a midpoint node numbered from nn0 + 1 (nn = the last one: midpoints and Q4 centres).
   subroutine build_edges(model, em, nn0, nn)
      type(model_t), intent(in) :: model
      type(edge_map_t), intent(out) :: em
      integer, intent(in) :: nn0
      integer, intent(out) :: nn
      integer, allocatable :: pairs(:, :), owner(:)
      integer :: i, j, a, b, slot, nq
      call collect_pairs(model, pairs, owner)
      allocate (em%start(nn0 + 1), em%cnt(nn0), source=0)
      do i = 1, size(pairs, 2)
         a = minval(pairs(:, i))
         em%cnt(a) = em%cnt(a) + 1
      end do
      em%start(1) = 1
      do i = 1, nn0
         em%start(i + 1) = em%start(i) + em%cnt(i)
      end do
      allocate (em%other(size(pairs, 2)), em%mid(size(pairs, 2)), em%nel(size(pairs, 2)), &
         source=0)
      em%cnt = 0
      nn = nn0
      do i = 1, size(pairs, 2)
         a = minval(pairs(:, i))
         b = maxval(pairs(:, i))
         slot = 0
         do j = em%start(a), em%start(a) + em%cnt(a) - 1
            if (em%other(j) == b) slot = j
         end do
         if (slot == 0) then
            slot = em%start(a) + em%cnt(a)
            em%cnt(a) = em%cnt(a) + 1
            em%other(slot) = b
            nn = nn + 1
            em%mid(slot) = nn
         end if
         em%nel(slot) = em%nel(slot) + owner(i)
      end do
      nq = 0
      do i = 1, size(model%mesh%esets)
         if (model%mesh%esets(i)%etype == 'Q4') nq = nq + size(model%mesh%esets(i)%conn, 2)
      end do
      nn = nn + nq
   end subroutine build_edges

   !> Node pairs of all edges; owner = 1 for an edge of a massif element, else 0.
   subroutine collect_pairs(model, pairs, owner)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: pairs(:, :), owner(:)
      integer :: s, k, i, nc, n
      n = 0
      do s = 1, size(model%mesh%esets)
         n = n + size(model%mesh%esets(s)%conn)
      end do
      do s = 1, size(model%joint_sets)
         n = n + 2*size(model%joint_sets(s)%conn, 2)
      end do
      do s = 1, size(model%mesh%edge_sets)
         n = n + size(model%mesh%edge_sets(s)%nodes, 2)
      end do
      do s = 1, size(model%patterns)
         if (allocated(model%patterns(s)%edge)) n = n + size(model%patterns(s)%edge, 2)
      end do
      allocate (pairs(2, n), owner(n), source=0)
      n = 0
      do s = 1, size(model%mesh%esets)
         associate (c => model%mesh%esets(s)%conn)
            nc = size(c, 1)
            do k = 1, size(c, 2)
               do i = 1, nc
                  n = n + 1
                  pairs(:, n) = [c(i, k), c(mod(i, nc) + 1, k)]
                  owner(n) = 1
               end do
            end do
         end associate
      end do
      do s = 1, size(model%joint_sets)
         associate (c => model%joint_sets(s)%conn)
            do k = 1, size(c, 2)
               pairs(:, n + 1) = c(1:2, k)
               pairs(:, n + 2) = c(3:4, k)
               n = n + 2
            end do
         end associate
      end do
      do s = 1, size(model%mesh%edge_sets)
         call append_edges(model%mesh%edge_sets(s)%nodes, pairs, n)
      end do
      do s = 1, size(model%patterns)
         if (allocated(model%patterns(s)%edge)) call append_edges(model%patterns(s)%edge, &
            pairs, n)
      end do
   end subroutine collect_pairs

   subroutine append_edges(e, pairs, n)
      integer, intent(in) :: e(:, :)
      integer, intent(inout) :: pairs(:, :), n
      pairs(:, n + 1:n + size(e, 2)) = e(1:2, :)
      n = n + size(e, 2)
   end subroutine append_edges

   !> The midpoint node of edge (a, b); 0 when it is not an edge.
   pure integer function mid(em, a, b) result(m)
      type(edge_map_t), intent(in) :: em
      integer, intent(in) :: a, b
      integer :: j, lo, hi
      lo = min(a, b)
      hi = max(a, b)
      m = 0
      do j = em%start(lo), em%start(lo) + em%cnt(lo) - 1
         if (em%other(j) == hi) m = em%mid(j)
      end do
   end function mid

   !> A joint face that is no element edge would leave its midpoint on the joint alone.
   subroutine joint_faces_on_elements(model, em, reason)
      type(model_t), intent(in) :: model
      type(edge_map_t), intent(in) :: em
      character(len=:), allocatable, intent(out) :: reason
      integer :: s, k, j
      do s = 1, size(model%joint_sets)
         associate (c => model%joint_sets(s)%conn)
            do k = 1, size(c, 2)
               do j = 1, 3, 2
                  if (edge_elements(em, c(j, k), c(j + 1, k)) == 0) then
                     reason = 'a face of joint set '//model%joint_sets(s)%name// &
                        ' is no element edge'
                     return
                  end if
               end do
            end do
         end associate
      end do
   end subroutine joint_faces_on_elements

   pure integer function edge_elements(em, a, b) result(n)
      type(edge_map_t), intent(in) :: em
      integer, intent(in) :: a, b
      integer :: j
      n = 0
      do j = em%start(min(a, b)), em%start(min(a, b)) + em%cnt(min(a, b)) - 1
         if (em%other(j) == max(a, b)) n = em%nel(j)
      end do
   end function edge_elements

   pure integer function count_q4(model) result(n)
      type(model_t), intent(in) :: model
      integer :: s
      n = 0
      do s = 1, size(model%mesh%esets)
         if (model%mesh%esets(s)%etype == 'Q4') n = n + size(model%mesh%esets(s)%conn, 2)
      end do
   end function count_q4

end module pecplas_model_refine_edges
