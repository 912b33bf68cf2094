!> The first contents of a results file (pecplas_io_results_file):
!>   /            attributes program, version, format_version, title, units (the *UNITS line),
!>                length_unit, force_unit, stress_unit (as read from it), deck_file,
!>                deck_text, analysis, thickness, threads, the threads of each part and
!>                the BLAS (see write_threads), created, status, complete,
!>                status_message, warnings (+ finished, and completed when status = 'completed',
!>                written by `finish`)
!>   /mesh        see pecplas_io_results_mesh (and the joints', anchors' and plates' meshes)
!>   /history     one row per converged increment: step, increment, global_increment, time,
!>                iterations, residual, cpu_time, fields (1 = field group written) and
!>                pattern_factors (npattern, nrow); attribute `patterns` (names); empty here
!>   /increments  empty here (pecplas_io_results_content writes the increments)
!> and the units of the datasets. Also the root attribute `warnings` written again at the
!> end of a run, and `timestamp`.
module pecplas_io_results_start
   use hdf5, only: hid_t
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: AXISYMMETRIC
   use pecplas_linalg_threads, only: thread_setting_t
   use pecplas_io_results_increment, only: gauss_coordinates_t, joint_points_t
   use pecplas_io_results_h5, only: h5_group, h5_close_group, h5_attr, h5_history_dataset
   use pecplas_io_results_mesh, only: write_mesh
   use pecplas_io_results_joints, only: write_joint_mesh
   use pecplas_io_results_plates, only: write_plate_mesh
   use pecplas_io_results_anchors, only: write_anchor_mesh
   use pecplas_io_results_anchor_geometry, only: write_anchor_geometry
   use pecplas_io_results_describe, only: results_units_t, describe_mesh, describe_history
   use pecplas_io_results_checksum, only: deck_checksum
   implicit none (type, external)
   private

   public :: write_start, write_warnings, timestamp

contains

   !> The first contents of the results file `file`: provenance, mesh, empty history.
   subroutine write_start(file, model, version, gauss_xy, points, units, error)
      integer(hid_t), intent(in) :: file
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: version
      type(gauss_coordinates_t), intent(in) :: gauss_xy(:)
      type(joint_points_t), intent(in) :: points(:)
      type(results_units_t), intent(in) :: units
      type(error_t), allocatable, intent(out) :: error
      call write_root(file, model, version, error)
      if (.not. allocated(error)) call write_mesh(file, model%mesh, gauss_xy, error)
      if (.not. allocated(error)) call write_joint_mesh(file, model, points, error)
      if (.not. allocated(error)) call write_anchor_mesh(file, model, units%length, &
         units%force, error)
      if (.not. allocated(error)) call write_plate_mesh(file, model, error)
      if (.not. allocated(error)) call write_anchor_geometry(file, model, units%length, &
         error)
      if (.not. allocated(error)) call create_history(file, model, error)
      if (.not. allocated(error)) call describe_mesh(file, model, units, error)
      if (.not. allocated(error)) call describe_history(file, units, error)
   end subroutine write_start

   subroutine write_root(file, model, version, error)
      integer(hid_t), intent(in) :: file
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: version
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: analysis
      analysis = 'plane strain'
      if (model%analysis%kind == AXISYMMETRIC) analysis = 'axisymmetric'
      call h5_attr(file, 'program', 'PECPLAS', error)
      if (.not. allocated(error)) call h5_attr(file, 'version', version, error)
      if (.not. allocated(error)) call h5_attr(file, 'format_version', 1, error)
      if (.not. allocated(error)) call h5_attr(file, 'title', text_or_empty(model%title), error)
      if (.not. allocated(error)) call h5_attr(file, 'units', text_or_empty(model%units), error)
      if (.not. allocated(error)) call h5_attr(file, 'length_unit', &
         model%unit_system%of('length'), error)
      if (.not. allocated(error)) call h5_attr(file, 'force_unit', &
         model%unit_system%of('force'), error)
      if (.not. allocated(error)) call h5_attr(file, 'stress_unit', &
         model%unit_system%of('stress'), error)
      if (.not. allocated(error)) call h5_attr(file, 'deck_file', &
         text_or_empty(model%deck_file), error)
      if (.not. allocated(error)) call h5_attr(file, 'deck_text', &
         text_or_empty(model%deck_text), error)
      if (.not. allocated(error)) call h5_attr(file, 'deck_text_checksum', &
         deck_checksum(text_or_empty(model%deck_text)), error)
      if (.not. allocated(error)) call h5_attr(file, 'analysis', analysis, error)
      if (.not. allocated(error)) call h5_attr(file, 'thickness', model%analysis%thickness, error)
      if (.not. allocated(error)) call h5_attr(file, 'threads', model%solver%threads, error)
      if (.not. allocated(error)) call write_threads(file, model%solver%threads_used, error)
      if (.not. allocated(error)) call h5_attr(file, 'created', timestamp(), error)
      if (.not. allocated(error)) call h5_attr(file, 'status', 'running', error)
      if (.not. allocated(error)) call h5_attr(file, 'complete', 0, error)
      if (.not. allocated(error)) call h5_attr(file, 'status_message', '', error)
      if (.not. allocated(error)) call write_warnings(file, model%warnings%lines(), error)
   end subroutine write_root

   !> The threads each part of the run got (pecplas_linalg_threads): root attributes
   !> threads_element_loops, threads_cholmod_regions, threads_blas, blas_flops_per_thread
   !> (0: every BLAS call gets threads_blas), blas, blas_threading, blas_core (OpenBLAS's
   !> kernels) and blas_core_source ('' when not known).
   subroutine write_threads(file, t, error)
      integer(hid_t), intent(in) :: file
      type(thread_setting_t), intent(in) :: t
      type(error_t), allocatable, intent(out) :: error
      call h5_attr(file, 'threads_element_loops', t%loops, error)
      if (.not. allocated(error)) call h5_attr(file, 'threads_cholmod_regions', t%regions, error)
      if (.not. allocated(error)) call h5_attr(file, 'threads_blas', t%blas_threads, error)
      if (.not. allocated(error)) call h5_attr(file, 'blas_flops_per_thread', &
         real(t%blas_work, wp), error)
      if (.not. allocated(error)) call h5_attr(file, 'blas', text_or_empty(t%blas), error)
      if (.not. allocated(error)) call h5_attr(file, 'blas_threading', &
         text_or_empty(t%blas_threading), error)
      if (.not. allocated(error)) call h5_attr(file, 'blas_core', text_or_empty(t%blas_core), error)
      if (.not. allocated(error)) call h5_attr(file, 'blas_core_source', &
         text_or_empty(t%blas_core_source), error)
   end subroutine write_threads

   !> Root attribute `warnings`: one string per warning, "file:line: warning: text" (an
   !> empty list when there is none). Written again with the whole list when more come.
   subroutine write_warnings(file, list, error)
      integer(hid_t), intent(in) :: file
      character(len=*), intent(in) :: list(:)
      type(error_t), allocatable, intent(out) :: error
      call h5_attr(file, 'warnings', list, error)
   end subroutine write_warnings

   subroutine create_history(file, model, error)
      integer(hid_t), intent(in) :: file
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: INTS(8) = [character(len=16) :: 'step', 'increment', &
         'global_increment', 'iterations', 'fields', 'method', 'line_searches', 'control']
      character(len=*), parameter :: REALS(3) = [character(len=8) :: 'time', 'residual', &
         'cpu_time']
      integer(hid_t) :: g
      integer :: i, npat, w
      call h5_group(file, 'history', g, error)
      if (allocated(error)) return
      do i = 1, size(INTS)
         call h5_history_dataset(g, trim(INTS(i)), .true., -1, error)
         if (allocated(error)) exit
      end do
      do i = 1, size(REALS)
         if (allocated(error)) exit
         call h5_history_dataset(g, trim(REALS(i)), .false., -1, error)
      end do
      npat = 0
      if (allocated(model%patterns)) npat = size(model%patterns)
      w = 1
      do i = 1, npat
         w = max(w, len(model%patterns(i)%name))
      end do
      if (.not. allocated(error)) call h5_history_dataset(g, 'pattern_factors', .false., npat, error)
      ! names of the columns of pattern_factors, in model%patterns order
      if (.not. allocated(error)) call write_pattern_names(g, model, npat, w, error)
      call h5_close_group(g)
      if (.not. allocated(error)) call h5_group(file, 'increments', g, error)
      call h5_close_group(g)
   end subroutine create_history

   subroutine write_pattern_names(g, model, npat, w, error)
      integer(hid_t), intent(in) :: g
      type(model_t), intent(in) :: model
      integer, intent(in) :: npat, w
      type(error_t), allocatable, intent(out) :: error
      character(len=w) :: names(npat)
      integer :: i
      do i = 1, npat
         names(i) = model%patterns(i)%name
      end do
      call h5_attr(g, 'patterns', names, error)
   end subroutine write_pattern_names

   pure function text_or_empty(text) result(out)
      character(len=:), allocatable, intent(in) :: text
      character(len=:), allocatable :: out
      out = ''
      if (allocated(text)) out = text
   end function text_or_empty

   !> Local date and time, ISO 8601 with offset.
   function timestamp() result(text)
      character(len=:), allocatable :: text
      character(len=8) :: d
      character(len=10) :: t
      character(len=5) :: z
      call date_and_time(d, t, z)
      text = d(1:4)//'-'//d(5:6)//'-'//d(7:8)//'T'//t(1:2)//':'//t(3:4)//':'//t(5:6)// &
         z(1:3)//':'//z(4:5)
   end function timestamp

end module pecplas_io_results_start
