!> Checks of a finished run that do not change its status but must reach the user.
module pecplas_solve_sanity
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: large_displacement_warning, LARGE_DISPLACEMENT_RATIO

   !> Warn when max |u| exceeds this fraction of the model size. Small-strain theory takes
   !> equilibrium in the undeformed geometry and strains and rotations << 1; a displacement
   !> of 10 % of the size means that the geometry (lever arms, areas) has changed by about
   !> that much, so the answer is off by the same order even where it converged.
   real(wp), parameter :: LARGE_DISPLACEMENT_RATIO = 0.1_wp

contains

   !> One-line warning when the largest nodal displacement of u(2, nnode) exceeds
   !> LARGE_DISPLACEMENT_RATIO times the model size (diagonal of the bounding box of the node
   !> coordinates x(2, nnode)); '' when it does not, or when there is nothing to measure.
   pure function large_displacement_warning(x, u) result(text)
      real(wp), intent(in) :: x(:, :), u(:, :)
      character(len=:), allocatable :: text
      real(wp) :: extent, umax
      character(len=32) :: a, b, c
      text = ''
      if (size(x, 2) == 0 .or. size(u, 2) == 0) return
      extent = norm2(maxval(x, dim=2) - minval(x, dim=2))
      umax = maxval(norm2(u, dim=1))
      if (.not. (extent > 0.0_wp) .or. .not. (umax > LARGE_DISPLACEMENT_RATIO*extent)) return
      write (a, '(es10.3)') umax
      if (umax/extent < 1.0e6_wp) then
         write (b, '(f12.2)') umax/extent
      else
         write (b, '(es10.2)') umax/extent
      end if
      write (c, '(es10.3)') extent
      text = 'max displacement '//trim(adjustl(a))//' is '//trim(adjustl(b))// &
         ' times the model size ('//trim(adjustl(c))//', bounding-box diagonal; warning above '// &
         '0.1): small-strain theory no longer holds'
   end function large_displacement_warning

end module pecplas_solve_sanity
