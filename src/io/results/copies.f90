!> The two copies of a running results file, so that `kill -9` at any moment leaves a
!> readable one. HDF5 writes its metadata in place, without a journal: a file is consistent
!> after a flush and may not be while it is written (the library also evicts metadata
!> between flushes). So every increment is written and committed (copies_flush: the file
!> closed and opened again) into one copy, that copy is published, and the increment is then
!> written and committed into the other:
!>
!>     .NAME.h5.<pid>.a, .NAME.h5.<pid>.b   the two copies (HDF5 files, kept open)
!>     .NAME.h5.<pid>.tmp                   another name (a hard link) of the copy published
!>
!> The published copy is never written: `.tmp` names, at every instant, a file flushed after
!> a whole increment, the newest one. Publishing is a link made under a staging name
!> (`.NAME.h5.<pid>.new`) and renamed onto `.tmp`, both atomic; where the file system has
!> no hard links a symbolic link is used. The cost: every increment is written twice, except
!> a run's final one, written into the copy not published only (pecplas_io_results_file).
!> The file's first contents (provenance, mesh) are written once: `clone` gives the other
!> copy the same bytes by a kernel file copy (falling back to writing them again).
module pecplas_io_results_copies
   use, intrinsic :: iso_fortran_env, only: int64
   use hdf5, only: hid_t, h5fcreate_f, h5fclose_f, h5fopen_f, H5F_ACC_TRUNC_F, H5F_ACC_RDWR_F
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_strings, only: itoa
   use pecplas_base_files, only: rename_file, remove_file, link_file, symlink_file, free_bytes
   use pecplas_io_results_kernel_copy, only: kernel_copy
   implicit none (type, external)
   private

   public :: copies_t

   type :: copies_t
      !> HDF5 ids of the copies (-1: closed) and their file names.
      integer(hid_t) :: ids(2) = -1
      character(len=:), allocatable :: names(:)
      !> The published name (.tmp) and the name the link is made under (.new).
      character(len=:), allocatable :: link, staging
      !> The copy written next (1 or 2); the other one is published once `publish` ran.
      integer :: next = 1
      !> False once a publication had to use a symbolic link (no hard links here).
      logical :: hard = .true.
      !> False: `clone` never asks the kernel (tests of the fallback).
      logical :: kernel = .true.
      !> Size of a copy after the last increment and what that increment added.
      integer(int64) :: bytes = 0, growth = 0
   contains
      procedure :: init => copies_init
      procedure :: create => copies_create
      procedure :: id => copies_id
      procedure :: name => copies_name
      procedure :: flush => copies_flush
      procedure :: clone => copies_clone
      procedure :: publish => copies_publish
      procedure :: close => copies_close
      procedure :: remove => copies_remove
      procedure :: check_space => copies_check_space
      procedure :: note_size => copies_note_size
   end type copies_t

contains

   !> Names of the copies for the published name `link` ('.a.h5.12.tmp' ->
   !> '.a.h5.12.a', '.a.h5.12.b', staging '.a.h5.12.new').
   subroutine copies_init(this, link)
      class(copies_t), intent(inout) :: this
      character(len=*), intent(in) :: link
      character(len=:), allocatable :: stem
      stem = link(1:len(link) - 4)
      this%link = link
      this%staging = stem//'.new'
      this%names = [character(len=len(stem) + 2) :: stem//'.a', stem//'.b']
      this%ids = -1
      this%next = 1
      this%hard = .true.
      this%bytes = 0
      this%growth = 0
   end subroutine copies_init

   !> Creates (truncates) copy `i`. A file left under its name by an earlier process of the
   !> same id is unlinked first, not truncated: it may be that run's published results.
   subroutine copies_create(this, i, error)
      class(copies_t), intent(inout) :: this
      integer, intent(in) :: i
      type(error_t), allocatable, intent(out) :: error
      integer :: err
      call remove_file(this%names(i))
      call h5fcreate_f(this%names(i), H5F_ACC_TRUNC_F, this%ids(i), err)
      if (err /= 0) then
         this%ids(i) = -1
         call fatal_error(error, 'cannot create results file '//this%names(i)// &
            ' (does its directory exist and is it writable?)')
      end if
   end subroutine copies_create

   !> HDF5 id of the copy written next (`which` = 'next') or of the published one ('shown').
   integer(hid_t) function copies_id(this, which) result(id)
      class(copies_t), intent(in) :: this
      character(len=*), intent(in) :: which
      id = this%ids(pick(this, which))
   end function copies_id

   !> File name of the copy written next or of the published one.
   function copies_name(this, which) result(name)
      class(copies_t), intent(in) :: this
      character(len=*), intent(in) :: which
      character(len=:), allocatable :: name
      name = this%names(pick(this, which))
   end function copies_name

   integer function pick(this, which)
      class(copies_t), intent(in) :: this
      character(len=*), intent(in) :: which
      pick = this%next
      if (which == 'shown') pick = 3 - this%next
   end function pick

   !> Commits what was written into the copy written next: the file is closed (everything
   !> written, the superblock marked closed) and opened again. A flush would do for the
   !> commit, but HDF5 (1.10) scans every entry of its metadata cache at each flush, and the
   !> cache keeps the metadata of every increment written: flushing after each increment
   !> made the output time grow as the square of the number of increments. A close empties
   !> the cache. The copy is not published at this moment, so no reader holds it.
   subroutine copies_flush(this, error)
      class(copies_t), intent(inout) :: this
      type(error_t), allocatable, intent(out) :: error
      integer :: err, i
      i = this%next
      call h5fclose_f(this%ids(i), err)
      this%ids(i) = -1
      if (err == 0) call h5fopen_f(this%names(i), H5F_ACC_RDWR_F, this%ids(i), err)
      if (err /= 0) then
         if (this%ids(i) > 0) call h5fclose_f(this%ids(i), err)
         this%ids(i) = -1
         call fatal_error(error, 'HDF5: cannot write results file '// &
            this%names(i)//' (disk full?)')
      end if
   end subroutine copies_flush

   !> Commits the copy written next (closed, then opened again, as `flush`) and makes the
   !> other copy a byte copy of it by the kernel (copy_file_range), opened too: both copies
   !> then hold the same committed contents, written by HDF5 once. `cloned` false (the other
   !> copy not made, the copy written next committed and open) when the kernel refuses or
   !> `kernel` is false: the caller then writes the other copy itself.
   subroutine copies_clone(this, cloned, error)
      class(copies_t), intent(inout) :: this
      logical, intent(out) :: cloned
      type(error_t), allocatable, intent(out) :: error
      integer :: err, i, j
      cloned = .false.
      if (.not. this%kernel) then
         call this%flush(error)
         return
      end if
      i = this%next
      j = 3 - i
      call h5fclose_f(this%ids(i), err)
      this%ids(i) = -1
      if (err == 0) then
         ! a file of an earlier process of the same id: unlinked, never written into
         call remove_file(this%names(j))
         cloned = kernel_copy(this%names(i), this%names(j))
         call h5fopen_f(this%names(i), H5F_ACC_RDWR_F, this%ids(i), err)
      end if
      if (err /= 0) then
         this%ids(i) = -1
         call fatal_error(error, 'HDF5: cannot write results file '// &
            this%names(i)//' (disk full?)')
         return
      end if
      if (.not. cloned) return
      call h5fopen_f(this%names(j), H5F_ACC_RDWR_F, this%ids(j), err)
      if (err /= 0) then
         ! a copy HDF5 cannot open is no copy: the caller writes one
         this%ids(j) = -1
         call remove_file(this%names(j))
         cloned = .false.
      end if
   end subroutine copies_clone

   !> Publishes the copy written next (committed by the caller) as `link`, atomically, and
   !> makes the other copy the next one written.
   subroutine copies_publish(this, error)
      class(copies_t), intent(inout) :: this
      type(error_t), allocatable, intent(out) :: error
      call remove_file(this%staging)
      if (this%hard) this%hard = link_file(this%names(this%next), this%staging)
      if (.not. this%hard .and. .not. symlink_file(this%names(this%next), this%staging)) then
         call fatal_error(error, 'cannot link '//this%names(this%next)//' as '// &
            this%staging//' (the results directory must allow hard or symbolic links)')
         return
      end if
      if (.not. rename_file(this%staging, this%link)) then
         call fatal_error(error, 'cannot rename '//this%staging//' onto '//this%link)
         return
      end if
      this%next = 3 - this%next
   end subroutine copies_publish

   !> Closes copy `which` ('next', 'shown' or 'both'); errors ignored, err of the last
   !> close returned.
   subroutine copies_close(this, which, err)
      class(copies_t), intent(inout) :: this
      character(len=*), intent(in) :: which
      integer, intent(out) :: err
      integer :: i
      err = 0
      do i = 1, 2
         if (which /= 'both' .and. i /= pick(this, which)) cycle
         if (this%ids(i) > 0) call h5fclose_f(this%ids(i), err)
         this%ids(i) = -1
      end do
   end subroutine copies_close

   !> Removes the names of the copies (the files stay until closed), the staging name and,
   !> with `link`, the published name. Without `link` the published copy keeps its own
   !> name when `link` is a symbolic link to it.
   subroutine copies_remove(this, link)
      class(copies_t), intent(in) :: this
      logical, intent(in) :: link
      integer :: i
      if (.not. allocated(this%names)) return
      do i = 1, 2
         if (link .or. this%hard .or. i == this%next) call remove_file(this%names(i))
      end do
      call remove_file(this%staging)
      if (link) call remove_file(this%link)
   end subroutine copies_remove

   !> Refuses to start an increment that may not fit on the disk (twice what the last one
   !> took in both copies, plus 64 KiB): HDF5 cut short by a full disk leaves a damaged
   !> last increment (in the copy being written; the published one stays whole).
   subroutine copies_check_space(this, error)
      class(copies_t), intent(in) :: this
      type(error_t), allocatable, intent(out) :: error
      integer(int64) :: free, need
      free = free_bytes(this%link)
      need = 4*this%growth + 65536_int64
      if (free >= 0 .and. free < need) call fatal_error(error, 'disk full: '// &
         itoa(int(free/1024))//' KiB left for '//this%link//', an increment needs about '// &
         itoa(int(need/1024))//' KiB')
   end subroutine copies_check_space

   !> After an increment: the size of the copy written next and what the increment added.
   subroutine copies_note_size(this)
      class(copies_t), intent(inout) :: this
      integer(int64) :: nbytes
      inquire (file=this%name('next'), size=nbytes)
      if (nbytes > 0) then
         this%growth = max(0_int64, nbytes - this%bytes)
         this%bytes = nbytes
      end if
   end subroutine copies_note_size

end module pecplas_io_results_copies
