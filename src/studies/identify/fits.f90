!> The small numerical tools of the identification: least-squares lines (free and through
!> the origin), a smoothed extremum (cubic least squares around the largest sample, so
!> that 1 % noise does not bias a peak upwards), linear interpolation and the least-squares
!> value of a curve at its end.
module pecplas_studies_identify_fits
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: line_fit, origin_fit, smooth_max, interpolate, end_value, origin_slope_upto
   public :: hyperbola_fit

contains

   !> Least-squares y = slope x + intercept (needs two distinct x).
   pure subroutine line_fit(x, y, slope, intercept)
      real(wp), intent(in) :: x(:), y(:)
      real(wp), intent(out) :: slope, intercept
      real(wp) :: xm, ym
      xm = sum(x)/size(x)
      ym = sum(y)/size(y)
      slope = sum((x - xm)*(y - ym))/sum((x - xm)**2)
      intercept = ym - slope*xm
   end subroutine line_fit

   !> Least-squares y = slope x.
   pure real(wp) function origin_fit(x, y) result(slope)
      real(wp), intent(in) :: x(:), y(:)
      slope = sum(x*y)/sum(x*x)
   end function origin_fit

   !> Least-squares slope through the origin of the points with 0 < x <= x_max (the secant
   !> modulus at x_max when the curve is straight there); the first point past x_max is
   !> used alone when none lies in (0, x_max].
   pure real(wp) function origin_slope_upto(x, y, x_max) result(slope)
      real(wp), intent(in) :: x(:), y(:), x_max
      logical :: in(size(x))
      integer :: k
      in = x > 0.0_wp .and. x <= x_max*(1.0_wp + 1.0e-12_wp)
      if (count(in) > 0) then
         slope = sum(pack(x*y, in))/sum(pack(x*x, in))
      else
         k = findloc(x > 0.0_wp, .true., dim=1)
         slope = y(k)/x(k)
      end if
   end function origin_slope_upto

   !> Extremum of y(x) (largest y): a cubic fitted by least squares to the samples within
   !> `window` of the largest sample; the root of its derivative nearest to that sample when
   !> it is a maximum inside the window, else the largest sample itself. A cubic (not a
   !> parabola) so that the asymmetry of a peak does not shift it: without noise the error is
   !> O(window^3) of the curve's fourth derivative; with noise the fit averages it out.
   pure subroutine smooth_max(x, y, window, xm, ym, imax)
      real(wp), intent(in) :: x(:), y(:), window
      real(wp), intent(out) :: xm, ym
      integer, intent(out) :: imax
      real(wp) :: m(4, 4), r(4), c(4), t, v(4), disc, roots(2), curv
      integer :: i, n, j
      logical :: ok
      imax = maxloc(y, dim=1)
      xm = x(imax)
      ym = y(imax)
      m = 0.0_wp
      r = 0.0_wp
      n = 0
      do i = 1, size(x)
         if (abs(x(i) - x(imax)) > window) cycle
         t = (x(i) - x(imax))/window
         v = [1.0_wp, t, t*t, t**3]
         m = m + spread(v, 2, 4)*spread(v, 1, 4)
         r = r + y(i)*v
         n = n + 1
      end do
      if (n < 7) return
      call solve_small(m, r, c, ok)
      if (.not. ok) return
      ! c2 + 2 c3 t + 3 c4 t^2 = 0, the root where 2 c3 + 6 c4 t < 0 nearest to 0
      if (abs(c(4)) <= 1.0e-12_wp*abs(c(3))) then
         if (.not. c(3) < 0.0_wp) return
         roots = -c(2)/(2.0_wp*c(3))
      else
         disc = c(3)**2 - 3.0_wp*c(2)*c(4)
         if (disc < 0.0_wp) return
         roots = [(-c(3) - sqrt(disc))/(3.0_wp*c(4)), (-c(3) + sqrt(disc))/(3.0_wp*c(4))]
      end if
      t = huge(1.0_wp)
      do j = 1, 2
         curv = 2.0_wp*c(3) + 6.0_wp*c(4)*roots(j)
         if (curv < 0.0_wp .and. abs(roots(j)) < abs(t)) t = roots(j)
      end do
      if (abs(t) > 1.0_wp) return
      xm = x(imax) + t*window
      ym = c(1) + c(2)*t + c(3)*t*t + c(4)*t**3
   end subroutine smooth_max

   !> Hyperbola y = t (x + x0) / (x + s) by least squares on its linear form
   !> y x = t x + (t x0) - s y (exact for exact data): the asymptote t, the shift x0 and s.
   !> `ok` is false when the normal equations are singular or t <= 0.
   pure subroutine hyperbola_fit(x, y, t, x0, s, ok)
      real(wp), intent(in) :: x(:), y(:)
      real(wp), intent(out) :: t, x0, s
      logical, intent(out) :: ok
      real(wp) :: m(3, 3), r(3), c(3), v(3), scale
      integer :: i
      t = 0.0_wp
      x0 = 0.0_wp
      s = 0.0_wp
      m = 0.0_wp
      r = 0.0_wp
      scale = maxval(abs(y))
      do i = 1, size(x)
         v = [x(i), 1.0_wp, -y(i)/scale]
         m = m + spread(v, 2, 3)*spread(v, 1, 3)
         r = r + y(i)*x(i)*v
      end do
      call solve_small(m, r, c, ok)
      if (.not. ok) return
      t = c(1)
      ok = t > 0.0_wp
      if (.not. ok) return
      x0 = c(2)/t
      s = c(3)/scale
   end subroutine hyperbola_fit

   !> y at x0 by linear interpolation (x increasing; clamped at the ends).
   pure real(wp) function interpolate(x, y, x0) result(y0)
      real(wp), intent(in) :: x(:), y(:), x0
      integer :: i
      if (x0 <= x(1)) then
         y0 = y(1)
         return
      end if
      do i = 2, size(x)
         if (x(i) >= x0) then
            y0 = y(i - 1) + (y(i) - y(i - 1))*(x0 - x(i - 1))/(x(i) - x(i - 1))
            return
         end if
      end do
      y0 = y(size(y))
   end function interpolate

   !> Value at the last x of the least-squares line through the points of the last
   !> `fraction` of the x range (the "limit" value of a curve, robust to noise).
   pure real(wp) function end_value(x, y, fraction) result(v)
      real(wp), intent(in) :: x(:), y(:), fraction
      logical :: in(size(x))
      real(wp) :: slope, intercept, x_end
      x_end = x(size(x))
      in = x >= x_end - fraction*(x_end - x(1))
      if (count(in) < 3) then
         v = y(size(y))
         return
      end if
      call line_fit(pack(x, in), pack(y, in), slope, intercept)
      v = slope*x_end + intercept
   end function end_value

   !> Gaussian elimination with partial pivoting (normal equations of a cubic, well scaled
   !> because the abscissae are centred on the extremum and divided by the window).
   pure subroutine solve_small(m, r, c, ok)
      real(wp), intent(in) :: m(:, :), r(:)
      real(wp), intent(out) :: c(:)
      logical, intent(out) :: ok
      real(wp) :: a(size(r), size(r) + 1), row(size(r) + 1)
      integer :: i, k, p, n
      n = size(r)
      a(:, 1:n) = m
      a(:, n + 1) = r
      ok = .false.
      c = 0.0_wp
      do k = 1, n
         p = k - 1 + maxloc(abs(a(k:n, k)), dim=1)
         if (.not. abs(a(p, k)) > 1.0e-14_wp*maxval(abs(m))) return
         row = a(k, :)
         a(k, :) = a(p, :)
         a(p, :) = row
         do i = k + 1, n
            a(i, k:) = a(i, k:) - a(i, k)/a(k, k)*a(k, k:)
         end do
      end do
      do k = n, 1, -1
         c(k) = (a(k, n + 1) - sum(a(k, k + 1:n)*c(k + 1:n)))/a(k, k)
      end do
      ok = .true.
   end subroutine solve_small

end module pecplas_studies_identify_fits
