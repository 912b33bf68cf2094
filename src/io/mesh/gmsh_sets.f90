!> What the Gmsh reader keeps between sections (physical names, entities, element blocks)
!> and the mapping of physical groups to element, edge and node sets (see pecplas_io_mesh_gmsh).
module pecplas_io_mesh_gmsh_sets
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_model_mesh, only: mesh_t, element_set_t, node_set_t, edge_set_t
   use pecplas_model_node_lookup, only: node_lookup_t
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private

   public :: gmsh_data_t, build_sets, grow, itoa, nodes_per_element

   !> Gmsh element types used here and their PECPLAS names.
   integer, parameter :: surface_types(4) = [2, 9, 3, 16]
   character(len=2), parameter :: surface_names(4) = ['T3', 'T6', 'Q4', 'Q8']

   !> One line of $PhysicalNames.
   type :: name_t
      integer :: dim = 0, tag = 0
      character(len=:), allocatable :: name
   end type name_t

   !> Entities of one dimension: tags and their physical tags phys(ptr(i):ptr(i+1)-1).
   type :: entities_t
      integer, allocatable :: tag(:), ptr(:), phys(:)
      type(node_lookup_t) :: lookup
   end type entities_t

   !> Reader state. Kept element blocks store element tags in el_id and connectivity
   !> (internal node numbers) flat in conn, block after block.
   type :: gmsh_data_t
      character(len=:), allocatable :: path
      type(name_t), allocatable :: names(:)
      type(entities_t) :: ents(0:2)
      !> Any physical point, curve or surface group in the file.
      logical :: has_phys = .false.
      !> Gmsh node tag -> internal node number.
      type(node_lookup_t) :: nodes
      integer :: nblock = 0, nel = 0, nconn = 0
      integer, allocatable :: b_dim(:), b_ent(:), b_type(:), b_nel(:), b_npe(:), b_first(:), &
                              b_cfirst(:)
      integer, allocatable :: el_id(:), conn(:)
   contains
      procedure :: used => data_used
      procedure :: add_block => data_add_block
   end type gmsh_data_t

contains

   !> Whether elements on entity number `ie` (0 = unknown) of dimension `edim` feed a set.
   pure logical function data_used(this, edim, ie) result(used)
      class(gmsh_data_t), intent(in) :: this
      integer, intent(in) :: edim, ie
      used = .false.
      if (edim < 0 .or. edim > 2) return
      if (this%has_phys) then
         if (ie > 0) used = this%ents(edim)%ptr(ie + 1) > this%ents(edim)%ptr(ie)
      else
         used = edim == 2
      end if
   end function data_used

   !> Reserves room for a block of nb elements of npe nodes (filled by the caller).
   subroutine data_add_block(this, edim, ie, gtype, nb, npe)
      class(gmsh_data_t), intent(inout) :: this
      integer, intent(in) :: edim, ie, gtype, nb, npe
      integer :: b
      b = this%nblock + 1
      call grow(this%b_dim, b); call grow(this%b_ent, b); call grow(this%b_type, b)
      call grow(this%b_nel, b); call grow(this%b_npe, b); call grow(this%b_first, b)
      call grow(this%b_cfirst, b)
      this%b_dim(b) = edim; this%b_ent(b) = ie; this%b_type(b) = gtype
      this%b_nel(b) = nb; this%b_npe(b) = npe
      this%b_first(b) = this%nel; this%b_cfirst(b) = this%nconn
      this%nblock = b
      this%nel = this%nel + nb; this%nconn = this%nconn + nb*npe
      call grow(this%el_id, this%nel); call grow(this%conn, this%nconn)
   end subroutine data_add_block

   !> Nodes per element of Gmsh type `gtype` on an entity of dimension `edim`, 0 if unsupported.
   pure integer function nodes_per_element(edim, gtype) result(n)
      integer, intent(in) :: edim, gtype
      n = 0
      select case (edim)
      case (2)
         select case (gtype)
         case (2); n = 3
         case (9); n = 6
         case (3); n = 4
         case (16); n = 8
         end select
      case (1)
         if (gtype == 1) n = 2
         if (gtype == 8) n = 3
      case (0)
         if (gtype == 15) n = 1
      end select
   end function nodes_per_element

   !> Element sets from surface groups, edge and node sets from curve groups, node sets
   !> from point groups (or 'ALL_<type>' sets when the file has no physical group).
   subroutine build_sets(g, mesh, error)
      type(gmsh_data_t), intent(in) :: g
      type(mesh_t), intent(inout) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: tags(:), mark(:)
      integer :: i, d
      allocate (mesh%esets(0), mesh%nsets(0), mesh%edge_sets(0))
      allocate (mark(mesh%nnode()))
      mark = 0
      if (.not. g%has_phys) then
         call surface_group(g, 0, mesh, error)
         return
      end if
      do d = 2, 0, -1
         tags = group_tags(g, d)
         do i = 1, size(tags)
            select case (d)
            case (2)
               call surface_group(g, tags(i), mesh, error)
            case (1)
               call curve_group(g, tags(i), mesh, mark, error)
            case (0)
               call point_group(g, tags(i), mesh, mark, error)
            end select
            if (allocated(error)) return
         end do
      end do
   end subroutine build_sets

   !> Physical surface group p (0: every surface) -> one element set per element type.
   subroutine surface_group(g, p, mesh, error)
      type(gmsh_data_t), intent(in) :: g
      integer, intent(in) :: p
      type(mesh_t), intent(inout) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(element_set_t) :: es
      integer :: n(4), t
      character(len=:), allocatable :: name
      do t = 1, 4
         n(t) = count_elements(g, 2, p, surface_types(t))
      end do
      name = 'ALL'
      if (p /= 0) name = group_name(g, 2, p)
      do t = 1, 4
         if (n(t) == 0) cycle
         es%name = name
         es%group = name
         if (p == 0 .or. count(n > 0) > 1) es%name = name//'_'//surface_names(t)
         es%etype = surface_names(t)
         call gather(g, 2, p, surface_types(t), es%ids, es%conn)
         if (mesh%find_eset(es%name) > 0) then
            call deck_error(error, g%path, 0, '$PhysicalNames', 'element set '''//es%name// &
               ''' is defined by two physical surface groups')
            return
         end if
         mesh%esets = [mesh%esets, es]
      end do
   end subroutine surface_group

   !> Physical curve group p -> edge set and node set of the same name.
   subroutine curve_group(g, p, mesh, mark, error)
      type(gmsh_data_t), intent(in) :: g
      integer, intent(in) :: p
      type(mesh_t), intent(inout) :: mesh
      integer, intent(inout) :: mark(:)
      type(error_t), allocatable, intent(out) :: error
      type(edge_set_t) :: eds
      integer, allocatable :: ids(:)
      integer :: n2, n3
      eds%name = group_name(g, 1, p)
      n2 = count_elements(g, 1, p, 1)
      n3 = count_elements(g, 1, p, 8)
      if (n2 > 0 .and. n3 > 0) then
         call deck_error(error, g%path, 0, '$Elements', 'physical curve '''//eds%name// &
            ''' mixes 2-node and 3-node lines')
         return
      end if
      if (mesh%find_edge_set(eds%name) > 0) then
         call deck_error(error, g%path, 0, '$PhysicalNames', 'edge set '''//eds%name// &
            ''' is defined by two physical curve groups')
         return
      end if
      call gather(g, 1, p, merge(8, 1, n3 > 0), ids, eds%nodes)
      mesh%edge_sets = [mesh%edge_sets, eds]
      call add_node_set(g, eds%name, eds%nodes, mesh, mark, error)
   end subroutine curve_group

   !> Physical point group p -> node set.
   subroutine point_group(g, p, mesh, mark, error)
      type(gmsh_data_t), intent(in) :: g
      integer, intent(in) :: p
      type(mesh_t), intent(inout) :: mesh
      integer, intent(inout) :: mark(:)
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: ids(:), conn(:, :)
      call gather(g, 0, p, 15, ids, conn)
      call add_node_set(g, group_name(g, 0, p), conn, mesh, mark, error)
   end subroutine point_group

   !> Node set of the distinct nodes of `conn`, in order of first appearance.
   subroutine add_node_set(g, name, conn, mesh, mark, error)
      type(gmsh_data_t), intent(in) :: g
      character(len=*), intent(in) :: name
      integer, intent(in) :: conn(:, :)
      type(mesh_t), intent(inout) :: mesh
      integer, intent(inout) :: mark(:)
      type(error_t), allocatable, intent(out) :: error
      type(node_set_t) :: ns
      integer :: i, j, n
      if (mesh%find_nset(name) > 0) then
         call deck_error(error, g%path, 0, '$PhysicalNames', 'node set '''//name// &
            ''' is defined by two physical groups (curve or point)')
         return
      end if
      allocate (ns%nodes(size(conn)))
      n = 0
      do j = 1, size(conn, 2)
         do i = 1, size(conn, 1)
            if (mark(conn(i, j)) /= 0) cycle
            mark(conn(i, j)) = 1
            n = n + 1
            ns%nodes(n) = conn(i, j)
         end do
      end do
      ns%nodes = ns%nodes(1:n)
      mark(ns%nodes) = 0
      ns%name = name
      mesh%nsets = [mesh%nsets, ns]
   end subroutine add_node_set

   !> Whether block b is in physical group p (p = 0: any block).
   pure logical function in_group(g, b, p)
      type(gmsh_data_t), intent(in) :: g
      integer, intent(in) :: b, p
      integer :: ie
      in_group = p == 0
      if (in_group) return
      ie = g%b_ent(b)
      associate (e => g%ents(g%b_dim(b)))
         in_group = any(e%phys(e%ptr(ie):e%ptr(ie + 1) - 1) == p)
      end associate
   end function in_group

   pure integer function count_elements(g, d, p, gtype) result(n)
      type(gmsh_data_t), intent(in) :: g
      integer, intent(in) :: d, p, gtype
      integer :: b
      n = 0
      do b = 1, g%nblock
         if (g%b_dim(b) == d .and. g%b_type(b) == gtype) then
            if (in_group(g, b, p)) n = n + g%b_nel(b)
         end if
      end do
   end function count_elements

   !> Element tags and connectivity of the type-`gtype` elements of group p, dimension d.
   subroutine gather(g, d, p, gtype, ids, conn)
      type(gmsh_data_t), intent(in) :: g
      integer, intent(in) :: d, p, gtype
      integer, allocatable, intent(out) :: ids(:), conn(:, :)
      integer :: b, n, npe, nb, c0
      npe = nodes_per_element(d, gtype)
      allocate (ids(count_elements(g, d, p, gtype)))
      allocate (conn(npe, size(ids)))
      n = 0
      do b = 1, g%nblock
         if (g%b_dim(b) /= d .or. g%b_type(b) /= gtype) cycle
         if (.not. in_group(g, b, p)) cycle
         nb = g%b_nel(b); c0 = g%b_cfirst(b)
         ids(n + 1:n + nb) = g%el_id(g%b_first(b) + 1:g%b_first(b) + nb)
         conn(:, n + 1:n + nb) = reshape(g%conn(c0 + 1:c0 + nb*npe), [npe, nb])
         n = n + nb
      end do
   end subroutine gather

   !> Distinct physical tags of the entities of dimension d, ascending.
   function group_tags(g, d) result(tags)
      type(gmsh_data_t), intent(in) :: g
      integer, intent(in) :: d
      integer, allocatable :: tags(:)
      integer :: i, j, n, t
      allocate (tags(size(g%ents(d)%phys)))
      n = 0
      do i = 1, size(g%ents(d)%phys)
         t = g%ents(d)%phys(i)
         if (any(tags(1:n) == t)) cycle
         ! insertion keeps the list sorted (groups are few)
         j = n
         do while (j > 0)
            if (tags(j) < t) exit
            tags(j + 1) = tags(j)
            j = j - 1
         end do
         tags(j + 1) = t
         n = n + 1
      end do
      tags = tags(1:n)
   end function group_tags

   !> Name of physical group (d, p) from $PhysicalNames, or 'PHYS<p>'.
   function group_name(g, d, p) result(name)
      type(gmsh_data_t), intent(in) :: g
      integer, intent(in) :: d, p
      character(len=:), allocatable :: name
      integer :: i
      name = 'PHYS'//itoa(p)
      if (.not. allocated(g%names)) return
      do i = 1, size(g%names)
         if (g%names(i)%dim == d .and. g%names(i)%tag == p) name = g%names(i)%name
      end do
   end function group_name

   !> Makes size(a) >= n, doubling so that repeated growth costs O(n) overall.
   pure subroutine grow(a, n)
      integer, allocatable, intent(inout) :: a(:)
      integer, intent(in) :: n
      integer, allocatable :: tmp(:)
      if (.not. allocated(a)) allocate (a(0))
      if (size(a) >= n) return
      allocate (tmp(max(n, 2*size(a), 16)))
      tmp(1:size(a)) = a
      call move_alloc(tmp, a)
   end subroutine grow


end module pecplas_io_mesh_gmsh_sets
