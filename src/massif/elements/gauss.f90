!> Integration rules on the reference line [-1, 1], square [-1, 1]^2 and triangle
!> (0,0), (1,0), (0,1). An unsupported number of points gives empty arrays (the
!> element types only ask for supported rules; callers with user input check `size`).
module pecplas_massif_elements_gauss
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: gauss_line, lobatto_line, gauss_quad, gauss_triangle

contains

   !> Gauss–Legendre rule of n = 1..4 points on [-1, 1], exact for degree 2n - 1.
   pure subroutine gauss_line(n, x, w)
      integer, intent(in) :: n
      real(wp), allocatable, intent(out) :: x(:), w(:)
      real(wp) :: a, b
      select case (n)
      case (1)
         x = [0.0_wp]
         w = [2.0_wp]
      case (2)
         a = 1.0_wp/sqrt(3.0_wp)
         x = [-a, a]
         w = [1.0_wp, 1.0_wp]
      case (3)
         a = sqrt(0.6_wp)
         x = [-a, 0.0_wp, a]
         w = [5.0_wp, 8.0_wp, 5.0_wp]/9.0_wp
      case (4)
         a = sqrt(3.0_wp/7.0_wp - 2.0_wp/7.0_wp*sqrt(1.2_wp))
         b = sqrt(3.0_wp/7.0_wp + 2.0_wp/7.0_wp*sqrt(1.2_wp))
         x = [-b, -a, a, b]
         w = [18.0_wp - sqrt(30.0_wp), 18.0_wp + sqrt(30.0_wp), 18.0_wp + sqrt(30.0_wp), &
              18.0_wp - sqrt(30.0_wp)]/36.0_wp
      case default
         allocate (x(0), w(0))
      end select
   end subroutine gauss_line

   !> Gauss–Lobatto rule of n = 2, 3 points on [-1, 1] (end points included), exact for
   !> degree 2n - 3. Used by joint elements to avoid traction oscillations.
   pure subroutine lobatto_line(n, x, w)
      integer, intent(in) :: n
      real(wp), allocatable, intent(out) :: x(:), w(:)
      select case (n)
      case (2)
         x = [-1.0_wp, 1.0_wp]
         w = [1.0_wp, 1.0_wp]
      case (3)
         x = [-1.0_wp, 0.0_wp, 1.0_wp]
         w = [1.0_wp, 4.0_wp, 1.0_wp]/3.0_wp
      case default
         allocate (x(0), w(0))
      end select
   end subroutine lobatto_line

   !> Tensor Gauss rule of n x n points on [-1, 1]^2; xi(2, n*n) with xi(1) running fastest.
   pure subroutine gauss_quad(n, xi, w)
      integer, intent(in) :: n
      real(wp), allocatable, intent(out) :: xi(:, :), w(:)
      real(wp), allocatable :: x1(:), w1(:)
      integer :: i, j, k
      call gauss_line(n, x1, w1)
      allocate (xi(2, size(x1)**2), w(size(x1)**2))
      k = 0
      do j = 1, size(x1)
         do i = 1, size(x1)
            k = k + 1
            xi(:, k) = [x1(i), x1(j)]
            w(k) = w1(i)*w1(j)
         end do
      end do
   end subroutine gauss_quad

   !> Symmetric rules on the triangle (0,0), (1,0), (0,1); weights sum to its area 1/2.
   !> npoint = 1 (degree 1, centroid), 3 (degree 2, interior points, point k nearest
   !> corner k), 6 (degree 4, Strang–Fix/Dunavant), 7 (degree 5, Radon).
   pure subroutine gauss_triangle(npoint, xi, w)
      integer, intent(in) :: npoint
      real(wp), allocatable, intent(out) :: xi(:, :), w(:)
      ! Degree-4 orbit parameters, solved from the moment equations to 30 digits.
      real(wp), parameter :: A4 = 0.445948490915964886318329253883_wp, &
                             B4 = 0.0915762135097707434595714634022_wp, &
                             WA4 = 0.223381589678011465695007008433_wp, &
                             WB4 = 0.1099517436553218676383263249_wp
      real(wp) :: a, b, wa, wb
      select case (npoint)
      case (1)
         xi = reshape([1.0_wp, 1.0_wp]/3.0_wp, [2, 1])
         w = [0.5_wp]
      case (3)
         allocate (xi(2, 3))
         call orbit(1.0_wp/6.0_wp, xi)
         w = [1.0_wp, 1.0_wp, 1.0_wp]/6.0_wp
      case (6)
         allocate (xi(2, 6))
         call orbit(A4, xi(:, 1:3))
         call orbit(B4, xi(:, 4:6))
         w = 0.5_wp*[WA4, WA4, WA4, WB4, WB4, WB4]
      case (7)
         a = (6.0_wp - sqrt(15.0_wp))/21.0_wp
         b = (6.0_wp + sqrt(15.0_wp))/21.0_wp
         wa = (155.0_wp - sqrt(15.0_wp))/1200.0_wp
         wb = (155.0_wp + sqrt(15.0_wp))/1200.0_wp
         allocate (xi(2, 7))
         xi(:, 1) = [1.0_wp, 1.0_wp]/3.0_wp
         call orbit(a, xi(:, 2:4))
         call orbit(b, xi(:, 5:7))
         w = 0.5_wp*[0.225_wp, wa, wa, wa, wb, wb, wb]
      case default
         allocate (xi(2, 0), w(0))
      end select
   end subroutine gauss_triangle

   !> The three points with area coordinates (1-2a, a, a) and permutations, point k
   !> nearest corner k when a < 1/3.
   pure subroutine orbit(a, xi)
      real(wp), intent(in) :: a
      real(wp), intent(out) :: xi(2, 3)
      xi(:, 1) = [a, a]
      xi(:, 2) = [1.0_wp - 2.0_wp*a, a]
      xi(:, 3) = [a, 1.0_wp - 2.0_wp*a]
   end subroutine orbit

end module pecplas_massif_elements_gauss
