!> A load per unit length of a curved 3-node plate element (doc/theory.md, §12 Plates):
!> f_k = q ∫ N_k(xi) s(xi) |dx/dxi| w(xi) dxi over [-1, 1], with w the thickness or 2 pi r and
!> s an optional nodal scale. On a parabola |dx/dxi| = sqrt(Q(xi)), Q a quadratic with complex
!> roots, is no polynomial, so no Gauss rule is exact; the integrand is analytic inside the
!> Bernstein ellipse through those roots, and the n-point Gauss error on a part [c - h, c + h]
!> is at most h (64/15) M rho^(-2n) / (rho^2 - 1), M a bound of the integrand on the ellipse
!> (Trefethen, Approximation Theory and Approximation Practice, 2013, Thm 19.3). Here the
!> bound decides: the element's own 3-point rule where that bound is below TOL of the load's
!> scale, else the 8-point rule on 2^j equal parts, j the smallest whose bound is below it.
module pecplas_structures_beam_arc
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: arc_three_points_exact, arc_line_load, ARC_TOL

   !> Target of the quadrature bound, relative to |q| times the chord times the largest
   !> thickness (or 2 pi r) and scale along the element.
   real(wp), parameter :: ARC_TOL = 1.0e-15_wp
   real(wp), parameter :: PI = acos(-1.0_wp)
   !> Largest ellipse parameter used (nearly straight elements: the roots of Q are far).
   real(wp), parameter :: RHO_MAX = 1.0e6_wp
   !> The parts are halved at most this many times (2^12 parts: a mid node almost at an end).
   integer, parameter :: MAX_HALVINGS = 12
   !> 8-point Gauss-Legendre rule on [-1, 1] (nodes and weights, the positive half).
   real(wp), parameter :: X8(4) = [0.1834346424956498049394761_wp, &
      0.5255324099163289858177390_wp, 0.7966664774136267395915539_wp, &
      0.9602898564975362316835609_wp]
   real(wp), parameter :: W8(4) = [0.3626837833783619829651504_wp, &
      0.3137066458778872873379622_wp, 0.2223810344533744705443560_wp, &
      0.1012285362903762591525314_wp]

contains

   !> Whether the 3-point Gauss rule integrates the load of the 3-node element x(2, 3) (axisym:
   !> w = 2 pi r; scale: optional nodal factors) to within ARC_TOL of its scale: always on a
   !> straight element (|dx/dxi| is then linear), else where the bound above allows it.
   pure logical function arc_three_points_exact(x, axisym, scale) result(exact)
      real(wp), intent(in) :: x(:, :)
      logical, intent(in) :: axisym
      real(wp), intent(in), optional :: scale(:)
      real(wp) :: d0(2), d1(2)
      d0 = 0.5_wp*(x(:, 2) - x(:, 1))
      d1 = x(:, 1) + x(:, 2) - 2.0_wp*x(:, 3)
      exact = d0(1)*d1(2) - d0(2)*d1(1) == 0.0_wp
      if (exact) return
      exact = part_bound(x, axisym, 3, 0.0_wp, 1.0_wp, scale) <= &
         ARC_TOL*load_scale(x, axisym, scale)
   end function arc_three_points_exact

   !> fe(9) (f_x, f_y, 0 per node) of the load q per unit length of the 3-node element x(2, 3)
   !> (per unit area of the shell in axisymmetry), times the interpolation of `scale` if
   !> given, by the 8-point rule on 2^j equal parts with the bound below ARC_TOL of the
   !> load's scale (2^MAX_HALVINGS parts at most).
   pure subroutine arc_line_load(x, axisym, thickness, q, fe, scale)
      real(wp), intent(in) :: x(:, :), q(2), thickness
      logical, intent(in) :: axisym
      real(wp), intent(out) :: fe(:)
      real(wp), intent(in), optional :: scale(:)
      real(wp) :: target, bound, h, c, xi, nf(3), dxd(2), f
      integer :: j, m, i, g, k, sgn
      target = ARC_TOL*load_scale(x, axisym, scale)
      m = 1
      do j = 0, MAX_HALVINGS
         m = 2**j
         h = 1.0_wp/real(m, wp)
         bound = 0.0_wp
         do i = 1, m
            c = -1.0_wp + (2*i - 1)*h
            bound = bound + part_bound(x, axisym, 8, c, h, scale)
         end do
         if (bound <= target) exit
      end do
      fe = 0.0_wp
      h = 1.0_wp/real(m, wp)
      do i = 1, m
         c = -1.0_wp + (2*i - 1)*h
         do g = 1, 4
            do sgn = -1, 1, 2
               xi = c + real(sgn, wp)*X8(g)*h
               nf = [0.5_wp*xi*(xi - 1.0_wp), 0.5_wp*xi*(xi + 1.0_wp), 1.0_wp - xi**2]
               dxd = 0.5_wp*(x(:, 2) - x(:, 1)) + xi*(x(:, 1) + x(:, 2) - 2.0_wp*x(:, 3))
               f = W8(g)*h*norm2(dxd)
               if (axisym) then
                  f = f*2.0_wp*PI*dot_product(nf, x(1, 1:3))
               else
                  f = f*thickness
               end if
               if (present(scale)) f = f*dot_product(nf, scale(1:3))
               do k = 1, 3
                  fe(3*k - 2:3*k - 1) = fe(3*k - 2:3*k - 1) + f*nf(k)*q
                  fe(3*k) = 0.0_wp
               end do
            end do
         end do
      end do
   end subroutine arc_line_load

   !> |q| = 1 times the chord times the largest thickness (2 pi |r| at a node) and |scale|:
   !> the size of the load the bound is measured against.
   pure real(wp) function load_scale(x, axisym, scale) result(v)
      real(wp), intent(in) :: x(:, :)
      logical, intent(in) :: axisym
      real(wp), intent(in), optional :: scale(:)
      v = norm2(x(:, 2) - x(:, 1))
      if (axisym) v = v*2.0_wp*PI*maxval(abs(x(1, 1:3)))
      if (present(scale)) v = v*maxval(abs(scale(1:3)))
   end function load_scale

   !> The bound h (64/15) M rho^(-2n) / (rho^2 - 1) of the n-point Gauss error on the part
   !> [c - h, c + h] of [-1, 1] for every f_k / |q| (in plane strain without the thickness,
   !> a common factor of the error and of load_scale). rho: the ellipse through the roots of
   !> Q (at most RHO_MAX: a smaller ellipse is a valid one too, and it keeps M finite); M: on
   !> it |xi| <= |c| + h (rho + 1/rho)/2 = R,
   !> |N_k| <= 1 + R + R^2, |dx/dxi| <= |d0| + |d1| R, |r| and |s| at most sum_k |N_k| |.|.
   pure real(wp) function part_bound(x, axisym, n, c, h, scale) result(b)
      real(wp), intent(in) :: x(:, :), c, h
      logical, intent(in) :: axisym
      integer, intent(in) :: n
      real(wp), intent(in), optional :: scale(:)
      real(wp) :: d0(2), d1(2), a2, al, be, rho, r, nb, m
      complex(wp) :: z, w
      d0 = 0.5_wp*(x(:, 2) - x(:, 1))
      d1 = x(:, 1) + x(:, 2) - 2.0_wp*x(:, 3)
      a2 = dot_product(d1, d1)
      if (a2 == 0.0_wp) then
         b = 0.0_wp
         return
      end if
      al = -dot_product(d0, d1)/a2
      be = abs(d0(1)*d1(2) - d0(2)*d1(1))/a2
      z = cmplx((al - c)/h, be/h, kind=wp)
      if (abs(z) > RHO_MAX) then
         rho = RHO_MAX
      else
         w = sqrt(z - 1.0_wp)*sqrt(z + 1.0_wp)
         rho = min(max(abs(z + w), abs(z - w)), RHO_MAX)
      end if
      if (.not. rho > 1.0_wp) then
         b = huge(1.0_wp)
         return
      end if
      r = abs(c) + h*0.5_wp*(rho + 1.0_wp/rho)
      nb = 1.0_wp + r + r*r
      m = nb*(norm2(d0) + sqrt(a2)*r)
      if (axisym) m = m*2.0_wp*PI*nb*sum(abs(x(1, 1:3)))
      if (present(scale)) m = m*nb*sum(abs(scale(1:3)))
      b = h*(64.0_wp/15.0_wp)*m*rho**(-2*n)/(rho*rho - 1.0_wp)
   end function part_bound

end module pecplas_structures_beam_arc
