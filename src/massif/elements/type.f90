!> Abstract isoparametric massif element (reference geometry, shape functions,
!> integration rule, edges). Concrete types: T3, T6, Q4, Q8, Q8R (one file each).
!> Node order: corners counter-clockwise, then mid-side nodes (Gmsh order).
module pecplas_massif_elements_type
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: massif_element_t, massif_element_box_t

   type, abstract :: massif_element_t
   contains
      !> Deck name: 'T3', 'T6', 'Q4', 'Q8', 'Q8R'.
      procedure(name_ifc), deferred :: name
      !> Nodes per element.
      procedure(count_ifc), deferred :: nnode
      !> Integration rule: points xi(2, ngauss) in the reference element, weights w(ngauss).
      procedure(gauss_ifc), deferred :: gauss
      !> Shape functions N(nnode) and derivatives dN(2, nnode) = dN/dxi at xi(2).
      procedure(shape_ifc), deferred :: shape
      !> Local node numbers of each edge (nodes per edge, nedges): end, end, [mid],
      !> ordered so that the element lies on the left of the edge.
      procedure(edges_ifc), deferred :: edges
   end type massif_element_t

   type :: massif_element_box_t
      class(massif_element_t), allocatable :: e
   end type massif_element_box_t

   abstract interface
      pure function name_ifc(this) result(name)
         import :: massif_element_t
         class(massif_element_t), intent(in) :: this
         character(len=:), allocatable :: name
      end function name_ifc

      pure integer function count_ifc(this)
         import :: massif_element_t
         class(massif_element_t), intent(in) :: this
      end function count_ifc

      pure subroutine gauss_ifc(this, xi, w)
         import :: massif_element_t, wp
         class(massif_element_t), intent(in) :: this
         real(wp), allocatable, intent(out) :: xi(:, :), w(:)
      end subroutine gauss_ifc

      pure subroutine shape_ifc(this, xi, n, dn)
         import :: massif_element_t, wp
         class(massif_element_t), intent(in) :: this
         real(wp), intent(in) :: xi(2)
         real(wp), intent(out) :: n(:), dn(:, :)
      end subroutine shape_ifc

      pure function edges_ifc(this) result(edges)
         import :: massif_element_t
         class(massif_element_t), intent(in) :: this
         integer, allocatable :: edges(:, :)
      end function edges_ifc
   end interface

end module pecplas_massif_elements_type
