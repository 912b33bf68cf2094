!> The /mesh group of the results file:
!>   /mesh/coordinates (2, nnode), /mesh/node_ids (nnode)
!>   /mesh/sets/<set>/{connectivity (npe, nel) 0-based, element_ids (nel),
!>                     gauss_coordinates (2, ngauss, nel)}, attributes name, etype, material
!>   /mesh/node_sets/<set>/{nodes (0-based), node_ids}, attribute name
!>   /mesh/edge_sets/<set>/nodes (nodes per edge, nedge) 0-based, -1 = no mid-side node
!> Shapes are Fortran order; h5py sees them reversed, e.g. coordinates (nnode, 2).
!> Node indices are 0-based rows of /mesh/coordinates (what XDMF expects).
module pecplas_io_results_mesh
   use hdf5, only: hid_t
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_mesh, only: mesh_t
   use pecplas_io_results_increment, only: gauss_coordinates_t
   use pecplas_io_results_h5, only: h5_group, h5_close_group, h5_write, h5_attr, safe_name
   implicit none (type, external)
   private

   public :: write_mesh

contains

   !> Writes /mesh under the open file `file`.
   subroutine write_mesh(file, mesh, gauss_xy, error)
      integer(hid_t), intent(in) :: file
      type(mesh_t), intent(in) :: mesh
      type(gauss_coordinates_t), intent(in) :: gauss_xy(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: gmesh, gsets
      integer :: i
      integer, allocatable :: ids(:)
      gsets = -1
      call h5_group(file, 'mesh', gmesh, error)
      if (allocated(error)) return
      allocate (ids, source=ids_or_index(mesh%node_id, mesh%nnode()))
      call h5_write(gmesh, 'coordinates', mesh%x, error)
      if (.not. allocated(error)) call h5_write(gmesh, 'node_ids', ids, error)
      if (.not. allocated(error)) call h5_group(gmesh, 'sets', gsets, error)
      if (.not. allocated(error) .and. allocated(mesh%esets)) then
         do i = 1, size(mesh%esets)
            call write_element_set(gsets, mesh, i, gauss_xy(i)%xy, error)
            if (allocated(error)) exit
         end do
      end if
      call h5_close_group(gsets)
      if (.not. allocated(error)) call write_node_sets(gmesh, mesh, error)
      if (.not. allocated(error)) call write_edge_sets(gmesh, mesh, error)
      call h5_close_group(gmesh)
   end subroutine write_mesh

   subroutine write_element_set(gsets, mesh, i, xy, error)
      integer(hid_t), intent(in) :: gsets
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: i
      real(wp), intent(in), contiguous :: xy(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: g
      character(len=:), allocatable :: material
      integer, allocatable :: conn0(:, :), ids(:)
      associate (set => mesh%esets(i))
         allocate (conn0, source=set%conn - 1)
         allocate (ids, source=ids_or_index(set%ids, size(set%conn, 2)))
         call h5_group(gsets, safe_name(set%name), g, error)
         if (allocated(error)) return
         material = ''
         if (allocated(set%material)) material = set%material
         call h5_attr(g, 'name', set%name, error)
         if (.not. allocated(error)) call h5_attr(g, 'etype', set%etype, error)
         if (.not. allocated(error)) call h5_attr(g, 'material', material, error)
         if (.not. allocated(error)) call h5_write(g, 'connectivity', conn0, error)
         if (.not. allocated(error)) call h5_write(g, 'element_ids', ids, error)
         if (.not. allocated(error)) call h5_write(g, 'gauss_coordinates', xy, error)
         call h5_close_group(g)
      end associate
   end subroutine write_element_set

   subroutine write_node_sets(gmesh, mesh, error)
      integer(hid_t), intent(in) :: gmesh
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: gall, g
      integer :: i
      integer, allocatable :: user(:), nodes0(:), ids(:)
      allocate (user, source=ids_or_index(mesh%node_id, mesh%nnode()))
      call h5_group(gmesh, 'node_sets', gall, error)
      if (allocated(error)) return
      if (allocated(mesh%nsets)) then
         do i = 1, size(mesh%nsets)
            associate (set => mesh%nsets(i))
               call h5_group(gall, safe_name(set%name), g, error)
               if (allocated(error)) exit
               if (allocated(nodes0)) deallocate (nodes0, ids)
               allocate (nodes0, source=set%nodes - 1)
               allocate (ids, source=user(set%nodes))
               call h5_attr(g, 'name', set%name, error)
               if (.not. allocated(error)) call h5_write(g, 'nodes', nodes0, error)
               if (.not. allocated(error)) call h5_write(g, 'node_ids', ids, error)
               call h5_close_group(g)
               if (allocated(error)) exit
            end associate
         end do
      end if
      call h5_close_group(gall)
   end subroutine write_node_sets

   subroutine write_edge_sets(gmesh, mesh, error)
      integer(hid_t), intent(in) :: gmesh
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: gall, g
      integer :: i
      integer, allocatable :: nodes0(:, :)
      call h5_group(gmesh, 'edge_sets', gall, error)
      if (allocated(error)) return
      if (allocated(mesh%edge_sets)) then
         do i = 1, size(mesh%edge_sets)
            associate (set => mesh%edge_sets(i))
               call h5_group(gall, safe_name(set%name), g, error)
               if (allocated(error)) exit
               call h5_attr(g, 'name', set%name, error)
               ! node 0 (no mid-side node) becomes -1, like every absent 0-based index
               if (allocated(nodes0)) deallocate (nodes0)
               allocate (nodes0, source=set%nodes - 1)
               if (.not. allocated(error)) call h5_write(g, 'nodes', nodes0, error)
               call h5_close_group(g)
               if (allocated(error)) exit
            end associate
         end do
      end if
      call h5_close_group(gall)
   end subroutine write_edge_sets

   !> User ids when the mesh has them, else the internal numbers 1..n.
   pure function ids_or_index(ids, n) result(out)
      integer, allocatable, intent(in) :: ids(:)
      integer, intent(in) :: n
      integer, allocatable :: out(:)
      integer :: k
      if (allocated(ids)) then
         out = ids
      else
         out = [(k, k=1, n)]
      end if
   end function ids_or_index

end module pecplas_io_results_mesh
