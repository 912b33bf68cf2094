!> Massif elements T3, T6, Q4, Q8: integration rules, shape functions, factory, strain
!> matrix B on distorted elements, stiffness invariants (rigid modes, eigenvalues).
module test_massif_elements
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_factory, only: new_massif_element, massif_element_nnode, &
      KNOWN_MASSIF_ELEMENTS
   use pecplas_massif_elements_gauss, only: gauss_line, lobatto_line, gauss_quad, gauss_triangle
   use pecplas_massif_kinematics, only: massif_point_t, massif_point, massif_rule_t, &
      new_massif_rule
   use pecplas_massif_element_matrices, only: massif_stiffness
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_massif, only: sample_xe, hooke, sym_eigenvalues, linear_field
   implicit none (type, external)
   private
   public :: collect_massif_elements

   character(len=2), parameter :: NAMES(4) = KNOWN_MASSIF_ELEMENTS

contains

   subroutine collect_massif_elements(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('gauss_monomials', test_gauss), &
               new_unittest('shape_partition_kronecker', test_shape_values), &
               new_unittest('shape_derivatives_fd', test_shape_fd), &
               new_unittest('edges_left_mid', test_edges), &
               new_unittest('factory_names', test_factory), &
               new_unittest('b_linear_field_plane', test_b_plane), &
               new_unittest('b_linear_field_axi', test_b_axi), &
               new_unittest('bad_geometry_errors', test_bad_geometry), &
               new_unittest('rigid_modes', test_rigid_modes), &
               new_unittest('stiffness_eigenvalues', test_eigen)]
   end subroutine collect_massif_elements

   !> Exact integral of x^a over [-1, 1].
   pure real(wp) function line_moment(a)
      integer, intent(in) :: a
      line_moment = merge(2.0_wp/real(a + 1, wp), 0.0_wp, mod(a, 2) == 0)
   end function line_moment

   !> Exact integral of xi^a eta^b over the reference triangle: a! b! / (a + b + 2)!.
   pure real(wp) function tri_moment(a, b)
      integer, intent(in) :: a, b
      tri_moment = gamma(real(a + 1, wp))*gamma(real(b + 1, wp))/gamma(real(a + b + 3, wp))
   end function tri_moment

   !> Every rule integrates every monomial up to its degree exactly (to rounding).
   subroutine test_gauss(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: x(:), w(:), xi(:, :)
      integer, parameter :: TRI_NP(4) = [1, 3, 6, 7], TRI_DEG(4) = [1, 2, 4, 5]
      integer :: n, a, b, i
      do n = 1, 4
         call gauss_line(n, x, w)
         do a = 0, 2*n - 1
            call check_close(error, sum(w*x**a), line_moment(a), 0.0_wp, 'Gauss line', 1.0e-14_wp)
            if (allocated(error)) return
         end do
      end do
      do n = 2, 3
         call lobatto_line(n, x, w)
         do a = 0, 2*n - 3
            call check_close(error, sum(w*x**a), line_moment(a), 0.0_wp, 'Lobatto', 1.0e-14_wp)
            if (allocated(error)) return
         end do
      end do
      do n = 1, 3
         call gauss_quad(n, xi, w)
         do a = 0, 2*n - 1
            do b = 0, 2*n - 1
               call check_close(error, sum(w*xi(1, :)**a*xi(2, :)**b), &
                  line_moment(a)*line_moment(b), 0.0_wp, 'Gauss quad', 1.0e-14_wp)
               if (allocated(error)) return
            end do
         end do
      end do
      do i = 1, size(TRI_NP)
         call gauss_triangle(TRI_NP(i), xi, w)
         call check(error, size(w) == TRI_NP(i), 'triangle rule size')
         if (allocated(error)) return
         do a = 0, TRI_DEG(i)
            do b = 0, TRI_DEG(i) - a
               call check_close(error, sum(w*xi(1, :)**a*xi(2, :)**b), tri_moment(a, b), &
                  0.0_wp, 'Gauss triangle', 1.0e-15_wp)
               if (allocated(error)) return
            end do
         end do
      end do
      call gauss_line(9, x, w)
      call check(error, size(x) == 0, 'unsupported rule must be empty')
   end subroutine test_gauss

   !> Reference coordinates of the nodes, in element node order.
   function reference_nodes(name) result(xn)
      character(len=2), intent(in) :: name
      real(wp), allocatable :: xn(:, :)
      select case (name)
      case ('T3')
         xn = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 3])
      case ('T6')
         xn = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.5_wp, 0.0_wp, &
                       0.5_wp, 0.5_wp, 0.0_wp, 0.5_wp], [2, 6])
      case ('Q4')
         xn = reshape([-1.0_wp, -1.0_wp, 1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp, 1.0_wp], [2, 4])
      case default
         xn = reshape([-1.0_wp, -1.0_wp, 1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp, 1.0_wp, &
                       0.0_wp, -1.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, -1.0_wp, 0.0_wp], [2, 8])
      end select
   end function reference_nodes

   !> Sample points inside the reference element (not Gauss points).
   function sample_points(name) result(p)
      character(len=2), intent(in) :: name
      real(wp) :: p(2, 3)
      if (name(1:1) == 'T') then
         p = reshape([0.2_wp, 0.3_wp, 0.6_wp, 0.1_wp, 0.05_wp, 0.85_wp], [2, 3])
      else
         p = reshape([0.3_wp, -0.7_wp, -0.5_wp, 0.2_wp, 0.9_wp, 0.95_wp], [2, 3])
      end if
   end function sample_points

   !> Partition of unity, zero derivative sums, Kronecker property at the nodes, and
   !> isoparametric reproduction of the reference coordinates (all exact to rounding).
   subroutine test_shape_values(error)
      type(error_t), allocatable, intent(out) :: error
      class(massif_element_t), allocatable :: elem
      real(wp), allocatable :: xn(:, :)
      real(wp) :: n(8), dn(2, 8), p(2, 3), eye
      integer :: ie, i, j, nn
      do ie = 1, size(NAMES)
         call new_massif_element(NAMES(ie), elem, error)
         if (allocated(error)) return
         nn = elem%nnode()
         xn = reference_nodes(NAMES(ie))
         p = sample_points(NAMES(ie))
         do i = 1, 3
            call elem%shape(p(:, i), n(1:nn), dn(:, 1:nn))
            call check_close(error, sum(n(1:nn)), 1.0_wp, 1.0e-14_wp, NAMES(ie)//' sum N')
            if (allocated(error)) return
            call check(error, all(abs(sum(dn(:, 1:nn), dim=2)) < 1.0e-14_wp), NAMES(ie)//' sum dN')
            if (allocated(error)) return
            call check(error, all(abs(matmul(xn, n(1:nn)) - p(:, i)) < 1.0e-14_wp), &
               NAMES(ie)//' sum N xi_i = xi')
            if (allocated(error)) return
         end do
         do j = 1, nn
            call elem%shape(xn(:, j), n(1:nn), dn(:, 1:nn))
            do i = 1, nn
               eye = merge(1.0_wp, 0.0_wp, i == j)
               call check_close(error, n(i), eye, 0.0_wp, NAMES(ie)//' N_i(x_j)', 1.0e-15_wp)
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_shape_values

   !> dN/dxi against central differences (h = 1e-5): the shape functions are at most
   !> quadratic along each axis, so the difference is exact up to rounding ~1e-16/h.
   subroutine test_shape_fd(error)
      type(error_t), allocatable, intent(out) :: error
      class(massif_element_t), allocatable :: elem
      real(wp), parameter :: H = 1.0e-5_wp
      real(wp) :: n(8), dn(2, 8), np(8), nm(8), dtmp(2, 8), p(2, 3), e(2)
      integer :: ie, i, a, nn
      do ie = 1, size(NAMES)
         call new_massif_element(NAMES(ie), elem, error)
         if (allocated(error)) return
         nn = elem%nnode()
         p = sample_points(NAMES(ie))
         do i = 1, 3
            call elem%shape(p(:, i), n(1:nn), dn(:, 1:nn))
            do a = 1, 2
               e = 0.0_wp
               e(a) = H
               call elem%shape(p(:, i) + e, np(1:nn), dtmp(:, 1:nn))
               call elem%shape(p(:, i) - e, nm(1:nn), dtmp(:, 1:nn))
               call check(error, all(abs((np(1:nn) - nm(1:nn))/(2.0_wp*H) - dn(a, 1:nn)) &
                  < 1.0e-9_wp), NAMES(ie)//' dN/dxi vs central differences')
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_shape_fd

   !> Each edge has the element on its left (cross product with the centroid direction
   !> positive) and its mid-side node at the midpoint of its ends (reference space).
   subroutine test_edges(error)
      type(error_t), allocatable, intent(out) :: error
      class(massif_element_t), allocatable :: elem
      real(wp), allocatable :: xn(:, :)
      integer, allocatable :: ed(:, :)
      real(wp) :: c(2), t(2), v(2)
      integer :: ie, k
      do ie = 1, size(NAMES)
         call new_massif_element(NAMES(ie), elem, error)
         if (allocated(error)) return
         xn = reference_nodes(NAMES(ie))
         ed = elem%edges()
         call check(error, size(ed, 2) == merge(3, 4, NAMES(ie)(1:1) == 'T') .and. &
            size(ed, 1) == merge(3, 2, elem%nnode() > 4), NAMES(ie)//' edge table shape')
         if (allocated(error)) return
         c = sum(xn(:, 1:size(ed, 2)), dim=2)/size(ed, 2)
         do k = 1, size(ed, 2)
            t = xn(:, ed(2, k)) - xn(:, ed(1, k))
            v = c - xn(:, ed(1, k))
            call check(error, t(1)*v(2) - t(2)*v(1) > 0.0_wp, NAMES(ie)//' element left of edge')
            if (allocated(error)) return
            if (size(ed, 1) == 3) then
               call check(error, all(abs(xn(:, ed(3, k)) - 0.5_wp*(xn(:, ed(1, k)) + &
                  xn(:, ed(2, k)))) < 1.0e-15_wp), NAMES(ie)//' mid-side node of edge')
               if (allocated(error)) return
            end if
         end do
      end do
   end subroutine test_edges

   !> Names are case-insensitive; an unknown name is an error listing the known ones.
   subroutine test_factory(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      class(massif_element_t), allocatable :: elem
      call new_massif_element(' q8', elem, error)
      if (allocated(error)) return
      call check(error, elem%name() == 'Q8' .and. elem%nnode() == 8, 'q8 gives Q8')
      if (allocated(error)) return
      call check(error, massif_element_nnode('t6') == 6 .and. massif_element_nnode('X9') == 0, &
         'massif_element_nnode')
      if (allocated(error)) return
      call new_massif_element('Q9', elem, e)
      call check(error, allocated(e), 'Q9 must be unknown')
      if (allocated(error)) return
      call check(error, index(e%text(), 'Q9') > 0 .and. index(e%text(), 'T3 T6 Q4 Q8') > 0, &
         'message names the type and lists the known ones: '//e%text())
   end subroutine test_factory

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
      character(len=2), intent(in) :: name
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
   subroutine test_eigen(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: KINDS(2) = [PLANE_STRAIN, AXISYMMETRIC]
      real(wp), allocatable :: ke(:, :), lam(:)
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
            call check(error, nzero == expected .and. lam(nzero + 1) > 1.0e-4_wp*lam(size(lam)) &
               .and. lam(1) > -1.0e-10_wp*lam(size(lam)), NAMES(ie)//' zero-energy modes')
            if (allocated(error)) return
            deallocate (lam)
         end do
      end do
   end subroutine test_eigen

end module test_massif_elements
