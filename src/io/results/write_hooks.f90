!> Test hooks of the results file (pecplas_io_results_file), read from the environment:
!> PECPLAS_TEST_FAIL_WRITE=N makes the N-th write (an increment, or the warnings found at
!> the end of the run) and every later write fail as a full disk would;
!> PECPLAS_TEST_NO_KERNEL_COPY=1 has the second copy of a new file written by HDF5 rather
!> than copied by the kernel, as where the kernel refuses.
module pecplas_io_results_write_hooks
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private

   public :: write_hook_t, test_no_kernel_copy

   !> The writes counted so far and the one from which they fail (0: never).
   type :: write_hook_t
      integer :: fail_at = 0, nwrite = 0
   contains
      procedure :: init => hook_init
      procedure :: count => hook_count
      procedure :: check => hook_check
   end type write_hook_t

contains

   !> No write counted yet; fail_at from PECPLAS_TEST_FAIL_WRITE.
   subroutine hook_init(this)
      class(write_hook_t), intent(inout) :: this
      this%nwrite = 0
      this%fail_at = test_fail_at()
   end subroutine hook_init

   !> Counts one write (an increment, or the warnings at the end of the run) and fails it
   !> when the test hook says so.
   subroutine hook_count(this, work, error)
      class(write_hook_t), intent(inout) :: this
      character(len=*), intent(in) :: work
      type(error_t), allocatable, intent(out) :: error
      this%nwrite = this%nwrite + 1
      call this%check(work, error)
   end subroutine hook_count

   !> PECPLAS_TEST_FAIL_WRITE: the fail_at-th write and every later one fail (`work`: the
   !> file named in the error).
   subroutine hook_check(this, work, error)
      class(write_hook_t), intent(in) :: this
      character(len=*), intent(in) :: work
      type(error_t), allocatable, intent(out) :: error
      if (this%fail_at > 0 .and. this%nwrite >= this%fail_at) call fatal_error(error, &
         'HDF5: cannot write results file '//work//' (write '//itoa(this%nwrite)// &
         ' failed on purpose: PECPLAS_TEST_FAIL_WRITE='//itoa(this%fail_at)//')')
   end subroutine hook_check

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

end module pecplas_io_results_write_hooks
