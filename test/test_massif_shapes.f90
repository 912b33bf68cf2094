!> Integration rules, shape functions (values, derivatives, node order, edges) and the
!> element factory of the massif elements T3, T6, Q4, Q8.
module test_massif_shapes
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_factory, only: new_massif_element, massif_element_nnode, &
      KNOWN_MASSIF_ELEMENTS
   use pecplas_massif_elements_gauss, only: gauss_line, lobatto_line, gauss_quad, gauss_triangle
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_massif, only: sample_points
   implicit none (type, external)
   private
   public :: collect_massif_shapes

   character(len=*), parameter :: NAMES(*) = KNOWN_MASSIF_ELEMENTS

contains

   subroutine collect_massif_shapes(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('gauss_monomials', test_gauss), &
               new_unittest('shape_partition_kronecker', test_shape_values), &
               new_unittest('shape_derivatives_fd', test_shape_fd), &
               new_unittest('edges_left_mid', test_edges), &
               new_unittest('factory_names', test_factory)]
   end subroutine collect_massif_shapes

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
      character(len=*), intent(in) :: name
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

end module test_massif_shapes
