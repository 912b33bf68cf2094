!> Element sides of a mesh, bucketed by end node for O(1) look-ups: which elements have
!> the side (a, b[, m])? Used to split meshes along interfaces and to check joints
!> against the bodies they join.
module pecplas_model_mesh_sides
   use pecplas_base_kinds, only: wp
   use pecplas_model_mesh, only: mesh_t
   use pecplas_model_mesh_tools, only: corner_count
   implicit none (type, external)
   private

   public :: side_table_t, build_side_table, find_sides, element_centroid

   !> Element sides bucketed (CSR) by the smaller key of their end nodes.
   type :: side_table_t
      integer, allocatable :: head(:), item(:)
      !> nodes(3, k): end, end, mid (0 on linear sides); set and element of side k.
      integer, allocatable :: nodes(:, :), set(:), elem(:)
      !> Key of each node (the node itself, or the node it was split from).
      integer, allocatable :: key(:)
   end type side_table_t

contains

   !> Side table of every element of `mesh`; sides are found by key(node) (default: the
   !> node numbers themselves).
   subroutine build_side_table(mesh, table, key)
      type(mesh_t), intent(in) :: mesh
      type(side_table_t), intent(out) :: table
      integer, intent(in), optional :: key(:)
      integer :: nside, s, j, i, nc, k, a, nn
      nn = mesh%nnode()
      if (present(key)) then
         table%key = key(1:nn)
      else
         table%key = [(i, i=1, nn)]
      end if
      nside = 0
      if (allocated(mesh%esets)) then
         do s = 1, size(mesh%esets)
            nside = nside + corner_count(mesh%esets(s)%etype)*size(mesh%esets(s)%conn, 2)
         end do
      end if
      allocate (table%nodes(3, nside), table%set(nside), table%elem(nside), table%item(nside))
      allocate (table%head(nn + 2), source=0)
      k = 0
      do s = 1, size(mesh%esets)
         associate (conn => mesh%esets(s)%conn)
            nc = corner_count(mesh%esets(s)%etype)
            do j = 1, size(conn, 2)
               do i = 1, nc
                  k = k + 1
                  table%nodes(:, k) = [conn(i, j), conn(mod(i, nc) + 1, j), 0]
                  if (size(conn, 1) == 2*nc) table%nodes(3, k) = conn(nc + i, j)
                  table%set(k) = s
                  table%elem(k) = j
                  a = min(table%key(table%nodes(1, k)), table%key(table%nodes(2, k)))
                  table%head(a + 2) = table%head(a + 2) + 1
               end do
            end do
         end associate
      end do
      table%head(1:2) = 1
      do i = 2, nn + 1
         table%head(i + 1) = table%head(i + 1) + table%head(i)
      end do
      do k = 1, nside
         a = min(table%key(table%nodes(1, k)), table%key(table%nodes(2, k)))
         table%item(table%head(a + 1)) = k
         table%head(a + 1) = table%head(a + 1) + 1
      end do
   end subroutine build_side_table

   !> Sides whose keys match the keys of edge = (end, end[, mid]) (ends in either order; a
   !> 2-node edge matches linear sides only, a 0 mid node too).
   pure function find_sides(table, edge) result(sides)
      type(side_table_t), intent(in) :: table
      integer, intent(in) :: edge(:)
      integer, allocatable :: sides(:)
      integer :: ke(3), ks(3), a, k, s, i
      allocate (sides(0))
      ke = 0
      do i = 1, min(size(edge), 3)
         if (edge(i) > 0) ke(i) = table%key(edge(i))
      end do
      a = min(ke(1), ke(2))
      if (a < 1 .or. a > size(table%head) - 2) return
      do k = table%head(a), table%head(a + 1) - 1
         s = table%item(k)
         ks = 0
         do i = 1, 3
            if (table%nodes(i, s) > 0) ks(i) = table%key(table%nodes(i, s))
         end do
         if (min(ks(1), ks(2)) /= a .or. max(ks(1), ks(2)) /= max(ke(1), ke(2))) cycle
         if (ks(3) /= ke(3)) cycle
         sides = [sides, s]
      end do
   end function find_sides

   !> Centroid of the corners of element j of set s.
   pure function element_centroid(mesh, s, j) result(c)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: s, j
      real(wp) :: c(2)
      integer :: nc
      nc = corner_count(mesh%esets(s)%etype)
      c = sum(mesh%x(:, mesh%esets(s)%conn(1:nc, j)), dim=2)/real(nc, wp)
   end function element_centroid

end module pecplas_model_mesh_sides
