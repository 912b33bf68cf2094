!> Maps deck joint type names (*JOINTS, TYPE=...) to joint element types.
module pecplas_joints_elements_factory
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error
   use pecplas_model_joints, only: JOINT_TYPES
   use pecplas_joints_elements_type, only: joint_element_t
   use pecplas_joints_elements_spring, only: spring_t
   use pecplas_joints_elements_goodman4, only: goodman4_t
   use pecplas_joints_elements_goodman6, only: goodman6_t
   use pecplas_joints_elements_thin_layer, only: thin_layer_t
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private

   public :: new_joint_element, joint_type_names, INTEGRATIONS

   !> Integration rules along line joints.
   character(len=*), parameter :: INTEGRATIONS(2) = [character(len=7) :: 'GAUSS', 'LOBATTO']

contains

   !> Allocates the joint element `name` (case-insensitive) for `nnode` nodes (THIN_LAYER:
   !> 4 or 6; the others have a fixed count that nnode must match), with the integration
   !> 'GAUSS' or 'LOBATTO' (line joints) and the thin layer thickness. An unknown name lists
   !> the known ones.
   subroutine new_joint_element(name, nnode, integration, thickness, elem, error)
      character(len=*), intent(in) :: name, integration
      integer, intent(in) :: nnode
      real(wp), intent(in) :: thickness
      class(joint_element_t), allocatable, intent(out) :: elem
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: type_name, rule
      logical :: lobatto
      type_name = upper(trim(adjustl(name)))
      rule = upper(trim(adjustl(integration)))
      if (len(rule) == 0) rule = 'GAUSS'
      if (rule /= 'GAUSS' .and. rule /= 'LOBATTO') then
         call input_error(error, 'unknown joint integration "'//trim(integration)// &
            '"; known: GAUSS LOBATTO')
         return
      end if
      lobatto = rule == 'LOBATTO'
      select case (type_name)
      case ('SPRING')
         if (nnode /= 2) call count_error(2)
         if (allocated(error)) return
         allocate (spring_t :: elem)
      case ('GOODMAN4')
         if (nnode /= 4) call count_error(4)
         if (allocated(error)) return
         allocate (elem, source=goodman4_t(ndoublet=2, lobatto=lobatto))
      case ('GOODMAN6')
         if (nnode /= 6) call count_error(6)
         if (allocated(error)) return
         allocate (elem, source=goodman6_t(ndoublet=3, lobatto=lobatto))
      case ('THIN_LAYER')
         if (nnode /= 4 .and. nnode /= 6) then
            call input_error(error, 'a THIN_LAYER joint has 4 or 6 nodes, not '//itoa(nnode))
            return
         end if
         if (.not. (thickness > 0.0_wp)) then
            call input_error(error, 'a THIN_LAYER joint needs a thickness THICKNESS=e > 0')
            return
         end if
         allocate (elem, source=thin_layer_t(ndoublet=nnode/2, lobatto=lobatto, &
            layer=thickness))
      case default
         call input_error(error, 'unknown joint type "'//trim(adjustl(name))// &
            '"; known types:'//joint_type_names())
      end select
   contains
      subroutine count_error(expected)
         integer, intent(in) :: expected
         call input_error(error, 'a '//type_name//' joint has '//itoa(expected)// &
            ' nodes, not '//itoa(nnode))
      end subroutine count_error
   end subroutine new_joint_element

   !> ' SPRING GOODMAN4 GOODMAN6 THIN_LAYER' (for messages).
   pure function joint_type_names() result(list)
      character(len=:), allocatable :: list
      integer :: i
      list = ''
      do i = 1, size(JOINT_TYPES)
         list = list//' '//trim(JOINT_TYPES(i))
      end do
   end function joint_type_names


   pure function upper(s) result(u)
      character(len=*), intent(in) :: s
      character(len=len(s)) :: u
      integer :: i
      u = s
      do i = 1, len(s)
         if (s(i:i) >= 'a' .and. s(i:i) <= 'z') u(i:i) = achar(iachar(s(i:i)) - 32)
      end do
   end function upper

end module pecplas_joints_elements_factory
