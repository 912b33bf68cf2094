!> Anchors beside plates in the XDMF sidecar (pecplas_io_results_xdmf,
!> pecplas_io_results_anchor_geometry): the grids of the structures appear only in the
!> increments where their set is active, with the right topology and counts; the end points
!> of node-to-node and fixed-end anchors. The run of a deck with both, read back through the
!> sidecar, is test/python/test_structure_output.py.
module test_io_results_structures
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use pecplas_model_type, only: model_t
   use pecplas_model_anchors, only: ANCHOR_NODE_TO_NODE, ANCHOR_FIXED_END
   use pecplas_io_results_xdmf, only: xdmf_layout_t, xdmf_text
   use pecplas_io_results_anchor_geometry, only: anchor_points, xdmf_anchors
   implicit none (type, external)
   private
   public :: collect_io_results_structures

contains

   subroutine collect_io_results_structures(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('xdmf_grids_of_active_structures', test_xdmf), &
               new_unittest('anchor_end_points', test_anchor_points)]
   end subroutine collect_io_results_structures

   !> One 3-node plate set (2 elements) and two anchor sets (2 bars, 1 bar); increment 1:
   !> the plate alone; increment 2: the plate and 'struts'. Counting is exact (text).
   subroutine test_xdmf(error)
      type(error_t), allocatable, intent(out) :: error
      type(xdmf_layout_t) :: layout
      type(model_t) :: model
      character(len=:), allocatable :: s
      logical :: psets(1, 2), asets(2, 2)
      call sample(model)
      layout%nnode = size(model%mesh%x, 2)
      allocate (layout%sets(0), layout%joints(0))
      allocate (layout%plates(1))
      layout%plates(1)%name = 'wall'
      layout%plates(1)%nel = 2
      layout%plates(1)%npe = 3
      layout%anchors = xdmf_anchors(model)
      call check(error, size(layout%anchors) == 2 .and. layout%anchors(1)%name == 'struts' &
         .and. layout%anchors(1)%nbar == 2 .and. layout%anchors(2)%nbar == 1, &
         'layout of the anchors: 2 bars and 1')
      if (allocated(error)) return
      psets(1, :) = [.true., .true.]
      asets(:, 1) = [.false., .false.]
      asets(:, 2) = [.true., .false.]
      s = xdmf_text(layout, 'r.h5', [1, 2], [0.5_wp, 1.0_wp], psets=psets, asets=asets)
      call check(error, count_of(s, '<Grid Name="plates_wall"') == 2, 'a plate grid per increment')
      if (allocated(error)) return
      call check(error, count_of(s, '<Grid Name="anchors_struts"') == 1, &
         'the anchor grid only where the set is active')
      if (allocated(error)) return
      call check(error, count_of(s, 'TopologyType="Edge_3" NumberOfElements="2" '// &
         'NodesPerElement="3"') == 2, 'a 3-node plate is quadratic edges')
      if (allocated(error)) return
      call check(error, count_of(s, 'TopologyType="Polyline" NumberOfElements="2" '// &
         'NodesPerElement="2"') == 1 .and. count_of(s, 'anchors_prop') == 0, &
         'one polyline per bar, none of the inactive set')
      if (allocated(error)) return
      call check(error, count_of(s, 'r.h5:/mesh/anchors/struts/point_coordinates') == 1 &
         .and. count_of(s, 'Dimensions="4 2" NumberType="Float"') == 1, &
         'the bars on their own points (2 per bar)')
      if (allocated(error)) return
      call check(error, count_of(s, 'r.h5:/increments/000002/anchors/struts/force<') == 1 &
         .and. count_of(s, '/increments/000001/anchors') == 0, 'anchor force in increment 2 only')
      if (allocated(error)) return
      ! no increment yet: the bare structures
      s = xdmf_text(layout, 'r.h5', [integer ::], [real(wp) ::])
      call check(error, count_of(s, '<Grid Name="plates_wall"') == 1 .and. &
         count_of(s, '<Grid Name="anchors_struts"') == 1 .and. &
         count_of(s, '<Grid Name="anchors_prop"') == 1 .and. count_of(s, 'Attribute') == 0, &
         'the mesh grid shows the structures without attributes')
   end subroutine test_xdmf

   !> A node-to-node bar ends at its nodes; a fixed-end bar at its node + LENGTH along its
   !> direction. The numbers are binary fractions and the direction a unit axis: the sum is
   !> exact, so the comparison is exact.
   subroutine test_anchor_points(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      real(wp), allocatable :: xy(:, :)
      call sample(model)
      xy = anchor_points(model, 1)
      call check(error, all(shape(xy) == [2, 4]), 'two points per bar')
      if (allocated(error)) return
      call check(error, all(xy(:, 1) == model%mesh%x(:, 1)) .and. &
         all(xy(:, 2) == model%mesh%x(:, 6)) .and. all(xy(:, 3) == model%mesh%x(:, 2)) .and. &
         all(xy(:, 4) == model%mesh%x(:, 6)), 'node-to-node bars: their nodes')
      if (allocated(error)) return
      xy = anchor_points(model, 2)
      call check(error, all(shape(xy) == [2, 2]) .and. all(xy(:, 1) == [1.5_wp, 2.0_wp]) .and. &
         all(xy(:, 2) == [1.5_wp, -0.5_wp]), 'fixed-end bar: node + L d')
   end subroutine test_anchor_points

   !> Nodes 1-6; plate 'wall' on (1, 3 | 2) and (3, 5 | 4); anchor set 'struts': 1-6 and
   !> 2-6 node to node; anchor set 'prop': node 4 fixed-end (L = 2.5 downwards).
   subroutine sample(model)
      type(model_t), intent(out) :: model
      model%mesh%x = reshape([0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 2.0_wp, 1.5_wp, 2.0_wp, &
         0.0_wp, 4.0_wp, 3.0_wp, 3.0_wp], [2, 6])
      allocate (model%plates(1))
      model%plates(1)%name = 'wall'
      model%plates(1)%nen = 3
      model%plates(1)%conn = reshape([1, 3, 2, 3, 5, 4], [3, 2])
      allocate (model%anchors(2))
      associate (a => model%anchors(1))
         a%name = 'struts'
         a%kind = ANCHOR_NODE_TO_NODE
         a%conn = reshape([1, 6, 2, 6], [2, 2])
         a%length = [5.0_wp, 4.0_wp]
         a%direction = reshape([0.6_wp, 0.8_wp, 0.75_wp, 0.5_wp], [2, 2])
      end associate
      associate (a => model%anchors(2))
         a%name = 'prop'
         a%kind = ANCHOR_FIXED_END
         a%conn = reshape([4, 0], [2, 1])
         a%length = [2.5_wp]
         a%direction = reshape([0.0_wp, -1.0_wp], [2, 1])
      end associate
   end subroutine sample

   pure integer function count_of(s, what) result(n)
      character(len=*), intent(in) :: s, what
      integer :: i, k
      n = 0
      i = 1
      do
         k = index(s(i:), what)
         if (k == 0) exit
         n = n + 1
         i = i + k + len(what) - 1
      end do
   end function count_of

end module test_io_results_structures
