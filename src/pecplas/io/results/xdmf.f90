!> XDMF 3 sidecar (<file>.xmf next to <file>.h5) so that ParaView opens the results: a
!> temporal collection of spatial collections (one per increment with fields), each holding
!> one unstructured grid per element set. Heavy data stay in the HDF5 file.
!>
!> ParaView's XDMF reader takes a "Vector" attribute only with 3 components, so the file
!> stores displacement3 / reaction3 (z = 0) next to the 2-component arrays and the XDMF
!> references those. stress_mean (4 components xx, yy, zz, xy) is a "Matrix" attribute.
module pecplas_io_results_xdmf
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t, fatal_error
   use pecplas_io_results_h5, only: increment_group
   use pecplas_strings, only: itoa
   implicit none (type, external)
   private

   public :: xdmf_set_t, xdmf_layout_t, xdmf_topology, xdmf_path, write_xdmf

   !> One element set as the XDMF sees it.
   type :: xdmf_set_t
      !> Group name under /mesh/sets (and /increments/<k>/sets).
      character(len=:), allocatable :: name
      !> XDMF TopologyType, e.g. 'Quadrilateral'.
      character(len=:), allocatable :: topology
      integer :: nel = 0, npe = 0
   end type xdmf_set_t

   !> What the results file holds: enough to write the XDMF without reading the HDF5 file.
   type :: xdmf_layout_t
      !> Name of the .h5 file as referenced from the .xmf (both in the same directory).
      character(len=:), allocatable :: h5_name
      integer :: nnode = 0
      type(xdmf_set_t), allocatable :: sets(:)
      logical :: reactions = .true., stresses = .true.
   end type xdmf_layout_t

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

   !> Writes (replaces) the .xmf for the increments written so far: global numbers
   !> `increments` at pseudo-times `times`. With no increment yet, one grid of the bare mesh
   !> at time 0 lets ParaView show the mesh of a run that has just started.
   subroutine write_xdmf(path, layout, increments, times, error)
      character(len=*), intent(in) :: path
      type(xdmf_layout_t), intent(in) :: layout
      integer, intent(in) :: increments(:)
      real(wp), intent(in) :: times(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios, k
      character(len=256) :: msg
      open (newunit=u, file=path, status='replace', action='write', form='formatted', &
         iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call fatal_error(error, 'cannot write XDMF file '//path//': '//trim(msg))
         return
      end if
      write (u, '(a)') '<?xml version="1.0" ?>'
      write (u, '(a)') '<Xdmf Version="3.0">'
      write (u, '(a)') ' <Domain>'
      write (u, '(a)') '  <Grid Name="PECPLAS" GridType="Collection" CollectionType="Temporal">'
      if (size(increments) == 0) then
         call write_increment(u, layout, 0, 0.0_wp)
      else
         do k = 1, size(increments)
            call write_increment(u, layout, increments(k), times(k))
         end do
      end if
      write (u, '(a)') '  </Grid>'
      write (u, '(a)') ' </Domain>'
      write (u, '(a)') '</Xdmf>'
      close (u, iostat=ios)
      if (ios /= 0) call fatal_error(error, 'cannot close XDMF file '//path)
   end subroutine write_xdmf

   !> One spatial collection; inc = 0 writes the mesh without attributes.
   subroutine write_increment(u, layout, inc, time)
      integer, intent(in) :: u, inc
      type(xdmf_layout_t), intent(in) :: layout
      real(wp), intent(in) :: time
      character(len=:), allocatable :: h5, group
      integer :: s
      h5 = xml_escape(layout%h5_name)//':'
      group = 'mesh'
      if (inc > 0) group = increment_group(inc)
      write (u, '(a)') '   <Grid Name="'//basename(group)//'" GridType="Collection" '// &
         'CollectionType="Spatial">'
      write (u, '(a)') '    <Time Value="'//real_text(time)//'"/>'
      do s = 1, size(layout%sets)
         associate (set => layout%sets(s))
            write (u, '(a)') '    <Grid Name="'//set%name//'" GridType="Uniform">'
            write (u, '(a)') '     <Topology TopologyType="'//set%topology//'" NumberOfElements="'// &
               itoa(set%nel)//'" NodesPerElement="'//itoa(set%npe)//'">'
            call data_item(u, h5//'/mesh/sets/'//set%name//'/connectivity', set%nel, set%npe, &
               'Int', 4)
            write (u, '(a)') '     </Topology>'
            write (u, '(a)') '     <Geometry GeometryType="XY">'
            call data_item(u, h5//'/mesh/coordinates', layout%nnode, 2, 'Float', 8)
            write (u, '(a)') '     </Geometry>'
            if (inc > 0) then
               call attribute(u, 'displacement', 'Vector', 'Node', &
                  h5//group//'/displacement3', layout%nnode, 3)
               if (layout%reactions) call attribute(u, 'reaction', 'Vector', 'Node', &
                  h5//group//'/reaction3', layout%nnode, 3)
               if (layout%stresses) call attribute(u, 'stress_mean', 'Matrix', 'Cell', &
                  h5//group//'/sets/'//set%name//'/stress_mean', set%nel, 4)
            end if
            write (u, '(a)') '    </Grid>'
         end associate
      end do
      write (u, '(a)') '   </Grid>'
   end subroutine write_increment

   subroutine attribute(u, name, kind, center, ref, rows, cols)
      integer, intent(in) :: u, rows, cols
      character(len=*), intent(in) :: name, kind, center, ref
      write (u, '(a)') '     <Attribute Name="'//name//'" AttributeType="'//kind// &
         '" Center="'//center//'">'
      call data_item(u, ref, rows, cols, 'Float', 8)
      write (u, '(a)') '     </Attribute>'
   end subroutine attribute

   !> An HDF5 DataItem; Dimensions are the h5py (C-order) shape of the dataset.
   subroutine data_item(u, ref, rows, cols, number_type, precision)
      integer, intent(in) :: u, rows, cols, precision
      character(len=*), intent(in) :: ref, number_type
      write (u, '(a)') '      <DataItem Dimensions="'//itoa(rows)//' '//itoa(cols)// &
         '" NumberType="'//number_type//'" Precision="'//itoa(precision)// &
         '" Format="HDF">'//ref//'</DataItem>'
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
