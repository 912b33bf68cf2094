!> Maps deck element names to massif element types.
module pecplas_massif_elements_factory
   use pecplas_base_error, only: error_t, input_error
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_t3, only: t3_element_t
   use pecplas_massif_elements_t6, only: t6_element_t
   use pecplas_massif_elements_q4, only: q4_element_t
   use pecplas_massif_elements_q8, only: q8_element_t
   use pecplas_massif_elements_q8r, only: q8r_element_t
   use pecplas_base_strings, only: upper
   implicit none (type, external)
   private

   public :: new_massif_element, massif_element_nnode, KNOWN_MASSIF_ELEMENTS

   !> Deck names of the massif elements, in the order listed in error messages.
   character(len=3), parameter :: KNOWN_MASSIF_ELEMENTS(5) = [character(len=3) :: 'T3', 'T6', 'Q4', &
      'Q8', 'Q8R']

contains

   !> Allocates the element type called `name` (case-insensitive, surrounding blanks
   !> ignored); an unknown name is an input error that lists the known names.
   subroutine new_massif_element(name, elem, error)
      character(len=*), intent(in) :: name
      class(massif_element_t), allocatable, intent(out) :: elem
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: known
      integer :: i
      select case (upper(trim(adjustl(name))))
      case ('T3')
         allocate (t3_element_t :: elem)
      case ('T6')
         allocate (t6_element_t :: elem)
      case ('Q4')
         allocate (q4_element_t :: elem)
      case ('Q8')
         allocate (q8_element_t :: elem)
      case ('Q8R')
         allocate (q8r_element_t :: elem)
      case default
         known = ''
         do i = 1, size(KNOWN_MASSIF_ELEMENTS)
            known = known//' '//trim(KNOWN_MASSIF_ELEMENTS(i))
         end do
         call input_error(error, 'unknown massif element type "'//trim(adjustl(name))// &
            '"; known types:'//known)
      end select
   end subroutine new_massif_element

   !> Nodes per element of the type called `name` (case-insensitive); 0 when unknown.
   pure integer function massif_element_nnode(name) result(nnode)
      character(len=*), intent(in) :: name
      select case (upper(trim(adjustl(name))))
      case ('T3')
         nnode = 3
      case ('T6')
         nnode = 6
      case ('Q4')
         nnode = 4
      case ('Q8', 'Q8R')
         nnode = 8
      case default
         nnode = 0
      end select
   end function massif_element_nnode

end module pecplas_massif_elements_factory
