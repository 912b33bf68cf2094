!> The results file of a run (HDF5), written while the run goes on:
!>   /            attributes program, version, format_version, title, units (the *UNITS line),
!>                length_unit, force_unit, stress_unit (as read from it), deck_file,
!>                deck_text, analysis, thickness, threads, the threads of each part and
!>                the BLAS (see write_threads), created, status, complete,
!>                status_message, warnings (+ finished, and completed when status = 'completed')
!>   /mesh        see pecplas_io_results_mesh
!>   /history     one row per converged increment: step, increment, global_increment, time,
!>                iterations, residual, cpu_time, fields (1 = field group written) and
!>                pattern_factors (npattern, nrow); attribute `patterns` (names)
!>   /increments/<NNNNNN>  fields of global increment NNNNNN: displacement (2, nnode),
!>                displacement3 (3, nnode, z = 0, for ParaView), reaction, reaction3,
!>                sets/<set>/{stress, strain (4, ngauss, nel), stress_mean (4, nel)},
!>                joints/<set>/... (see pecplas_io_results_joints); the sets not active
!>                in the increment's phase have no group there
!>   /phases/<k>  the phases of a staged run (see pecplas_io_results_phase_log, add_phase)
!> While the run goes on, the file is written as two copies in the target's directory, one
!> of them always published as `.NAME.h5.<pid>.tmp` (see `temporary_path` and
!> pecplas_io_results_copies), with its XDMF sidecar (`.NAME.xmf.<pid>.tmp`); `finish`
!> renames the finished copy onto the target, so an earlier result of the same name is
!> replaced only by a finished file and never damaged by a run that dies. Every increment
!> is flushed into both copies, and the published one is never written: a run killed at any
!> moment leaves a `.tmp` file flushed after its last whole increment, whose status is
!> still 'running' and complete = 0; only finish(RUN_COMPLETED) sets complete = 1.
!> The final increment of a run (write_increment with `final`) goes into the copy not
!> published only, which `finish` then completes and renames onto the target: a kill
!> between that write and the rename (the time of one increment's write) leaves the `.tmp`
!> one increment behind, still whole; `free` publishes the copy with the final increment.
!> The sidecar is rewritten whole (through a staging file and a rename) at most once a
!> second and at most 5 % of the time, and at the end: its cost stays linear in the number
!> of increments. Test hook: PECPLAS_TEST_FAIL_WRITE=N in the environment makes the N-th
!> write (`write_increment`, or the warnings found at the end of the run) and every later
!> write fail as a full disk would.
module pecplas_io_results_file
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hdf5, only: hid_t
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_run_status, only: RUN_COMPLETED, is_run_status, status_name
   use pecplas_base_strings, only: itoa
   use pecplas_base_files, only: rename_file, remove_file, process_id, path_base, free_bytes
   use pecplas_io_results_copies, only: copies_t
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: AXISYMMETRIC
   use pecplas_linalg_threads, only: thread_setting_t
   use pecplas_io_results_increment, only: increment_result_t, gauss_coordinates_t, &
      joint_points_t, limit_point_t
   use pecplas_io_results_h5, only: h5_init, h5_group, h5_close_group, h5_attr, &
      h5_history_dataset, safe_name, h5_write, h5_describe, h5_exists, increment_group
   use pecplas_io_results_mesh, only: write_mesh
   use pecplas_io_results_restart, only: restart_data_t, restart_item_t, swap_restart, &
      restart_next_open, restart_put, restart_link
   use pecplas_io_results_xdmf, only: xdmf_layout_t, xdmf_topology, xdmf_path, xdmf_text, &
      write_xdmf
   use pecplas_io_results_fields, only: check_increment, write_history_row, write_fields, &
      has_plastic_state
   use pecplas_io_results_plates, only: write_plate_mesh, write_plate_fields
   use pecplas_io_results_joints, only: joint_layout_t, plan_joints, write_joint_mesh, &
      check_joint_fields, write_joint_fields
   use pecplas_io_results_describe, only: results_units_t, plan_units, describe_mesh, &
      describe_history
   use pecplas_io_results_checksum, only: deck_checksum
   use pecplas_io_results_phase_log, only: phase_record_t, write_phase_group
   use pecplas_io_results_safety, only: safety_record_t, write_safety_group
   use pecplas_io_results_anchors, only: write_anchor_mesh, write_anchor_fields
   use pecplas_io_results_anchor_geometry, only: write_anchor_geometry, xdmf_anchors
   implicit none (type, external)
   private

   public :: results_file_t, temporary_path

   !> The running sidecar is rewritten at most every XMF_PERIOD seconds and when its last
   !> write took at most 1/XMF_SHARE of the time since.
   real(wp), parameter :: XMF_PERIOD = 1.0_wp, XMF_SHARE = 20.0_wp

   !> An open results file. Do not copy an open one: the copy would share the HDF5 id.
   type :: results_file_t
      private
      !> The two copies written while the run goes on (the published one is `work`).
      type(copies_t) :: copies
      !> Targets (.h5 and .xmf), the temporary files of the run (the published copy and its
      !> sidecar), and the staging name through which every .xmf is written.
      character(len=:), allocatable :: path, xmf, work, work_xmf, staging
      !> Fields groups listed in the running .xmf; time of its last write and its cost [s].
      integer :: xmf_count = -1
      real(wp) :: xmf_at = 0.0_wp, xmf_cost = 0.0_wp
      !> Test hook: writes fail from the fail_at-th write on (write_increment, and the
      !> warnings at the end of the run; 0: never).
      integer :: fail_at = 0, nwrite = 0
      !> The first write error of the file (disk full, permissions), kept for the command layer;
      !> broken: the HDF5 library itself failed (its file can no longer be closed cleanly).
      character(len=:), allocatable :: failure
      logical :: broken = .false.
      !> The final increment is written (into the copy not published): no more increments.
      logical :: ended = .false.
      !> Detached: every write does nothing (the ranks above 0 of an MPI run; rank 0 writes).
      logical, public :: detached = .false.
      !> Size of a copy after the last increment and what that increment added.
      integer(int64) :: bytes = 0, growth = 0
      type(xdmf_layout_t) :: layout
      integer :: npattern = 0, nrows = 0
      !> Gauss points per element of each set.
      integer, allocatable :: ngauss(:)
      !> Joint sets (PECJOIN): points, elements and history size of each.
      type(joint_layout_t), allocatable :: joints(:)
      !> Units and component names written next to the datasets.
      type(results_units_t) :: units
      logical :: strains = .true.
      !> Global numbers and times of the increments with fields (for the XDMF).
      integer, allocatable :: written(:)
      real(wp), allocatable :: written_time(:)
      !> Phases recorded by add_phase, and the one each written increment belongs to
      !> (0: none recorded yet, every set active).
      type(phase_record_t), allocatable :: phases(:)
      integer, allocatable :: written_phase(:)
      !> The plate sets active in each written increment (nplate, nwritten): their grids in
      !> the XDMF.
      logical, allocatable :: written_plates(:, :)
      !> The anchor sets active in each written increment (nanchor, nwritten).
      logical, allocatable :: written_anchors(:, :)
   contains
      procedure :: create => results_create
      procedure :: write_increment => results_write_increment
      procedure :: finish => results_finish
      procedure :: write_limit => results_write_limit
      procedure :: write_safety => results_write_safety
      procedure :: add_phase => results_add_phase
      procedure :: warnings => results_warnings
      procedure :: is_open => results_is_open
      procedure :: working_path => results_working_path
      procedure :: write_failure => results_write_failure
      procedure :: note_failure => results_note_failure
      procedure :: is_broken => results_is_broken
      procedure :: free => results_free
      procedure :: discard => abandon
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
      integer :: i
      logical :: cloned
      if (this%detached) return
      if (this%is_open()) then
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
      call plan_units(model, this%units)
      call plan_xdmf_joints(this)
      this%layout%anchors = xdmf_anchors(model)
      if (allocated(this%written_anchors)) deallocate (this%written_anchors)
      allocate (this%written_anchors(size(this%layout%anchors), 0))
      ! the plastic indicators are written with the sets' fields (write_fields)
      do i = 1, size(this%layout%sets)
         this%layout%sets(i)%plastic = has_plastic_state(this%units%sets(i)%state) .and. &
            (this%layout%stresses .or. this%strains .or. this%layout%error_estimate)
      end do
      call h5_init(error)
      if (allocated(error)) return
      this%path = path
      this%xmf = xdmf_path(path)
      this%work = temporary_path(path)
      this%work_xmf = temporary_path(this%xmf)
      this%staging = this%work_xmf(1:len(this%work_xmf) - 4)//'.new'
      call this%copies%init(this%work)
      this%xmf_count = -1
      this%nwrite = 0
      this%broken = .false.
      this%ended = .false.
      this%bytes = 0
      this%growth = 0
      if (allocated(this%failure)) deallocate (this%failure)
      this%fail_at = test_fail_at()
      this%copies%kernel = .not. test_no_kernel_copy()
      ! both copies whole and committed before the first is published: a .tmp is readable.
      ! The second is a kernel copy of the first when the system allows, else written.
      do i = 1, 2
         call this%copies%create(this%copies%next, error)
         if (allocated(error)) exit
         call write_start(this, model, version, gauss_xy, points, error)
         cloned = .false.
         if (.not. allocated(error)) then
            if (i == 1) then
               call this%copies%clone(cloned, error)
            else
               call this%copies%flush(error)
            end if
         end if
         if (allocated(error)) exit
         if (i == 1) call this%copies%publish(error)
         if (allocated(error) .or. cloned) exit
      end do
      if (.not. allocated(error)) call commit(this, .true., error)
      if (allocated(error)) then
         this%broken = .true.
         call abandon(this)
      end if
   end subroutine results_create

   !> The first contents of a results file (into the copy written next): provenance, mesh,
   !> empty history.
   subroutine write_start(this, model, version, gauss_xy, points, error)
      class(results_file_t), intent(inout) :: this
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: version
      type(gauss_coordinates_t), intent(in) :: gauss_xy(:)
      type(joint_points_t), intent(in) :: points(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: file
      file = this%copies%id('next')
      call write_root(file, model, version, error)
      if (.not. allocated(error)) call write_mesh(file, model%mesh, gauss_xy, error)
      if (.not. allocated(error)) call write_joint_mesh(file, model, points, error)
      if (.not. allocated(error)) call write_anchor_mesh(file, model, this%units%length, &
         this%units%force, error)
      if (.not. allocated(error)) call write_plate_mesh(file, model, error)
      if (.not. allocated(error)) call write_anchor_geometry(file, model, this%units%length, &
         error)
      if (.not. allocated(error)) call create_history(file, model, error)
      if (.not. allocated(error)) call describe_mesh(file, model, this%units, error)
      if (.not. allocated(error)) call describe_history(file, this%units, error)
   end subroutine write_start

   !> Where the results of `path` can be read while the run goes on: a hidden file of the
   !> same directory named after the target and this process, 'out/a.h5' ->
   !> 'out/.a.h5.<pid>.tmp' (the same directory, so that the final rename is atomic).
   function temporary_path(path) result(tmp)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: tmp
      integer :: i
      i = index(path, '/', back=.true.)
      tmp = path(1:i)//'.'//path_base(path)//'.'//itoa(process_id())//'.tmp'
   end function temporary_path

   !> PECPLAS_TEST_FAIL_WRITE (test hook), 0 when unset or not a positive integer.
   integer function test_fail_at() result(n)
      character(len=32) :: text
      integer :: length, stat, ios
      n = 0
      call get_environment_variable('PECPLAS_TEST_FAIL_WRITE', text, length, stat)
      if (stat /= 0 .or. length == 0) return
      read (text, *, iostat=ios) n
      if (ios /= 0 .or. n < 0) n = 0
   end function test_fail_at

   !> PECPLAS_TEST_NO_KERNEL_COPY (test hook) set to 1: the second copy of a new file is
   !> written by HDF5 rather than copied by the kernel, as where the kernel refuses.
   logical function test_no_kernel_copy() result(off)
      character(len=8) :: text
      integer :: length, stat
      call get_environment_variable('PECPLAS_TEST_NO_KERNEL_COPY', text, length, stat)
      off = stat == 0 .and. text == '1'
   end function test_no_kernel_copy

   !> Closes the file and removes its temporary files (a file that could not be created,
   !> a scratch run).
   subroutine abandon(this)
      class(results_file_t), intent(inout) :: this
      integer :: err
      call this%copies%close('both', err)
      call this%copies%remove(.true.)
      if (allocated(this%work_xmf)) call remove_file(this%work_xmf)
      if (allocated(this%staging)) call remove_file(this%staging)
   end subroutine abandon

   !> The plate sets as the XDMF sees them (none without plates).
   subroutine plan_xdmf_plates(this, model)
      class(results_file_t), intent(inout) :: this
      type(model_t), intent(in) :: model
      integer :: s, n
      n = 0
      if (allocated(model%plates)) n = size(model%plates)
      if (allocated(this%layout%plates)) deallocate (this%layout%plates)
      allocate (this%layout%plates(n))
      do s = 1, n
         this%layout%plates(s)%name = safe_name(model%plates(s)%name)
         this%layout%plates(s)%nel = size(model%plates(s)%conn, 2)
         this%layout%plates(s)%npe = model%plates(s)%nen
      end do
      if (allocated(this%written_plates)) deallocate (this%written_plates)
      allocate (this%written_plates(n, 0))
   end subroutine plan_xdmf_plates

   !> The joint sets as the XDMF sees them.
   subroutine plan_xdmf_joints(this)
      class(results_file_t), intent(inout) :: this
      integer :: s
      if (allocated(this%layout%joints)) deallocate (this%layout%joints)
      allocate (this%layout%joints(size(this%joints)))
      do s = 1, size(this%joints)
         this%layout%joints(s)%name = this%joints(s)%name
         this%layout%joints(s)%npoint = this%joints(s)%npoint
         this%layout%joints(s)%nel = this%joints(s)%nel
      end do
   end subroutine plan_xdmf_joints

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
      this%layout%error_estimate = model%output%error_estimate
      this%strains = model%output%strains
      this%npattern = 0
      if (allocated(model%patterns)) this%npattern = size(model%patterns)
      this%nrows = 0
      this%written = [integer ::]
      this%written_time = [real(wp) ::]
      this%written_phase = [integer ::]
      call plan_xdmf_plates(this, model)
      if (allocated(this%phases)) deallocate (this%phases)
      allocate (this%phases(0))
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

   !> Replaces the root attribute `warnings` of an open file by `list` (the deck's warnings
   !> and those found during the run, e.g. by the driver), one "file:line: warning: text"
   !> string each.
   subroutine results_warnings(this, list, error)
      class(results_file_t), intent(inout) :: this
      character(len=*), intent(in) :: list(:)
      type(error_t), allocatable, intent(out) :: error
      if (this%detached) return
      if (.not. this%is_open()) then
         call fatal_error(error, 'results file: warnings written to a file not open')
         return
      end if
      call start_write(this, error)
      ! into the copy that `finish` completes (the published one is never written)
      if (.not. allocated(error)) call write_warnings(this%copies%id('next'), list, error)
      if (allocated(error)) call this%note_failure(error%text())
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

   !> Appends one converged increment (history row, and fields when inc%write_fields) to
   !> both copies, one after the other, each flushed (and, when due, rewrites the running
   !> XDMF). Refuses non-finite
   !> values and wrong shapes before writing anything. A failed write (disk full,
   !> permissions) is also kept as `write_failure`.
   !> `restart`: the state to restart from, written in the same flush as the increment.
   !> `final`: the last increment of the run (`finish` follows): written into the copy not
   !> published only, which `finish` renames onto the target (half the writing); the
   !> published `.tmp` keeps the increment before until then. No increment may follow.
   subroutine results_write_increment(this, inc, error, restart, final)
      class(results_file_t), intent(inout) :: this
      type(increment_result_t), intent(in) :: inc
      type(error_t), allocatable, intent(out) :: error
      type(restart_data_t), intent(in), optional :: restart
      logical, intent(in), optional :: final
      logical :: last
      if (this%detached) return
      if (.not. this%is_open()) then
         call fatal_error(error, 'results file is not open')
         return
      end if
      if (this%ended) then
         call fatal_error(error, 'results file: increment '//itoa(inc%global_increment)// &
            ' written after the final one (write_increment with final = .true. must be '// &
            'the last increment; finish comes next)')
         return
      end if
      last = .false.
      if (present(final)) last = final
      call check_increment(inc, this%layout, this%ngauss, this%npattern, this%strains, error)
      if (allocated(error)) return
      if (inc%write_fields) then
         call check_joint_fields(inc%joint_fields, this%joints, 'results file: ', error)
         if (allocated(error)) return
      end if
      call start_write(this, error)
      if (.not. allocated(error)) call check_space(this, error)
      if (allocated(error)) then
         call this%note_failure(error%text())
         return
      end if
      call mark_phase_start(this, inc)
      call write_checked(this, inc, last, error, restart)
      if (allocated(error)) then
         this%broken = .true.
         call this%note_failure(error%text())
      end if
   end subroutine results_write_increment

   !> Refuses to start an increment that may not fit on the disk (twice what the last one
   !> took in both copies, plus 64 KiB): HDF5 cut short by a full disk leaves a damaged
   !> last increment (in the copy being written; the published one stays whole).
   subroutine check_space(this, error)
      class(results_file_t), intent(in) :: this
      type(error_t), allocatable, intent(out) :: error
      integer(int64) :: free, need
      free = free_bytes(this%work)
      need = 4*this%growth + 65536_int64
      if (free >= 0 .and. free < need) call fatal_error(error, 'disk full: '// &
         itoa(int(free/1024))//' KiB left for '//this%work//', an increment needs about '// &
         itoa(int(need/1024))//' KiB')
   end subroutine check_space

   !> The writing part of write_increment: the copy written next gets the increment and is
   !> flushed and published, then the other one (no longer published) gets it too. A copy
   !> is written only while the other one is published, so the published copy is always
   !> one flushed after a whole increment. `final`: the copy written next only, flushed and
   !> not published (`finish` renames it, `free` publishes it); the running sidecar, which
   !> names the published copy, is left without the increment.
   subroutine write_checked(this, inc, final, error, restart)
      class(results_file_t), intent(inout) :: this
      type(increment_result_t), intent(in) :: inc
      logical, intent(in) :: final
      type(error_t), allocatable, intent(out) :: error
      type(restart_data_t), intent(in), optional :: restart
      integer(int64) :: nbytes
      integer :: i
      do i = 1, 2
         call write_copy(this, this%copies%id('next'), inc, error, restart)
         if (.not. allocated(error)) call this%copies%flush(error)
         if (allocated(error) .or. final) exit
         if (i == 1) call this%copies%publish(error)
         if (allocated(error)) return
      end do
      if (allocated(error)) return
      if (inc%write_fields) then
         call note_plates(this, inc)
         call note_anchors(this, inc)
         this%written = [this%written, inc%global_increment]
         this%written_time = [this%written_time, inc%time]
         this%written_phase = [this%written_phase, size(this%phases)]
      end if
      this%phases(:)%pending = .false.
      this%nrows = this%nrows + 1
      this%ended = final
      if (.not. final) call commit(this, .false., error)
      if (allocated(error)) return
      inquire (file=this%copies%name('next'), size=nbytes)
      if (nbytes > 0) then
         this%growth = max(0_int64, nbytes - this%bytes)
         this%bytes = nbytes
      end if
   end subroutine write_checked

   !> One increment into the copy `file` (not flushed): fields, restart state, history row.
   subroutine write_copy(this, file, inc, error, restart)
      class(results_file_t), intent(in) :: this
      integer(hid_t), intent(in) :: file
      type(increment_result_t), intent(in) :: inc
      type(error_t), allocatable, intent(out) :: error
      type(restart_data_t), intent(in), optional :: restart
      logical, allocatable :: jon(:)
      if (inc%write_fields) then
         call write_fields(file, inc, this%layout, this%strains, this%units, error)
         if (allocated(error)) return
         jon = this%layout%joints(:)%active
         if (size(this%joints) > 0) call write_joint_fields(file, inc%global_increment, &
            inc%joint_fields, this%joints, this%units, error, jon)
         if (allocated(error)) return
         if (allocated(inc%anchor_fields)) call write_anchor_fields(file, &
            inc%global_increment, inc%anchor_fields, this%units%length, this%units%force, error)
         if (allocated(inc%plate_fields)) call write_plate_fields(file, inc%global_increment, &
            inc%plate_fields, this%units, error)
         if (allocated(error)) return
      end if
      call write_pending_phases(this, file, error)
      if (allocated(error)) return
      if (present(restart)) then
         ! after the fields: the items given by reference are links to them
         call write_restart(this, file, inc, restart, error)
         if (.not. allocated(error)) call swap_restart(file, error)
         if (allocated(error)) return
      end if
      call write_history_row(file, this%nrows + 1, inc, error)
   end subroutine write_copy

   !> The restart state as /restart_next of `file`: its values, and for an item given by
   !> reference to a field of `inc`, a hard link to that field's dataset when written in
   !> this increment, else the field's values (written unscaled, as the fields are).
   subroutine write_restart(this, file, inc, restart, error)
      class(results_file_t), intent(in) :: this
      integer(hid_t), intent(in) :: file
      type(increment_result_t), intent(in) :: inc
      type(restart_data_t), intent(in) :: restart
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: g
      integer :: i
      call restart_next_open(file, g, error)
      if (allocated(error)) return
      do i = 1, restart%n
         associate (item => restart%items(i))
            if (allocated(item%v)) then
               call restart_put(g, item%name, size(item%v), item%v, error)
            else
               call put_field(this, file, g, inc, item, error)
            end if
         end associate
         if (allocated(error)) exit
      end do
      call h5_close_group(g)
   end subroutine write_restart

   !> A restart item given by reference to a field of `inc` (see restart_item_t).
   subroutine put_field(this, file, g, inc, item, error)
      class(results_file_t), intent(in) :: this
      integer(hid_t), intent(in) :: file, g
      type(increment_result_t), intent(in) :: inc
      type(restart_item_t), intent(in) :: item
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: path
      logical :: have
      have = inc%write_fields
      if (have .and. item%field /= 'displacement') have = item%set >= 1 .and. &
         item%set <= size(this%layout%sets) .and. allocated(inc%set_fields)
      if (.not. have) then
         call fatal_error(error, 'restart item '//item%name//' refers to the field '// &
            item%field//' of increment '//itoa(inc%global_increment)//', which has none')
         return
      end if
      path = increment_group(inc%global_increment)//'/'//item%field
      if (item%field /= 'displacement') path = increment_group(inc%global_increment)// &
         '/sets/'//this%layout%sets(item%set)%name//'/'//item%field
      if (h5_exists(file, path)) then
         call restart_link(file, g, item%name, path, error)
         return
      end if
      ! a field not written (e.g. *OUTPUT without stresses): its values
      if (item%field == 'displacement') then
         call restart_put(g, item%name, size(inc%displacement), inc%displacement, error)
         return
      end if
      associate (f => inc%set_fields(item%set))
         select case (item%field)
         case ('stress')
            if (allocated(f%stress)) &
               call restart_put(g, item%name, size(f%stress), f%stress, error)
            have = allocated(f%stress)
         case ('strain')
            if (allocated(f%strain)) &
               call restart_put(g, item%name, size(f%strain), f%strain, error)
            have = allocated(f%strain)
         case ('state')
            if (allocated(f%state)) &
               call restart_put(g, item%name, size(f%state), f%state, error)
            have = allocated(f%state)
         case default
            have = .false.
         end select
      end associate
      if (.not. have .and. .not. allocated(error)) call fatal_error(error, 'restart item '// &
         item%name//' refers to the field '//item%field//' of set '//itoa(item%set)// &
         ', which increment '//itoa(inc%global_increment)//' does not hold')
   end subroutine put_field

   !> Counts one write (an increment, or the warnings at the end of the run) and fails it
   !> when the test hook says so.
   subroutine start_write(this, error)
      class(results_file_t), intent(inout) :: this
      type(error_t), allocatable, intent(out) :: error
      this%nwrite = this%nwrite + 1
      call test_hook(this, error)
   end subroutine start_write

   !> PECPLAS_TEST_FAIL_WRITE: the fail_at-th write and every later one fail.
   subroutine test_hook(this, error)
      class(results_file_t), intent(in) :: this
      type(error_t), allocatable, intent(out) :: error
      if (this%fail_at > 0 .and. this%nwrite >= this%fail_at) call fatal_error(error, &
         'HDF5: cannot write results file '//this%work//' (write '//itoa(this%nwrite)// &
         ' failed on purpose: PECPLAS_TEST_FAIL_WRITE='//itoa(this%fail_at)//')')
   end subroutine test_hook

   !> Records how the run ended in the copy not published, closes it and renames it onto the
   !> target (then the final XDMF, naming the target), then removes the published copy.
   !> status: a run status of pecplas_base_run_status, written as its word (status_name);
   !> complete = 1 only for RUN_COMPLETED; a file never finished keeps 'running'. On error the
   !> temporary file stays where `working_path` says.
   subroutine results_finish(this, status, message, error)
      class(results_file_t), intent(inout) :: this
      integer, intent(in) :: status
      character(len=*), intent(in) :: message
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: file
      integer :: complete, err
      if (this%detached) return
      if (this%copies%id('next') <= 0) then
         call fatal_error(error, 'results file is not open')
         return
      end if
      if (.not. is_run_status(status)) then
         call fatal_error(error, 'results file: '//itoa(status)//' is no run status '// &
            '(pecplas_base_run_status)')
         return
      end if
      if (allocated(this%failure)) call test_hook(this, error)
      if (.not. allocated(error) .and. allocated(this%failure)) call check_space(this, error)
      if (allocated(error)) return
      complete = 0
      if (status == RUN_COMPLETED) complete = 1
      file = this%copies%id('next')
      ! a phase the run ended in before any increment of it
      call write_pending_phases(this, file, error)
      if (.not. allocated(error)) call h5_attr(file, 'status', status_name(status), error)
      if (.not. allocated(error)) call h5_attr(file, 'status_message', message, error)
      if (.not. allocated(error)) call h5_attr(file, 'finished', timestamp(), error)
      if (.not. allocated(error) .and. complete == 1) &
         call h5_attr(file, 'completed', timestamp(), error)
      ! complete last: a crash in between leaves complete = 0
      if (.not. allocated(error)) call h5_attr(file, 'complete', complete, error)
      if (allocated(error)) return
      ! closed, not committed first (a commit is a close and an open): nothing is written
      ! into it after, and it is published only by the rename below
      call this%copies%close('next', err)
      if (err /= 0) then
         call fatal_error(error, 'HDF5: cannot close results file '// &
            this%copies%name('next')//' (disk full?)')
         return
      end if
      ! the final sidecar is staged first: the two renames then follow each other closely
      call write_xdmf(this%staging, '', sidecar_text(this, path_base(this%path)), error)
      if (allocated(error)) return
      if (.not. rename_file(this%copies%name('next'), this%path)) then
         call fatal_error(error, 'cannot rename '//this%copies%name('next')//' onto '// &
            this%path//'; the finished results are in '//this%copies%name('next'))
         return
      end if
      if (.not. rename_file(this%staging, this%xmf)) then
         call fatal_error(error, 'cannot rename '//this%staging//' onto '//this%xmf)
         return
      end if
      ! the running sidecar first (it names the published copy), then the published copy:
      ! names first, then closed (a close may still write)
      call remove_file(this%work_xmf)
      call this%copies%remove(.true.)
      call this%copies%close('both', err)
   end subroutine results_finish

   !> /limit: where the load of the run had its maximum (written before `finish`).
   subroutine results_write_limit(this, limit, error)
      class(results_file_t), intent(inout) :: this
      type(limit_point_t), intent(in) :: limit
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: g
      if (this%detached) return
      if (.not. this%is_open()) then
         call fatal_error(error, 'results file is not open')
         return
      end if
      ! into the copy that `finish` completes (the published one is never written)
      call h5_group(this%copies%id('next'), 'limit', g, error)
      if (allocated(error)) return
      call h5_attr(g, 'kind', limit%kind, error)
      if (.not. allocated(error)) call h5_attr(g, 'step', limit%step, error)
      if (.not. allocated(error)) call h5_attr(g, 'global_increment', limit%global_increment, &
         error)
      if (.not. allocated(error)) call h5_attr(g, 'fraction', limit%fraction, error)
      if (.not. allocated(error)) call h5_attr(g, 'stiffness_parameter', &
         limit%stiffness_parameter, error)
      if (.not. allocated(error)) call h5_write(g, 'pattern_factors', limit%pattern_factors, &
         error)
      if (.not. allocated(error)) call h5_describe(g, 'pattern_factors', '1', error, &
         this%units%patterns)
      call h5_close_group(g)
   end subroutine results_write_limit

   !> /safety: what a safety step found (pecplas_io_results_safety; written before `finish`);
   !> its mechanism is shown on the last increment of the XDMF sidecar.
   subroutine results_write_safety(this, rec, error)
      class(results_file_t), intent(inout) :: this
      type(safety_record_t), intent(in) :: rec
      type(error_t), allocatable, intent(out) :: error
      if (this%detached) return
      if (.not. this%is_open()) then
         call fatal_error(error, 'results file is not open')
         return
      end if
      call write_safety_group(this%copies%id('next'), rec, error)
      if (allocated(error)) return
      this%layout%mechanism = allocated(rec%mechanism)
   end subroutine results_write_safety

   !> Records the start of a phase (a step of a staged run; pecplas_io_results_phases):
   !> from now on, the element and joint sets not active in `rec` have no fields in the
   !> increments written, nor a grid in the XDMF. The group /phases/<index> is written with
   !> the phase's next increment (which it names as its first), or by `finish`.
   subroutine results_add_phase(this, rec, error)
      class(results_file_t), intent(inout) :: this
      type(phase_record_t), intent(in) :: rec
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      if (this%detached) return
      if (.not. this%is_open()) then
         call fatal_error(error, 'results file is not open')
         return
      end if
      if (this%ended) then
         call fatal_error(error, 'results file: phase '//itoa(rec%index)// &
            ' recorded after the final increment')
         return
      end if
      if (.not. allocated(rec%name) .or. .not. allocated(rec%changes) .or. &
         .not. allocated(rec%active_esets) .or. .not. allocated(rec%active_jsets)) then
         call fatal_error(error, 'results file: phase '//itoa(rec%index)//' is incomplete')
         return
      end if
      if (size(rec%active_esets) /= size(this%layout%sets) .or. &
         size(rec%active_jsets) /= size(this%layout%joints)) then
         call fatal_error(error, 'results file: phase '//itoa(rec%index)//' has masks of '// &
            itoa(size(rec%active_esets))//' element sets and '//itoa(size(rec%active_jsets))// &
            ' joint sets; the model has '//itoa(size(this%layout%sets))//' and '// &
            itoa(size(this%layout%joints)))
         return
      end if
      if (rec%index < 1) then
         call fatal_error(error, 'results file: phase index '//itoa(rec%index)//' < 1')
         return
      end if
      ! a phase recorded again before any increment replaces the one pending
      if (size(this%phases) > 0) then
         if (this%phases(size(this%phases))%pending) this%phases = &
            this%phases(1:size(this%phases) - 1)
      end if
      this%phases = [this%phases, rec]
      this%phases(size(this%phases))%pending = .true.
      this%phases(size(this%phases))%first_global_increment = -1
      this%phases(size(this%phases))%first_history_row = -1
      do i = 1, size(this%layout%sets)
         this%layout%sets(i)%active = rec%active_esets(i)
      end do
      do i = 1, size(this%layout%joints)
         this%layout%joints(i)%active = rec%active_jsets(i)
      end do
   end subroutine results_add_phase

   !> The phases still pending start with increment `inc`.
   subroutine mark_phase_start(this, inc)
      class(results_file_t), intent(inout) :: this
      type(increment_result_t), intent(in) :: inc
      integer :: i
      do i = 1, size(this%phases)
         if (.not. this%phases(i)%pending) cycle
         this%phases(i)%first_global_increment = inc%global_increment
         this%phases(i)%first_history_row = this%nrows + 1
      end do
   end subroutine mark_phase_start

   !> The pending phases into the copy `file`.
   subroutine write_pending_phases(this, file, error)
      class(results_file_t), intent(in) :: this
      integer(hid_t), intent(in) :: file
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: enames(:), jnames(:)
      integer :: i, w
      if (.not. allocated(this%phases)) return
      if (.not. any(this%phases(:)%pending)) return
      w = 1
      do i = 1, size(this%layout%sets)
         w = max(w, len(this%layout%sets(i)%name))
      end do
      allocate (character(len=w) :: enames(size(this%layout%sets)))
      do i = 1, size(this%layout%sets)
         enames(i) = this%layout%sets(i)%name
      end do
      w = 1
      do i = 1, size(this%layout%joints)
         w = max(w, len(this%layout%joints(i)%name))
      end do
      allocate (character(len=w) :: jnames(size(this%layout%joints)))
      do i = 1, size(this%layout%joints)
         jnames(i) = this%layout%joints(i)%name
      end do
      do i = 1, size(this%phases)
         if (.not. this%phases(i)%pending) cycle
         call write_phase_group(file, this%phases(i), enames, jnames, error)
         if (allocated(error)) return
      end do
   end subroutine write_pending_phases

   !> Records which plate sets the increment written now holds (its XDMF grids).
   subroutine note_plates(this, inc)
      class(results_file_t), intent(inout) :: this
      type(increment_result_t), intent(in) :: inc
      logical :: on(size(this%written_plates, 1))
      integer :: n
      on = .true.
      if (allocated(inc%plate_fields)) then
         if (size(inc%plate_fields) == size(on)) on = inc%plate_fields(:)%active
      end if
      n = size(this%written_plates, 2)
      this%written_plates = reshape([this%written_plates, on], [size(on), n + 1])
   end subroutine note_plates

   !> Records which anchor sets the increment written now holds (its XDMF grids).
   subroutine note_anchors(this, inc)
      class(results_file_t), intent(inout) :: this
      type(increment_result_t), intent(in) :: inc
      logical :: on(size(this%written_anchors, 1))
      integer :: n
      on = .true.
      if (allocated(inc%anchor_fields)) then
         if (size(inc%anchor_fields) == size(on)) on = inc%anchor_fields(:)%active
      end if
      n = size(this%written_anchors, 2)
      this%written_anchors = reshape([this%written_anchors, on], [size(on), n + 1])
   end subroutine note_anchors

   !> The XDMF text of the increments written so far, each with the sets active in its
   !> phase.
   function sidecar_text(this, h5_name) result(text)
      class(results_file_t), intent(in) :: this
      character(len=*), intent(in) :: h5_name
      character(len=:), allocatable :: text
      logical, allocatable :: esets(:, :), jsets(:, :)
      integer :: k, p
      allocate (esets(size(this%layout%sets), size(this%written)), &
         jsets(size(this%layout%joints), size(this%written)))
      esets = .true.
      jsets = .true.
      do k = 1, size(this%written)
         p = this%written_phase(k)
         if (p < 1) cycle
         esets(:, k) = this%phases(p)%active_esets
         jsets(:, k) = this%phases(p)%active_jsets
      end do
      text = xdmf_text(this%layout, h5_name, this%written, this%written_time, esets, jsets, &
         this%written_plates, this%written_anchors)
   end function sidecar_text

   !> True between a successful `create` and `finish` / `free`.
   pure logical function results_is_open(this)
      class(results_file_t), intent(in) :: this
      results_is_open = any(this%copies%ids > 0)
   end function results_is_open

   !> The file being written (temporary name) until `finish` renames it onto the target.
   function results_working_path(this) result(path)
      class(results_file_t), intent(in) :: this
      character(len=:), allocatable :: path
      path = ''
      if (allocated(this%work)) path = this%work
   end function results_working_path

   !> The first write error of the file ('' if none): disk full, permissions, test hook.
   function results_write_failure(this) result(text)
      class(results_file_t), intent(in) :: this
      character(len=:), allocatable :: text
      text = ''
      if (allocated(this%failure)) text = this%failure
   end function results_write_failure

   !> Keeps `text` as the file's write failure when it has none: this file's own (the first
   !> write that failed), or another MPI rank's, which writes the file (this rank's copy is
   !> detached), so that every rank ends alike.
   subroutine results_note_failure(this, text)
      class(results_file_t), intent(inout) :: this
      character(len=*), intent(in) :: text
      if (.not. allocated(this%failure)) this%failure = text
   end subroutine results_note_failure

   !> True when the HDF5 library failed on this file: the command layer should then end
   !> the process without the library's exit handler (pecplas_base_files: exit_now).
   pure logical function results_is_broken(this)
      class(results_file_t), intent(in) :: this
      results_is_broken = this%broken
   end function results_is_broken

   !> Closes the file without touching its status: a run stopped without `finish` keeps
   !> status 'running' and complete = 0, under its temporary name, next to an XDMF sidecar
   !> (also temporary) that lists every increment written. The copy not published, unless
   !> a write into it failed, is closed and published in turn, then the other one goes
   !> (after a final increment, that copy alone holds it).
   subroutine results_free(this)
      class(results_file_t), intent(inout) :: this
      type(error_t), allocatable :: error
      integer :: err
      if (.not. this%is_open()) return
      if (this%copies%id('next') > 0) then
         if (.not. this%broken) then
            call this%copies%close('next', err)
            if (err == 0) call this%copies%publish(error)
         end if
         ! the copy not published: its name first, then closed (a close may still write)
         if (.not. allocated(error)) call this%copies%remove(.false.)
         call this%copies%close('next', err)
      end if
      call this%copies%close('both', err)
      if (allocated(error)) deallocate (error)
      if (.not. allocated(this%failure) .and. this%xmf_count /= size(this%written)) &
         call write_running_xmf(this, error)
   end subroutine results_free

   subroutine results_final(this)
      type(results_file_t), intent(inout) :: this
      call this%free()
   end subroutine results_final

   !> After an increment is in both copies: rewrites the running XDMF when it lacks
   !> increments and `force` or its period has passed (see XMF_PERIOD, XMF_SHARE).
   subroutine commit(this, force, error)
      class(results_file_t), intent(inout) :: this
      logical, intent(in) :: force
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: since
      if (this%xmf_count == size(this%written)) return
      since = clock() - this%xmf_at
      if (force .or. since >= max(XMF_PERIOD, XMF_SHARE*this%xmf_cost)) &
         call write_running_xmf(this, error)
   end subroutine commit

   !> The XDMF of the temporary file, naming it, through the staging file and a rename.
   subroutine write_running_xmf(this, error)
      class(results_file_t), intent(inout) :: this
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: t0
      t0 = clock()
      call write_xdmf(this%work_xmf, this%staging, sidecar_text(this, path_base(this%work)), &
         error)
      if (allocated(error)) return
      this%xmf_count = size(this%written)
      this%xmf_at = clock()
      this%xmf_cost = this%xmf_at - t0
   end subroutine write_running_xmf

   !> Wall-clock seconds (monotonic).
   real(wp) function clock()
      integer(int64) :: count, rate
      call system_clock(count, rate)
      clock = real(count, wp)/real(max(rate, 1_int64), wp)
   end function clock

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
