!> One-pass readers of the common mesh data lines (`id, x, y` of *NODES, `id, n1, ..., nN`
!> of *ELEMENTS): fields found, checked and converted in a single sweep over the line's
!> text in the deck buffer, no allocation. They accept only lines that the general path
!> (split_fields, parse_int, parse_real) reads without error, and give the same values;
!> anything else returns .false. and is left to that path, whose checks name the fault.
module pecplas_io_deck_mesh_lines
   use iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   use pecplas_io_text_number, only: decimal_real, decimal_value
   implicit none (type, external)
   private

   public :: quick_node, quick_ids

   ! character codes (a test against ' ' makes gfortran call len_trim)
   integer, parameter :: BLANK = 32, COMMA = 44, DOT = 46, ZERO = 48, NINE = 57, PLUS = 43, &
      MINUS = 45

contains

   !> A node line of exactly three fields: a positive id, two finite reals.
   logical function quick_node(text, id, x, y) result(ok)
      character(len=*), intent(in) :: text
      integer, intent(out) :: id
      real(wp), intent(out) :: x, y
      integer :: p
      x = 0.0_wp; y = 0.0_wp
      p = 1
      call next_int(text, p, id, ok)
      if (ok) call next_real(text, p, x, ok)
      if (ok) call next_real(text, p, y, ok)
      if (ok) ok = at_end(text, p)
   end function quick_node

   !> A line of exactly size(ids) positive integers.
   logical function quick_ids(text, ids) result(ok)
      character(len=*), intent(in) :: text
      integer, intent(out) :: ids(:)
      integer :: p, k
      p = 1
      ok = .true.
      do k = 1, size(ids)
         call next_int(text, p, ids(k), ok)
         if (.not. ok) return
      end do
      ok = at_end(text, p)
   end function quick_ids

   !> Moves p past blanks and commas.
   pure subroutine skip_separators(text, p)
      character(len=*), intent(in) :: text
      integer, intent(inout) :: p
      integer :: c
      do while (p <= len(text))
         c = iachar(text(p:p))
         if (c /= BLANK .and. c /= COMMA) exit
         p = p + 1
      end do
   end subroutine skip_separators

   !> Whether nothing but separators is left.
   pure logical function at_end(text, p) result(yes)
      character(len=*), intent(in) :: text
      integer, intent(in) :: p
      integer :: q
      q = p
      call skip_separators(text, q)
      yes = q > len(text)
   end function at_end

   !> Whether text(p) ends a field (end of text, blank or comma).
   pure logical function field_end(text, p) result(yes)
      character(len=*), intent(in) :: text
      integer, intent(in) :: p
      integer :: c
      yes = p > len(text)
      if (yes) return
      c = iachar(text(p:p))
      yes = c == BLANK .or. c == COMMA
   end function field_end

   !> Next field as a positive integer of 1 to 9 digits (no sign: a signed id is left to
   !> the general path, like parse_int's digit limit).
   pure subroutine next_int(text, p, v, ok)
      character(len=*), intent(in) :: text
      integer, intent(inout) :: p
      integer, intent(out) :: v
      logical, intent(out) :: ok
      integer :: c, p0
      v = 0
      call skip_separators(text, p)
      p0 = p
      do while (p <= len(text))
         c = iachar(text(p:p))
         if (c < ZERO .or. c > NINE) exit
         v = 10*v + (c - ZERO)
         p = p + 1
         if (p - p0 > 9) then
            ok = .false.
            return
         end if
      end do
      ok = p > p0 .and. v > 0
      if (ok) ok = field_end(text, p)
   end subroutine next_int

   !> Next field as a finite real in parse_real's strict form ([sign] digits[.digits] |
   !> .digits, optional exponent e/E/d/D [sign] digits), converted as decimal_real does:
   !> the first 18 significant digits make the mantissa (leading zeros are not
   !> significant), the digits after the dot among them lower the exponent.
   pure subroutine next_real(text, p, v, ok)
      character(len=*), intent(in) :: text
      integer, intent(inout) :: p
      real(wp), intent(out) :: v
      logical, intent(out) :: ok
      integer(int64) :: mant
      integer :: c, q, n, p0, ndig, nd, e10, ex, nexp
      logical :: neg, negx
      v = 0.0_wp
      ok = .false.
      n = len(text)
      ! a local cursor stays in a register (the dummy p would be stored at every step)
      q = p
      call skip_separators(text, q)
      p0 = q
      if (q > n) return
      c = iachar(text(q:q))
      neg = c == MINUS
      if (neg .or. c == PLUS) q = q + 1
      mant = 0; ndig = 0; nd = 0; e10 = 0
      ! integer part: leading zeros, then significant digits
      do while (q <= n)
         if (iachar(text(q:q)) /= ZERO) exit
         ndig = ndig + 1
         q = q + 1
      end do
      do while (q <= n)
         c = iachar(text(q:q)) - ZERO
         if (c < 0 .or. c > 9) exit
         nd = nd + 1
         if (nd <= 18) mant = 10*mant + c
         q = q + 1
      end do
      ndig = ndig + nd
      if (q <= n) then
         if (iachar(text(q:q)) == DOT) then
            q = q + 1
            ! zeros before the first significant digit only scale
            if (mant == 0) then
               do while (q <= n)
                  if (iachar(text(q:q)) /= ZERO) exit
                  ndig = ndig + 1
                  e10 = e10 - 1
                  q = q + 1
               end do
            end if
            do while (q <= n)
               c = iachar(text(q:q)) - ZERO
               if (c < 0 .or. c > 9) exit
               ndig = ndig + 1
               nd = nd + 1
               if (nd <= 18) then
                  mant = 10*mant + c
                  e10 = e10 - 1
               end if
               q = q + 1
            end do
         end if
      end if
      if (ndig == 0) return
      if (.not. field_end(text, q)) then
         ! only an exponent may follow the digits
         select case (text(q:q))
         case ('e', 'E', 'd', 'D')
         case default
            return
         end select
         q = q + 1
         negx = .false.
         if (q <= n) then
            c = iachar(text(q:q))
            negx = c == MINUS
            if (negx .or. c == PLUS) q = q + 1
         end if
         ex = 0; nexp = 0
         do while (q <= n)
            c = iachar(text(q:q)) - ZERO
            if (c < 0 .or. c > 9) exit
            ex = min(10*ex + c, 100000)
            nexp = nexp + 1
            q = q + 1
         end do
         if (nexp == 0 .or. .not. field_end(text, q)) return
         if (negx) ex = -ex
         e10 = e10 + ex
      end if
      p = q
      call decimal_value(mant, nd, e10, neg, v, ok)
      if (.not. ok) v = decimal_real(text(p0:q - 1))
      ok = abs(v) <= huge(v)
   end subroutine next_real

end module pecplas_io_deck_mesh_lines
