!> 8-node serendipity quadrilateral, 3 x 3 Gauss integration. Reference corners
!> (-1,-1), (1,-1), (1,1), (-1,1); node 5 on edge 1-2, 6 on 2-3, 7 on 3-4, 8 on 4-1.
module pecplas_massif_elements_q8
   use pecplas_base_kinds, only: wp
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_gauss, only: gauss_quad
   implicit none (type, external)
   private

   public :: q8_element_t

   !> Serendipity quadrilateral Q8.
   type, extends(massif_element_t) :: q8_element_t
   contains
      procedure :: name => q8_name
      procedure :: nnode => q8_nnode
      procedure :: gauss => q8_gauss
      procedure :: shape => q8_shape
      procedure :: edges => q8_edges
   end type q8_element_t

   real(wp), parameter :: XN(8) = [-1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, -1.0_wp]
   real(wp), parameter :: YN(8) = [-1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp]

contains

   pure function q8_name(this) result(name)
      class(q8_element_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = 'Q8'
   end function q8_name

   pure integer function q8_nnode(this)
      class(q8_element_t), intent(in) :: this
      q8_nnode = 8
   end function q8_nnode

   !> Full 3 x 3 rule: the 2 x 2 rule would leave a spurious zero-energy mode.
   pure subroutine q8_gauss(this, xi, w)
      class(q8_element_t), intent(in) :: this
      real(wp), allocatable, intent(out) :: xi(:, :), w(:)
      call gauss_quad(3, xi, w)
   end subroutine q8_gauss

   pure subroutine q8_shape(this, xi, n, dn)
      class(q8_element_t), intent(in) :: this
      real(wp), intent(in) :: xi(2)
      real(wp), intent(out) :: n(:), dn(:, :)
      real(wp) :: s, t, a, b
      integer :: i
      s = xi(1)
      t = xi(2)
      do i = 1, 4
         a = 1.0_wp + XN(i)*s
         b = 1.0_wp + YN(i)*t
         n(i) = 0.25_wp*a*b*(XN(i)*s + YN(i)*t - 1.0_wp)
         dn(1, i) = 0.25_wp*XN(i)*b*(2.0_wp*XN(i)*s + YN(i)*t)
         dn(2, i) = 0.25_wp*YN(i)*a*(XN(i)*s + 2.0_wp*YN(i)*t)
      end do
      do i = 5, 7, 2 ! nodes at xi = 0
         b = 1.0_wp + YN(i)*t
         n(i) = 0.5_wp*(1.0_wp - s*s)*b
         dn(1, i) = -s*b
         dn(2, i) = 0.5_wp*(1.0_wp - s*s)*YN(i)
      end do
      do i = 6, 8, 2 ! nodes at eta = 0
         a = 1.0_wp + XN(i)*s
         n(i) = 0.5_wp*a*(1.0_wp - t*t)
         dn(1, i) = 0.5_wp*XN(i)*(1.0_wp - t*t)
         dn(2, i) = -a*t
      end do
   end subroutine q8_shape

   pure function q8_edges(this) result(edges)
      class(q8_element_t), intent(in) :: this
      integer, allocatable :: edges(:, :)
      edges = reshape([1, 2, 5, 2, 3, 6, 3, 4, 7, 4, 1, 8], [3, 4])
   end function q8_edges

end module pecplas_massif_elements_q8
