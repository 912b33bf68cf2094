!> The results file of a run (HDF5), written while the run goes on:
!>   /            attributes program, version, format_version, title, units, deck_file,
!>                deck_text, analysis, thickness, created, status, complete,
!>                status_message, warnings (+ finished, and completed when status = 'completed')
!>   /mesh        see pecplas_io_results_mesh
!>   /history     one row per converged increment: step, increment, global_increment, time,
!>                iterations, residual, cpu_time, fields (1 = field group written) and
!>                pattern_factors (npattern, nrow); attribute `patterns` (names)
!>   /increments/<NNNNNN>  fields of global increment NNNNNN: displacement (2, nnode),
!>                displacement3 (3, nnode, z = 0, for ParaView), reaction, reaction3,
!>                sets/<set>/{stress, strain (4, ngauss, nel), stress_mean (4, nel)},
!>                joints/<set>/... (see pecplas_io_results_joints)
!> Every increment is flushed, so a run that crashes leaves a readable file whose status
!> is still 'running' and complete = 0; only finish('completed') sets complete = 1.
module pecplas_io_results_file
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hdf5, only: hid_t, h5fcreate_f, h5fclose_f, h5fflush_f, H5F_ACC_TRUNC_F, H5F_SCOPE_GLOBAL_F
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t, fatal_error
   use pecplas_model, only: model_t
   use pecplas_model_options, only: AXISYMMETRIC
   use pecplas_io_results_increment, only: increment_result_t, gauss_coordinates_t, &
      joint_points_t
   use pecplas_io_results_h5, only: h5_init, h5_group, h5_close_group, h5_attr, &
      h5_history_dataset, safe_name
   use pecplas_io_results_mesh, only: write_mesh
   use pecplas_io_results_xdmf, only: xdmf_layout_t, xdmf_topology, xdmf_path, write_xdmf
   use pecplas_io_results_fields, only: check_increment, write_history_row, write_fields
   use pecplas_io_results_joints, only: joint_layout_t, plan_joints, write_joint_mesh, &
      check_joint_fields, write_joint_fields
   implicit none (type, external)
   private

   public :: results_file_t, RESULT_STATUSES

   !> Final statuses accepted by `finish`; a file never finished keeps 'running'.
   character(len=*), parameter :: RESULT_STATUSES(4) = [character(len=10) :: 'completed', &
      'limit load', 'diverged', 'failed']

   !> An open results file. Do not copy an open one: the copy would share the HDF5 id.
   type :: results_file_t
      private
      integer(hid_t) :: file = -1
      character(len=:), allocatable :: path, xmf
      type(xdmf_layout_t) :: layout
      integer :: npattern = 0, nrows = 0
      !> Gauss points per element of each set.
      integer, allocatable :: ngauss(:)
      !> Joint sets (PECJOIN): points, elements and history size of each.
      type(joint_layout_t), allocatable :: joints(:)
      logical :: strains = .true.
      !> Global numbers and times of the increments with fields (for the XDMF).
      integer, allocatable :: written(:)
      real(wp), allocatable :: written_time(:)
   contains
      procedure :: create => results_create
      procedure :: write_increment => results_write_increment
      procedure :: finish => results_finish
      procedure :: warnings => results_warnings
      procedure :: is_open => results_is_open
      procedure :: free => results_free
      final :: results_final
   end type results_file_t

contains

   !> Creates (truncates) `path` with the run's provenance, the mesh and an empty history,
   !> and writes the XDMF sidecar. gauss_xy(i)%xy(2, ngauss, nel) per element set;
   !> joint_points (one per joint set) is required when the model has joints.
   subroutine results_create(this, path, model, version, gauss_xy, error, joint_points)
      class(results_file_t), intent(inout) :: this
      character(len=*), intent(in) :: path, version
      type(model_t), intent(in) :: model
      type(gauss_coordinates_t), intent(in) :: gauss_xy(:)
      type(error_t), allocatable, intent(out) :: error
      type(joint_points_t), intent(in), optional :: joint_points(:)
      type(joint_points_t), allocatable :: points(:)
      integer :: err
      if (this%file > 0) then
         call fatal_error(error, 'results file '//this%path//' is already open')
         return
      end if
      call plan(this, model, gauss_xy, error)
      if (allocated(error)) return
      if (present(joint_points)) then
         points = joint_points
      else
         allocate (points(0))
      end if
      call plan_joints(model, points, this%joints, error)
      if (allocated(error)) return
      call h5_init(error)
      if (allocated(error)) return
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, this%file, err)
      if (err /= 0) then
         this%file = -1
         call fatal_error(error, 'cannot create results file '//path// &
            ' (does its directory exist and is it writable?)')
         return
      end if
      this%path = path
      this%xmf = xdmf_path(path)
      this%layout%h5_name = path(index(path, '/', back=.true.) + 1:)
      call write_root(this%file, model, version, error)
      if (allocated(error)) return
      call write_mesh(this%file, model%mesh, gauss_xy, error)
      if (allocated(error)) return
      call write_joint_mesh(this%file, model, points, error)
      if (allocated(error)) return
      call create_history(this%file, model, error)
      if (allocated(error)) return
      call commit(this, error)
   end subroutine results_create

   !> Checks the model and gauss_xy and records the layout of the file.
   subroutine plan(this, model, gauss_xy, error)
      class(results_file_t), intent(inout) :: this
      type(model_t), intent(in) :: model
      type(gauss_coordinates_t), intent(in) :: gauss_xy(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: i, nset
      if (.not. allocated(model%mesh%x) .or. .not. allocated(model%mesh%esets)) then
         call fatal_error(error, 'results file: the model has no mesh')
         return
      end if
      nset = size(model%mesh%esets)
      if (size(gauss_xy) /= nset) then
         call fatal_error(error, 'results file: gauss_xy must have one entry per element set')
         return
      end if
      if (.not. all(ieee_is_finite(model%mesh%x))) then
         call fatal_error(error, 'results file: non-finite node coordinate')
         return
      end if
      this%layout%nnode = model%mesh%nnode()
      this%layout%reactions = model%output%reactions
      this%layout%stresses = model%output%stresses
      this%strains = model%output%strains
      this%npattern = 0
      if (allocated(model%patterns)) this%npattern = size(model%patterns)
      this%nrows = 0
      this%written = [integer ::]
      this%written_time = [real(wp) ::]
      if (allocated(this%ngauss)) deallocate (this%ngauss)
      if (allocated(this%layout%sets)) deallocate (this%layout%sets)
      allocate (this%ngauss(nset))
      allocate (this%layout%sets(nset))
      do i = 1, nset
         associate (set => model%mesh%esets(i), s => this%layout%sets(i))
            s%name = safe_name(set%name)
            s%nel = size(set%conn, 2)
            call xdmf_topology(set%etype, s%topology, s%npe, error)
            if (allocated(error)) return
            if (s%npe /= size(set%conn, 1)) then
               call fatal_error(error, 'results file: set '//set%name//' ('//set%etype// &
                  ') has the wrong number of nodes per element')
               return
            end if
            if (.not. allocated(gauss_xy(i)%xy)) then
               call fatal_error(error, 'results file: no Gauss coordinates for set '//set%name)
               return
            end if
            this%ngauss(i) = size(gauss_xy(i)%xy, 2)
            if (size(gauss_xy(i)%xy, 1) /= 2 .or. size(gauss_xy(i)%xy, 3) /= s%nel .or. &
               .not. all(ieee_is_finite(gauss_xy(i)%xy))) then
               call fatal_error(error, 'results file: Gauss coordinates of set '//set%name// &
                  ' must be finite, of shape (2, ngauss, nel)')
               return
            end if
         end associate
      end do
   end subroutine plan

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
      if (.not. allocated(error)) call h5_attr(file, 'deck_file', &
         text_or_empty(model%deck_file), error)
      if (.not. allocated(error)) call h5_attr(file, 'deck_text', &
         text_or_empty(model%deck_text), error)
      if (.not. allocated(error)) call h5_attr(file, 'analysis', analysis, error)
      if (.not. allocated(error)) call h5_attr(file, 'thickness', model%analysis%thickness, error)
      if (.not. allocated(error)) call h5_attr(file, 'created', timestamp(), error)
      if (.not. allocated(error)) call h5_attr(file, 'status', 'running', error)
      if (.not. allocated(error)) call h5_attr(file, 'complete', 0, error)
      if (.not. allocated(error)) call h5_attr(file, 'status_message', '', error)
      if (.not. allocated(error)) call write_warnings(file, model%warnings%lines(), error)
   end subroutine write_root

   !> Replaces the root attribute `warnings` of an open file by `list` (the deck's warnings
   !> and those found during the run, e.g. by the driver), one "file:line: warning: text"
   !> string each.
   subroutine results_warnings(this, list, error)
      class(results_file_t), intent(inout) :: this
      character(len=*), intent(in) :: list(:)
      type(error_t), allocatable, intent(out) :: error
      if (this%file < 0) then
         call fatal_error(error, 'results file: warnings written to a file not open')
         return
      end if
      call write_warnings(this%file, list, error)
   end subroutine results_warnings

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
      character(len=*), parameter :: INTS(5) = [character(len=16) :: 'step', 'increment', &
         'global_increment', 'iterations', 'fields']
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

   !> Appends one converged increment (history row, and fields when inc%write_fields),
   !> then flushes the file and rewrites the XDMF. Refuses non-finite values and wrong
   !> shapes before writing anything.
   subroutine results_write_increment(this, inc, error)
      class(results_file_t), intent(inout) :: this
      type(increment_result_t), intent(in) :: inc
      type(error_t), allocatable, intent(out) :: error
      if (this%file <= 0) then
         call fatal_error(error, 'results file is not open')
         return
      end if
      call check_increment(inc, this%layout, this%ngauss, this%npattern, this%strains, error)
      if (allocated(error)) return
      if (inc%write_fields) then
         call check_joint_fields(inc%joint_fields, this%joints, 'results file: ', error)
         if (allocated(error)) return
         call write_fields(this%file, inc, this%layout, this%strains, error)
         if (allocated(error)) return
         if (size(this%joints) > 0) call write_joint_fields(this%file, inc%global_increment, &
            inc%joint_fields, this%joints, error)
         if (allocated(error)) return
         this%written = [this%written, inc%global_increment]
         this%written_time = [this%written_time, inc%time]
      end if
      call write_history_row(this%file, this%nrows + 1, inc, error)
      if (allocated(error)) return
      this%nrows = this%nrows + 1
      call commit(this, error)
   end subroutine results_write_increment

   !> Records how the run ended and closes the file. status: one of RESULT_STATUSES;
   !> complete = 1 only for 'completed'.
   subroutine results_finish(this, status, message, error)
      class(results_file_t), intent(inout) :: this
      character(len=*), intent(in) :: status, message
      type(error_t), allocatable, intent(out) :: error
      integer :: complete
      if (this%file <= 0) then
         call fatal_error(error, 'results file is not open')
         return
      end if
      if (.not. any(RESULT_STATUSES == status)) then
         call fatal_error(error, 'results file: unknown status "'//status// &
            '"; known: completed, limit load, diverged, failed')
         return
      end if
      complete = 0
      if (status == 'completed') complete = 1
      call h5_attr(this%file, 'status', status, error)
      if (.not. allocated(error)) call h5_attr(this%file, 'status_message', message, error)
      if (.not. allocated(error)) call h5_attr(this%file, 'finished', timestamp(), error)
      if (.not. allocated(error) .and. complete == 1) &
         call h5_attr(this%file, 'completed', timestamp(), error)
      ! complete last: a crash in between leaves complete = 0
      if (.not. allocated(error)) call h5_attr(this%file, 'complete', complete, error)
      if (allocated(error)) return
      call commit(this, error)
      if (allocated(error)) return
      call this%free()
   end subroutine results_finish

   !> True between a successful `create` and `finish` / `free`.
   pure logical function results_is_open(this)
      class(results_file_t), intent(in) :: this
      results_is_open = this%file > 0
   end function results_is_open

   !> Closes the file without touching its status: a run stopped without `finish` keeps
   !> status 'running' and complete = 0.
   subroutine results_free(this)
      class(results_file_t), intent(inout) :: this
      integer :: err
      if (this%file > 0) then
         call h5fflush_f(this%file, H5F_SCOPE_GLOBAL_F, err)
         call h5fclose_f(this%file, err)
      end if
      this%file = -1
   end subroutine results_free

   subroutine results_final(this)
      type(results_file_t), intent(inout) :: this
      call this%free()
   end subroutine results_final

   !> Flushes to disk (the commit point of an increment) and rewrites the XDMF.
   subroutine commit(this, error)
      class(results_file_t), intent(inout) :: this
      type(error_t), allocatable, intent(out) :: error
      integer :: err
      call h5fflush_f(this%file, H5F_SCOPE_GLOBAL_F, err)
      if (err /= 0) then
         call fatal_error(error, 'HDF5: cannot flush results file '//this%path)
         return
      end if
      call write_xdmf(this%xmf, this%layout, this%written, this%written_time, error)
   end subroutine commit

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

end module pecplas_io_results_file
