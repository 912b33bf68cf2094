!> 4-node bilinear quadrilateral, 2 x 2 Gauss integration. Reference nodes
!> (-1,-1), (1,-1), (1,1), (-1,1).
module pecplas_massif_elements_q4
   use pecplas_base_kinds, only: wp
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_gauss, only: gauss_quad
   implicit none (type, external)
   private

   public :: q4_element_t

   !> Bilinear quadrilateral Q4.
   type, extends(massif_element_t) :: q4_element_t
   contains
      procedure :: name => q4_name
      procedure :: nnode => q4_nnode
      procedure :: gauss => q4_gauss
      procedure :: shape => q4_shape
      procedure :: edges => q4_edges
   end type q4_element_t

   real(wp), parameter :: XN(4) = [-1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp]
   real(wp), parameter :: YN(4) = [-1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp]

contains

   pure function q4_name(this) result(name)
      class(q4_element_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = 'Q4'
   end function q4_name

   pure integer function q4_nnode(this)
      class(q4_element_t), intent(in) :: this
      q4_nnode = 4
   end function q4_nnode

   !> Full 2 x 2 rule (no spurious zero-energy modes).
   pure subroutine q4_gauss(this, xi, w)
      class(q4_element_t), intent(in) :: this
      real(wp), allocatable, intent(out) :: xi(:, :), w(:)
      call gauss_quad(2, xi, w)
   end subroutine q4_gauss

   pure subroutine q4_shape(this, xi, n, dn)
      class(q4_element_t), intent(in) :: this
      real(wp), intent(in) :: xi(2)
      real(wp), intent(out) :: n(:), dn(:, :)
      integer :: i
      do i = 1, 4
         n(i) = 0.25_wp*(1.0_wp + XN(i)*xi(1))*(1.0_wp + YN(i)*xi(2))
         dn(1, i) = 0.25_wp*XN(i)*(1.0_wp + YN(i)*xi(2))
         dn(2, i) = 0.25_wp*YN(i)*(1.0_wp + XN(i)*xi(1))
      end do
   end subroutine q4_shape

   pure function q4_edges(this) result(edges)
      class(q4_element_t), intent(in) :: this
      integer, allocatable :: edges(:, :)
      edges = reshape([1, 2, 2, 3, 3, 4, 4, 1], [2, 4])
   end function q4_edges

end module pecplas_massif_elements_q4
