!> XDMF 3 sidecar (<file>.xmf next to <file>.h5) so that ParaView opens the results: a
!> temporal collection of spatial collections (one per increment with fields), each holding
!> one unstructured grid per element set. Heavy data stay in the HDF5 file.
!>
!> ParaView's XDMF reader takes a "Vector" attribute only with 3 components, so the file
!> stores displacement3 / reaction3 (z = 0) next to the 2-component arrays and the XDMF
!> references those. stress_mean (4 components xx, yy, zz, xy) is a "Matrix" attribute; a
!> soil with plastic history adds the cell scalars eps_p_eq and plastic_fraction.
!>
!> Each plate set is a grid of its own in the increments where it is active: its elements as
!> polylines on the mesh's nodes, with the displacements and the cell attributes N, Q, M.
!> Each anchor set likewise: a Polyline per bar (/mesh/anchors/<set>/point_coordinates, the
!> fixed end of a fixed-end bar included) with the cell attributes force and force_per_width.
!>
!> Each joint set is a grid of its own in every increment: its integration points as a
!> Polyline per joint element (a Polyvertex for springs, one point each) through
!> /mesh/joint_sets/<set>/point_connectivity, with node attributes sigma_n, tau, eps_n, eps_t
!> (HyperSlabs of the two-component stress and relative_displacement), mode and
!> plastic_slip, so that ParaView plots them along the interface (Plot Over Line, or a
!> spreadsheet sorted by the coordinates).
module pecplas_io_results_xdmf
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_io_results_h5, only: increment_group
   use pecplas_base_strings, only: itoa
   use pecplas_base_files, only: rename_file, remove_file
   implicit none (type, external)
   private

   public :: xdmf_set_t, xdmf_joint_t, xdmf_layout_t, xdmf_topology, xdmf_path, xdmf_text, write_xdmf
   public :: xdmf_plate_t, xdmf_anchor_t

   !> One element set as the XDMF sees it.
   type :: xdmf_set_t
      !> Group name under /mesh/sets (and /increments/<k>/sets).
      character(len=:), allocatable :: name
      !> XDMF TopologyType, e.g. 'Quadrilateral'.
      character(len=:), allocatable :: topology
      integer :: nel = 0, npe = 0
      !> Active in the phase under way (a staged run): the fields are written.
      logical :: active = .true.
      !> Cell attributes eps_p_eq and plastic_fraction (a soil with plastic history).
      logical :: plastic = .false.
   end type xdmf_set_t

   !> One joint set: group name under /mesh/joint_sets, points per element, elements.
   type :: xdmf_joint_t
      character(len=:), allocatable :: name
      integer :: npoint = 0, nel = 0
      !> Active in the phase under way (a staged run): the fields are written.
      logical :: active = .true.
   end type xdmf_joint_t

   !> One plate set: group name under /mesh/plates, elements, nodes per element.
   type :: xdmf_plate_t
      character(len=:), allocatable :: name
      integer :: nel = 0, npe = 2
   end type xdmf_plate_t

   !> One anchor set: group name under /mesh/anchors, bars.
   type :: xdmf_anchor_t
      character(len=:), allocatable :: name
      integer :: nbar = 0
   end type xdmf_anchor_t

   !> What the results file holds: enough to write the XDMF without reading the HDF5 file.
   type :: xdmf_layout_t
      integer :: nnode = 0
      type(xdmf_set_t), allocatable :: sets(:)
      type(xdmf_joint_t), allocatable :: joints(:)
      type(xdmf_plate_t), allocatable :: plates(:)
      type(xdmf_anchor_t), allocatable :: anchors(:)
      logical :: reactions = .true., stresses = .true.
      !> Cell attribute error_indicator (*OUTPUT, ERROR_ESTIMATE=YES).
      logical :: error_estimate = .false.
      !> The last increment shows /safety/mechanism3 (a safety step's mechanism).
      logical :: mechanism = .false.
   end type xdmf_layout_t

   !> A growing text (amortised doubling).
   type :: text_buffer_t
      character(len=:), allocatable :: s
      integer :: n = 0
   end type text_buffer_t

contains

   !> XDMF topology of a deck element type; error naming the known types otherwise.
   subroutine xdmf_topology(etype, topology, npe, error)
      character(len=*), intent(in) :: etype
      character(len=:), allocatable, intent(out) :: topology
      integer, intent(out) :: npe
      type(error_t), allocatable, intent(out) :: error
      select case (etype)
      case ('T3')
         topology = 'Triangle'; npe = 3
      case ('T6')
         topology = 'Triangle_6'; npe = 6
      case ('Q4')
         topology = 'Quadrilateral'; npe = 4
      case ('Q8', 'Q8R')
         topology = 'Quadrilateral_8'; npe = 8
      case default
         npe = 0
         call fatal_error(error, 'results file: no XDMF topology for element type "'// &
            etype//'"; known types: T3 T6 Q4 Q8 Q8R')
      end select
   end subroutine xdmf_topology

   !> The .xmf path of a results file: a trailing .h5 / .hdf5 is replaced, else .xmf is added.
   pure function xdmf_path(h5_path) result(path)
      character(len=*), intent(in) :: h5_path
      character(len=:), allocatable :: path
      integer :: n
      n = len_trim(h5_path)
      if (ends_with(h5_path(1:n), '.h5')) then
         path = h5_path(1:n - 3)//'.xmf'
      else if (ends_with(h5_path(1:n), '.hdf5')) then
         path = h5_path(1:n - 5)//'.xmf'
      else
         path = h5_path(1:n)//'.xmf'
      end if
   end function xdmf_path

   pure logical function ends_with(s, tail)
      character(len=*), intent(in) :: s, tail
      ends_with = .false.
      if (len(s) >= len(tail)) ends_with = s(len(s) - len(tail) + 1:) == tail
   end function ends_with

   !> The whole .xmf text for the increments written so far: global numbers `increments`
   !> at pseudo-times `times`, heavy data in `h5_name` (a file of the same directory). With
   !> no increment yet, one grid of the bare mesh at time 0 lets ParaView show the mesh of a
   !> run that has just started. Built in memory: the file is then written in one call.
   !> esets(nset, k) / jsets(njset, k), when given: the element / joint sets active in
   !> increment k (a staged run); an inactive set has no grid in that increment, so that
   !> ParaView shows only what the phase holds (it plays an excavation).
   function xdmf_text(layout, h5_name, increments, times, esets, jsets, psets, asets) &
      result(text)
      type(xdmf_layout_t), intent(in) :: layout
      character(len=*), intent(in) :: h5_name
      integer, intent(in) :: increments(:)
      real(wp), intent(in) :: times(:)
      logical, intent(in), optional :: esets(:, :), jsets(:, :)
      !> psets(nplate, k): the plate sets active in increment k.
      logical, intent(in), optional :: psets(:, :)
      !> asets(nanchor, k): the anchor sets active in increment k.
      logical, intent(in), optional :: asets(:, :)
      character(len=:), allocatable :: text
      type(text_buffer_t) :: b
      logical, allocatable :: eon(:), jon(:), pon(:), aon(:)
      integer :: k, nj, np, na
      call put(b, '<?xml version="1.0" ?>')
      call put(b, '<Xdmf Version="3.0">')
      call put(b, ' <Domain>')
      call put(b, '  <Grid Name="PECPLAS" GridType="Collection" CollectionType="Temporal">')
      nj = 0
      if (allocated(layout%joints)) nj = size(layout%joints)
      np = 0
      if (allocated(layout%plates)) np = size(layout%plates)
      na = 0
      if (allocated(layout%anchors)) na = size(layout%anchors)
      allocate (eon(size(layout%sets)), jon(nj), pon(np), aon(na))
      eon = .true.
      jon = .true.
      pon = .true.
      aon = .true.
      if (size(increments) == 0) then
         call put_increment(b, layout, h5_name, 0, 0.0_wp, eon, jon, pon, aon)
      else
         do k = 1, size(increments)
            if (present(esets)) eon = esets(:, k)
            if (present(jsets)) jon = jsets(:, k)
            if (present(psets)) then
               if (size(psets, 1) == np .and. size(psets, 2) >= k) pon = psets(:, k)
            end if
            if (present(asets)) then
               if (size(asets, 1) == na .and. size(asets, 2) >= k) aon = asets(:, k)
            end if
            call put_increment(b, layout, h5_name, increments(k), times(k), eon, jon, pon, aon, &
               layout%mechanism .and. k == size(increments))
         end do
      end if
      call put(b, '  </Grid>')
      call put(b, ' </Domain>')
      call put(b, '</Xdmf>')
      text = b%s(1:b%n)
   end function xdmf_text

   !> Writes `text` to `path` through `staging` (same directory) and a rename, so that
   !> `path` is always a whole file: the old one or the new one, never a part. With an
   !> empty `staging`, writes `path` directly.
   subroutine write_xdmf(path, staging_in, text, error)
      character(len=*), intent(in) :: path, staging_in, text
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: staging
      integer :: u, ios
      character(len=256) :: msg
      staging = staging_in
      if (len(staging) == 0) staging = path
      open (newunit=u, file=staging, status='replace', action='write', access='stream', &
         form='unformatted', iostat=ios, iomsg=msg)
      if (ios == 0) write (u, iostat=ios, iomsg=msg) text
      if (ios /= 0) then
         close (u, status='delete', iostat=ios)
         call fatal_error(error, 'cannot write XDMF file '//staging//': '//trim(msg))
         return
      end if
      close (u, iostat=ios)
      if (ios /= 0) then
         call remove_file(staging)
         call fatal_error(error, 'cannot close XDMF file '//staging)
         return
      end if
      if (staging == path) return
      if (.not. rename_file(staging, path)) then
         call remove_file(staging)
         call fatal_error(error, 'cannot rename '//staging//' onto '//path)
      end if
   end subroutine write_xdmf

   !> Appends `line` and a newline, doubling the buffer when full (linear total cost).
   subroutine put(b, line)
      type(text_buffer_t), intent(inout) :: b
      character(len=*), intent(in) :: line
      character(len=:), allocatable :: grown
      integer :: need
      need = b%n + len(line) + 1
      if (.not. allocated(b%s)) allocate (character(len=max(4096, need)) :: b%s)
      if (need > len(b%s)) then
         allocate (character(len=max(2*len(b%s), need)) :: grown)
         grown(1:b%n) = b%s(1:b%n)
         call move_alloc(grown, b%s)
      end if
      b%s(b%n + 1:need) = line//new_line('a')
      b%n = need
   end subroutine put

   !> One spatial collection; inc = 0 writes the mesh without attributes. Only the sets
   !> with eon / jon true get a grid.
   subroutine put_increment(b, layout, h5_name, inc, time, eon, jon, pon, aon, mechanism)
      type(text_buffer_t), intent(inout) :: b
      !> Add the attribute `mechanism` (/safety/mechanism3).
      logical, intent(in), optional :: mechanism
      type(xdmf_layout_t), intent(in) :: layout
      character(len=*), intent(in) :: h5_name
      integer, intent(in) :: inc
      real(wp), intent(in) :: time
      logical, intent(in) :: eon(:), jon(:), pon(:), aon(:)
      character(len=:), allocatable :: h5, group
      integer :: s
      h5 = xml_escape(h5_name)//':'
      group = 'mesh'
      if (inc > 0) group = increment_group(inc)
      call put(b, '   <Grid Name="'//basename(group)//'" GridType="Collection" '// &
         'CollectionType="Spatial">')
      call put(b, '    <Time Value="'//real_text(time)//'"/>')
      do s = 1, size(layout%sets)
         if (.not. eon(s)) cycle
         associate (set => layout%sets(s))
            call put(b, '    <Grid Name="'//set%name//'" GridType="Uniform">')
            call put(b, '     <Topology TopologyType="'//set%topology//'" NumberOfElements="'// &
               itoa(set%nel)//'" NodesPerElement="'//itoa(set%npe)//'">')
            call data_item(b, h5//'/mesh/sets/'//set%name//'/connectivity', set%nel, set%npe, &
               'Int', 4)
            call put(b, '     </Topology>')
            call put(b, '     <Geometry GeometryType="XY">')
            call data_item(b, h5//'/mesh/coordinates', layout%nnode, 2, 'Float', 8)
            call put(b, '     </Geometry>')
            if (inc > 0) then
               call attribute(b, 'displacement', 'Vector', 'Node', &
                  h5//group//'/displacement3', layout%nnode, 3)
               if (present(mechanism)) then
                  if (mechanism) call attribute(b, 'mechanism', 'Vector', 'Node', &
                     h5//'/safety/mechanism3', layout%nnode, 3)
               end if
               if (layout%reactions) call attribute(b, 'reaction', 'Vector', 'Node', &
                  h5//group//'/reaction3', layout%nnode, 3)
               if (layout%stresses) call attribute(b, 'stress_mean', 'Matrix', 'Cell', &
                  h5//group//'/sets/'//set%name//'/stress_mean', set%nel, 4)
               if (layout%error_estimate) call scalar_attribute(b, 'error_indicator', &
                  h5//group//'/sets/'//set%name//'/error_indicator', set%nel)
               if (set%plastic) call scalar_attribute(b, 'eps_p_eq', &
                  h5//group//'/sets/'//set%name//'/eps_p_eq', set%nel)
               if (set%plastic) call scalar_attribute(b, 'plastic_fraction', &
                  h5//group//'/sets/'//set%name//'/plastic_fraction', set%nel)
            end if
            call put(b, '    </Grid>')
         end associate
      end do
      if (allocated(layout%joints)) then
         do s = 1, size(layout%joints)
            if (.not. jon(s)) cycle
            call put_joint_grid(b, layout%joints(s), h5, group, inc)
         end do
      end if
      if (allocated(layout%plates)) then
         do s = 1, size(layout%plates)
            if (.not. pon(s)) cycle
            call put_plate_grid(b, layout%plates(s), layout%nnode, h5, group, inc)
         end do
      end if
      if (allocated(layout%anchors)) then
         do s = 1, size(layout%anchors)
            if (aon(s)) call put_anchor_grid(b, layout%anchors(s), h5, group, inc)
         end do
      end if
      call put(b, '   </Grid>')
   end subroutine put_increment

   !> The grid of one anchor set, a Polyline per bar; inc = 0: the bars without attributes.
   subroutine put_anchor_grid(b, anchor, h5, group, inc)
      type(text_buffer_t), intent(inout) :: b
      type(xdmf_anchor_t), intent(in) :: anchor
      character(len=*), intent(in) :: h5, group
      integer, intent(in) :: inc
      character(len=:), allocatable :: mesh, fields
      mesh = h5//'/mesh/anchors/'//anchor%name
      fields = h5//group//'/anchors/'//anchor%name
      call put(b, '    <Grid Name="anchors_'//anchor%name//'" GridType="Uniform">')
      call put(b, '     <Topology TopologyType="Polyline" NumberOfElements="'// &
         itoa(anchor%nbar)//'" NodesPerElement="2">')
      call data_item(b, mesh//'/point_connectivity', anchor%nbar, 2, 'Int', 4)
      call put(b, '     </Topology>')
      call put(b, '     <Geometry GeometryType="XY">')
      call data_item(b, mesh//'/point_coordinates', 2*anchor%nbar, 2, 'Float', 8)
      call put(b, '     </Geometry>')
      if (inc > 0) then
         call scalar_attribute(b, 'force', fields//'/force', anchor%nbar)
         call scalar_attribute(b, 'force_per_width', fields//'/force_per_width', anchor%nbar)
      end if
      call put(b, '    </Grid>')
   end subroutine put_anchor_grid

   !> The grid of one plate set: its elements as polylines (Edge_3 for 3-node elements) on
   !> the mesh's nodes, with the node displacements and the cell attributes N, Q, M (the
   !> mean of the element's two ends, /increments/<k>/plates/<set>/element_forces).
   subroutine put_plate_grid(b, plate, nnode, h5, group, inc)
      type(text_buffer_t), intent(inout) :: b
      type(xdmf_plate_t), intent(in) :: plate
      integer, intent(in) :: nnode, inc
      character(len=*), intent(in) :: h5, group
      character(len=:), allocatable :: mesh, fields, topology
      character(len=1), parameter :: NQM(3) = ['N', 'Q', 'M']
      integer :: k
      mesh = h5//'/mesh/plates/'//plate%name
      fields = h5//group//'/plates/'//plate%name
      topology = 'Polyline'
      if (plate%npe == 3) topology = 'Edge_3'
      call put(b, '    <Grid Name="plates_'//plate%name//'" GridType="Uniform">')
      call put(b, '     <Topology TopologyType="'//topology//'" NumberOfElements="'// &
         itoa(plate%nel)//'" NodesPerElement="'//itoa(plate%npe)//'">')
      call data_item(b, mesh//'/connectivity', plate%nel, plate%npe, 'Int', 4)
      call put(b, '     </Topology>')
      call put(b, '     <Geometry GeometryType="XY">')
      call data_item(b, h5//'/mesh/coordinates', nnode, 2, 'Float', 8)
      call put(b, '     </Geometry>')
      if (inc > 0) then
         call attribute(b, 'displacement', 'Vector', 'Node', h5//group//'/displacement3', &
            nnode, 3)
         do k = 1, 3
            call put(b, '     <Attribute Name="'//NQM(k)//'" AttributeType="Scalar" '// &
               'Center="Cell">')
            call put(b, '      <DataItem ItemType="HyperSlab" Dimensions="'// &
               itoa(plate%nel)//' 1" Type="HyperSlab">')
            call put(b, '       <DataItem Dimensions="3 2" Format="XML">0 '//itoa(k - 1)// &
               ' 1 1 '//itoa(plate%nel)//' 1</DataItem>')
            call put(b, '       <DataItem Dimensions="'//itoa(plate%nel)//' 3" '// &
               'NumberType="Float" Precision="8" Format="HDF">'//fields// &
               '/element_forces</DataItem>')
            call put(b, '      </DataItem>')
            call put(b, '     </Attribute>')
         end do
      end if
      call put(b, '    </Grid>')
   end subroutine put_plate_grid

   !> The grid of the points of one joint set; inc = 0: the points without attributes.
   subroutine put_joint_grid(b, joint, h5, group, inc)
      type(text_buffer_t), intent(inout) :: b
      type(xdmf_joint_t), intent(in) :: joint
      character(len=*), intent(in) :: h5, group
      integer, intent(in) :: inc
      character(len=:), allocatable :: mesh, fields, topology, dims
      mesh = h5//'/mesh/joint_sets/'//joint%name
      fields = h5//group//'/joints/'//joint%name
      topology = 'Polyline'
      if (joint%npoint == 1) topology = 'Polyvertex'
      dims = itoa(joint%nel)//' '//itoa(joint%npoint)
      call put(b, '    <Grid Name="joints_'//joint%name//'" GridType="Uniform">')
      call put(b, '     <Topology TopologyType="'//topology//'" NumberOfElements="'// &
         itoa(joint%nel)//'" NodesPerElement="'//itoa(joint%npoint)//'">')
      call data_item(b, mesh//'/point_connectivity', joint%nel, joint%npoint, 'Int', 4)
      call put(b, '     </Topology>')
      call put(b, '     <Geometry GeometryType="XY">')
      call put(b, '      <DataItem Dimensions="'//dims//' 2" NumberType="Float" '// &
         'Precision="8" Format="HDF">'//mesh//'/point_coordinates</DataItem>')
      call put(b, '     </Geometry>')
      if (inc > 0) then
         call component(b, 'sigma_n', fields//'/stress', dims, 0)
         call component(b, 'tau', fields//'/stress', dims, 1)
         call component(b, 'eps_n', fields//'/relative_displacement', dims, 0)
         call component(b, 'eps_t', fields//'/relative_displacement', dims, 1)
         call put(b, '     <Attribute Name="mode" AttributeType="Scalar" Center="Node">')
         call data_item(b, fields//'/mode', joint%nel, joint%npoint, 'Int', 4)
         call put(b, '     </Attribute>')
         call attribute(b, 'plastic_slip', 'Scalar', 'Node', fields//'/plastic_slip', &
            joint%nel, joint%npoint)
      end if
      call put(b, '    </Grid>')
   end subroutine put_joint_grid

   !> Scalar node attribute: component k (0-based) of a (nel, npoint, 2) dataset.
   subroutine component(b, name, ref, dims, k)
      type(text_buffer_t), intent(inout) :: b
      character(len=*), intent(in) :: name, ref, dims
      integer, intent(in) :: k
      call put(b, '     <Attribute Name="'//name//'" AttributeType="Scalar" Center="Node">')
      call put(b, '      <DataItem ItemType="HyperSlab" Dimensions="'//dims//' 1" '// &
         'Type="HyperSlab">')
      call put(b, '       <DataItem Dimensions="3 3" Format="XML">0 0 '//itoa(k)// &
         ' 1 1 1 '//dims//' 1</DataItem>')
      call put(b, '       <DataItem Dimensions="'//dims//' 2" NumberType="Float" '// &
         'Precision="8" Format="HDF">'//ref//'</DataItem>')
      call put(b, '      </DataItem>')
      call put(b, '     </Attribute>')
   end subroutine component

   subroutine attribute(b, name, kind, center, ref, rows, cols)
      type(text_buffer_t), intent(inout) :: b
      integer, intent(in) :: rows, cols
      character(len=*), intent(in) :: name, kind, center, ref
      call put(b, '     <Attribute Name="'//name//'" AttributeType="'//kind// &
         '" Center="'//center//'">')
      call data_item(b, ref, rows, cols, 'Float', 8)
      call put(b, '     </Attribute>')
   end subroutine attribute

   !> A cell scalar of a one-dimensional dataset (n).
   subroutine scalar_attribute(b, name, ref, n)
      type(text_buffer_t), intent(inout) :: b
      integer, intent(in) :: n
      character(len=*), intent(in) :: name, ref
      call put(b, '     <Attribute Name="'//name//'" AttributeType="Scalar" Center="Cell">')
      call put(b, '      <DataItem Dimensions="'//itoa(n)//'" NumberType="Float" '// &
         'Precision="8" Format="HDF">'//ref//'</DataItem>')
      call put(b, '     </Attribute>')
   end subroutine scalar_attribute

   !> An HDF5 DataItem; Dimensions are the h5py (C-order) shape of the dataset.
   subroutine data_item(b, ref, rows, cols, number_type, precision)
      type(text_buffer_t), intent(inout) :: b
      integer, intent(in) :: rows, cols, precision
      character(len=*), intent(in) :: ref, number_type
      call put(b, '      <DataItem Dimensions="'//itoa(rows)//' '//itoa(cols)// &
         '" NumberType="'//number_type//'" Precision="'//itoa(precision)// &
         '" Format="HDF">'//ref//'</DataItem>')
   end subroutine data_item

   pure function basename(path) result(name)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: name
      name = path(index(path, '/', back=.true.) + 1:)
   end function basename


   function real_text(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=32) :: buf
      write (buf, '(es24.16e3)') x
      text = trim(adjustl(buf))
   end function real_text

   !> Escapes the XML special characters of a file name.
   pure function xml_escape(s) result(e)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: e
      integer :: i
      e = ''
      do i = 1, len(s)
         select case (s(i:i))
         case ('&')
            e = e//'&amp;'
         case ('<')
            e = e//'&lt;'
         case ('>')
            e = e//'&gt;'
         case ('"')
            e = e//'&quot;'
         case default
            e = e//s(i:i)
         end select
      end do
   end function xml_escape

end module pecplas_io_results_xdmf
