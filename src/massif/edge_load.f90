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

   public :: edge_pressure_forces, edge_traction_forces

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
         spread([0.0_wp, 0.0_wp], 2, size(xedge, 2)), 0, fe, error)
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
         spread([0.0_wp, 0.0_wp], 2, size(xedge, 2)), size(xedge, 2) - 1, fe, error)
   end subroutine pressure_nodal

   subroutine traction_uniform(analysis_kind, thickness, xedge, t, fe, error)
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness, xedge(:, :), t(2)
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      call edge_forces(analysis_kind, thickness, xedge, spread(0.0_wp, 1, size(xedge, 2)), &
         spread(t, 2, size(xedge, 2)), 0, fe, error)
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
         t, size(xedge, 2) - 1, fe, error)
   end subroutine traction_nodal

   !> Integrates N (t |dx/ds| - p n_out |dx/ds|) weight ds with nodal p(nen), t(2, nen)
   !> of polynomial degree load_degree along the edge.
   subroutine edge_forces(analysis_kind, thickness, xedge, p, t, load_degree, fe, error)
      integer, intent(in) :: analysis_kind, load_degree
      real(wp), intent(in) :: thickness, xedge(:, :), p(:), t(:, :)
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: s(:), w(:)
      real(wp) :: n(3), dn(3), x(2), tang(2), f(2), weight, len_t
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
      fe = 0.0_wp
      do ig = 1, size(s)
         call edge_shape(nen, s(ig), n, dn)
         x = matmul(xedge, n(1:nen))
         tang = matmul(xedge, dn(1:nen))
         len_t = norm2(tang)
         if (.not. (len_t > 0.0_wp)) then
            write (buf, '(a,2es11.3,a)') ' near (', x, ')'
            call input_error(error, 'loaded edge has zero length'//trim(buf))
            return
         end if
         if (analysis_kind == AXISYMMETRIC) then
            if (x(1) < 0.0_wp) then
               write (buf, '(a,2es11.3,a)') ' at (', x, ')'
               call input_error(error, 'axisymmetric edge load at r < 0'//trim(buf))
               return
            end if
            weight = w(ig)*TWO_PI*x(1)
         else
            weight = w(ig)*thickness
         end if
         ! -p n_out |t| = p (-t_y, t_x)
         f = (dot_product(p, n(1:nen))*[-tang(2), tang(1)] + matmul(t, n(1:nen))*len_t)*weight
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
