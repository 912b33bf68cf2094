!> Case handling of names (keywords, parameters, set/material/law names are compared
!> case-insensitively everywhere) and the short number texts of messages and tables.
module pecplas_base_strings
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: upper, same_name, itoa, decimal_text, g6

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

   !> An integer as text, no blanks.
   pure function itoa(i) result(s)
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=16) :: buf
      write (buf, '(i0)') i
      s = trim(buf)
   end function itoa

   !> x with at most `digits` decimals and no trailing zeros: 0.5, 1, 2.25, -0.125.
   pure function decimal_text(x, digits) result(s)
      real(wp), intent(in) :: x
      integer, intent(in) :: digits
      character(len=:), allocatable :: s
      character(len=48) :: buf
      character(len=16) :: fmt
      integer :: i
      write (fmt, '(a,i0,a)') '(f0.', digits, ')'
      write (buf, fmt) x
      s = trim(adjustl(buf))
      if (index(s, '.') > 0) then
         i = len(s)
         do while (s(i:i) == '0')
            i = i - 1
         end do
         if (s(i:i) == '.') i = i - 1
         s = s(1:i)
      end if
      ! a value that rounds to zero (e.g. '-.000' trimmed to '-') is '0', never '-0'
      if (s == '' .or. s == '-') s = '0'
      if (s(1:1) == '.') s = '0'//s
      if (len(s) > 1) then
         if (s(1:2) == '-.') s = '-0'//s(2:)
      end if
   end function decimal_text

   !> Six significant digits, no blanks, in the notation an engineer reads: "0.990099",
   !> "0.0942241", "-2.50000"; outside 1e-4 <= |x| < 1e6 in scientific notation
   !> ("4.38107E-05", "1.23457E+06").
   pure function g6(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=32) :: buf
      character(len=16) :: fmt
      real(wp) :: ax
      ax = abs(x)
      if (ax >= 1.0e-4_wp .and. ax < 0.1_wp) then
         ! digits after the point for six significant ones (0.0942241: 7)
         write (fmt, '(a,i0,a)') '(f24.', 5 - floor(log10(ax)), ')'
         write (buf, fmt) x
      else if (ax > 1.0e-99_wp .and. ax < 1.0e99_wp .and. (ax < 1.0e-4_wp .or. ax >= 1.0e6_wp)) then
         write (buf, '(es12.5e2)') x
      else
         write (buf, '(g0.6)') x
      end if
      s = trim(adjustl(buf))
   end function g6

end module pecplas_base_strings
