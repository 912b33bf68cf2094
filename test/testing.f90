!> A small test framework in the test-drive style (pFUnit is not obtainable here).
!> A suite is a `collect_<name>(tests)` routine returning `new_unittest` entries; each test
!> is a subroutine `(error)` that leaves `error` allocated on failure.
module pecplas_testing
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   implicit none (type, external)
   private

   public :: unittest_t, testsuite_t, new_unittest, new_testsuite, run_testsuite
   public :: check, check_close, near, test_ifc, collect_ifc

   abstract interface
      !> One test: leaves `error` allocated when it fails.
      subroutine test_ifc(error)
         import :: error_t
         type(error_t), allocatable, intent(out) :: error
      end subroutine test_ifc
   end interface

   type :: unittest_t
      character(len=:), allocatable :: name
      procedure(test_ifc), pointer, nopass :: run => null()
   end type unittest_t

   abstract interface
      !> Collects the tests of one suite.
      subroutine collect_ifc(tests)
         import :: unittest_t
         type(unittest_t), allocatable, intent(out) :: tests(:)
      end subroutine collect_ifc
   end interface

   type :: testsuite_t
      character(len=:), allocatable :: name
      procedure(collect_ifc), pointer, nopass :: collect => null()
   end type testsuite_t

   interface check
      module procedure check_logical
   end interface check

contains

   !> Equal up to 2 ulp. Values read from deck text and the same decimal literals in a
   !> test are both correctly rounded, so they agree to the last bit; the margin only keeps
   !> the comparison a tolerance comparison.
   elemental logical function near(a, b)
      real(wp), intent(in) :: a, b
      near = abs(a - b) <= 2.0_wp*epsilon(1.0_wp)*abs(b)
   end function near

   function new_unittest(name, run) result(test)
      character(len=*), intent(in) :: name
      procedure(test_ifc) :: run
      type(unittest_t) :: test
      test%name = name
      test%run => run
   end function new_unittest

   function new_testsuite(name, collect) result(suite)
      character(len=*), intent(in) :: name
      procedure(collect_ifc) :: collect
      type(testsuite_t) :: suite
      suite%name = name
      suite%collect => collect
   end function new_testsuite

   !> Fails with `message` unless `condition` holds.
   subroutine check_logical(error, condition, message)
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in) :: condition
      character(len=*), intent(in) :: message
      if (.not. condition) call fatal_error(error, message)
   end subroutine check_logical

   !> Fails unless |actual - expected| <= rtol*|expected| + atol (atol defaults to 0).
   subroutine check_close(error, actual, expected, rtol, message, atol)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in) :: actual, expected, rtol
      character(len=*), intent(in) :: message
      real(wp), intent(in), optional :: atol
      real(wp) :: tol
      character(len=160) :: buf
      tol = rtol*abs(expected)
      if (present(atol)) tol = tol + atol
      if (.not. (abs(actual - expected) <= tol)) then
         write (buf, '(a,es22.14,a,es22.14,a,es9.2)') ' got ', actual, ' expected ', expected, &
            ' tol ', tol
         call fatal_error(error, message//trim(buf))
      end if
   end subroutine check_close

   !> Runs every test of a suite (or only `only` when given); adds failures to `nfail`.
   !> A test name `only` that the suite does not hold counts as a failure and lists the
   !> suite's test names, so a misspelt name cannot pass as "0 passed, 0 failed".
   subroutine run_testsuite(suite, npass, nfail, only)
      type(testsuite_t), intent(in) :: suite
      integer, intent(inout) :: npass, nfail
      character(len=*), intent(in), optional :: only
      type(unittest_t), allocatable :: tests(:)
      type(error_t), allocatable :: error
      integer :: i
      logical :: filtered
      call suite%collect(tests)
      filtered = .false.
      if (present(only)) filtered = len_trim(only) > 0
      if (filtered) then
         if (.not. any([(tests(i)%name == only, i=1, size(tests))])) then
            nfail = nfail + 1
            write (*, '(a)') '  FAIL  '//suite%name//': unknown test '//trim(only)// &
               '; known tests of this suite:'
            do i = 1, size(tests)
               write (*, '(a)') '          '//tests(i)%name
            end do
            return
         end if
      end if
      do i = 1, size(tests)
         if (filtered) then
            if (tests(i)%name /= only) cycle
         end if
         call tests(i)%run(error)
         if (allocated(error)) then
            nfail = nfail + 1
            write (*, '(a)') '  FAIL  '//suite%name//'/'//tests(i)%name//': '//error%text()
         else
            npass = npass + 1
            write (*, '(a)') '  pass  '//suite%name//'/'//tests(i)%name
         end if
      end do
   end subroutine run_testsuite

end module pecplas_testing
