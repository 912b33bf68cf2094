!> Mesh utilities used after reading: merging meshes, element checks (orientation,
!> degeneracy) and orienting edge sets so the body lies on their left.
!> Typical order: append every mesh, `check_elements`, then `orient_edge_sets`.
module pecplas_model_mesh_tools
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error, fatal_error
   use pecplas_model_mesh, only: mesh_t, element_set_t, node_set_t, edge_set_t
   use pecplas_model_node_lookup, only: node_lookup_t
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private

   public :: node_lookup_t, append_mesh, orient_edge_sets, check_elements, corner_count, id_list

contains

   !> Adds the nodes and sets of `other` to `mesh` (other's node numbers are shifted).
   !> A user node id in both meshes, or a set name in both (same kind of set), is an error.
   subroutine append_mesh(mesh, other, error)
      type(mesh_t), intent(inout) :: mesh
      type(mesh_t), intent(in) :: other
      type(error_t), allocatable, intent(out) :: error
      type(node_lookup_t) :: lookup
      type(element_set_t) :: es
      type(node_set_t) :: ns
      type(edge_set_t) :: eds
      real(wp), allocatable :: x(:, :)
      integer :: n1, n2, i, off
      ! (sets are copied through local variables: gfortran 12 loses deferred-length names
      ! of structure constructors placed in array constructors)
      n1 = mesh%nnode(); n2 = other%nnode()
      if (n2 > 0) then
         call lookup%build_ids([mesh%node_id(1:n1), other%node_id(1:n2)], 'node id', error)
         if (allocated(error)) then
            error%message = 'appending meshes: '//error%message
            return
         end if
      end if
      if (allocated(other%esets)) then
         do i = 1, size(other%esets)
            if (mesh%find_eset(other%esets(i)%name) > 0) then
               call input_error(error, 'appending meshes: element set '''//other%esets(i)%name// &
                  ''' is defined twice')
               return
            end if
         end do
      end if
      if (allocated(other%nsets)) then
         do i = 1, size(other%nsets)
            if (mesh%find_nset(other%nsets(i)%name) > 0) then
               call input_error(error, 'appending meshes: node set '''//other%nsets(i)%name// &
                  ''' is defined twice')
               return
            end if
         end do
      end if
      if (allocated(other%edge_sets)) then
         do i = 1, size(other%edge_sets)
            if (mesh%find_edge_set(other%edge_sets(i)%name) > 0) then
               call input_error(error, 'appending meshes: edge set '''//other%edge_sets(i)%name// &
                  ''' is defined twice')
               return
            end if
         end do
      end if

      off = n1
      if (n2 > 0) then
         allocate (x(2, n1 + n2))
         if (n1 > 0) x(:, 1:n1) = mesh%x
         x(:, n1 + 1:) = other%x
         call move_alloc(x, mesh%x)
         if (n1 > 0) then
            mesh%node_id = [mesh%node_id(1:n1), other%node_id(1:n2)]
         else
            mesh%node_id = other%node_id(1:n2)
         end if
      end if
      if (.not. allocated(mesh%esets)) allocate (mesh%esets(0))
      if (.not. allocated(mesh%nsets)) allocate (mesh%nsets(0))
      if (.not. allocated(mesh%edge_sets)) allocate (mesh%edge_sets(0))
      if (allocated(other%esets)) then
         do i = 1, size(other%esets)
            es = other%esets(i)
            es%conn = es%conn + off
            mesh%esets = [mesh%esets, es]
         end do
      end if
      if (allocated(other%nsets)) then
         do i = 1, size(other%nsets)
            ns = other%nsets(i)
            ns%nodes = ns%nodes + off
            mesh%nsets = [mesh%nsets, ns]
         end do
      end if
      if (allocated(other%edge_sets)) then
         do i = 1, size(other%edge_sets)
            eds = other%edge_sets(i)
            eds%nodes = eds%nodes + off
            mesh%edge_sets = [mesh%edge_sets, eds]
         end do
      end if
   end subroutine append_mesh

   !> Corner nodes of an element type ('T3', 'T6' -> 3; 'Q4', 'Q8', 'Q8R' -> 4), 0 if unknown.
   pure integer function corner_count(etype) result(nc)
      character(len=*), intent(in) :: etype
      select case (etype)
      case ('T3', 'T6')
         nc = 3
      case ('Q4', 'Q8', 'Q8R')
         nc = 4
      case default
         nc = 0
      end select
   end function corner_count

   !> Checks every element: known type, node numbers in range and distinct, non-zero area,
   !> convex quadrilaterals. Clockwise elements are renumbered counter-clockwise in place
   !> (midside nodes follow); `nflipped` counts them so the caller can report it.
   subroutine check_elements(mesh, nflipped, error, bad)
      type(mesh_t), intent(inout) :: mesh
      integer, intent(out) :: nflipped
      type(error_t), allocatable, intent(out) :: error
      !> Set and element of the failing element ([0, 0] when none or not one element).
      integer, intent(out), optional :: bad(2)
      integer :: s, j, i, k, nc, npe, nn
      integer :: c(8)
      real(wp) :: area, h2, xc(2, 4), e1(2), e2(2)
      nflipped = 0
      if (present(bad)) bad = 0
      if (.not. allocated(mesh%esets)) return
      nn = mesh%nnode()
      do s = 1, size(mesh%esets)
         associate (es => mesh%esets(s))
            nc = corner_count(es%etype)
            npe = size(es%conn, 1)
            if (nc == 0 .or. (npe /= nc .and. npe /= 2*nc)) then
               call input_error(error, 'element set '''//es%name//''': unknown element type ''' &
                  //es%etype//''' with '//itoa(npe)//' nodes')
               return
            end if
            do j = 1, size(es%conn, 2)
               if (present(bad)) bad = [s, j]
               c(1:npe) = es%conn(:, j)
               if (any(c(1:npe) < 1) .or. any(c(1:npe) > nn)) then
                  call fatal_error(error, 'element '//eid(es, j)//' of set '''//es%name// &
                     ''' refers to a node number out of range')
                  return
               end if
               do i = 2, npe
                  if (any(c(1:i - 1) == c(i))) then
                     call input_error(error, 'element '//eid(es, j)//' of set '''//es%name// &
                        ''' uses node '//itoa(mesh%node_id(c(i)))//' twice')
                     return
                  end if
               end do
               xc(:, 1:nc) = mesh%x(:, c(1:nc))
               area = 0.0_wp; h2 = 0.0_wp
               do i = 1, nc
                  k = modulo(i, nc) + 1
                  area = area + 0.5_wp*(xc(1, i)*xc(2, k) - xc(1, k)*xc(2, i))
                  h2 = max(h2, sum((xc(:, k) - xc(:, i))**2))
               end do
               if (abs(area) <= 1.0e-12_wp*h2) then
                  call input_error(error, 'element '//eid(es, j)//' of set '''//es%name// &
                     ''' has zero area (degenerate)')
                  return
               end if
               if (area < 0.0_wp) then
                  es%conn(:, j) = reversed(c(1:npe), nc)
                  xc(:, 1:nc) = mesh%x(:, es%conn(1:nc, j))
                  nflipped = nflipped + 1
               end if
               ! After orientation, a convex polygon turns left at every corner; a quad that
               ! does not has a vanishing Jacobian inside.
               do i = 1, nc
                  k = modulo(i, nc) + 1
                  e1 = xc(:, i) - xc(:, modulo(i - 2, nc) + 1)
                  e2 = xc(:, k) - xc(:, i)
                  if (e1(1)*e2(2) - e1(2)*e2(1) <= 1.0e-12_wp*h2) then
                     call input_error(error, 'element '//eid(es, j)//' of set '''//es%name// &
                        ''' is not convex at node '//itoa(mesh%node_id(es%conn(i, j))))
                     return
                  end if
               end do
            end do
         end associate
      end do
      if (present(bad)) bad = 0
   end subroutine check_elements

   !> Orders the nodes of every edge of every edge set (end, end, [mid]) so that an element
   !> lies on the left when walking from the first to the second end node.
   !> An edge between two elements keeps its given direction (it has one on its left).
   !> Errors: an edge of no element; a 2-node edge on a quadratic element side or a 3-node
   !> edge on a linear one. Cost O(nodes + elements + edges): edges are bucketed by their
   !> smaller end node and every element side looks into one short bucket.
   subroutine orient_edge_sets(mesh, error)
      type(mesh_t), intent(inout) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: head(:), item(:), set_of(:), pos_of(:), found(:), clash(:, :)
      integer :: nn, ne, s, k, f, j, i, nc, npe, p, q, a
      real(wp) :: area

      if (.not. allocated(mesh%edge_sets)) return
      nn = mesh%nnode()
      ne = 0
      do s = 1, size(mesh%edge_sets)
         k = size(mesh%edge_sets(s)%nodes, 1)
         if (k /= 2 .and. k /= 3) then
            call input_error(error, 'edge set '''//mesh%edge_sets(s)%name//''' has edges of '// &
               itoa(k)//' nodes (2 or 3 expected)')
            return
         end if
         ne = ne + size(mesh%edge_sets(s)%nodes, 2)
      end do
      ! Buckets (CSR) of flat edge numbers f by smaller end node: item(head(a):head(a+1)-1).
      allocate (head(nn + 2), item(ne), set_of(ne), pos_of(ne), found(ne), clash(2, ne))
      head = 0; found = 0; clash = 0
      f = 0
      do s = 1, size(mesh%edge_sets)
         associate (en => mesh%edge_sets(s)%nodes)
            do k = 1, size(en, 2)
               f = f + 1
               set_of(f) = s; pos_of(f) = k
               if (minval(en(:, k)) < 1 .or. maxval(en(:, k)) > nn) then
                  call fatal_error(error, 'edge set '''//mesh%edge_sets(s)%name// &
                     ''' refers to a node number out of range')
                  return
               end if
               a = minval(en(1:2, k))
               head(a + 2) = head(a + 2) + 1
            end do
         end associate
      end do
      head(1:2) = 1
      do i = 2, nn + 1
         head(i + 1) = head(i + 1) + head(i)
      end do
      ! head(a+1) is now the fill cursor of bucket a; after filling it is the bucket's end.
      do f = 1, ne
         a = minval(mesh%edge_sets(set_of(f))%nodes(1:2, pos_of(f)))
         item(head(a + 1)) = f
         head(a + 1) = head(a + 1) + 1
      end do
      if (.not. allocated(mesh%esets)) allocate (mesh%esets(0))

      do s = 1, size(mesh%esets)
         associate (es => mesh%esets(s))
            nc = corner_count(es%etype)
            npe = size(es%conn, 1)
            if (nc == 0) cycle
            do j = 1, size(es%conn, 2)
               area = 0.0_wp
               do i = 1, nc
                  k = modulo(i, nc) + 1
                  area = area + mesh%x(1, es%conn(i, j))*mesh%x(2, es%conn(k, j)) &
                         - mesh%x(1, es%conn(k, j))*mesh%x(2, es%conn(i, j))
               end do
               do i = 1, nc
                  p = es%conn(i, j); q = es%conn(modulo(i, nc) + 1, j)
                  ! Body on the left of p -> q for a counter-clockwise element.
                  if (area < 0.0_wp) then
                     a = p; p = q; q = a
                  end if
                  a = min(p, q)
                  do k = head(a), head(a + 1) - 1
                     f = item(k)
                     associate (en => mesh%edge_sets(set_of(f))%nodes(:, pos_of(f)))
                        if (max(en(1), en(2)) /= max(p, q)) cycle
                        if ((size(en) == 3) .neqv. (npe == 2*nc)) then
                           if (clash(1, f) == 0) clash(:, f) = [s, j]
                           cycle
                        end if
                        if (size(en) == 3) then
                           if (en(3) /= es%conn(nc + i, j)) cycle
                        end if
                        if (en(1) == p) then
                           found(f) = ior(found(f), 1)
                        else
                           found(f) = ior(found(f), 2)
                        end if
                     end associate
                  end do
               end do
            end do
         end associate
      end do

      do f = 1, ne
         associate (en => mesh%edge_sets(set_of(f))%nodes(:, pos_of(f)), &
                    name => mesh%edge_sets(set_of(f))%name)
            if (iand(found(f), 1) /= 0) cycle
            if (found(f) /= 0) then
               en(1:2) = en([2, 1])
            else if (clash(1, f) /= 0) then
               call input_error(error, 'edge set '''//name//''': the '//itoa(size(en))// &
                  '-node edge '//id_list(mesh, en)//' lies on a side of element '// &
                  eid(mesh%esets(clash(1, f)), clash(2, f))//' (set '''// &
                  mesh%esets(clash(1, f))%name//''', type '//mesh%esets(clash(1, f))%etype// &
                  ') with a different number of nodes')
               return
            else
               call input_error(error, 'edge set '''//name//''': the edge '//id_list(mesh, en)// &
                  ' is not a side of any element (3-node edges must match the midside node)')
               return
            end if
         end associate
      end do
   end subroutine orient_edge_sets

   !> "(id id [id])": user ids of internal node numbers (numbers below 1, no node, left out).
   function id_list(mesh, nodes) result(s)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: nodes(:)
      character(len=:), allocatable :: s
      integer :: i
      s = '('
      do i = 1, size(nodes)
         if (nodes(i) < 1) cycle
         if (i > 1) s = s//' '
         s = s//itoa(mesh%node_id(nodes(i)))
      end do
      s = s//')'
   end function id_list

   !> Node list of the same element walked the other way: corners c1, cn, ..., c2 and
   !> midside k (between new corners k and k+1) = old midside n+1-k.
   pure function reversed(c, nc) result(r)
      integer, intent(in) :: c(:), nc
      integer :: r(size(c)), k
      r(1) = c(1)
      do k = 2, nc
         r(k) = c(nc + 2 - k)
      end do
      if (size(c) == 2*nc) then
         do k = 1, nc
            r(nc + k) = c(2*nc + 1 - k)
         end do
      end if
   end function reversed

   function eid(es, j) result(s)
      type(element_set_t), intent(in) :: es
      integer, intent(in) :: j
      character(len=:), allocatable :: s
      if (allocated(es%ids)) then
         s = itoa(es%ids(j))
      else
         s = '#'//itoa(j)
      end if
   end function eid


end module pecplas_model_mesh_tools
