!> Geometry of the anchors for the XDMF sidecar (doc/results.md, `/mesh`):
!>   /mesh/anchors/<set>/point_coordinates (2 nbar, 2)   both ends of each bar (a fixed-end
!>        anchor's fixed point drawn at its node + LENGTH along its direction)
!>   /mesh/anchors/<set>/point_connectivity (nbar, 2)    0-based rows of point_coordinates
!> (h5py shapes). The XDMF draws each bar as a line on its own two points, so that a
!> fixed-end bar, which has a single node, is drawn too and its force attaches to it.
!> Also the anchor sets as the XDMF layout sees them (xdmf_anchors).
module pecplas_io_results_anchor_geometry
   use hdf5, only: hid_t
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_io_results_h5, only: h5_write, safe_name, h5_describe
   use pecplas_io_results_describe, only: XY
   use pecplas_io_results_xdmf, only: xdmf_anchor_t
   implicit none (type, external)
   private

   public :: write_anchor_geometry, xdmf_anchors, anchor_points

contains

   !> The datasets above, into the groups write_anchor_mesh created; coordinates in
   !> `length_unit`.
   subroutine write_anchor_geometry(file, model, length_unit, error)
      integer(hid_t), intent(in) :: file
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: length_unit
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: pconn(:, :)
      real(wp), allocatable :: points(:, :)
      character(len=:), allocatable :: g
      integer :: s, b
      if (.not. allocated(model%anchors)) return
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
   end subroutine write_anchor_geometry

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

   !> The anchor sets of `model` as the XDMF layout sees them (none without anchors).
   pure function xdmf_anchors(model) result(anchors)
      type(model_t), intent(in) :: model
      type(xdmf_anchor_t), allocatable :: anchors(:)
      integer :: s
      allocate (anchors(0))
      if (.not. allocated(model%anchors)) return
      deallocate (anchors)
      allocate (anchors(size(model%anchors)))
      do s = 1, size(model%anchors)
         anchors(s)%name = safe_name(model%anchors(s)%name)
         anchors(s)%nbar = model%anchors(s)%nbar()
      end do
   end function xdmf_anchors

end module pecplas_io_results_anchor_geometry
