!> Kinematics of a massif element at one integration point: shape functions, strain
!> matrix B, volume measure and physical position. Plane strain: dvol = w detJ thickness.
!> Axisymmetric (x = r, y = z): dvol = w detJ 2 pi r, integrals over the full ring, so
!> nodal forces are total ring forces. Strain order (xx, yy, zz, xy), zz = 0 in plane
!> strain and u_r / r (hoop) in axisymmetry, xy engineering shear.
module pecplas_massif_kinematics
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error, input_error
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC
   use pecplas_massif_elements_type, only: massif_element_t
   implicit none (type, external)
   private

   public :: MAX_NODES, massif_point_t, massif_rule_t, new_massif_rule
   public :: massif_point, massif_gauss_point, massif_gauss_derivs

   !> Largest number of nodes of a massif element (Q8); sizes the fixed point arrays.
   integer, parameter :: MAX_NODES = 8

   real(wp), parameter :: TWO_PI = 2.0_wp*acos(-1.0_wp)

   !> Data of one integration point. Fixed-size arrays so that evaluating a point does
   !> not allocate; only the first `nnode` columns (2*nnode for b) are meaningful.
   type :: massif_point_t
      integer :: nnode = 0
      !> Shape functions.
      real(wp) :: n(MAX_NODES)
      !> Physical derivatives dN/dx, dN/dy (dN/dr, dN/dz).
      real(wp) :: dndx(2, MAX_NODES)
      !> Strain matrix, DOF order u1, v1, u2, v2, ...
      real(wp) :: b(4, 2*MAX_NODES)
      !> Physical coordinates of the point.
      real(wp) :: x(2)
      !> Jacobian determinant of the reference-to-physical map.
      real(wp) :: detj
      !> Volume measure: w detJ thickness (plane strain) or w detJ 2 pi r (axisymmetric).
      real(wp) :: dvol
   end type massif_point_t

   !> Integration rule of one element type with its shape functions tabulated at the
   !> points: build once per element type and reuse for every element of that type.
   type :: massif_rule_t
      integer :: nnode = 0, ngauss = 0
      !> Reference coordinates xi(2, ngauss) and weights w(ngauss).
      real(wp), allocatable :: xi(:, :), w(:)
      !> n(nnode, ngauss) and dn(2, nnode, ngauss) = dN/dxi at the points.
      real(wp), allocatable :: n(:, :), dn(:, :, :)
   end type massif_rule_t

contains

   !> Tabulates the integration rule and shape functions of `elem`.
   pure subroutine new_massif_rule(rule, elem)
      type(massif_rule_t), intent(out) :: rule
      class(massif_element_t), intent(in) :: elem
      integer :: ig
      call elem%gauss(rule%xi, rule%w)
      rule%nnode = elem%nnode()
      rule%ngauss = size(rule%w)
      allocate (rule%n(rule%nnode, rule%ngauss), rule%dn(2, rule%nnode, rule%ngauss))
      do ig = 1, rule%ngauss
         call elem%shape(rule%xi(:, ig), rule%n(:, ig), rule%dn(:, :, ig))
      end do
   end subroutine new_massif_rule

   !> Point data at reference coordinates xi with integration weight w, for nodal
   !> coordinates xe(2, nnode). Fails when detJ <= 0 (inverted or clockwise element) or,
   !> in axisymmetry, when r <= 0 at the point.
   subroutine massif_point(elem, analysis_kind, thickness, xe, xi, w, pt, error)
      class(massif_element_t), intent(in) :: elem
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness, xe(:, :), xi(2), w
      type(massif_point_t), intent(out) :: pt
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: n(MAX_NODES), dn(2, MAX_NODES)
      integer :: nn
      nn = elem%nnode()
      if (size(xe, 1) /= 2 .or. size(xe, 2) /= nn) then
         call fatal_error(error, 'massif_point: xe must be (2, nnode) for element '//elem%name())
         return
      end if
      call elem%shape(xi, n(1:nn), dn(:, 1:nn))
      call point_from_shape(n(1:nn), dn(:, 1:nn), analysis_kind, thickness, xe, w, pt, error)
   end subroutine massif_point

   !> Point data at integration point `ig` of a tabulated rule (no shape evaluation).
   subroutine massif_gauss_point(rule, ig, analysis_kind, thickness, xe, pt, error)
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: ig, analysis_kind
      real(wp), intent(in) :: thickness, xe(:, :)
      type(massif_point_t), intent(out) :: pt
      type(error_t), allocatable, intent(out) :: error
      call point_from_shape(rule%n(:, ig), rule%dn(:, :, ig), analysis_kind, thickness, xe, &
         rule%w(ig), pt, error)
   end subroutine massif_gauss_point

   !> Jacobian data of integration point `ig` of a tabulated rule without the strain
   !> matrix: dndx(2, nnode) = dN/dx, dN/dy; hr(nnode) = N/r, the hoop row of B
   !> (axisymmetric; zero in plane strain); dvol. The structured kernels
   !> (pecplas_massif_point_kernels) need only these; B is never formed or zeroed.
   subroutine massif_gauss_derivs(rule, ig, analysis_kind, thickness, xe, dndx, hr, dvol, error)
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: ig, analysis_kind
      ! explicit shapes: no descriptors and no packing checks in the element loops
      real(wp), intent(in) :: thickness, xe(2, rule%nnode)
      real(wp), intent(out) :: dndx(2, rule%nnode), hr(rule%nnode), dvol
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: x(2), detj
      call point_derivatives(rule%nnode, rule%n(:, ig), rule%dn(:, :, ig), analysis_kind, &
         thickness, xe, rule%w(ig), x, detj, dndx, hr, dvol, error)
   end subroutine massif_gauss_derivs

   subroutine point_from_shape(n, dn, analysis_kind, thickness, xe, w, pt, error)
      real(wp), intent(in) :: n(:), dn(:, :)
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness, xe(:, :), w
      type(massif_point_t), intent(out) :: pt
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: hr(MAX_NODES)
      integer :: k, nn
      nn = size(n)
      pt%nnode = nn
      pt%n(1:nn) = n
      call point_derivatives(nn, n, dn, analysis_kind, thickness, xe, w, pt%x, pt%detj, &
         pt%dndx(:, 1:nn), hr(1:nn), pt%dvol, error)
      if (allocated(error)) return
      pt%b(:, 1:2*nn) = 0.0_wp
      do k = 1, nn
         pt%b(1, 2*k - 1) = pt%dndx(1, k)
         pt%b(2, 2*k) = pt%dndx(2, k)
         pt%b(3, 2*k - 1) = hr(k)
         pt%b(4, 2*k - 1) = pt%dndx(2, k)
         pt%b(4, 2*k) = pt%dndx(1, k)
      end do
   end subroutine point_from_shape

   !> Position x, detJ, dN/dx, N/r (zero in plane strain) and dvol at a point with shape
   !> values n(nn) and reference derivatives dn(2, nn): the one place where the Jacobian
   !> and its error messages live.
   subroutine point_derivatives(nn, n, dn, analysis_kind, thickness, xe, w, x, detj, dndx, &
         hr, dvol, error)
      integer, intent(in) :: nn, analysis_kind
      real(wp), intent(in) :: n(nn), dn(2, nn), xe(2, nn)
      real(wp), intent(in) :: thickness, w
      real(wp), intent(out) :: x(2), detj, dvol
      real(wp), intent(out) :: dndx(2, nn), hr(nn)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: jac(2, 2), r, rdet
      character(len=120) :: buf
      integer :: k
      ! jac(a, b) = d x_b / d xi_a, so dN/dxi = jac dN/dx
      x = 0.0_wp
      jac = 0.0_wp
      do k = 1, nn
         x = x + xe(:, k)*n(k)
         jac(:, 1) = jac(:, 1) + dn(:, k)*xe(1, k)
         jac(:, 2) = jac(:, 2) + dn(:, k)*xe(2, k)
      end do
      detj = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
      if (.not. (detj > 0.0_wp)) then
         write (buf, '(a,es10.3,a,2es11.3,a)') 'detJ =', detj, ' near (', x, ')'
         call input_error(error, 'massif element inverted or nodes not counter-clockwise: ' &
            //trim(buf))
         return
      end if
      rdet = 1.0_wp/detj
      do k = 1, nn
         dndx(1, k) = (jac(2, 2)*dn(1, k) - jac(1, 2)*dn(2, k))*rdet
         dndx(2, k) = (jac(1, 1)*dn(2, k) - jac(2, 1)*dn(1, k))*rdet
      end do
      select case (analysis_kind)
      case (PLANE_STRAIN)
         hr = 0.0_wp
         dvol = w*detj*thickness
      case (AXISYMMETRIC)
         r = x(1)
         if (.not. (r > 0.0_wp)) then
            write (buf, '(a,es10.3,a,2es11.3,a)') 'r =', r, ' at integration point (', x, ')'
            call input_error(error, 'axisymmetric massif element needs r > 0 inside it: ' &
               //trim(buf))
            return
         end if
         hr = n/r
         dvol = w*detj*TWO_PI*r
      case default
         call fatal_error(error, 'massif kinematics: unknown analysis kind')
      end select
   end subroutine point_derivatives

end module pecplas_massif_kinematics
