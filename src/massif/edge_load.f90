!> Consistent nodal forces of distributed loads on one element edge of 2 or 3 nodes,
!> ordered end, end, [mid] with the body on the LEFT when walking from the first end to
!> the second: the outward normal is (t_y, -t_x)/|t| for the tangent t = dx/ds.
!> A pressure p > 0 pushes INTO the body (traction -p n_out). Plane strain integrates
!> over the thickness; axisymmetric (x = r) over the full ring (weight 2 pi r), giving
!> total ring forces. Loads are uniform or given by nodal values, interpolated like the
!> geometry; the Gauss order is exact for the resulting polynomial (for tractions given
!> per unit length this needs a straight edge, as |t| is then polynomial).
module pecplas_massif_edge_load
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error, input_error
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC
   use pecplas_massif_elements_gauss, only: gauss_line
   implicit none (type, external)
   private

   public :: edge_pressure_forces, edge_traction_forces, edge_linear_pressure_forces
   public :: edge_part_pressure_forces

   !> fe(2*nen) of a pressure: uniform p, or nodal values p(nen).
   interface edge_pressure_forces
      module procedure pressure_uniform, pressure_nodal
   end interface edge_pressure_forces

   !> fe(2*nen) of a traction vector (force per unit edge area, global axes):
   !> uniform t(2), or nodal values t(2, nen).
   interface edge_traction_forces
      module procedure traction_uniform, traction_nodal
   end interface edge_traction_forces

   real(wp), parameter :: TWO_PI = 2.0_wp*acos(-1.0_wp)

contains

   subroutine pressure_uniform(analysis_kind, thickness, xedge, p, fe, error)
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness, xedge(:, :), p
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      call edge_forces(analysis_kind, thickness, xedge, spread(p, 1, size(xedge, 2)), &
         spread([0.0_wp, 0.0_wp], 2, size(xedge, 2)), 0, -1.0_wp, 1.0_wp, fe, error)
   end subroutine pressure_uniform

   subroutine pressure_nodal(analysis_kind, thickness, xedge, p, fe, error)
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness, xedge(:, :), p(:)
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      if (size(p) /= size(xedge, 2)) then
         call fatal_error(error, 'edge_pressure_forces: one pressure value per edge node')
         return
      end if
      call edge_forces(analysis_kind, thickness, xedge, p, &
         spread([0.0_wp, 0.0_wp], 2, size(xedge, 2)), size(xedge, 2) - 1, -1.0_wp, 1.0_wp, fe, &
         error)
   end subroutine pressure_nodal

   !> fe(2*nen) of a pressure varying linearly with the depth, p(y) = p_ref + gradient
   !> (y_ref - y), floored at p_min when given: max(p_min, p(y)) (e.g. p_min = 0: no suction
   !> above a water table). Exact: y is interpolated along the edge by its own shape functions,
   !> so p(y(s)) is too (nodal values, degree nen - 1 in s), and the floor cuts the edge at
   !> the roots of p(y(s)) = p_min, each piece integrated by the Gauss rule exact for it.
   subroutine edge_linear_pressure_forces(analysis_kind, thickness, xedge, p_ref, gradient, &
      y_ref, fe, error, p_min)
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness, xedge(:, :), p_ref, gradient, y_ref
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: p_min
      real(wp), allocatable :: q(:), cuts(:), part(:)
      integer :: nen, i
      nen = size(xedge, 2)
      q = p_ref + gradient*(y_ref - xedge(2, :))
      if (.not. present(p_min)) then
         call edge_pressure_forces(analysis_kind, thickness, xedge, q, fe, error)
         return
      end if
      ! max(p_min, p) = p_min + max(0, p - p_min): the uniform floor and the part above it
      call edge_pressure_forces(analysis_kind, thickness, xedge, p_min, fe, error)
      if (allocated(error)) return
      q = q - p_min
      cuts = [-1.0_wp, roots_in(q), 1.0_wp]
      allocate (part(size(fe)))
      do i = 1, size(cuts) - 1
         if (.not. (cuts(i + 1) > cuts(i))) cycle
         if (.not. (along(q, 0.5_wp*(cuts(i) + cuts(i + 1))) > 0.0_wp)) cycle
         call edge_forces(analysis_kind, thickness, xedge, q, &
            spread([0.0_wp, 0.0_wp], 2, nen), nen - 1, cuts(i), cuts(i + 1), part, error)
         if (allocated(error)) return
         fe = fe + part
      end do
   end subroutine edge_linear_pressure_forces

   !> fe(2*nen) of a pressure p on the part a <= s <= b of the edge (s in [-1, 1]), p the
   !> polynomial of degree nen - 1 in s with the values p3 at a, (a + b)/2 and b: a piece of
   !> a pressure that is polynomial on each part of the edge only, such as the water's under
   !> a polyline level (pecplas_water_wet_parts). The Gauss rule is that of nodal values.
   subroutine edge_part_pressure_forces(analysis_kind, thickness, xedge, a, b, p3, fe, error)
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness, xedge(:, :), a, b, p3(3)
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: nen
      nen = size(xedge, 2)
      call edge_forces(analysis_kind, thickness, xedge, spread(0.0_wp, 1, nen), &
         spread([0.0_wp, 0.0_wp], 2, nen), nen - 1, a, b, fe, error, p3)
   end subroutine edge_part_pressure_forces

   !> q(s) = sum N_k(s) q_k on the edge (2 or 3 nodal values).
   pure real(wp) function along(q, s) result(v)
      real(wp), intent(in) :: q(:), s
      real(wp) :: n(3), dn(3)
      call edge_shape(size(q), s, n, dn)
      v = dot_product(n(1:size(q)), q)
   end function along

   !> The roots of q(s) = sum N_k(s) q_k in (-1, 1), ascending: q is linear in s on a 2-node
   !> edge, q3 + s (q2 - q1)/2 + s**2 ((q1 + q2)/2 - q3) on a 3-node edge.
   pure function roots_in(q) result(r)
      real(wp), intent(in) :: q(:)
      real(wp), allocatable :: r(:)
      real(wp) :: a, b, c, disc, t, r1, r2
      allocate (r(0))
      if (size(q) == 2) then
         a = 0.0_wp
         b = 0.5_wp*(q(2) - q(1))
         c = 0.5_wp*(q(1) + q(2))
      else
         a = 0.5_wp*(q(1) + q(2)) - q(3)
         b = 0.5_wp*(q(2) - q(1))
         c = q(3)
      end if
      if (abs(a) <= epsilon(1.0_wp)*(abs(b) + abs(c))) then
         ! linear (a straight edge with its mid-side node at the middle, or a 2-node edge)
         if (b /= 0.0_wp) r = [-c/b]
      else
         disc = b*b - 4.0_wp*a*c
         if (disc < 0.0_wp) return
         ! the stable pair of roots: t and c / (a r1)
         t = -0.5_wp*(b + sign(sqrt(disc), b))
         r1 = t/a
         if (t /= 0.0_wp) then
            r2 = c/t
            r = [min(r1, r2), max(r1, r2)]
         else
            r = [r1]
         end if
      end if
      r = pack(r, r > -1.0_wp .and. r < 1.0_wp)
   end function roots_in

   subroutine traction_uniform(analysis_kind, thickness, xedge, t, fe, error)
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness, xedge(:, :), t(2)
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      call edge_forces(analysis_kind, thickness, xedge, spread(0.0_wp, 1, size(xedge, 2)), &
         spread(t, 2, size(xedge, 2)), 0, -1.0_wp, 1.0_wp, fe, error)
   end subroutine traction_uniform

   subroutine traction_nodal(analysis_kind, thickness, xedge, t, fe, error)
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness, xedge(:, :), t(:, :)
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      if (size(t, 1) /= 2 .or. size(t, 2) /= size(xedge, 2)) then
         call fatal_error(error, 'edge_traction_forces: traction must be (2, edge nodes)')
         return
      end if
      call edge_forces(analysis_kind, thickness, xedge, spread(0.0_wp, 1, size(xedge, 2)), &
         t, size(xedge, 2) - 1, -1.0_wp, 1.0_wp, fe, error)
   end subroutine traction_nodal

   !> Integrates N (t |dx/ds| - p n_out |dx/ds|) weight ds with nodal p(nen), t(2, nen)
   !> of polynomial degree load_degree along the part a <= s <= b of the edge; with `p3`,
   !> p is instead the polynomial of degree <= 2 with the values p3 at a, (a + b)/2, b.
   subroutine edge_forces(analysis_kind, thickness, xedge, p, t, load_degree, a, b, fe, error, &
      p3)
      integer, intent(in) :: analysis_kind, load_degree
      real(wp), intent(in) :: thickness, xedge(:, :), p(:), t(:, :), a, b
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: p3(3)
      real(wp), allocatable :: s(:), w(:), tl(:)
      real(wp) :: n(3), dn(3), x(2), tang(2), f(2), weight, len_t, pg
      integer :: nen, g, degree, ig, k
      character(len=60) :: buf
      nen = size(xedge, 2)
      if (size(xedge, 1) /= 2 .or. nen < 2 .or. nen > 3 .or. size(fe) /= 2*nen) then
         call fatal_error(error, 'edge load: xedge must be (2, 2 or 3 nodes), fe 2*nodes long')
         return
      end if
      if (analysis_kind /= PLANE_STRAIN .and. analysis_kind /= AXISYMMETRIC) then
         call fatal_error(error, 'edge load: unknown analysis kind')
         return
      end if
      ! degree of N, of the tangent, of the load and of r (axisymmetric weight)
      g = nen - 1
      degree = g + (g - 1) + load_degree
      if (analysis_kind == AXISYMMETRIC) degree = degree + g
      call gauss_line(degree/2 + 1, s, w)
      tl = 0.5_wp*(s + 1.0_wp)
      ! the rule on [-1, 1] mapped onto [a, b]
      s = 0.5_wp*(a + b) + 0.5_wp*(b - a)*s
      w = 0.5_wp*(b - a)*w
      fe = 0.0_wp
      do ig = 1, size(s)
         call edge_shape(nen, s(ig), n, dn)
         x = matmul(xedge, n(1:nen))
         tang = matmul(xedge, dn(1:nen))
         len_t = norm2(tang)
         if (.not. (len_t > 0.0_wp)) then
            write (buf, '(a,2es11.3,a)') ' near (', x, ')'
            call input_error(error, 'loaded edge has zero length'//trim(buf)// &
               ': expected distinct nodes along the edge')
            return
         end if
         if (analysis_kind == AXISYMMETRIC) then
            if (x(1) < 0.0_wp) then
               write (buf, '(a,2es11.3,a)') ' at (', x, ')'
               call input_error(error, 'axisymmetric edge load at r < 0'//trim(buf)// &
                  ': expected r >= 0 along the edge (is a midside node off the middle of '// &
                  'its side?)')
               return
            end if
            weight = w(ig)*TWO_PI*x(1)
         else
            weight = w(ig)*thickness
         end if
         ! -p n_out |t| = p (-t_y, t_x)
         pg = dot_product(p, n(1:nen))
         if (present(p3)) pg = p3(1)*(1.0_wp - tl(ig))*(1.0_wp - 2.0_wp*tl(ig)) + &
            4.0_wp*p3(2)*tl(ig)*(1.0_wp - tl(ig)) + p3(3)*tl(ig)*(2.0_wp*tl(ig) - 1.0_wp)
         f = (pg*[-tang(2), tang(1)] + matmul(t, n(1:nen))*len_t)*weight
         do k = 1, nen
            fe(2*k - 1:2*k) = fe(2*k - 1:2*k) + n(k)*f
         end do
      end do
   end subroutine edge_forces

   !> Line shape functions on s in [-1, 1]: ends at -1 and +1, mid-side node at 0.
   pure subroutine edge_shape(nen, s, n, dn)
      integer, intent(in) :: nen
      real(wp), intent(in) :: s
      real(wp), intent(out) :: n(3), dn(3)
      if (nen == 2) then
         n = [0.5_wp*(1.0_wp - s), 0.5_wp*(1.0_wp + s), 0.0_wp]
         dn = [-0.5_wp, 0.5_wp, 0.0_wp]
      else
         n = [0.5_wp*s*(s - 1.0_wp), 0.5_wp*s*(s + 1.0_wp), 1.0_wp - s*s]
         dn = [s - 0.5_wp, s + 0.5_wp, -2.0_wp*s]
      end if
   end subroutine edge_shape

end module pecplas_massif_edge_load
