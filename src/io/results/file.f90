!> The results file of a run (HDF5), written while the run goes on: the root attributes,
!> /mesh and the empty /history at `create` (pecplas_io_results_start), one history row and
!> the fields of /increments/<NNNNNN> per increment (pecplas_io_results_content), /phases
!> (add_phase), /limit, /safety and the run's status at the end (`finish`).
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
!> The sidecar: pecplas_io_results_sidecar; the test hooks that make writes fail:
!> pecplas_io_results_write_hooks.
module pecplas_io_results_file
   use hdf5, only: hid_t
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_run_status, only: RUN_COMPLETED, is_run_status, status_name
   use pecplas_base_strings, only: itoa
   use pecplas_base_files, only: rename_file, process_id, path_base
   use pecplas_io_results_copies, only: copies_t
   use pecplas_model_type, only: model_t
   use pecplas_io_results_increment, only: increment_result_t, gauss_coordinates_t, &
      joint_points_t, limit_point_t
   use pecplas_io_results_h5, only: h5_init, h5_attr
   use pecplas_io_results_restart, only: restart_data_t
   use pecplas_io_results_xdmf, only: xdmf_path
   use pecplas_io_results_sidecar, only: sidecar_t
   use pecplas_io_results_write_hooks, only: write_hook_t, test_no_kernel_copy
   use pecplas_io_results_content, only: results_content_t
   use pecplas_io_results_start, only: write_start, write_warnings, timestamp
   use pecplas_io_results_limit, only: write_limit_group
   use pecplas_io_results_phase_log, only: phase_record_t
   use pecplas_io_results_safety, only: safety_record_t, write_safety_group
   implicit none (type, external)
   private

   public :: results_file_t, temporary_path

   !> An open results file. Do not copy an open one: the copy would share the HDF5 id.
   type :: results_file_t
      private
      !> The two copies written while the run goes on (the published one is `work`).
      type(copies_t) :: copies
      !> The target and the temporary file of the run (the published copy).
      character(len=:), allocatable :: path, work
      !> The XDMF sidecar, running and final.
      type(sidecar_t) :: xmf
      !> Test hook: writes fail from the fail_at-th write on (write_increment, and the
      !> warnings at the end of the run).
      type(write_hook_t) :: hook
      !> The first write error of the file (disk full, permissions), kept for the command layer;
      !> broken: the HDF5 library itself failed (its file can no longer be closed cleanly).
      character(len=:), allocatable :: failure
      logical :: broken = .false.
      !> The final increment is written (into the copy not published): no more increments.
      logical :: ended = .false.
      !> Detached: every write does nothing (the ranks above 0 of an MPI run; rank 0 writes).
      logical, public :: detached = .false.
      !> The layout, the history rows and increments written, the phases.
      type(results_content_t) :: content
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
      if (present(joint_points)) then
         points = joint_points
      else
         allocate (points(0))
      end if
      call this%content%plan(model, gauss_xy, points, error)
      if (allocated(error)) return
      call h5_init(error)
      if (allocated(error)) return
      this%path = path
      this%work = temporary_path(path)
      call this%xmf%init(xdmf_path(path), temporary_path(xdmf_path(path)))
      call this%copies%init(this%work)
      this%broken = .false.
      this%ended = .false.
      if (allocated(this%failure)) deallocate (this%failure)
      call this%hook%init()
      this%copies%kernel = .not. test_no_kernel_copy()
      ! both copies whole and committed before the first is published: a .tmp is readable.
      ! The second is a kernel copy of the first when the system allows, else written.
      do i = 1, 2
         call this%copies%create(this%copies%next, error)
         if (allocated(error)) exit
         call write_start(this%copies%id('next'), model, version, gauss_xy, points, &
            this%content%units, error)
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
      if (.not. allocated(error)) call this%xmf%commit(this%content, path_base(this%work), &
         .true., error)
      if (allocated(error)) then
         this%broken = .true.
         call abandon(this)
      end if
   end subroutine results_create

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

   !> Closes the file and removes its temporary files (a file that could not be created,
   !> a scratch run).
   subroutine abandon(this)
      class(results_file_t), intent(inout) :: this
      integer :: err
      call this%copies%close('both', err)
      call this%copies%remove(.true.)
      call this%xmf%remove(.true.)
   end subroutine abandon

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
      call this%hook%count(this%work, error)
      ! into the copy that `finish` completes (the published one is never written)
      if (.not. allocated(error)) call write_warnings(this%copies%id('next'), list, error)
      if (allocated(error)) call this%note_failure(error%text())
   end subroutine results_warnings


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
      call this%content%check(inc, error)
      if (allocated(error)) return
      call this%hook%count(this%work, error)
      if (.not. allocated(error)) call this%copies%check_space(error)
      if (allocated(error)) then
         call this%note_failure(error%text())
         return
      end if
      call this%content%mark_phase_start(inc)
      call write_checked(this, inc, last, error, restart)
      if (allocated(error)) then
         this%broken = .true.
         call this%note_failure(error%text())
      end if
   end subroutine results_write_increment

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
      integer :: i
      do i = 1, 2
         call this%content%write_copy(this%copies%id('next'), inc, error, restart)
         if (.not. allocated(error)) call this%copies%flush(error)
         if (allocated(error) .or. final) exit
         if (i == 1) call this%copies%publish(error)
         if (allocated(error)) return
      end do
      if (allocated(error)) return
      call this%content%note_written(inc)
      this%ended = final
      if (.not. final) call this%xmf%commit(this%content, path_base(this%work), .false., &
         error)
      if (allocated(error)) return
      call this%copies%note_size()
   end subroutine write_checked

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
      if (allocated(this%failure)) call this%hook%check(this%work, error)
      if (.not. allocated(error) .and. allocated(this%failure)) &
         call this%copies%check_space(error)
      if (allocated(error)) return
      complete = 0
      if (status == RUN_COMPLETED) complete = 1
      file = this%copies%id('next')
      ! a phase the run ended in before any increment of it
      call this%content%write_pending_phases(file, error)
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
      call this%xmf%finish(this%content, path_base(this%path), .true., error)
      if (allocated(error)) return
      if (.not. rename_file(this%copies%name('next'), this%path)) then
         call fatal_error(error, 'cannot rename '//this%copies%name('next')//' onto '// &
            this%path//'; the finished results are in '//this%copies%name('next'))
         return
      end if
      call this%xmf%finish(this%content, path_base(this%path), .false., error)
      if (allocated(error)) return
      ! the running sidecar first (it names the published copy), then the published copy:
      ! names first, then closed (a close may still write)
      call this%xmf%remove(.false.)
      call this%copies%remove(.true.)
      call this%copies%close('both', err)
   end subroutine results_finish

   !> /limit: where the load of the run had its maximum (written before `finish`).
   subroutine results_write_limit(this, limit, error)
      class(results_file_t), intent(inout) :: this
      type(limit_point_t), intent(in) :: limit
      type(error_t), allocatable, intent(out) :: error
      if (this%detached) return
      if (.not. this%is_open()) then
         call fatal_error(error, 'results file is not open')
         return
      end if
      ! into the copy that `finish` completes (the published one is never written)
      call write_limit_group(this%copies%id('next'), limit, this%content%units%patterns, &
         error)
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
      this%content%layout%mechanism = allocated(rec%mechanism)
   end subroutine results_write_safety

   !> Records the start of a phase (a step of a staged run; pecplas_io_results_phases):
   !> from now on, the element and joint sets not active in `rec` have no fields in the
   !> increments written, nor a grid in the XDMF. The group /phases/<index> is written with
   !> the phase's next increment (which it names as its first), or by `finish`.
   subroutine results_add_phase(this, rec, error)
      class(results_file_t), intent(inout) :: this
      type(phase_record_t), intent(in) :: rec
      type(error_t), allocatable, intent(out) :: error
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
      call this%content%add_phase(rec, error)
   end subroutine results_add_phase

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
      if (.not. allocated(this%failure) .and. this%xmf%behind(this%content)) &
         call this%xmf%write_running(this%content, path_base(this%work), error)
   end subroutine results_free

   subroutine results_final(this)
      type(results_file_t), intent(inout) :: this
      call this%free()
   end subroutine results_final

end module pecplas_io_results_file