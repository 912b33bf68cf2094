!> The second copy of a new results file made by the kernel (copies_t%clone, a
!> copy_file_range through pecplas_io_results_kernel_copy) and its fallback: the copy is
!> byte for byte the first and opens as an HDF5 file; where the kernel refuses, nothing is
!> left under the copy's name and the caller writes it.
module test_io_results_copies
   use, intrinsic :: iso_fortran_env, only: int8
   use pecplas_base_run_status, only: RUN_COMPLETED
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use pecplas_model_type, only: model_t
   use pecplas_io_results_h5, only: h5_init, h5_write, h5_attr
   use pecplas_io_results_copies, only: copies_t
   use pecplas_io_results_kernel_copy, only: kernel_copy
   use pecplas_io_results_file, only: results_file_t
   use pecplas_io_results_increment, only: increment_result_t
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_base_files, only: remove_file
   use test_io_results_data, only: sample_model, sample_gauss, sample_increment, &
      same_bits, OUT_DIR, make_out_dir
   implicit none (type, external)
   private
   public :: collect_io_results_copies

contains

   subroutine collect_io_results_copies(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('clone_same_bytes', test_clone_same_bytes), &
               new_unittest('clone_refused', test_clone_refused), &
               new_unittest('kernel_copy_refusals', test_kernel_copy_refusals), &
               new_unittest('cloned_copy_finished', test_cloned_copy_finished)]
   end subroutine collect_io_results_copies

   !> Copy 1 gets a dataset and an attribute and is cloned: both copies open, and once
   !> closed their bytes are identical (a byte copy of a committed file); the clone opens
   !> as an HDF5 file and reads back the dataset bit for bit.
   subroutine test_clone_same_bytes(error)
      type(error_t), allocatable, intent(out) :: error
      type(copies_t) :: cp
      type(results_reader_t) :: rd
      integer(int8), allocatable :: a(:), b(:)
      real(wp), allocatable :: x(:, :)
      logical :: cloned
      integer :: err
      call start(cp, 'io_results_clone', error)
      if (allocated(error)) return
      call cp%clone(cloned, error)
      if (allocated(error)) return
      call check(error, cloned, 'the kernel copies a file of a local file system')
      if (allocated(error)) return
      call check(error, all(cp%ids > 0), 'both copies open after the clone')
      if (allocated(error)) return
      call cp%close('both', err)
      a = bytes_of(cp%names(1))
      b = bytes_of(cp%names(2))
      call check(error, size(a) > 0 .and. size(a) == size(b), 'the copies have the same size')
      if (allocated(error)) return
      call check(error, all(a == b), 'the copies are byte for byte the same')
      if (allocated(error)) return
      call rd%open(cp%names(2), error)
      if (allocated(error)) return
      call rd%dataset('/x', x, error)
      if (allocated(error)) return
      call check(error, same_bits(x, coordinates()), 'the copy reads back the values written')
      call rd%close()
      call cp%remove(.true.)
   end subroutine test_clone_same_bytes

   !> `kernel` false (what PECPLAS_TEST_NO_KERNEL_COPY=1 gives a results file): no clone,
   !> copy 1 committed and open, nothing under copy 2's name; the caller then creates it.
   subroutine test_clone_refused(error)
      type(error_t), allocatable, intent(out) :: error
      type(copies_t) :: cp
      logical :: cloned, exists
      integer :: err
      call start(cp, 'io_results_noclone', error)
      if (allocated(error)) return
      cp%kernel = .false.
      call cp%clone(cloned, error)
      if (allocated(error)) return
      call check(error, .not. cloned, 'no clone when the kernel copy is off')
      if (allocated(error)) return
      inquire (file=cp%names(2), exist=exists)
      call check(error, cp%ids(1) > 0 .and. cp%ids(2) < 0 .and. .not. exists, &
         'copy 1 open, copy 2 not made')
      if (allocated(error)) return
      call cp%create(2, error)
      if (allocated(error)) return
      call check(error, cp%ids(2) > 0, 'the caller creates copy 2 itself')
      call cp%close('both', err)
      call cp%remove(.true.)
   end subroutine test_clone_refused

   !> kernel_copy refuses a missing source (no target left) and an existing target (left
   !> as it was: the O_EXCL open fails before anything is written).
   subroutine test_kernel_copy_refusals(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: SRC = OUT_DIR//'/io_results_kcopy.src', &
         DST = OUT_DIR//'/io_results_kcopy.dst'
      integer(int8), allocatable :: before(:)
      logical :: exists
      integer :: u
      call make_out_dir(error)
      if (allocated(error)) return
      call remove_file(SRC)
      call remove_file(DST)
      call check(error, .not. kernel_copy(SRC, DST), 'a missing source is refused')
      if (allocated(error)) return
      inquire (file=DST, exist=exists)
      call check(error, .not. exists, 'a refused copy leaves no target')
      if (allocated(error)) return
      open (newunit=u, file=SRC, access='stream', form='unformatted', status='replace')
      write (u) 'source bytes'
      close (u)
      open (newunit=u, file=DST, access='stream', form='unformatted', status='replace')
      write (u) 'kept'
      close (u)
      before = bytes_of(DST)
      call check(error, .not. kernel_copy(SRC, DST), 'an existing target is refused')
      if (allocated(error)) return
      call check(error, size(bytes_of(DST)) == size(before), 'the existing target is kept')
      if (allocated(error)) return
      call check(error, all(bytes_of(DST) == before), 'the existing target is unchanged')
      call remove_file(SRC)
      call remove_file(DST)
   end subroutine test_kernel_copy_refusals

   !> A one-increment run whose final increment goes into the cloned copy: the finished
   !> file reads back the mesh coordinates and the increment bit for bit.
   subroutine test_cloned_copy_finished(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: rf
      type(results_reader_t) :: rd
      type(model_t) :: model
      type(increment_result_t) :: inc
      real(wp), allocatable :: x(:, :), u(:, :)
      character(len=*), parameter :: TARGET = OUT_DIR//'/io_results_cloned.h5'
      character(len=:), allocatable :: status
      call make_out_dir(error)
      if (allocated(error)) return
      model = sample_model()
      call rf%create(TARGET, model, '0.1.0-test', sample_gauss(), error)
      if (allocated(error)) return
      call rf%write_increment(sample_increment(1), error, final=.true.)
      if (allocated(error)) return
      call rf%finish(RUN_COMPLETED, 'normal end', error)
      if (allocated(error)) return
      call rd%open(TARGET, error)
      if (allocated(error)) return
      call rd%attribute('/', 'status', status, error)
      if (allocated(error)) return
      call check(error, status == 'completed', 'status of the finished clone: '//status)
      if (allocated(error)) return
      call rd%dataset('/mesh/coordinates', x, error)
      if (allocated(error)) return
      call check(error, same_bits(x, model%mesh%x), 'mesh coordinates as written')
      if (allocated(error)) return
      call rd%displacement(1, u, error)
      if (allocated(error)) return
      inc = sample_increment(1)
      call check(error, same_bits(u, inc%displacement), 'the final increment in the cloned copy')
      call rd%close()
      call remove_file(TARGET)
      call remove_file(OUT_DIR//'/io_results_cloned.xmf')
   end subroutine test_cloned_copy_finished

   !> Names the copies after OUT_DIR/.NAME.h5.1.tmp, creates copy 1 and writes a dataset
   !> /x and a root attribute into it.
   subroutine start(cp, name, error)
      type(copies_t), intent(inout) :: cp
      character(len=*), intent(in) :: name
      type(error_t), allocatable, intent(out) :: error
      call make_out_dir(error)
      if (allocated(error)) return
      call h5_init(error)
      if (allocated(error)) return
      call cp%init(OUT_DIR//'/.'//name//'.h5.1.tmp')
      call cp%remove(.true.)
      call cp%create(1, error)
      if (allocated(error)) return
      call h5_write(cp%ids(1), 'x', coordinates(), error)
      if (.not. allocated(error)) call h5_attr(cp%ids(1), 'status', 'running', error)
   end subroutine start

   pure function coordinates() result(x)
      real(wp) :: x(2, 3)
      x = reshape([0.0_wp, 0.0_wp, 1.5_wp, -2.0_wp, 1.0e300_wp, 3.25_wp], [2, 3])
   end function coordinates

   !> The bytes of file `path` (none when it cannot be read).
   function bytes_of(path) result(bytes)
      character(len=*), intent(in) :: path
      integer(int8), allocatable :: bytes(:)
      integer :: u, ios, n
      allocate (bytes(0))
      open (newunit=u, file=path, access='stream', form='unformatted', action='read', &
         status='old', iostat=ios)
      if (ios /= 0) return
      inquire (unit=u, size=n)
      deallocate (bytes)
      allocate (bytes(max(n, 0)))
      read (u, iostat=ios) bytes
      close (u)
      if (ios /= 0) deallocate (bytes)
      if (ios /= 0) allocate (bytes(0))
   end function bytes_of

end module test_io_results_copies
