!> Nodes, element sets, node sets and edge (boundary) sets of a 2D mesh.
!> Internal node and element numbers are dense (1..n); user ids are kept for messages.
module pecplas_model_mesh
   use pecplas_base_kinds, only: wp
   use pecplas_base_strings, only: same_name
   implicit none (type, external)
   private

   public :: mesh_t, element_set_t, node_set_t, edge_set_t

   !> Elements of one type sharing a material (one block of the deck or one Gmsh group).
   type :: element_set_t
      character(len=:), allocatable :: name
      !> Element type name as in the deck: 'T3', 'T6', 'Q4', 'Q8', 'Q8R'.
      character(len=:), allocatable :: etype
      !> Connectivity (nodes per element, number of elements), internal node numbers,
      !> corners counter-clockwise first, then mid-side nodes (node i+n/2 between i and i+1).
      integer, allocatable :: conn(:, :)
      !> User element ids (for messages).
      integer, allocatable :: ids(:)
      !> Material name given by *SECTION, and its index in model%materials.
      character(len=:), allocatable :: material
      integer :: material_index = 0
      !> The Gmsh physical group the set is the part of one element type of (a group mixing
      !> types is split into <group>_T3, <group>_Q8, ...), so that the group's name names
      !> them all (mesh_t%find_esets); absent for deck sets.
      character(len=:), allocatable :: group
   end type element_set_t

   !> A named list of nodes.
   type :: node_set_t
      character(len=:), allocatable :: name
      integer, allocatable :: nodes(:)
   end type node_set_t

   !> A named list of element edges (for pressures and, later, joints).
   !> nodes(:, k) are the edge nodes: end, end, [mid] with the body on the left when
   !> walking from the first to the second end node.
   type :: edge_set_t
      character(len=:), allocatable :: name
      integer, allocatable :: nodes(:, :)
   end type edge_set_t

   type :: mesh_t
      !> Coordinates (2, nnode): x, y (plane) or r, z (axisymmetric).
      real(wp), allocatable :: x(:, :)
      !> User node ids, internal number i has user id node_id(i).
      integer, allocatable :: node_id(:)
      type(element_set_t), allocatable :: esets(:)
      type(node_set_t), allocatable :: nsets(:)
      type(edge_set_t), allocatable :: edge_sets(:)
   contains
      procedure :: nnode => mesh_nnode
      procedure :: nelem => mesh_nelem
      procedure :: find_eset => mesh_find_eset
      procedure :: find_esets => mesh_find_esets
      procedure :: find_nset => mesh_find_nset
      procedure :: find_edge_set => mesh_find_edge_set
      procedure :: node_of => mesh_node_of
   end type mesh_t

contains

   pure integer function mesh_nnode(this) result(n)
      class(mesh_t), intent(in) :: this
      n = 0
      if (allocated(this%x)) n = size(this%x, 2)
   end function mesh_nnode

   !> Total number of massif elements over all sets.
   pure integer function mesh_nelem(this) result(n)
      class(mesh_t), intent(in) :: this
      integer :: i
      n = 0
      if (.not. allocated(this%esets)) return
      do i = 1, size(this%esets)
         n = n + size(this%esets(i)%conn, 2)
      end do
   end function mesh_nelem

   !> Index of the element set named `name` (case-insensitive), 0 if none.
   integer function mesh_find_eset(this, name) result(k)
      class(mesh_t), intent(in) :: this
      character(len=*), intent(in) :: name
      integer :: i
      k = 0
      if (.not. allocated(this%esets)) return
      do i = 1, size(this%esets)
         if (same_name(this%esets(i)%name, name)) k = i
      end do
   end function mesh_find_eset

   !> The element sets `name` names: the set of that name, or else every part of the Gmsh
   !> physical group of that name (one set per element type); none when neither exists.
   function mesh_find_esets(this, name) result(list)
      class(mesh_t), intent(in) :: this
      character(len=*), intent(in) :: name
      integer, allocatable :: list(:)
      integer :: i
      allocate (list(0))
      i = this%find_eset(name)
      if (i > 0) then
         list = [i]
         return
      end if
      if (.not. allocated(this%esets)) return
      do i = 1, size(this%esets)
         if (.not. allocated(this%esets(i)%group)) cycle
         if (same_name(this%esets(i)%group, name)) list = [list, i]
      end do
   end function mesh_find_esets

   integer function mesh_find_nset(this, name) result(k)
      class(mesh_t), intent(in) :: this
      character(len=*), intent(in) :: name
      integer :: i
      k = 0
      if (.not. allocated(this%nsets)) return
      do i = 1, size(this%nsets)
         if (same_name(this%nsets(i)%name, name)) k = i
      end do
   end function mesh_find_nset

   integer function mesh_find_edge_set(this, name) result(k)
      class(mesh_t), intent(in) :: this
      character(len=*), intent(in) :: name
      integer :: i
      k = 0
      if (.not. allocated(this%edge_sets)) return
      do i = 1, size(this%edge_sets)
         if (same_name(this%edge_sets(i)%name, name)) k = i
      end do
   end function mesh_find_edge_set

   !> The one node that `ref` names where a keyword takes a single node: a user node id
   !> (digits), or the name of a node set of one node. A set whose nodes all sit at one point
   !> (a node and the duplicates that generated joints add to its sets) names its first node,
   !> the one written in the deck. inode = 0 and `msg` says why otherwise.
   subroutine mesh_node_of(this, ref, inode, msg)
      class(mesh_t), intent(in) :: this
      character(len=*), intent(in) :: ref
      integer, intent(out) :: inode
      character(len=:), allocatable, intent(out) :: msg
      character(len=:), allocatable :: t
      character(len=12) :: buf
      integer :: id, ios, k
      inode = 0
      t = trim(adjustl(ref))
      if (len(t) == 0) then
         msg = 'expected a node id or the name of a node set of one node, found nothing'
         return
      end if
      if (verify(t, '0123456789') == 0) then
         read (t, *, iostat=ios) id
         if (ios == 0 .and. allocated(this%node_id)) inode = findloc(this%node_id, id, 1)
         if (inode == 0) msg = 'no node '//t
         return
      end if
      k = this%find_nset(t)
      if (k == 0) then
         msg = "no node set '"//t//"' (expected a node id or the name of a node set of "// &
            'one node)'
         return
      end if
      associate (nodes => this%nsets(k)%nodes)
         if (size(nodes) == 0) then
            msg = "node set '"//t//"' is empty; expected a node set of one node"
            return
         end if
         if (any(this%x(1, nodes) /= this%x(1, nodes(1)) .or. &
                 this%x(2, nodes) /= this%x(2, nodes(1)))) then
            write (buf, '(i0)') size(nodes)
            msg = "node set '"//t//"' has "//trim(buf)//' nodes; expected a node id or a '// &
               'node set of one node'
            return
         end if
         inode = nodes(1)
      end associate
   end subroutine mesh_node_of

end module pecplas_model_mesh
