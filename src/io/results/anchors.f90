!> Anchors in the results file (doc/results.md, Anchors):
!>   /mesh/anchors/<name>  attributes name, type (NODE_TO_NODE or FIXED_END), ea, spacing,
!>        tension_limit, compression_limit (absent: none); datasets connectivity (2, nbar)
!>        0-based nodes (-1: the fixed end), length (nbar), direction (2, nbar)
!>   /increments/<NNNNNN>/anchors/<name>   (the anchors active in the increment's phase)
!>        force (nbar)            axial force N of one anchor, tension positive [force]
!>        force_per_width (nbar)  N / L_s, the force per unit out-of-plane length
!>                                [force/length]
module pecplas_io_results_anchors
   use hdf5, only: hid_t
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_base_units, only: UNITS_NOT_STATED
   use pecplas_io_results_increment, only: anchor_fields_t
   use pecplas_io_results_h5, only: h5_group, h5_close_group, h5_write, h5_attr, safe_name, &
      increment_group, h5_describe
   implicit none (type, external)
   private

   public :: write_anchor_mesh, write_anchor_fields

contains

   !> /mesh/anchors (nothing when the model has no anchors).
   subroutine write_anchor_mesh(file, model, length_unit, force_unit, error)
      integer(hid_t), intent(in) :: file
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: length_unit, force_unit
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: gall, g
      integer, allocatable :: conn0(:, :)
      integer :: s
      if (.not. allocated(model%anchors)) return
      if (size(model%anchors) == 0) return
      call h5_group(file, '/mesh/anchors', gall, error)
      if (allocated(error)) return
      do s = 1, size(model%anchors)
         associate (a => model%anchors(s))
            call h5_group(gall, safe_name(a%name), g, error)
            if (allocated(error)) exit
            conn0 = a%conn - 1
            call h5_attr(g, 'name', a%name, error)
            if (.not. allocated(error)) call h5_attr(g, 'type', a%type_name(), error)
            if (.not. allocated(error)) call h5_attr(g, 'ea', a%ea, error)
            if (.not. allocated(error)) call h5_attr(g, 'ea_units', force_unit, error)
            if (.not. allocated(error)) call h5_attr(g, 'spacing', a%spacing, error)
            if (.not. allocated(error)) call h5_attr(g, 'spacing_units', length_unit, error)
            if (.not. allocated(error) .and. a%tension_limit < huge(1.0_wp)) &
               call h5_attr(g, 'tension_limit', a%tension_limit, error)
            if (.not. allocated(error) .and. a%compression_limit < huge(1.0_wp)) &
               call h5_attr(g, 'compression_limit', a%compression_limit, error)
            if (.not. allocated(error)) call h5_write(g, 'connectivity', conn0, error)
            if (.not. allocated(error)) call h5_write(g, 'length', a%length, error)
            if (.not. allocated(error)) call h5_write(g, 'direction', a%direction, error)
            if (.not. allocated(error)) call h5_describe(g, 'length', length_unit, error)
            if (.not. allocated(error)) call h5_describe(g, 'direction', '1', error)
            call h5_close_group(g)
            if (allocated(error)) exit
         end associate
      end do
      call h5_close_group(gall)
   end subroutine write_anchor_mesh

   !> /increments/<NNNNNN>/anchors/<name> of the active anchors (the increment group exists).
   subroutine write_anchor_fields(file, global_increment, fields, length_unit, force_unit, &
      error)
      integer(hid_t), intent(in) :: file
      integer, intent(in) :: global_increment
      type(anchor_fields_t), intent(in) :: fields(:)
      character(len=*), intent(in) :: length_unit, force_unit
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: gall, g
      integer :: s
      if (.not. any(fields%active)) return
      call h5_group(file, increment_group(global_increment)//'/anchors', gall, error)
      if (allocated(error)) return
      do s = 1, size(fields)
         if (.not. fields(s)%active) cycle
         call h5_group(gall, safe_name(fields(s)%name), g, error)
         if (allocated(error)) exit
         call h5_write(g, 'force', fields(s)%force, error)
         if (.not. allocated(error)) call h5_write(g, 'force_per_width', &
            fields(s)%force_per_width, error)
         if (.not. allocated(error)) call h5_describe(g, 'force', force_unit, error)
         if (.not. allocated(error)) then
            if (force_unit == UNITS_NOT_STATED .or. length_unit == UNITS_NOT_STATED) then
               call h5_describe(g, 'force_per_width', UNITS_NOT_STATED, error)
            else
               call h5_describe(g, 'force_per_width', force_unit//'/'//length_unit, error)
            end if
         end if
         call h5_close_group(g)
         if (allocated(error)) exit
      end do
      call h5_close_group(gall)
   end subroutine write_anchor_fields

end module pecplas_io_results_anchors
