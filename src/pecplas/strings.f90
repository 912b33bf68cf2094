!> Case handling of names: keywords, parameters, set/material/law names are compared
!> case-insensitively everywhere.
module pecplas_strings
   implicit none (type, external)
   private

   public :: upper, same_name

contains

   !> Upper-case copy without leading or trailing blanks.
   pure function upper(s) result(u)
      character(len=*), intent(in) :: s
      character(len=len_trim(adjustl(s))) :: u
      integer :: i, c
      u = trim(adjustl(s))
      do i = 1, len(u)
         c = iachar(u(i:i))
         if (c >= 97 .and. c <= 122) u(i:i) = achar(c - 32)
      end do
   end function upper

   !> Case-insensitive comparison of two names.
   pure logical function same_name(a, b)
      character(len=*), intent(in) :: a, b
      same_name = upper(a) == upper(b)
   end function same_name

end module pecplas_strings
