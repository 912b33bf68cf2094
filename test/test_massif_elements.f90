!> Massif elements T3, T6, Q4, Q8 on distorted elements: strain matrix B of linear
!> fields, geometry errors, stiffness invariants (rigid modes, eigenvalues), internal
!> and body forces.
module test_massif_elements
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_factory, only: new_massif_element, KNOWN_MASSIF_ELEMENTS
   use pecplas_massif_kinematics, only: massif_point_t, massif_point, massif_rule_t, &
      new_massif_rule, massif_gauss_point
   use pecplas_massif_element_matrices, only: massif_stiffness, massif_internal_force, &
      massif_strains, massif_body_force, massif_gauss_coordinates
   use pecplas_testing, only: unittest_t, new_unittest, check
   use fixtures_massif, only: sample_xe, hooke, sym_eigenvalues, linear_field, sample_points
   implicit none (type, external)
   private
   public :: collect_massif_elements

   character(len=*), parameter :: NAMES(*) = KNOWN_MASSIF_ELEMENTS
   real(wp), parameter :: TWO_PI = 2.0_wp*acos(-1.0_wp)

contains

   subroutine collect_massif_elements(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('b_linear_field_plane', test_b_plane), &
               new_unittest('b_linear_field_axi', test_b_axi), &
               new_unittest('bad_geometry_errors', test_bad_geometry), &
               new_unittest('rigid_modes', test_rigid_modes), &
               new_unittest('stiffness_eigenvalues', test_eigen), &
               new_unittest('internal_force_vs_stiffness', test_internal_force), &
               new_unittest('body_force_volume_centroid', test_body_force)]
   end subroutine collect_massif_elements

   !> Plane strain: B of a linear field on a distorted (curved for T6/Q8) element gives
   !> the exact constant strain at Gauss and other points (isoparametric completeness).
   subroutine test_b_plane(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: A(2, 2) = reshape([1.0e-3_wp, -4.0e-4_wp, 2.5e-3_wp, &
                                                -1.5e-3_wp], [2, 2])
      real(wp), parameter :: EXACT(4) = [A(1, 1), A(2, 2), 0.0_wp, A(1, 2) + A(2, 1)]
      call check_linear_strain(PLANE_STRAIN, A, [0.3_wp, -0.2_wp], EXACT, error)
   end subroutine test_b_plane

   !> Axisymmetric: u_r = a r, u_z = b z + c r + d gives eps = (a, b, a, c) exactly.
   subroutine test_b_axi(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: AR = 2.0e-3_wp, BZ = -1.0e-3_wp, CR = 7.0e-4_wp
      call check_linear_strain(AXISYMMETRIC, reshape([AR, CR, 0.0_wp, BZ], [2, 2]), &
         [0.0_wp, 0.05_wp], [AR, BZ, AR, CR], error)
   end subroutine test_b_axi

   subroutine check_linear_strain(kind, a, c, exact, error)
      integer, intent(in) :: kind
      real(wp), intent(in) :: a(2, 2), c(2), exact(4)
      type(error_t), allocatable, intent(out) :: error
      class(massif_element_t), allocatable :: elem
      type(massif_point_t) :: pt
      real(wp), allocatable :: xe(:, :), xi(:, :), w(:), ue(:)
      real(wp) :: p(2, 3), eps(4)
      integer :: ie, ig, nd
      do ie = 1, size(NAMES)
         call new_massif_element(NAMES(ie), elem, error)
         if (allocated(error)) return
         xe = sample_xe(NAMES(ie))
         ue = linear_field(xe, a, c)
         nd = size(ue)
         call elem%gauss(xi, w)
         p = sample_points(NAMES(ie))
         xi = reshape([xi, p], [2, size(w) + 3])
         do ig = 1, size(xi, 2)
            call massif_point(elem, kind, 1.0_wp, xe, xi(:, ig), 1.0_wp, pt, error)
            if (allocated(error)) return
            eps = matmul(pt%b(:, 1:nd), ue)
            call check(error, all(abs(eps - exact) <= 1.0e-12_wp*maxval(abs(exact))), &
               NAMES(ie)//' strain of a linear field')
            if (allocated(error)) return
         end do
      end do
   end subroutine check_linear_strain

   !> A clockwise element gives detJ < 0 and an axisymmetric element across the axis
   !> r <= 0: both are errors, not stops.
   subroutine test_bad_geometry(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      class(massif_element_t), allocatable :: elem
      type(massif_point_t) :: pt
      real(wp), allocatable :: xe(:, :)
      call new_massif_element('Q4', elem, error)
      if (allocated(error)) return
      xe = sample_xe('Q4')
      call massif_point(elem, PLANE_STRAIN, 1.0_wp, xe(:, [1, 4, 3, 2]), [0.0_wp, 0.0_wp], &
         1.0_wp, pt, e)
      call check(error, allocated(e), 'clockwise element must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'counter-clockwise') > 0, 'message says why: '//e%text())
      if (allocated(error)) return
      deallocate (e)
      xe(1, :) = xe(1, :) - 1.6_wp
      call massif_point(elem, AXISYMMETRIC, 1.0_wp, xe, [-0.5_wp, 0.0_wp], 1.0_wp, pt, e)
      call check(error, allocated(e), 'axisymmetric point at r < 0 must be an error')
   end subroutine test_bad_geometry

   !> Element stiffness (E = 1, nu = 0.3) of the distorted sample element.
   subroutine sample_stiffness(name, kind, ke, error)
      character(len=*), intent(in) :: name
      integer, intent(in) :: kind
      real(wp), allocatable, intent(out) :: ke(:, :)
      type(error_t), allocatable, intent(out) :: error
      class(massif_element_t), allocatable :: elem
      type(massif_rule_t) :: rule
      real(wp), allocatable :: d(:, :, :)
      integer :: ig
      call new_massif_element(name, elem, error)
      if (allocated(error)) return
      call new_massif_rule(rule, elem)
      allocate (d(4, 4, rule%ngauss), ke(2*rule%nnode, 2*rule%nnode))
      do ig = 1, rule%ngauss
         d(:, :, ig) = hooke(1.0_wp, 0.3_wp)
      end do
      call massif_stiffness(rule, kind, 1.0_wp, sample_xe(name), d, ke, error)
   end subroutine sample_stiffness

   !> K u = 0 for the plane rigid modes (two translations, rotation); in axisymmetry only
   !> the z-translation: an r-translation strains the hoop direction.
   subroutine test_rigid_modes(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: ke(:, :), xe(:, :), modes(:, :)
      real(wp) :: scale
      integer :: ie, m
      do ie = 1, size(NAMES)
         xe = sample_xe(NAMES(ie))
         modes = reshape([linear_field(xe, reshape([0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], [2, 2]), &
            [1.0_wp, 0.0_wp]), linear_field(xe, reshape([0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], &
            [2, 2]), [0.0_wp, 1.0_wp]), linear_field(xe, reshape([0.0_wp, 1.0_wp, -1.0_wp, &
            0.0_wp], [2, 2]), [0.0_wp, 0.0_wp])], [2*size(xe, 2), 3])
         call sample_stiffness(NAMES(ie), PLANE_STRAIN, ke, error)
         if (allocated(error)) return
         scale = maxval(abs(ke))
         do m = 1, 3
            call check(error, maxval(abs(matmul(ke, modes(:, m)))) <= 1.0e-12_wp*scale* &
               maxval(abs(modes(:, m))), NAMES(ie)//' plane rigid mode has zero force')
            if (allocated(error)) return
         end do
         call sample_stiffness(NAMES(ie), AXISYMMETRIC, ke, error)
         if (allocated(error)) return
         scale = maxval(abs(ke))
         call check(error, maxval(abs(matmul(ke, modes(:, 2)))) <= 1.0e-12_wp*scale, &
            NAMES(ie)//' axisymmetric z-translation has zero force')
         if (allocated(error)) return
         call check(error, maxval(abs(matmul(ke, modes(:, 1)))) > 1.0e-3_wp*scale, &
            NAMES(ie)//' axisymmetric r-translation is resisted (hoop strain)')
         if (allocated(error)) return
      end do
   end subroutine test_rigid_modes

   !> Stiffness symmetric (to rounding) and its zero eigenvalues (< 1e-10 lambda_max)
   !> are exactly the rigid modes, well separated (next one > 1e-4 lambda_max): 3 in plane
   !> strain, 1 in axisymmetry; the one-point T3 has 2 in axisymmetry, since the hoop
   !> strain is sampled only at the centroid (a rotation about it is free in one element).
   !> Q8R (2 x 2 points, 12 strain samples for 13 deformation modes) has exactly one
   !> spurious mode in plane strain: 4 zero eigenvalues.
   subroutine test_eigen(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: KINDS(2) = [PLANE_STRAIN, AXISYMMETRIC]
      real(wp), allocatable :: ke(:, :), lam(:)
      real(wp) :: gap
      integer :: ie, ik, info, nzero, expected
      do ie = 1, size(NAMES)
         do ik = 1, 2
            call sample_stiffness(NAMES(ie), KINDS(ik), ke, error)
            if (allocated(error)) return
            call check(error, maxval(abs(ke - transpose(ke))) <= 1.0e-14_wp*maxval(abs(ke)), &
               NAMES(ie)//' symmetric stiffness')
            if (allocated(error)) return
            allocate (lam(size(ke, 1)))
            call sym_eigenvalues(ke, lam, info)
            call check(error, info == 0, 'dsyev failed')
            if (allocated(error)) return
            nzero = count(abs(lam) < 1.0e-10_wp*lam(size(lam)))
            expected = merge(3, 1, KINDS(ik) == PLANE_STRAIN)
            if (NAMES(ie) == 'T3' .and. KINDS(ik) == AXISYMMETRIC) expected = 2
            gap = 1.0e-4_wp
            if (NAMES(ie) == 'Q8R') then
               ! plane strain: + 1 spurious mode; axisymmetry: that mode only meets the hoop
               ! strain u_r/r (9e-6 lambda_max on this element), weak but not zero
               if (KINDS(ik) == PLANE_STRAIN) expected = 4
               if (KINDS(ik) == AXISYMMETRIC) gap = 1.0e-6_wp
            end if
            call check(error, nzero == expected .and. lam(nzero + 1) > gap*lam(size(lam)) &
               .and. lam(1) > -1.0e-10_wp*lam(size(lam)), NAMES(ie)//' zero-energy modes')
            if (allocated(error)) return
            deallocate (lam)
         end do
      end do
   end subroutine test_eigen

   !> The internal force of the elastic stress D B u equals K u (same B, same points),
   !> for an arbitrary u; rounding only.
   subroutine test_internal_force(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: KINDS(2) = [PLANE_STRAIN, AXISYMMETRIC]
      class(massif_element_t), allocatable :: elem
      type(massif_rule_t) :: rule
      real(wp), allocatable :: ke(:, :), u(:), eps(:, :), fe(:), xe(:, :)
      real(wp) :: d(4, 4)
      integer :: ie, ik, i
      d = hooke(1.0_wp, 0.3_wp)
      do ie = 1, size(NAMES)
         call new_massif_element(NAMES(ie), elem, error)
         if (allocated(error)) return
         call new_massif_rule(rule, elem)
         xe = sample_xe(NAMES(ie))
         u = [(1.0e-3_wp*sin(1.7_wp*i), i=1, 2*rule%nnode)]
         allocate (eps(4, rule%ngauss), fe(size(u)))
         do ik = 1, 2
            call sample_stiffness(NAMES(ie), KINDS(ik), ke, error)
            if (allocated(error)) return
            call massif_strains(rule, KINDS(ik), 1.0_wp, xe, u, eps, error)
            if (allocated(error)) return
            call massif_internal_force(rule, KINDS(ik), 1.0_wp, xe, matmul(d, eps), fe, error)
            if (allocated(error)) return
            call check(error, all(abs(fe - matmul(ke, u)) <= 1.0e-12_wp*maxval(abs(fe))), &
               NAMES(ie)//' internal force = K u')
            if (allocated(error)) return
         end do
         deallocate (eps, fe)
      end do
   end subroutine test_internal_force

   !> Straight-sided elements (mid-side nodes at midpoints): the nodal forces of a
   !> uniform body force b sum to b V, with V = A t (plane) or 2 pi A r_c (Pappus), and
   !> sum dvol x_g = t A x_c (plane); A, x_c from the corner polygon. The rules are exact.
   subroutine test_body_force(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: T = 0.7_wp, B(2) = [0.4_wp, -18.0_wp]
      class(massif_element_t), allocatable :: elem
      type(massif_rule_t) :: rule
      type(massif_point_t) :: pt
      real(wp), allocatable :: xe(:, :), fe(:), xg(:, :)
      real(wp) :: area, xc(2), cross, mom(2)
      integer :: ie, nc, k, k1, ig
      do ie = 1, size(NAMES)
         call new_massif_element(NAMES(ie), elem, error)
         if (allocated(error)) return
         call new_massif_rule(rule, elem)
         nc = merge(3, 4, NAMES(ie)(1:1) == 'T')
         xe = sample_xe(NAMES(ie))
         area = 0.0_wp
         xc = 0.0_wp
         do k = 1, nc
            k1 = mod(k, nc) + 1
            if (rule%nnode > nc) xe(:, nc + k) = 0.5_wp*(xe(:, k) + xe(:, k1))
            cross = xe(1, k)*xe(2, k1) - xe(1, k1)*xe(2, k)
            area = area + 0.5_wp*cross
            xc = xc + cross*(xe(:, k) + xe(:, k1))/6.0_wp
         end do
         xc = xc/area
         allocate (fe(2*rule%nnode), xg(2, rule%ngauss))
         call massif_body_force(rule, PLANE_STRAIN, T, xe, B, fe, error)
         if (allocated(error)) return
         call check(error, all(abs([sum(fe(1::2)), sum(fe(2::2))] - B*area*T) <= &
            1.0e-13_wp*maxval(abs(B*area*T))), NAMES(ie)//' plane body force resultant')
         if (allocated(error)) return
         call massif_body_force(rule, AXISYMMETRIC, T, xe, B, fe, error)
         if (allocated(error)) return
         call check(error, all(abs([sum(fe(1::2)), sum(fe(2::2))] - B*area*TWO_PI*xc(1)) <= &
            1.0e-13_wp*maxval(abs(B*area*TWO_PI*xc(1)))), NAMES(ie)//' ring body force resultant')
         if (allocated(error)) return
         call massif_gauss_coordinates(rule, xe, xg)
         mom = 0.0_wp
         do ig = 1, rule%ngauss
            call massif_gauss_point(rule, ig, PLANE_STRAIN, T, xe, pt, error)
            if (allocated(error)) return
            call check(error, all(abs(pt%x - xg(:, ig)) <= 1.0e-15_wp*maxval(abs(xe))), &
               NAMES(ie)//' Gauss coordinates = point position')
            if (allocated(error)) return
            mom = mom + pt%dvol*xg(:, ig)
         end do
         call check(error, all(abs(mom - T*area*xc) <= 1.0e-13_wp*maxval(abs(T*area*xc))), &
            NAMES(ie)//' first moment of area from Gauss coordinates')
         if (allocated(error)) return
         deallocate (fe, xg)
      end do
   end subroutine test_body_force

end module test_massif_elements
