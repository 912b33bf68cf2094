!> What the adaptive loop (pecplas_adapt_adapt) cannot refine along with the mesh: phases,
!> plates and anchors. One reason, for the deck's *ADAPT line and for --target-error alike.
module pecplas_model_adapt_scope
   use pecplas_model_type, only: model_t
   use pecplas_model_phase_plan, only: is_phased
   implicit none (type, external)
   private

   public :: adapt_refusal

contains

   !> Why adaptive refinement is not available for `model` ('' when it is), with what the
   !> user can do instead.
   function adapt_refusal(model) result(reason)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: reason
      character(len=*), parameter :: BY_HAND = '; refine the mesh of the deck by hand'
      reason = ''
      if (is_phased(model)) then
         reason = 'adaptive refinement is not available for a phased deck (doc/deck.md, '// &
            'Phases): the sets a phase activates or removes would have to be refined with it'// &
            BY_HAND
      else if (has_plates(model)) then
         reason = 'adaptive refinement is not available for a deck with plates (*PLATE): '// &
            'the refinement does not carry plates along'//BY_HAND
      else if (has_anchors(model)) then
         reason = 'adaptive refinement is not available for a deck with anchors (*ANCHOR): '// &
            'the refinement does not carry anchors along'//BY_HAND
      end if
   end function adapt_refusal

   pure logical function has_plates(model)
      type(model_t), intent(in) :: model
      has_plates = .false.
      if (allocated(model%plates)) has_plates = size(model%plates) > 0
   end function has_plates

   pure logical function has_anchors(model)
      type(model_t), intent(in) :: model
      has_anchors = .false.
      if (allocated(model%anchors)) has_anchors = size(model%anchors) > 0
   end function has_anchors

end module pecplas_model_adapt_scope
