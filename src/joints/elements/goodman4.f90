!> GOODMAN4: zero-thickness joint of two node doublets (B.7–B.8), linear along the joint;
!> attaches to linear element sides (T3, Q4).
module pecplas_joints_elements_goodman4
   use pecplas_joints_elements_line, only: line_joint_t
   implicit none (type, external)
   private

   public :: goodman4_t

   type, extends(line_joint_t) :: goodman4_t
   contains
      procedure :: name => goodman4_name
   end type goodman4_t

contains

   pure function goodman4_name(this) result(name)
      class(goodman4_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = 'GOODMAN4'
   end function goodman4_name

end module pecplas_joints_elements_goodman4
