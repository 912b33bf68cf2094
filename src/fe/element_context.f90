!> Context for an error raised by one massif element: its id and set in the message, its
!> deck line (model%provenance) as the error's position.
module pecplas_fe_element_context
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_provenance, only: place_t
   implicit none (type, external)
   private

   public :: element_context

contains

   !> Prefixes "element <id> of set <name>: " and gives the error the element's deck line.
   subroutine element_context(error, model, s, e)
      type(error_t), allocatable, intent(inout) :: error
      type(model_t), intent(in) :: model
      integer, intent(in) :: s, e
      type(place_t) :: p
      character(len=:), allocatable :: keyword
      character(len=32) :: buf
      if (.not. allocated(error)) return
      write (buf, '(i0)') model%mesh%esets(s)%ids(e)
      error%message = 'element '//trim(buf)//' of set '//model%mesh%esets(s)%name//': '// &
         error%message
      call model%provenance%element(s, e, p, keyword)
      call model%provenance%locate(error, p, keyword)
   end subroutine element_context

end module pecplas_fe_element_context
