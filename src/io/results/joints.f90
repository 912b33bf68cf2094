!> Joint sets in the results file (PECJOIN):
!>   /mesh/joint_sets/<set>  attributes name, etype, law, integration, thickness, mode_names,
!>        state_names (the law's history variables, when the law names them),
!>        law_description (the law's own summary, e.g. MODJOIN's unit conversion, if any)
!>        connectivity (npe, nel) 0-based in (B.8) order, element_ids (nel),
!>        point_connectivity (np, nel): 0-based numbers of the points (for the XDMF grid),
!>        point_coordinates (2, np, nel), point_tangents (2, np, nel) (n = (-t_y, t_x)),
!>        tributary (nel, springs only)
!>   /increments/<NNNNNN>/joints/<set>
!>        relative_displacement (2, np, nel)  eps_n (closure positive), eps_t
!>                                            (strains, i.e. / thickness, for THIN_LAYER)
!>        stress (2, np, nel)                 sigma_n (compression positive), tau
!>        mode (np, nel)                      1 stick, 2 slip, 3 open
!>        plastic_slip (np, nel)              the law's accumulated plastic slip (0 if none)
!>        state (nstate, np, nel)             law history variables (when the law has any)
!> Shapes are Fortran order (h5py sees them reversed).
module pecplas_io_results_joints
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hdf5, only: hid_t
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_io_results_increment, only: joint_fields_t, joint_points_t
   use pecplas_io_results_h5, only: h5_group, h5_close_group, h5_write, h5_attr, safe_name, &
      increment_group, h5_describe
   use pecplas_io_results_describe, only: results_units_t, JOINT_EPS, JOINT_SIGMA, MIXED_UNITS
   implicit none (type, external)
   private

   public :: joint_layout_t, plan_joints, write_joint_mesh, check_joint_fields, &
      write_joint_fields

   !> What the file holds for one joint set.
   type :: joint_layout_t
      character(len=:), allocatable :: name
      integer :: npoint = 0, nel = 0, nstate = 0
   end type joint_layout_t

contains

   !> Layout of the joint sets of `model`; points(s) must be (2, np, nel) and finite.
   subroutine plan_joints(model, points, layout, error)
      type(model_t), intent(in) :: model
      type(joint_points_t), intent(in) :: points(:)
      type(joint_layout_t), allocatable, intent(out) :: layout(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: s, n
      n = 0
      if (allocated(model%joint_sets)) n = size(model%joint_sets)
      allocate (layout(n))
      if (size(points) /= n) then
         call fatal_error(error, 'results file: joint points must have one entry per joint set')
         return
      end if
      do s = 1, n
         associate (set => model%joint_sets(s), p => points(s))
            layout(s)%name = safe_name(set%name)
            layout(s)%nel = size(set%conn, 2)
            layout(s)%nstate = 0
            if (.not. set%is_katona()) layout(s)%nstate = model%laws(set%law_index)%law%nstate()
            if (.not. (allocated(p%xy) .and. allocated(p%tangent))) then
               call fatal_error(error, 'results file: no point coordinates for joint set '// &
                  set%name)
               return
            end if
            layout(s)%npoint = size(p%xy, 2)
            if (size(p%xy, 1) /= 2 .or. size(p%xy, 3) /= layout(s)%nel .or. &
                any(shape(p%tangent) /= shape(p%xy)) .or. .not. all(ieee_is_finite(p%xy))) then
               call fatal_error(error, 'results file: point coordinates of joint set '// &
                  set%name//' must be finite, of shape (2, npoint, nel)')
               return
            end if
         end associate
      end do
   end subroutine plan_joints

   !> /mesh/joint_sets (an empty group when the model has no joints).
   subroutine write_joint_mesh(file, model, points, error)
      integer(hid_t), intent(in) :: file
      type(model_t), intent(in) :: model
      type(joint_points_t), intent(in) :: points(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: gall, g
      integer, allocatable :: conn0(:, :), ids(:)
      character(len=16), allocatable :: names(:)
      integer :: s
      call h5_group(file, '/mesh/joint_sets', gall, error)
      if (allocated(error)) return
      do s = 1, size(points)
         associate (set => model%joint_sets(s))
            call h5_group(gall, safe_name(set%name), g, error)
            if (allocated(error)) exit
            if (allocated(conn0)) deallocate (conn0)
            allocate (conn0, source=set%conn - 1)
            ids = set%ids
            call h5_attr(g, 'name', set%name, error)
            if (.not. allocated(error)) call h5_attr(g, 'etype', set%type_name(), error)
            if (.not. allocated(error)) call h5_attr(g, 'law', set%law, error)
            if (.not. allocated(error)) call h5_attr(g, 'integration', set%integration, error)
            if (.not. allocated(error)) call h5_attr(g, 'thickness', set%thickness, error)
            if (.not. allocated(error)) call h5_attr(g, 'mode_names', &
               [character(len=5) :: 'stick', 'slip', 'open'], error)
            if (.not. allocated(error)) call h5_write(g, 'connectivity', conn0, error)
            if (.not. allocated(error)) call h5_write(g, 'element_ids', ids, error)
            if (.not. allocated(error)) call h5_write(g, 'point_coordinates', points(s)%xy, error)
            if (.not. allocated(error)) call h5_write(g, 'point_connectivity', &
               point_numbers(size(points(s)%xy, 2), size(points(s)%xy, 3)), error)
            if (.not. allocated(error)) call h5_write(g, 'point_tangents', points(s)%tangent, &
               error)
            if (.not. allocated(error) .and. allocated(set%tributary)) &
               call h5_write(g, 'tributary', set%tributary, error)
            ! (a Katona set has no law at its points: no description, no history)
            if (.not. set%is_katona()) then
               if (.not. allocated(error) .and. &
                   len(model%laws(set%law_index)%law%describe()) > 0) call h5_attr(g, &
                  'law_description', model%laws(set%law_index)%law%describe(), error)
               call model%laws(set%law_index)%law%state_names(names)
               if (.not. allocated(error) .and. size(names) > 0) &
                  call h5_attr(g, 'state_names', names, error)
            end if
            call h5_close_group(g)
            if (allocated(error)) exit
         end associate
      end do
      call h5_close_group(gall)
   end subroutine write_joint_mesh

   !> 0-based numbers of the (np, nel) points in storage order.
   pure function point_numbers(np, nel) result(k)
      integer, intent(in) :: np, nel
      integer :: k(np, nel)
      integer :: i, e
      do e = 1, nel
         do i = 1, np
            k(i, e) = (e - 1)*np + i - 1
         end do
      end do
   end function point_numbers

   !> Shapes and finite values of the joint fields of one increment.
   subroutine check_joint_fields(fields, layout, where, error)
      type(joint_fields_t), allocatable, intent(in) :: fields(:)
      type(joint_layout_t), intent(in) :: layout(:)
      character(len=*), intent(in) :: where
      type(error_t), allocatable, intent(out) :: error
      integer :: s
      logical :: ok
      if (size(layout) == 0) return
      if (.not. allocated(fields)) then
         call fatal_error(error, where//'joint fields missing')
         return
      end if
      if (size(fields) /= size(layout)) then
         call fatal_error(error, where//'joint fields need one entry per joint set')
         return
      end if
      do s = 1, size(layout)
         associate (f => fields(s), l => layout(s))
            ok = allocated(f%eps) .and. allocated(f%sigma) .and. allocated(f%slip) .and. &
               allocated(f%mode) .and. allocated(f%state)
            if (ok) ok = all(shape(f%eps) == [2, l%npoint, l%nel]) .and. &
               all(shape(f%sigma) == [2, l%npoint, l%nel]) .and. &
               all(shape(f%slip) == [l%npoint, l%nel]) .and. &
               all(shape(f%mode) == [l%npoint, l%nel]) .and. &
               all(shape(f%state) == [l%nstate, l%npoint, l%nel])
            if (.not. ok) then
               call fatal_error(error, where//'joint fields of set '//l%name// &
                  ' are missing or have the wrong shape')
               return
            end if
            if (.not. (all(ieee_is_finite(f%eps)) .and. all(ieee_is_finite(f%sigma)) .and. &
                       all(ieee_is_finite(f%slip)) .and. all(ieee_is_finite(f%state)))) then
               call fatal_error(error, where//'joint fields of set '//l%name// &
                  ' have a non-finite value')
               return
            end if
         end associate
      end do
   end subroutine check_joint_fields

   !> /increments/<NNNNNN>/joints/<set> (the increment group exists already), each dataset
   !> with its `units` (and `components` for the two-component ones).
   subroutine write_joint_fields(file, global_increment, fields, layout, units, error, active)
      integer(hid_t), intent(in) :: file
      integer, intent(in) :: global_increment
      type(joint_fields_t), intent(in) :: fields(:)
      type(joint_layout_t), intent(in) :: layout(:)
      type(results_units_t), intent(in) :: units
      type(error_t), allocatable, intent(out) :: error
      !> The sets active in the phase under way (a staged run); the others get no group.
      logical, intent(in), optional :: active(:)
      integer(hid_t) :: gall, g
      integer :: s
      if (size(layout) == 0) return
      call h5_group(file, increment_group(global_increment)//'/joints', gall, error)
      if (allocated(error)) return
      do s = 1, size(layout)
         if (present(active)) then
            if (.not. active(s)) cycle
         end if
         call h5_group(gall, layout(s)%name, g, error)
         if (allocated(error)) exit
         associate (f => fields(s))
            call h5_write(g, 'relative_displacement', f%eps, error)
            if (.not. allocated(error)) call h5_write(g, 'stress', f%sigma, error)
            if (.not. allocated(error)) call h5_write(g, 'mode', f%mode, error)
            if (.not. allocated(error)) call h5_write(g, 'plastic_slip', f%slip, error)
            if (allocated(f%error_indicator) .and. .not. allocated(error)) &
               call h5_write(g, 'error_indicator', f%error_indicator, error)
            if (.not. allocated(error) .and. layout(s)%nstate > 0) &
               call h5_write(g, 'state', f%state, error)
         end associate
         associate (u => units%joints(s))
            if (.not. allocated(error)) call h5_describe(g, 'relative_displacement', u%eps, &
               error, JOINT_EPS)
            if (.not. allocated(error)) call h5_describe(g, 'stress', units%stress, error, &
               JOINT_SIGMA)
            if (.not. allocated(error)) call h5_describe(g, 'plastic_slip', u%eps, error)
            if (.not. allocated(error) .and. layout(s)%nstate > 0) then
               if (size(u%state) == layout(s)%nstate) then
                  call h5_describe(g, 'state', MIXED_UNITS, error, u%state)
               else
                  call h5_describe(g, 'state', MIXED_UNITS, error)
               end if
            end if
         end associate
         call h5_close_group(g)
         if (allocated(error)) exit
      end do
      call h5_close_group(gall)
   end subroutine write_joint_fields

end module pecplas_io_results_joints
