!> 6-node quadratic triangle, 3-point (degree 2) integration. Reference corners
!> (0,0), (1,0), (0,1); node 4 on edge 1-2, 5 on 2-3, 6 on 3-1 (Gmsh order).
module pecplas_massif_elements_t6
   use pecplas_base_kinds, only: wp
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_gauss, only: gauss_triangle
   implicit none (type, external)
   private

   public :: t6_element_t

   !> Quadratic triangle T6.
   type, extends(massif_element_t) :: t6_element_t
   contains
      procedure :: name => t6_name
      procedure :: nnode => t6_nnode
      procedure :: gauss => t6_gauss
      procedure :: shape => t6_shape
      procedure :: edges => t6_edges
   end type t6_element_t

contains

   pure function t6_name(this) result(name)
      class(t6_element_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = 'T6'
   end function t6_name

   pure integer function t6_nnode(this)
      class(t6_element_t), intent(in) :: this
      t6_nnode = 6
   end function t6_nnode

   !> Degree-2 rule: exact stiffness for straight-sided elements in plane strain.
   pure subroutine t6_gauss(this, xi, w)
      class(t6_element_t), intent(in) :: this
      real(wp), allocatable, intent(out) :: xi(:, :), w(:)
      call gauss_triangle(3, xi, w)
   end subroutine t6_gauss

   !> Area coordinates L1 = 1 - xi - eta, L2 = xi, L3 = eta; corners L(2L - 1),
   !> mid-sides 4 Li Lj.
   pure subroutine t6_shape(this, xi, n, dn)
      class(t6_element_t), intent(in) :: this
      real(wp), intent(in) :: xi(2)
      real(wp), intent(out) :: n(:), dn(:, :)
      real(wp) :: l1, l2, l3
      l1 = 1.0_wp - xi(1) - xi(2)
      l2 = xi(1)
      l3 = xi(2)
      n(1:6) = [l1*(2.0_wp*l1 - 1.0_wp), l2*(2.0_wp*l2 - 1.0_wp), l3*(2.0_wp*l3 - 1.0_wp), &
                4.0_wp*l1*l2, 4.0_wp*l2*l3, 4.0_wp*l3*l1]
      ! d/dxi = d/dL2 - d/dL1, d/deta = d/dL3 - d/dL1
      dn(:, 1) = -(4.0_wp*l1 - 1.0_wp)
      dn(:, 2) = [4.0_wp*l2 - 1.0_wp, 0.0_wp]
      dn(:, 3) = [0.0_wp, 4.0_wp*l3 - 1.0_wp]
      dn(:, 4) = 4.0_wp*[l1 - l2, -l2]
      dn(:, 5) = 4.0_wp*[l3, l2]
      dn(:, 6) = 4.0_wp*[-l3, l1 - l3]
   end subroutine t6_shape

   pure function t6_edges(this) result(edges)
      class(t6_element_t), intent(in) :: this
      integer, allocatable :: edges(:, :)
      edges = reshape([1, 2, 4, 2, 3, 5, 3, 1, 6], [3, 3])
   end function t6_edges

end module pecplas_massif_elements_t6
