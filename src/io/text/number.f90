!> Fast conversion of number text that has already been checked to be a plain decimal
!> ([sign] digits[.digits] | .digits, optional exponent e/E/d/D with digits): the common
!> short forms by exact integer arithmetic, the others by the C library's correctly rounded
!> strtod, which is what a Fortran list-directed read calls underneath (same value, without
!> the cost of Fortran internal I/O; mesh files hold millions of numbers). Mantissas of up
!> to 18 digits (17-digit coordinates written by mesh generators) with a decimal exponent
!> |e| <= 27 go through one product or quotient in extended precision (64-bit significand),
!> rounded once more to double; the one case where that second rounding can differ from
!> the correct one (the extended result falls exactly halfway between two doubles) is sent
!> to strtod.
module pecplas_io_text_number
   use, intrinsic :: iso_c_binding, only: c_char, c_double, c_ptr, c_null_char, c_null_ptr
   use iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: decimal_real, decimal_value, decimal_int

   !> Extended precision with a significand of at least 64 bits (x87 real(10), or quad),
   !> when the compiler has one; HAVE_XP is .false. otherwise (all long forms to strtod).
   integer, parameter :: XP_WANTED = selected_real_kind(18)
   integer, parameter :: xp = merge(XP_WANTED, wp, XP_WANTED > 0)
   logical, parameter :: HAVE_XP = XP_WANTED > 0 .and. digits(1.0_xp) >= 64

   !> Powers of ten 1e0..1e27, exact in a 64-bit significand (5**27 < 2**63).
   real(xp), parameter :: pow10x(0:27) = [1.0e0_xp, 1.0e1_xp, 1.0e2_xp, 1.0e3_xp, 1.0e4_xp, &
      1.0e5_xp, 1.0e6_xp, 1.0e7_xp, 1.0e8_xp, 1.0e9_xp, 1.0e10_xp, 1.0e11_xp, 1.0e12_xp, &
      1.0e13_xp, 1.0e14_xp, 1.0e15_xp, 1.0e16_xp, 1.0e17_xp, 1.0e18_xp, 1.0e19_xp, 1.0e20_xp, &
      1.0e21_xp, 1.0e22_xp, 1.0e23_xp, 1.0e24_xp, 1.0e25_xp, 1.0e26_xp, 1.0e27_xp]

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
      integer(int64) :: mant
      integer :: i, n, c, nd, e10, ex
      logical :: neg, negx, ok
      ! on the heap: a token may be as long as a line (an automatic buffer of its length
      ! was on the stack, and a number of 20 million digits overflowed it)
      character(kind=c_char, len=:), allocatable :: buf
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
      call decimal_value(mant, nd, e10, neg, v, ok)
      if (ok) return
      allocate (character(kind=c_char, len=n + 1) :: buf)
      buf(1:n) = s
      do i = 1, n
         if (buf(i:i) == 'd' .or. buf(i:i) == 'D') buf(i:i) = 'e'
      end do
      buf(n + 1:n + 1) = c_null_char
      v = real(c_strtod(buf, c_null_ptr), wp)
   end function decimal_real

   !> Value of a decimal read as its first 18 significant digits `mant` (nd significant
   !> digits in all), decimal exponent `e10` and sign, without the text: ok = .false. when
   !> only the text can give the correctly rounded value (more than 18 digits, a large
   !> exponent, a double-rounding tie); then use decimal_real.
   pure subroutine decimal_value(mant, nd, e10, neg, v, ok)
      integer(int64), intent(in) :: mant
      integer, intent(in) :: nd, e10
      logical, intent(in) :: neg
      real(wp), intent(out) :: v
      logical, intent(out) :: ok
      integer(int64), parameter :: max_exact = 2_int64**53
      ok = .true.
      if (mant == 0) then
         v = 0.0_wp
      else if (nd <= 18 .and. mant <= max_exact .and. abs(e10) <= 22) then
         if (e10 >= 0) then
            v = real(mant, wp)*pow10(e10)
         else
            v = real(mant, wp)/pow10(-e10)
         end if
      else
         v = 0.0_wp
         ok = .false.
         if (HAVE_XP .and. nd <= 18 .and. abs(e10) <= 27) call extended(mant, e10, v, ok)
         if (.not. ok) return
      end if
      if (neg) v = -v
   end subroutine decimal_value

   !> mant * 10**e10 rounded to double through one extended-precision operation: exact
   !> operands (mant < 2**60, 10**|e10| <= 10**27), one correct rounding to 64 bits, then
   !> one to 53. Double rounding errs only when the first result lies exactly halfway
   !> between two doubles (a halfway point strictly between the exact value and its nearest
   !> 64-bit neighbour cannot exist); then ok = .false. and strtod decides.
   pure subroutine extended(mant, e10, v, ok)
      integer(int64), intent(in) :: mant
      integer, intent(in) :: e10
      real(wp), intent(out) :: v
      logical, intent(out) :: ok
      real(xp) :: r, gap, ulp
      if (e10 >= 0) then
         r = real(mant, xp)*pow10x(e10)
      else
         r = real(mant, xp)/pow10x(-e10)
      end if
      v = real(r, wp)
      gap = abs(r - real(v, xp))
      ulp = real(spacing(v), xp)
      ! halfway above |v| (half its spacing) or below a power of two (a quarter of it)
      ok = gap /= 0.5_xp*ulp .and. gap /= 0.25_xp*ulp
   end subroutine extended

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

end module pecplas_io_text_number
