!> Plate sets in the results file:
!>   /mesh/plates/<set>  attributes name, EA, EI, nu, w, Np, Mp, nodes_per_element;
!>        connectivity (nen, nel) 0-based node indices (end, end[, mid]), nodes (nnode_plate)
!>        0-based indices of the plate's nodes in the order of its elements
!>   /increments/<NNNNNN>/plates/<set>
!>        end_forces (3, 2, nel)     N, Q, M at end 1 and end 2 of each element
!>        node_forces (3, nnode_plate)  N, Q, M at the plate's nodes (mean of the ends there)
!>        element_forces (3, nel)    N, Q, M: the mean of each element's two ends (XDMF cells)
!>        displacement (2, nnode_plate), rotation (nnode_plate), moment_reaction (nnode_plate)
!>        (the moment at a held rotation: F_int - F_ext there, 0 elsewhere)
!>        resultants (5, np, nel)    N_s, Q, M_s, N_theta, M_theta at the elements' points
!>        plastic (3, np, nel)       plastic axial strain, plastic curvature, multiplier
!> Forces per unit width (plane strain) or per unit length of circumference (axisymmetry).
module pecplas_io_results_plates
   use hdf5, only: hid_t
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_io_results_increment, only: plate_fields_t
   use pecplas_io_results_h5, only: h5_group, h5_close_group, h5_write, h5_attr, safe_name, &
      increment_group, h5_describe
   use pecplas_io_results_describe, only: results_units_t, XY
   use pecplas_base_units, only: UNITS_NOT_STATED
   implicit none (type, external)
   private

   public :: write_plate_mesh, write_plate_fields

   character(len=*), parameter :: NQM(3) = [character(len=1) :: 'N', 'Q', 'M']
   character(len=*), parameter :: RESULTANTS(5) = [character(len=7) :: 'N_s', 'Q', 'M_s', &
      'N_theta', 'M_theta']

contains

   !> /mesh/plates (nothing when the model has no plates).
   subroutine write_plate_mesh(file, model, error)
      integer(hid_t), intent(in) :: file
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: gall, g
      integer, allocatable :: nodes(:)
      integer :: s, e, k
      if (.not. allocated(model%plates)) return
      if (size(model%plates) == 0) return
      call h5_group(file, '/mesh/plates', gall, error)
      if (allocated(error)) return
      do s = 1, size(model%plates)
         associate (pl => model%plates(s))
            call h5_group(gall, safe_name(pl%name), g, error)
            if (allocated(error)) exit
            call h5_attr(g, 'name', pl%name, error)
            if (.not. allocated(error)) call h5_attr(g, 'EA', pl%section%ea, error)
            if (.not. allocated(error)) call h5_attr(g, 'EI', pl%section%ei, error)
            if (.not. allocated(error)) call h5_attr(g, 'nu', pl%section%nu, error)
            if (.not. allocated(error)) call h5_attr(g, 'w', pl%section%w, error)
            if (.not. allocated(error)) call h5_attr(g, 'Np', pl%section%np, error)
            if (.not. allocated(error)) call h5_attr(g, 'Mp', pl%section%mp, error)
            if (.not. allocated(error)) call h5_attr(g, 'nodes_per_element', pl%nen, error)
            if (.not. allocated(error)) call h5_write(g, 'connectivity', pl%conn - 1, error)
            allocate (nodes(0))
            do e = 1, size(pl%conn, 2)
               do k = 1, size(pl%conn, 1)
                  if (.not. any(nodes == pl%conn(k, e))) nodes = [nodes, pl%conn(k, e)]
               end do
            end do
            if (.not. allocated(error)) call h5_write(g, 'nodes', nodes - 1, error)
            deallocate (nodes)
            call h5_close_group(g)
         end associate
         if (allocated(error)) exit
      end do
      call h5_close_group(gall)
   end subroutine write_plate_mesh

   !> /increments/<n>/plates/<set> of the plate sets active now.
   subroutine write_plate_fields(file, global_increment, fields, units, error)
      integer(hid_t), intent(in) :: file
      integer, intent(in) :: global_increment
      type(plate_fields_t), intent(in) :: fields(:)
      type(results_units_t), intent(in) :: units
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: gall, g
      character(len=:), allocatable :: fw, mw
      integer :: s
      if (size(fields) == 0) return
      ! per unit width (length of circumference): force/length, force length/length
      fw = units%force//'/'//units%length
      mw = units%force
      if (units%force == UNITS_NOT_STATED .or. units%length == UNITS_NOT_STATED) then
         fw = UNITS_NOT_STATED
         mw = UNITS_NOT_STATED
      end if
      call h5_group(file, increment_group(global_increment)//'/plates', gall, error)
      if (allocated(error)) return
      do s = 1, size(fields)
         if (.not. fields(s)%active) cycle
         call h5_group(gall, safe_name(fields(s)%name), g, error)
         if (allocated(error)) exit
         associate (f => fields(s))
            call h5_write(g, 'end_forces', f%end_forces, error)
            if (.not. allocated(error)) call h5_write(g, 'node_forces', f%node_forces, error)
            if (.not. allocated(error)) call h5_write(g, 'element_forces', &
               0.5_wp*(f%end_forces(:, 1, :) + f%end_forces(:, 2, :)), error)
            if (.not. allocated(error)) call h5_write(g, 'displacement', f%displacement, error)
            if (.not. allocated(error)) call h5_write(g, 'rotation', f%rotation, error)
            if (.not. allocated(error)) call h5_write(g, 'resultants', f%resultants, error)
            if (.not. allocated(error)) call h5_write(g, 'plastic', f%plastic, error)
            if (.not. allocated(error) .and. allocated(f%moment_reaction)) &
               call h5_write(g, 'moment_reaction', f%moment_reaction, error)
         end associate
         ! N, Q per unit width; M force x length per unit width
         if (.not. allocated(error)) call h5_describe(g, 'end_forces', 'N, Q: '//fw// &
            '; M: '//mw//'*'//units%length//'/'//units%length, error, NQM)
         if (.not. allocated(error)) call h5_describe(g, 'node_forces', 'N, Q: '//fw// &
            '; M: '//mw//'*'//units%length//'/'//units%length, error, NQM)
         if (.not. allocated(error)) call h5_describe(g, 'element_forces', 'N, Q: '//fw// &
            '; M: '//mw//'*'//units%length//'/'//units%length, error, NQM)
         if (.not. allocated(error)) call h5_describe(g, 'displacement', units%length, error, XY)
         if (.not. allocated(error)) call h5_describe(g, 'rotation', 'rad', error)
         if (.not. allocated(error) .and. allocated(fields(s)%moment_reaction)) &
            call h5_describe(g, 'moment_reaction', mw//'*'//units%length, error)
         if (.not. allocated(error)) call h5_describe(g, 'resultants', 'N: '//fw//'; M: '// &
            mw//'*'//units%length//'/'//units%length, error, RESULTANTS)
         if (.not. allocated(error)) call h5_describe(g, 'plastic', 'mixed: 1, 1/'// &
            units%length//', 1', error, [character(len=9) :: 'eps_p', 'kappa_p', 'lambda'])
         call h5_close_group(g)
         if (allocated(error)) exit
      end do
      call h5_close_group(gall)
   end subroutine write_plate_fields

end module pecplas_io_results_plates
