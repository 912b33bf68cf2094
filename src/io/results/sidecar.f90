!> The XDMF sidecar of a results file while the run goes on (pecplas_io_results_file):
!> the running sidecar (`.NAME.xmf.<pid>.tmp`, naming the published copy) is rewritten
!> whole through a staging file and a rename, at most every XMF_PERIOD seconds and when
!> its last write took at most 1/XMF_SHARE of the time since (its cost stays linear in the
!> number of increments), and at the end; the final sidecar (naming the target) is staged
!> and renamed onto NAME.xmf by `finish`.
module pecplas_io_results_sidecar
   use, intrinsic :: iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_files, only: rename_file, remove_file
   use pecplas_io_results_xdmf, only: write_xdmf
   use pecplas_io_results_content, only: results_content_t
   implicit none (type, external)
   private

   public :: sidecar_t

   !> The running sidecar is rewritten at most every XMF_PERIOD seconds and when its last
   !> write took at most 1/XMF_SHARE of the time since.
   real(wp), parameter :: XMF_PERIOD = 1.0_wp, XMF_SHARE = 20.0_wp

   !> The sidecar files of one results file.
   type :: sidecar_t
      !> The target .xmf, the running one, and the staging name through which every .xmf
      !> is written.
      character(len=:), allocatable :: path, work, staging
      !> Fields groups listed in the running .xmf; time of its last write and its cost [s].
      integer :: count = -1
      real(wp) :: at = 0.0_wp, cost = 0.0_wp
   contains
      procedure :: init => sidecar_init
      procedure :: commit => sidecar_commit
      procedure :: write_running
      procedure :: behind => sidecar_behind
      procedure :: finish => sidecar_finish
      procedure :: remove => sidecar_remove
   end type sidecar_t

contains

   !> The sidecar `path` of a new file, running as `work` (nothing listed yet).
   subroutine sidecar_init(this, path, work)
      class(sidecar_t), intent(inout) :: this
      character(len=*), intent(in) :: path, work
      this%path = path
      this%work = work
      this%staging = work(1:len(work) - 4)//'.new'
      this%count = -1
   end subroutine sidecar_init

   !> After an increment is in both copies: rewrites the running XDMF (naming the copy
   !> `h5_name`) when it lacks increments and `force` or its period has passed.
   subroutine sidecar_commit(this, content, h5_name, force, error)
      class(sidecar_t), intent(inout) :: this
      type(results_content_t), intent(in) :: content
      character(len=*), intent(in) :: h5_name
      logical, intent(in) :: force
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: since
      if (this%count == size(content%written)) return
      since = clock() - this%at
      if (force .or. since >= max(XMF_PERIOD, XMF_SHARE*this%cost)) &
         call this%write_running(content, h5_name, error)
   end subroutine sidecar_commit

   !> The running XDMF, naming the temporary file `h5_name`, through the staging file and a
   !> rename.
   subroutine write_running(this, content, h5_name, error)
      class(sidecar_t), intent(inout) :: this
      type(results_content_t), intent(in) :: content
      character(len=*), intent(in) :: h5_name
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: t0
      t0 = clock()
      call write_xdmf(this%work, this%staging, content%sidecar_text(h5_name), error)
      if (allocated(error)) return
      this%count = size(content%written)
      this%at = clock()
      this%cost = this%at - t0
   end subroutine write_running

   !> True when the running sidecar lacks increments of `content`.
   pure logical function sidecar_behind(this, content)
      class(sidecar_t), intent(in) :: this
      type(results_content_t), intent(in) :: content
      sidecar_behind = this%count /= size(content%written)
   end function sidecar_behind

   !> The final sidecar, naming the target `h5_name`: `stage` writes it as the staging
   !> file; then (stage false) renames it onto the target .xmf.
   subroutine sidecar_finish(this, content, h5_name, stage, error)
      class(sidecar_t), intent(inout) :: this
      type(results_content_t), intent(in) :: content
      character(len=*), intent(in) :: h5_name
      logical, intent(in) :: stage
      type(error_t), allocatable, intent(out) :: error
      if (stage) then
         call write_xdmf(this%staging, '', content%sidecar_text(h5_name), error)
      else if (.not. rename_file(this%staging, this%path)) then
         call fatal_error(error, 'cannot rename '//this%staging//' onto '//this%path)
      end if
   end subroutine sidecar_finish

   !> Removes the running sidecar, and the staging file when `staging`.
   subroutine sidecar_remove(this, staging)
      class(sidecar_t), intent(inout) :: this
      logical, intent(in) :: staging
      if (allocated(this%work)) call remove_file(this%work)
      if (staging .and. allocated(this%staging)) call remove_file(this%staging)
   end subroutine sidecar_remove

   !> Wall-clock seconds (monotonic).
   real(wp) function clock()
      integer(int64) :: count, rate
      call system_clock(count, rate)
      clock = real(count, wp)/real(max(rate, 1_int64), wp)
   end function clock

end module pecplas_io_results_sidecar
