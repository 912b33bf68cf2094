!> 8-node serendipity quadrilateral with reduced 2 x 2 Gauss integration (deck name Q8R,
!> Abaqus CPE8R/CAX8R). Same shape functions, nodes and edges as Q8; only the rule differs.
!>
!> Why: with 3 x 3 points an element of isochoric (perfectly plastic, phi = psi = 0) material
!> must keep 9 volume constraints for 16 - 3 free displacements, and a mesh locks after plastic
!> flow (the collapse load is overestimated or never reached). 2 x 2 points halve the constraints.
!> Price: one spurious zero-energy mode per element (3 rigid modes + 1, against 13 strain modes
!> with 4 points x 3 strains = 12). It is not communicable: an element sharing a full side
!> (3 nodes) with another one, or with a side held by supports, cannot deform in it (see
!> doc/theory.md, "Elements for collapse loads", and the test massif_q8r).
module pecplas_massif_elements_q8r
   use pecplas_base_kinds, only: wp
   use pecplas_massif_elements_q8, only: q8_element_t
   use pecplas_massif_elements_gauss, only: gauss_quad
   implicit none (type, external)
   private

   public :: q8r_element_t

   !> Serendipity quadrilateral with reduced integration, Q8R.
   type, extends(q8_element_t) :: q8r_element_t
   contains
      procedure :: name => q8r_name
      procedure :: gauss => q8r_gauss
   end type q8r_element_t

contains

   pure function q8r_name(this) result(name)
      class(q8r_element_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = 'Q8R'
   end function q8r_name

   !> Reduced 2 x 2 rule: exact for the stiffness of a parallelogram up to the quadratic
   !> terms of B^T D B, so the patch test holds.
   pure subroutine q8r_gauss(this, xi, w)
      class(q8r_element_t), intent(in) :: this
      real(wp), allocatable, intent(out) :: xi(:, :), w(:)
      call gauss_quad(2, xi, w)
   end subroutine q8r_gauss

end module pecplas_massif_elements_q8r
