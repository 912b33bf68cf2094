!> What a results file holds (pecplas_io_results_file): its layout planned from the model
!> (sets, joints, plates, anchors, units), the history rows and the increments with fields
!> written so far, and the phases of a staged run. It writes one increment into one copy of
!> the file (write_copy) and gives the XDMF text of the increments written (sidecar_text);
!> the copies, their publishing and the sidecar's files are the results file's.
!>   /increments/<NNNNNN>  fields of global increment NNNNNN: displacement (2, nnode),
!>                displacement3 (3, nnode, z = 0, for ParaView), reaction, reaction3,
!>                sets/<set>/{stress, strain (4, ngauss, nel), stress_mean (4, nel)},
!>                joints/<set>/... (see pecplas_io_results_joints); the sets not active
!>                in the increment's phase have no group there
!>   /phases/<k>  the phases of a staged run (see pecplas_io_results_phase_log, add_phase)
module pecplas_io_results_content
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hdf5, only: hid_t
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_strings, only: itoa
   use pecplas_model_type, only: model_t
   use pecplas_io_results_increment, only: increment_result_t, gauss_coordinates_t, &
      joint_points_t
   use pecplas_io_results_h5, only: safe_name
   use pecplas_io_results_restart, only: restart_data_t, swap_restart
   use pecplas_io_results_restart_write, only: write_restart
   use pecplas_io_results_xdmf, only: xdmf_layout_t, xdmf_topology, xdmf_text
   use pecplas_io_results_fields, only: check_increment, write_history_row, write_fields, &
      has_plastic_state
   use pecplas_io_results_plates, only: write_plate_fields
   use pecplas_io_results_joints, only: joint_layout_t, plan_joints, check_joint_fields, &
      write_joint_fields
   use pecplas_io_results_describe, only: results_units_t, plan_units
   use pecplas_io_results_phase_log, only: phase_record_t, write_phase_group
   use pecplas_io_results_anchors, only: write_anchor_fields
   use pecplas_io_results_anchor_geometry, only: xdmf_anchors
   implicit none (type, external)
   private

   public :: results_content_t

   !> The contents of one results file (the same in both of its copies).
   type :: results_content_t
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
      procedure :: plan => content_plan
      procedure :: check => content_check
      procedure :: add_phase => content_add_phase
      procedure :: mark_phase_start
      procedure :: write_pending_phases
      procedure :: write_copy
      procedure :: note_written
      procedure :: sidecar_text
   end type results_content_t

contains

   !> Checks the model, gauss_xy and the joint points (one per joint set) and plans the
   !> layout of the file: nothing written yet.
   subroutine content_plan(this, model, gauss_xy, points, error)
      class(results_content_t), intent(inout) :: this
      type(model_t), intent(in) :: model
      type(gauss_coordinates_t), intent(in) :: gauss_xy(:)
      type(joint_points_t), intent(in) :: points(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      call plan(this, model, gauss_xy, error)
      if (allocated(error)) return
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
   end subroutine content_plan

   !> Refuses non-finite values and wrong shapes of `inc` before anything is written.
   subroutine content_check(this, inc, error)
      class(results_content_t), intent(in) :: this
      type(increment_result_t), intent(in) :: inc
      type(error_t), allocatable, intent(out) :: error
      call check_increment(inc, this%layout, this%ngauss, this%npattern, this%strains, error)
      if (allocated(error)) return
      if (inc%write_fields) &
         call check_joint_fields(inc%joint_fields, this%joints, 'results file: ', error)
   end subroutine content_check

   !> The plate sets as the XDMF sees them (none without plates).
   subroutine plan_xdmf_plates(this, model)
      class(results_content_t), intent(inout) :: this
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
      class(results_content_t), intent(inout) :: this
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
      class(results_content_t), intent(inout) :: this
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

   !> One increment into the copy `file` (not flushed): fields, restart state, history row.
   subroutine write_copy(this, file, inc, error, restart)
      class(results_content_t), intent(in) :: this
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
         call write_restart(file, inc, restart, this%layout, error)
         if (.not. allocated(error)) call swap_restart(file, error)
         if (allocated(error)) return
      end if
      call write_history_row(file, this%nrows + 1, inc, error)
   end subroutine write_copy

   !> Records the increment `inc` just written into both copies (or the final one): a
   !> history row, its fields' grids in the XDMF, the phases pending no more.
   subroutine note_written(this, inc)
      class(results_content_t), intent(inout) :: this
      type(increment_result_t), intent(in) :: inc
      if (inc%write_fields) then
         call note_plates(this, inc)
         call note_anchors(this, inc)
         this%written = [this%written, inc%global_increment]
         this%written_time = [this%written_time, inc%time]
         this%written_phase = [this%written_phase, size(this%phases)]
      end if
      this%phases(:)%pending = .false.
      this%nrows = this%nrows + 1
   end subroutine note_written

   !> Records the start of a phase (see results_file_t%add_phase): checks `rec` against the
   !> layout, replaces a phase still pending, and makes `rec`'s sets the active ones.
   subroutine content_add_phase(this, rec, error)
      class(results_content_t), intent(inout) :: this
      type(phase_record_t), intent(in) :: rec
      type(error_t), allocatable, intent(out) :: error
      integer :: i
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
   end subroutine content_add_phase

   !> The phases still pending start with increment `inc`.
   subroutine mark_phase_start(this, inc)
      class(results_content_t), intent(inout) :: this
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
      class(results_content_t), intent(in) :: this
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
      class(results_content_t), intent(inout) :: this
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
      class(results_content_t), intent(inout) :: this
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
      class(results_content_t), intent(in) :: this
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

end module pecplas_io_results_content
