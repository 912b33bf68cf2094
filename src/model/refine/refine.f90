!> Uniform refinement (h/2) of a model read from a deck, in memory (the mesh level of
!> `pecplas --advise`): every element marked for the local refiner (pecplas_model_refine_local),
!> so Q4 -> 4 Q4, Q8 -> 4 Q8, T3 and T6 -> 4 triangles (bisections), joints of every type
!> split with their neighbours, node sets, supports, imposed displacements, pressures and
!> edge sets carried over. Original nodes keep their internal numbers and ids; new nodes
!> come after them, with ids above the largest. Refused with a one-line reason (no model):
!> point forces on both ends of an edge, supports or imposed displacements on both ends of an
!> interior edge (their share on the new node is not knowable from the resolved lists).
module pecplas_model_refine_refine
   use pecplas_model_type, only: model_t
   use pecplas_model_refine_local, only: refine_marked
   implicit none (type, external)
   private

   public :: refine_model

contains

   !> `fine` = `model` refined once; `reason` is allocated (and `fine` undefined) when refused.
   subroutine refine_model(model, fine, reason)
      type(model_t), intent(in) :: model
      type(model_t), intent(out) :: fine
      character(len=:), allocatable, intent(out) :: reason
      logical, allocatable :: all_marked(:)
      allocate (all_marked(model%mesh%nelem()), source=.true.)
      call refine_marked(model, all_marked, fine, reason)
   end subroutine refine_model

end module pecplas_model_refine_refine
