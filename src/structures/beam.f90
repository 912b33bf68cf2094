!> Plate (beam) elements: shear-deformable (Timoshenko) beams with nodal dofs (u_x, u_y,
!> theta), 2-node and 3-node, in plane strain (per unit width) and in axisymmetry (a conical
!> shell of revolution: hoop strain u_r / r and hoop curvature theta t_r / r). The element
!> gives its integration points: the generalized strains e = B U, e = (eps_s, gamma, kappa_s,
!> eps_theta, kappa_theta), and the point's share of the length (times the thickness, or
!> 2 pi r), so that K = sum w B^T C B and f = sum w B^T s (theory.md, plates).
!>
!> Shear locking: the 2-node element uses linked (interdependent) interpolation — w cubic
!> and theta quadratic, the homogeneous solutions of the Timoshenko beam for its section
!> (Reddy's IIE) — so its shear strain is constant and vanishes with the shear flexibility;
!> its nodal values are exact for point loads and, with its consistent load vector, for
!> distributed loads (plane strain). Points: 3-point Lobatto (the ends and the middle; exact
!> for the linear curvature, and a plastic hinge forms at a node) in plane strain, 3-point
!> Gauss in axisymmetry (no point on the axis). The 3-node element interpolates u and theta
!> quadratically (isoparametric, curved sides allowed) and integrates every term with
!> 2 Gauss points (uniform reduced integration: no locking, no spurious mode).
module pecplas_structures_beam
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_plates, only: plate_section_t
   use pecplas_structures_beam_arc, only: arc_three_points_exact, arc_line_load
   implicit none (type, external)
   private

   public :: NGEN, MAX_BEAM_DOFS, beam_point_t, beam_npoint, beam_points, beam_line_load
   public :: beam_part_load, beam_curved_pressure, beam_on_chord
   public :: beam_frame, shear_stiffness

   !> Generalized strains per point: eps_s, gamma, kappa_s, eps_theta, kappa_theta.
   integer, parameter :: NGEN = 5
   !> Dofs of the largest element (3 nodes x 3).
   integer, parameter :: MAX_BEAM_DOFS = 9
   real(wp), parameter :: PI = acos(-1.0_wp)

   !> One integration point: B (NGEN, 3 nen), its weight (length x thickness or 2 pi r),
   !> and its position along the element (0 at node 1, 1 at node 2).
   type :: beam_point_t
      real(wp) :: b(NGEN, MAX_BEAM_DOFS) = 0.0_wp
      real(wp) :: weight = 0.0_wp
      real(wp) :: at = 0.0_wp
   end type beam_point_t

contains

   !> Integration points of an element of nen nodes.
   pure integer function beam_npoint(nen) result(n)
      integer, intent(in) :: nen
      n = merge(3, 2, nen == 2)
   end function beam_npoint

   !> Shear stiffness per unit width: 5/6 of G t with G = E / (2 (1 + nu)) and the equivalent
   !> thickness t = sqrt(12 EI / EA) of a rectangular section: 5 EA / (12 (1 + nu)).
   pure real(wp) function shear_stiffness(section) result(gas)
      type(plate_section_t), intent(in) :: section
      gas = 5.0_wp*section%ea/(12.0_wp*(1.0_wp + section%nu))
   end function shear_stiffness

   !> Length and unit tangent of the chord node 1 -> node 2 (normal n = (-t_y, t_x)).
   pure subroutine beam_frame(x, h, t)
      real(wp), intent(in) :: x(:, :)
      real(wp), intent(out) :: h, t(2)
      h = norm2(x(:, 2) - x(:, 1))
      t = (x(:, 2) - x(:, 1))/h
   end subroutine beam_frame

   !> The frame of the linked-interpolation 2-node element: chord length h, tangent t,
   !> normal n = (-t_y, t_x), the ratio om of bending to shear stiffness
   !> (EI/(1 - nu^2)/GA_s) and the local-to-global map g.
   pure subroutine linked_frame(x, section, h, t, n, om, g)
      real(wp), intent(in) :: x(:, :)
      type(plate_section_t), intent(in) :: section
      real(wp), intent(out) :: h, t(2), n(2), om, g(4, 6)
      call beam_frame(x, h, t)
      n = [-t(2), t(1)]
      om = section%ei/(1.0_wp - section%nu**2)/shear_stiffness(section)
      g = local_to_global(n)
   end subroutine linked_frame

   !> The integration points of the element with nodes x(2, nen). `axisym`: 2 pi r weights
   !> and hoop rows; else `thickness` (out of plane) weights and zero hoop rows.
   subroutine beam_points(x, section, axisym, thickness, pts, error)
      real(wp), intent(in) :: x(:, :)
      type(plate_section_t), intent(in) :: section
      logical, intent(in) :: axisym
      real(wp), intent(in) :: thickness
      type(beam_point_t), intent(out) :: pts(:)
      type(error_t), allocatable, intent(out) :: error
      if (size(x, 2) == 2) then
         call linked_points(x, section, axisym, thickness, pts, error)
      else
         call quadratic_points(x, axisym, thickness, pts, error)
      end if
   end subroutine beam_points

   !> Shape of the linked 2-node element at s in [0, h]: the rows of w(s), theta(s),
   !> kappa(s) over the local dofs q = (w1, theta1, w2, theta2), and gamma (constant).
   !> theta = a + b s + c s^2 and w = w1 + a s + b s^2/2 + c (s^3/3 - 2 Om s) with
   !> Om = EI / GAs solve the Timoshenko beam without load (M' = -Q).
   pure subroutine linked_shape(h, om, s, dw, dth, dk, dg)
      real(wp), intent(in) :: h, om, s
      real(wp), intent(out) :: dw(4), dth(4), dk(4), dg(4)
      real(wp) :: dc(4), db(4), kc
      kc = -6.0_wp/(h**3*(1.0_wp + 12.0_wp*om/h**2))
      dc = kc*[-1.0_wp, -0.5_wp*h, 1.0_wp, -0.5_wp*h]
      db = [0.0_wp, -1.0_wp/h, 0.0_wp, 1.0_wp/h] - h*dc
      dw = [1.0_wp, s, 0.0_wp, 0.0_wp] + 0.5_wp*s**2*db + (s**3/3.0_wp - 2.0_wp*om*s)*dc
      dth = [0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp] + s*db + s**2*dc
      dk = db + 2.0_wp*s*dc
      dg = -2.0_wp*om*dc
   end subroutine linked_shape

   !> Global dof rows of the local (w1, theta1, w2, theta2): w_i = n . u_i.
   pure function local_to_global(n) result(g)
      real(wp), intent(in) :: n(2)
      real(wp) :: g(4, 6)
      g = 0.0_wp
      g(1, 1:2) = n
      g(2, 3) = 1.0_wp
      g(3, 4:5) = n
      g(4, 6) = 1.0_wp
   end function local_to_global

   subroutine linked_points(x, section, axisym, thickness, pts, error)
      real(wp), intent(in) :: x(:, :)
      type(plate_section_t), intent(in) :: section
      logical, intent(in) :: axisym
      real(wp), intent(in) :: thickness
      type(beam_point_t), intent(out) :: pts(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: LOBATTO(3) = [0.0_wp, 0.5_wp, 1.0_wp], &
         LOBATTO_W(3) = [1.0_wp, 4.0_wp, 1.0_wp]/6.0_wp
      real(wp), parameter :: GAUSS(3) = 0.5_wp + 0.5_wp*[-sqrt(0.6_wp), 0.0_wp, sqrt(0.6_wp)], &
         GAUSS_W(3) = [5.0_wp, 8.0_wp, 5.0_wp]/18.0_wp
      real(wp) :: h, t(2), n(2), om, s, r, g(4, 6), dw(4), dth(4), dk(4), dg(4), us(6)
      real(wp) :: xi(3), wt(3)
      integer :: p
      call linked_frame(x, section, h, t, n, om, g)
      if (axisym) then
         xi = GAUSS
         wt = GAUSS_W
      else
         xi = LOBATTO
         wt = LOBATTO_W
      end if
      do p = 1, size(pts)
         s = xi(p)*h
         call linked_shape(h, om, s, dw, dth, dk, dg)
         pts(p)%at = xi(p)
         pts(p)%b = 0.0_wp
         pts(p)%b(1, 1:6) = [-t(1), -t(2), 0.0_wp, t(1), t(2), 0.0_wp]/h
         pts(p)%b(2, 1:6) = matmul(dg, g)
         pts(p)%b(3, 1:6) = matmul(dk, g)
         if (axisym) then
            r = x(1, 1) + xi(p)*(x(1, 2) - x(1, 1))
            if (.not. r > 0.0_wp) then
               call fatal_error(error, 'axisymmetric plate element with a point at r <= 0')
               return
            end if
            ! u_r = t_x u_s + n_x w, u_s linear
            us = [(1.0_wp - xi(p))*t(1), (1.0_wp - xi(p))*t(2), 0.0_wp, xi(p)*t(1), &
               xi(p)*t(2), 0.0_wp]
            pts(p)%b(4, 1:6) = (t(1)*us + n(1)*matmul(dw, g))/r
            pts(p)%b(5, 1:6) = t(1)*matmul(dth, g)/r
            pts(p)%weight = 2.0_wp*PI*r*h*wt(p)
         else
            pts(p)%weight = thickness*h*wt(p)
         end if
      end do
   end subroutine linked_points

   !> Quadratic shape functions (end, end, mid at xi = -1, 1, 0) and their derivatives.
   pure subroutine quadratic(xi, nf, dn)
      real(wp), intent(in) :: xi
      real(wp), intent(out) :: nf(3), dn(3)
      nf = [0.5_wp*xi*(xi - 1.0_wp), 0.5_wp*xi*(xi + 1.0_wp), 1.0_wp - xi**2]
      dn = [xi - 0.5_wp, xi + 0.5_wp, -2.0_wp*xi]
   end subroutine quadratic

   subroutine quadratic_points(x, axisym, thickness, pts, error)
      real(wp), intent(in) :: x(:, :)
      logical, intent(in) :: axisym
      real(wp), intent(in) :: thickness
      type(beam_point_t), intent(out) :: pts(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: XG(2) = [-1.0_wp, 1.0_wp]/sqrt(3.0_wp)
      real(wp) :: nf(3), dn(3), dxd(2), jac, t(2), n(2), ds(3), r
      integer :: p, k
      do p = 1, size(pts)
         call quadratic(XG(p), nf, dn)
         dxd = matmul(x(:, 1:3), dn)
         jac = norm2(dxd)
         if (.not. jac > 0.0_wp) then
            call fatal_error(error, '3-node plate element with a zero Jacobian')
            return
         end if
         t = dxd/jac
         n = [-t(2), t(1)]
         ds = dn/jac
         pts(p)%at = 0.5_wp*(XG(p) + 1.0_wp)
         pts(p)%b = 0.0_wp
         do k = 1, 3
            pts(p)%b(1, 3*k - 2:3*k - 1) = t*ds(k)
            pts(p)%b(2, 3*k - 2:3*k - 1) = n*ds(k)
            pts(p)%b(2, 3*k) = -nf(k)
            pts(p)%b(3, 3*k) = ds(k)
         end do
         if (axisym) then
            r = dot_product(nf, x(1, 1:3))
            if (.not. r > 0.0_wp) then
               call fatal_error(error, 'axisymmetric plate element with a point at r <= 0')
               return
            end if
            do k = 1, 3
               pts(p)%b(4, 3*k - 2) = nf(k)/r
               pts(p)%b(5, 3*k) = t(1)*nf(k)/r
            end do
            pts(p)%weight = 2.0_wp*PI*r*jac
         else
            pts(p)%weight = thickness*jac
         end if
      end do
   end subroutine quadratic_points

   !> Consistent nodal vector (3 nen: f_x, f_y, moment per node) of a uniform load q (force
   !> per unit length of plate along x, y; per unit area of the shell in axisymmetry),
   !> integrated with the element's own displacement interpolation (for the 2-node element
   !> the linked one: its end moments are those of a built-in beam, q h^2 / 12 for a straight
   !> element without shear flexibility). 3-point Gauss, or on a curved 3-node element whose
   !> bound says it is not exact the rule of pecplas_structures_beam_arc. `scale`
   !> (optional, one value per node): the load is q times their interpolation (linear between the ends of a 2-node
   !> element, quadratic on a 3-node one), e.g. a hydrostatic water pressure.
   pure subroutine beam_line_load(x, section, axisym, thickness, q, fe, scale)
      real(wp), intent(in) :: x(:, :), q(2)
      type(plate_section_t), intent(in) :: section
      logical, intent(in) :: axisym
      real(wp), intent(in) :: thickness
      real(wp), intent(out) :: fe(:)
      real(wp), intent(in), optional :: scale(:)
      real(wp), parameter :: XG(3) = [-sqrt(0.6_wp), 0.0_wp, sqrt(0.6_wp)], &
         WG(3) = [5.0_wp, 8.0_wp, 5.0_wp]/9.0_wp
      real(wp) :: h, t(2), n(2), om, s, dw(4), dth(4), dk(4), dg(4), g(4, 6), wrow(6), nf(3)
      real(wp) :: dn(3), dxd(2), jac, r, f, xi
      integer :: p, k
      fe = 0.0_wp
      if (size(x, 2) == 2) then
         call linked_frame(x, section, h, t, n, om, g)
         do p = 1, 3
            xi = 0.5_wp*(XG(p) + 1.0_wp)
            s = xi*h
            call linked_shape(h, om, s, dw, dth, dk, dg)
            wrow = matmul(dw, g)
            r = x(1, 1) + xi*(x(1, 2) - x(1, 1))
            f = 0.5_wp*WG(p)*h*merge(2.0_wp*PI*r, thickness, axisym)
            if (present(scale)) f = f*((1.0_wp - xi)*scale(1) + xi*scale(2))
            ! u(s) = t u_s + n w: the load's work q . t u_s + q . n w
            fe(1:2) = fe(1:2) + f*dot_product(q, t)*(1.0_wp - xi)*t
            fe(4:5) = fe(4:5) + f*dot_product(q, t)*xi*t
            fe(1:6) = fe(1:6) + f*dot_product(q, n)*wrow
         end do
      else if (.not. arc_three_points_exact(x, axisym, scale)) then
         ! a curved element: |dx/dxi| is no polynomial (pecplas_structures_beam_arc)
         call arc_line_load(x, axisym, thickness, q, fe, scale)
      else
         do p = 1, 3
            call quadratic(XG(p), nf, dn)
            dxd = matmul(x(:, 1:3), dn)
            jac = norm2(dxd)
            r = dot_product(nf, x(1, 1:3))
            f = WG(p)*jac*merge(2.0_wp*PI*r, thickness, axisym)
            if (present(scale)) f = f*dot_product(nf, scale(1:3))
            do k = 1, 3
               fe(3*k - 2:3*k - 1) = fe(3*k - 2:3*k - 1) + f*nf(k)*q
            end do
         end do
      end if
   end subroutine beam_line_load

   !> Consistent nodal vector (3 nen, as beam_line_load) of the load q p(a) on the part
   !> a0 <= a <= a1 of the element, a in [0, 1] its parameter (0 at node 1, 1 at node 2, the
   !> mid node of a 3-node element at 1/2) and p the polynomial of degree <= 2 in a with the
   !> values p3 at a0, (a0 + a1)/2 and a1: a piece of a load that is polynomial on each
   !> part of the element only, such as a water pressure cut at its level
   !> (pecplas_water_wet_parts). Gauss rules on the part exact for the integrand: 3 points
   !> on the 2-node element (its w cubic, p linear, r linear: degree 5), 4 on the 3-node
   !> one (N and p quadratic, r quadratic, |dx/dxi| linear on a straight element: degree 7).
   !> q is fixed along the element: for a pressure on a curved 3-node element, whose normal
   !> turns along it, see beam_curved_pressure.
   pure subroutine beam_part_load(x, section, axisym, thickness, q, a0, a1, p3, fe)
      real(wp), intent(in) :: x(:, :), q(2), a0, a1, p3(3)
      type(plate_section_t), intent(in) :: section
      logical, intent(in) :: axisym
      real(wp), intent(in) :: thickness
      real(wp), intent(out) :: fe(:)
      real(wp), parameter :: X3(3) = [-sqrt(0.6_wp), 0.0_wp, sqrt(0.6_wp)], &
         W3(3) = [5.0_wp, 8.0_wp, 5.0_wp]/9.0_wp
      real(wp), parameter :: X4A = sqrt(3.0_wp/7.0_wp - 2.0_wp/7.0_wp*sqrt(1.2_wp)), &
         X4B = sqrt(3.0_wp/7.0_wp + 2.0_wp/7.0_wp*sqrt(1.2_wp)), &
         X4(4) = [-X4B, -X4A, X4A, X4B], &
         W4(4) = [18.0_wp - sqrt(30.0_wp), 18.0_wp + sqrt(30.0_wp), &
         18.0_wp + sqrt(30.0_wp), 18.0_wp - sqrt(30.0_wp)]/36.0_wp
      real(wp) :: h, t(2), n(2), om, s, dw(4), dth(4), dk(4), dg(4), g(4, 6), wrow(6), nf(3)
      real(wp) :: dn(3), dxd(2), jac, r, f, xi, a, tl, pl
      integer :: i, k
      fe = 0.0_wp
      if (size(x, 2) == 2) then
         call linked_frame(x, section, h, t, n, om, g)
         do i = 1, 3
            tl = 0.5_wp*(X3(i) + 1.0_wp)
            a = a0 + tl*(a1 - a0)
            pl = part_value(p3, tl)
            s = a*h
            call linked_shape(h, om, s, dw, dth, dk, dg)
            wrow = matmul(dw, g)
            r = x(1, 1) + a*(x(1, 2) - x(1, 1))
            f = 0.5_wp*W3(i)*(a1 - a0)*h*merge(2.0_wp*PI*r, thickness, axisym)*pl
            fe(1:2) = fe(1:2) + f*dot_product(q, t)*(1.0_wp - a)*t
            fe(4:5) = fe(4:5) + f*dot_product(q, t)*a*t
            fe(1:6) = fe(1:6) + f*dot_product(q, n)*wrow
         end do
      else
         do i = 1, 4
            tl = 0.5_wp*(X4(i) + 1.0_wp)
            a = a0 + tl*(a1 - a0)
            pl = part_value(p3, tl)
            xi = 2.0_wp*a - 1.0_wp
            call quadratic(xi, nf, dn)
            dxd = matmul(x(:, 1:3), dn)
            jac = norm2(dxd)
            r = dot_product(nf, x(1, 1:3))
            ! d xi = 2 da, and the rule on [a0, a1] weighs (a1 - a0) / 2
            f = W4(i)*(a1 - a0)*jac*merge(2.0_wp*PI*r, thickness, axisym)*pl
            do k = 1, 3
               fe(3*k - 2:3*k - 1) = fe(3*k - 2:3*k - 1) + f*nf(k)*q
            end do
         end do
      end if
   end subroutine beam_part_load

   !> Whether the element with nodes x(2, nen) is its chord with a uniform map: 2 nodes, or
   !> a mid node exactly at the middle of the ends (then p and r are linear along it and its
   !> normal is the chord's, so beam_line_load's 3-point rule is exact for a pressure).
   pure logical function beam_on_chord(x) result(chord)
      real(wp), intent(in) :: x(:, :)
      chord = size(x, 2) == 2
      if (.not. chord) chord = all(x(:, 3) == 0.5_wp*(x(:, 1) + x(:, 2)))
   end function beam_on_chord

   !> Consistent nodal vector fe(9) of a pressure p(a) normal to the 3-node element's own
   !> (isoparametric, parabolic) geometry on its part a0 <= a <= a1 (a as in beam_part_load,
   !> p the polynomial of degree <= 2 with the values p3 at a0, (a0 + a1)/2 and a1), pushing
   !> from its left (side = +1: towards -n, n = (-t_y, t_x) the local normal) or right (-1):
   !> f_k = int N_k p side (dy/da, -dx/da) da times the thickness or 2 pi r. The normal times
   !> the length element, (dy/da, -dx/da) da, is a polynomial (linear) in a, so the integrand
   !> is one of degree 2 + 2 + 1 (+ 2 for r in axisymmetry) = 7: the 4-point Gauss rule on
   !> the part is exact, on a curved element as on a straight one. No nodal moments (the
   !> element interpolates theta apart from u).
   pure subroutine beam_curved_pressure(x, axisym, thickness, side, a0, a1, p3, fe)
      real(wp), intent(in) :: x(:, :), a0, a1, p3(3), thickness
      logical, intent(in) :: axisym
      integer, intent(in) :: side
      real(wp), intent(out) :: fe(:)
      real(wp), parameter :: X4A = sqrt(3.0_wp/7.0_wp - 2.0_wp/7.0_wp*sqrt(1.2_wp)), &
         X4B = sqrt(3.0_wp/7.0_wp + 2.0_wp/7.0_wp*sqrt(1.2_wp)), &
         X4(4) = [-X4B, -X4A, X4A, X4B], &
         W4(4) = [18.0_wp - sqrt(30.0_wp), 18.0_wp + sqrt(30.0_wp), &
         18.0_wp + sqrt(30.0_wp), 18.0_wp - sqrt(30.0_wp)]/36.0_wp
      real(wp) :: nf(3), dn(3), dxd(2), r, f, load(2), tl, a
      integer :: i, k
      fe = 0.0_wp
      do i = 1, 4
         tl = 0.5_wp*(X4(i) + 1.0_wp)
         a = a0 + tl*(a1 - a0)
         call quadratic(2.0_wp*a - 1.0_wp, nf, dn)
         dxd = matmul(x(:, 1:3), dn)
         r = dot_product(nf, x(1, 1:3))
         ! d xi = 2 da and the rule on [a0, a1] weighs (a1 - a0) / 2: dx/da da -> dxd W4 (a1 - a0)
         f = W4(i)*(a1 - a0)*merge(2.0_wp*PI*r, thickness, axisym)*part_value(p3, tl)
         load = real(side, wp)*f*[dxd(2), -dxd(1)]
         do k = 1, 3
            fe(3*k - 2:3*k - 1) = fe(3*k - 2:3*k - 1) + nf(k)*load
         end do
      end do
   end subroutine beam_curved_pressure

   !> The polynomial of degree <= 2 with the values p3 at t = 0, 1/2, 1, at t.
   pure real(wp) function part_value(p3, t) result(v)
      real(wp), intent(in) :: p3(3), t
      v = p3(1)*(1.0_wp - t)*(1.0_wp - 2.0_wp*t) + 4.0_wp*p3(2)*t*(1.0_wp - t) + &
         p3(3)*t*(2.0_wp*t - 1.0_wp)
   end function part_value

end module pecplas_structures_beam
