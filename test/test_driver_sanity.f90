!> The large-displacement warning: silent at and below 0.1 times the model size (bounding-box
!> diagonal), one line above it naming the displacement, the ratio and the reason.
module test_driver_sanity
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_solve_sanity, only: large_displacement_warning, LARGE_DISPLACEMENT_RATIO
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_driver_sanity

   !> Nodes of a 3 x 4 rectangle offset from the origin: size 5 (the diagonal).
   real(wp), parameter :: X(2, 4) = reshape([10.0_wp, 20.0_wp, 13.0_wp, 20.0_wp, 13.0_wp, &
                                             24.0_wp, 10.0_wp, 24.0_wp], [2, 4])

contains

   subroutine collect_driver_sanity(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('small_displacements_silent', test_silent), &
               new_unittest('large_displacements_warn', test_warn), &
               new_unittest('degenerate_input_silent', test_degenerate)]
   end subroutine collect_driver_sanity

   !> max |u| = 0.5 = exactly 0.1 x 5 (the threshold itself is still fine), and u = 0.
   subroutine test_silent(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: u(2, 4)
      u = 0.0_wp
      u(:, 3) = [0.3_wp, -0.4_wp]
      call check(error, LARGE_DISPLACEMENT_RATIO == 0.1_wp .and. &
         len(large_displacement_warning(X, u)) == 0, 'no warning at |u| = 0.1 x size')
      if (allocated(error)) return
      call check(error, len(large_displacement_warning(X, 0.0_wp*u)) == 0, 'no warning at u = 0')
   end subroutine test_silent

   !> max |u| = 650 on a size-5 model: 130 times the size, stated in the text.
   subroutine test_warn(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: u(2, 4)
      character(len=:), allocatable :: w
      u = 1.0e-3_wp
      u(:, 2) = [-250.0_wp, 600.0_wp]
      w = large_displacement_warning(X, u)
      write (*, '(a)') '        '//w
      call check(error, index(w, 'max displacement 6.500E+02 is 130.00 times the model size') == 1 &
         .and. index(w, 'small-strain theory no longer holds') > 0 .and. &
         index(w, new_line('a')) == 0, 'warning text: "'//w//'"')
      if (allocated(error)) return
      u(:, 2) = [0.0_wp, 0.51_wp]
      call check(error, len(large_displacement_warning(X, u)) > 0, 'warning just above 0.1 x size')
   end subroutine test_warn

   !> No nodes, or all nodes at one point (size 0): nothing to compare, no warning.
   subroutine test_degenerate(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: x0(2, 0), u0(2, 0), xp(2, 2), up(2, 2)
      xp = 1.0_wp
      up = 5.0_wp
      call check(error, len(large_displacement_warning(x0, u0)) == 0 .and. &
         len(large_displacement_warning(xp, up)) == 0, 'degenerate models give no warning')
   end subroutine test_degenerate

end module test_driver_sanity
