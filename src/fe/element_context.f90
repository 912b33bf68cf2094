!> Context for an error raised by one massif element (or a loaded side of one): its id and
!> set in the message, its deck line (model%provenance) as the error's position.
module pecplas_fe_element_context
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_provenance, only: place_t
   implicit none (type, external)
   private

   public :: element_context, edge_context

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

   !> Prefixes "load <name>, edge (<node ids>): " to an error of a loaded edge and gives it
   !> the deck line of the element whose side the edge is (its geometry is at fault).
   subroutine edge_context(error, model, name, edge)
      type(error_t), allocatable, intent(inout) :: error
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      integer, intent(in) :: edge(:)
      type(place_t) :: p
      character(len=:), allocatable :: keyword, ids
      character(len=32) :: buf
      integer :: s, e, j
      if (.not. allocated(error)) return
      ids = ''
      do j = 1, size(edge)
         write (buf, '(i0)') model%mesh%node_id(edge(j))
         ids = ids//trim(buf)//merge(' ', ')', j < size(edge))
      end do
      error%message = "load '"//name//"', edge ("//ids//': '//error%message
      do s = 1, size(model%mesh%esets)
         do e = 1, size(model%mesh%esets(s)%conn, 2)
            if (all([(any(model%mesh%esets(s)%conn(:, e) == edge(j)), j=1, size(edge))])) then
               write (buf, '(i0)') model%mesh%esets(s)%ids(e)
               error%message = error%message//' (a side of element '//trim(buf)//' of set '// &
                  model%mesh%esets(s)%name//')'
               call model%provenance%element(s, e, p, keyword)
               call model%provenance%locate(error, p, keyword)
               return
            end if
         end do
      end do
   end subroutine edge_context

end module pecplas_fe_element_context
