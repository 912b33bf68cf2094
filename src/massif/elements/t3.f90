!> 3-node linear triangle (constant strain in plane strain), one-point integration.
!> Reference nodes (0,0), (1,0), (0,1).
module pecplas_massif_elements_t3
   use pecplas_base_kinds, only: wp
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_gauss, only: gauss_triangle
   implicit none (type, external)
   private

   public :: t3_element_t

   !> Linear triangle T3.
   type, extends(massif_element_t) :: t3_element_t
   contains
      procedure :: name => t3_name
      procedure :: nnode => t3_nnode
      procedure :: gauss => t3_gauss
      procedure :: shape => t3_shape
      procedure :: edges => t3_edges
   end type t3_element_t

contains

   pure function t3_name(this) result(name)
      class(t3_element_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = 'T3'
   end function t3_name

   pure integer function t3_nnode(this)
      class(t3_element_t), intent(in) :: this
      t3_nnode = 3
   end function t3_nnode

   !> Centroid rule: exact for the constant B of plane strain. In axisymmetry the hoop
   !> term N/r is evaluated at the centroid (the classical choice; patch test exact).
   pure subroutine t3_gauss(this, xi, w)
      class(t3_element_t), intent(in) :: this
      real(wp), allocatable, intent(out) :: xi(:, :), w(:)
      call gauss_triangle(1, xi, w)
   end subroutine t3_gauss

   pure subroutine t3_shape(this, xi, n, dn)
      class(t3_element_t), intent(in) :: this
      real(wp), intent(in) :: xi(2)
      real(wp), intent(out) :: n(:), dn(:, :)
      n(1:3) = [1.0_wp - xi(1) - xi(2), xi(1), xi(2)]
      dn(:, 1) = [-1.0_wp, -1.0_wp]
      dn(:, 2) = [1.0_wp, 0.0_wp]
      dn(:, 3) = [0.0_wp, 1.0_wp]
   end subroutine t3_shape

   pure function t3_edges(this) result(edges)
      class(t3_element_t), intent(in) :: this
      integer, allocatable :: edges(:, :)
      edges = reshape([1, 2, 2, 3, 3, 1], [2, 3])
   end function t3_edges

end module pecplas_massif_elements_t3
