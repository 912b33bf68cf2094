!> GOODMAN6: zero-thickness joint of three node doublets (B.9–B.10, last entry of row 1
!> read as N3 C), quadratic along the joint; attaches to quadratic sides (T6, Q8).
module pecplas_joints_elements_goodman6
   use pecplas_joints_elements_line, only: line_joint_t
   implicit none (type, external)
   private

   public :: goodman6_t

   type, extends(line_joint_t) :: goodman6_t
   contains
      procedure :: name => goodman6_name
   end type goodman6_t

contains

   pure function goodman6_name(this) result(name)
      class(goodman6_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = 'GOODMAN6'
   end function goodman6_name

end module pecplas_joints_elements_goodman6
