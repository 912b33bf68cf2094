!> Fast conversion of number text that has already been checked to be a plain decimal
!> ([sign] digits[.digits] | .digits, optional exponent e/E/d/D with digits): the common
!> short forms by exact integer arithmetic, the others by the C library's correctly rounded
!> strtod, which is what a Fortran list-directed read calls underneath (same value, without
!> the cost of Fortran internal I/O; mesh files hold millions of numbers).
module pecplas_io_number
   use, intrinsic :: iso_c_binding, only: c_char, c_double, c_ptr, c_null_char, c_null_ptr
   use iso_fortran_env, only: int64
   use pecplas_kinds, only: wp
   implicit none (type, external)
   private

   public :: decimal_real, decimal_int

   !> Exact powers of ten 1e0..1e22 (all representable in double precision).
   real(wp), parameter :: pow10(0:22) = [1.0e0_wp, 1.0e1_wp, 1.0e2_wp, 1.0e3_wp, 1.0e4_wp, &
      1.0e5_wp, 1.0e6_wp, 1.0e7_wp, 1.0e8_wp, 1.0e9_wp, 1.0e10_wp, 1.0e11_wp, 1.0e12_wp, &
      1.0e13_wp, 1.0e14_wp, 1.0e15_wp, 1.0e16_wp, 1.0e17_wp, 1.0e18_wp, 1.0e19_wp, &
      1.0e20_wp, 1.0e21_wp, 1.0e22_wp]

   interface
      pure function c_strtod(s, endp) bind(c, name='strtod') result(v)
         import :: c_char, c_double, c_ptr
         character(kind=c_char), intent(in) :: s(*)
         type(c_ptr), intent(in), value :: endp
         real(c_double) :: v
      end function c_strtod
   end interface

contains

   !> Value of the checked decimal `s` (no blanks). Mantissas up to 2**53 with a decimal
   !> exponent |e| <= 22 are converted by one correctly rounded product or quotient
   !> (Clinger's fast path); other forms by strtod. The result may be infinite (overflow):
   !> the caller decides what is acceptable.
   pure function decimal_real(s) result(v)
      character(len=*), intent(in) :: s
      real(wp) :: v
      integer(int64), parameter :: max_exact = 2_int64**53
      integer(int64) :: mant
      integer :: i, n, c, nd, e10, ex
      logical :: neg, negx
      character(kind=c_char, len=len(s) + 1) :: buf
      n = len(s)
      i = 1
      neg = .false.
      if (n >= 1) then
         neg = s(1:1) == '-'
         if (neg .or. s(1:1) == '+') i = 2
      end if
      mant = 0; nd = 0; e10 = 0
      do while (i <= n)
         c = iachar(s(i:i))
         if (c == 46) then
            i = i + 1
            exit
         end if
         if (c < 48 .or. c > 57) exit
         if (mant > 0 .or. c > 48) nd = nd + 1
         ! beyond 18 significant digits the value goes to strtod: mant is not used
         if (nd <= 18) mant = 10*mant + (c - 48)
         i = i + 1
      end do
      if (i > 1) then
         if (s(i - 1:i - 1) == '.') then
            do while (i <= n)
               c = iachar(s(i:i))
               if (c < 48 .or. c > 57) exit
               if (mant > 0 .or. c > 48) nd = nd + 1
               if (nd <= 18) then
                  mant = 10*mant + (c - 48)
                  e10 = e10 - 1
               end if
               i = i + 1
            end do
         end if
      end if
      if (i <= n) then
         ! exponent letter, sign, digits (capped: the value is then far out of range anyway)
         i = i + 1
         negx = .false.
         if (i <= n) then
            negx = s(i:i) == '-'
            if (negx .or. s(i:i) == '+') i = i + 1
         end if
         ex = 0
         do while (i <= n)
            ex = min(10*ex + (iachar(s(i:i)) - 48), 100000)
            i = i + 1
         end do
         if (negx) ex = -ex
         e10 = e10 + ex
      end if
      if (mant == 0) then
         v = 0.0_wp
      else if (nd <= 18 .and. mant <= max_exact .and. abs(e10) <= 22) then
         if (e10 >= 0) then
            v = real(mant, wp)*pow10(e10)
         else
            v = real(mant, wp)/pow10(-e10)
         end if
      else
         buf(1:n) = s
         do i = 1, n
            if (buf(i:i) == 'd' .or. buf(i:i) == 'D') buf(i:i) = 'e'
         end do
         buf(n + 1:n + 1) = c_null_char
         v = real(c_strtod(buf, c_null_ptr), wp)
         return
      end if
      if (neg) v = -v
   end function decimal_real

   !> Value of the checked digit string `s` ([sign] digits, at most 18 digits).
   pure function decimal_int(s) result(v)
      character(len=*), intent(in) :: s
      integer(int64) :: v
      integer :: i, i0
      i0 = 1
      if (s(1:1) == '-' .or. s(1:1) == '+') i0 = 2
      v = 0
      do i = i0, len(s)
         v = 10*v + (iachar(s(i:i)) - 48)
      end do
      if (s(1:1) == '-') v = -v
   end function decimal_int

end module pecplas_io_number
