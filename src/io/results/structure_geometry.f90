!> Geometry of the structures for the XDMF sidecar (doc/results.md, Plates and Anchors):
!>   /mesh/plates/<set>/node_coordinates (nnode_plate, 2)  the plate's nodes in the order of
!>        /mesh/plates/<set>/nodes (and of node_forces, displacement, rotation)
!>   /mesh/plates/<set>/local_connectivity (nel, nen)     0-based rows of node_coordinates
!>   /mesh/anchors/<set>/point_coordinates (2 nbar, 2)     both ends of each bar (a fixed-end
!>        anchor's fixed point drawn at its node + LENGTH along its direction)
!>   /mesh/anchors/<set>/point_connectivity (nbar, 2)      0-based rows of point_coordinates
!> (h5py shapes). The XDMF draws each structure as polylines on these points, so that the
!> per-node forces of a plate and the per-bar force of an anchor attach to them directly.
!> Also the structures as the XDMF layout sees them (xdmf_structures).
module pecplas_io_results_structure_geometry
   use hdf5, only: hid_t
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_io_results_h5, only: h5_write, safe_name, h5_describe
   use pecplas_io_results_describe, only: XY
   use pecplas_io_results_xdmf, only: xdmf_plate_t, xdmf_anchor_t
   implicit none (type, external)
   private

   public :: write_structure_geometry, xdmf_structures, plate_node_order, anchor_points

contains

   !> The datasets above, into groups write_plate_mesh and write_anchor_mesh created;
   !> coordinates in `length_unit`.
   subroutine write_structure_geometry(file, model, length_unit, error)
      integer(hid_t), intent(in) :: file
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: length_unit
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: nodes(:), local(:, :), pconn(:, :)
      real(wp), allocatable :: points(:, :)
      character(len=:), allocatable :: g
      integer :: s, b
      if (allocated(model%plates)) then
         do s = 1, size(model%plates)
            g = '/mesh/plates/'//safe_name(model%plates(s)%name)
            call plate_node_order(model%plates(s)%conn, nodes, local)
            points = model%mesh%x(:, nodes)
            call h5_write(file, g//'/node_coordinates', points, error)
            if (.not. allocated(error)) call h5_describe(file, g//'/node_coordinates', &
               length_unit, error, XY)
            if (.not. allocated(error)) call h5_write(file, g//'/local_connectivity', &
               local - 1, error)
            if (allocated(error)) return
         end do
      end if
      if (allocated(model%anchors)) then
         do s = 1, size(model%anchors)
            g = '/mesh/anchors/'//safe_name(model%anchors(s)%name)
            allocate (pconn(2, model%anchors(s)%nbar()))
            do b = 1, size(pconn, 2)
               pconn(:, b) = [2*b - 2, 2*b - 1]
            end do
            points = anchor_points(model, s)
            call h5_write(file, g//'/point_coordinates', points, error)
            if (.not. allocated(error)) call h5_describe(file, g//'/point_coordinates', &
               length_unit, error, XY)
            if (.not. allocated(error)) call h5_write(file, g//'/point_connectivity', pconn, &
               error)
            deallocate (pconn)
            if (allocated(error)) return
         end do
      end if
   end subroutine write_structure_geometry

   !> The plate's nodes in the order of their first appearance in conn (nen, nel), and conn
   !> in 1-based positions of that list.
   pure subroutine plate_node_order(conn, nodes, local)
      integer, intent(in) :: conn(:, :)
      integer, allocatable, intent(out) :: nodes(:), local(:, :)
      integer :: e, k, i
      allocate (nodes(0), local(size(conn, 1), size(conn, 2)))
      do e = 1, size(conn, 2)
         do k = 1, size(conn, 1)
            i = findloc(nodes, conn(k, e), 1)
            if (i == 0) then
               nodes = [nodes, conn(k, e)]
               i = size(nodes)
            end if
            local(k, e) = i
         end do
      end do
   end subroutine plate_node_order

   !> Both ends of each bar of anchor set s (2, 2 nbar): its node 1, then its node 2 or, for
   !> a fixed-end anchor, the point at LENGTH from its node along its direction.
   pure function anchor_points(model, s) result(xy)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      real(wp), allocatable :: xy(:, :)
      integer :: b
      associate (a => model%anchors(s))
         allocate (xy(2, 2*a%nbar()))
         do b = 1, a%nbar()
            xy(:, 2*b - 1) = model%mesh%x(:, a%conn(1, b))
            if (a%conn(2, b) > 0) then
               xy(:, 2*b) = model%mesh%x(:, a%conn(2, b))
            else
               xy(:, 2*b) = xy(:, 2*b - 1) + a%length(b)*a%direction(:, b)
            end if
         end do
      end associate
   end function anchor_points

   !> The plate and anchor sets of `model` as the XDMF layout sees them.
   subroutine xdmf_structures(model, plates, anchors)
      type(model_t), intent(in) :: model
      type(xdmf_plate_t), allocatable, intent(out) :: plates(:)
      type(xdmf_anchor_t), allocatable, intent(out) :: anchors(:)
      integer, allocatable :: nodes(:), local(:, :)
      integer :: s
      allocate (plates(0), anchors(0))
      if (allocated(model%plates)) then
         deallocate (plates)
         allocate (plates(size(model%plates)))
         do s = 1, size(model%plates)
            call plate_node_order(model%plates(s)%conn, nodes, local)
            plates(s)%name = safe_name(model%plates(s)%name)
            plates(s)%nen = size(local, 1)
            plates(s)%nel = size(local, 2)
            plates(s)%nnode = size(nodes)
         end do
      end if
      if (allocated(model%anchors)) then
         deallocate (anchors)
         allocate (anchors(size(model%anchors)))
         do s = 1, size(model%anchors)
            anchors(s)%name = safe_name(model%anchors(s)%name)
            anchors(s)%nbar = model%anchors(s)%nbar()
         end do
      end if
   end subroutine xdmf_structures

end module pecplas_io_results_structure_geometry
