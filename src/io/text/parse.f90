!> Text helpers of the deck reader: strict number parsing (the Fortran forms 1e5, 1.0d-3,
!> -2., .5 and nothing else), case folding and name lists for messages.
module pecplas_io_text_parse
   use pecplas_base_kinds, only: wp
   use pecplas_base_strings, only: upper, same_name, itoa
   use pecplas_io_text_number, only: decimal_real, decimal_int
   implicit none (type, external)
   private

   public :: parse_real, parse_int, upper, same_name, add_name, itoa

contains

   !> Strict Fortran real: [sign] digits[.digits] | .digits, optional exponent e/E/d/D.
   pure subroutine parse_real(s, value, ok)
      character(len=*), intent(in) :: s
      real(wp), intent(out) :: value
      logical, intent(out) :: ok
      integer :: i, n, ndig, nexp
      value = 0.0_wp
      ok = .false.
      n = trimmed_len(s)
      if (n == 0) return
      i = 1
      if (s(i:i) == '+' .or. s(i:i) == '-') i = i + 1
      ndig = 0
      do while (i <= n)
         if (.not. is_digit(s(i:i))) exit
         ndig = ndig + 1; i = i + 1
      end do
      if (i <= n) then
         if (s(i:i) == '.') then
            i = i + 1
            do while (i <= n)
               if (.not. is_digit(s(i:i))) exit
               ndig = ndig + 1; i = i + 1
            end do
         end if
      end if
      if (ndig == 0) return
      if (i <= n) then
         if (index('eEdD', s(i:i)) == 0) return
         i = i + 1
         if (i <= n) then
            if (s(i:i) == '+' .or. s(i:i) == '-') i = i + 1
         end if
         nexp = 0
         do while (i <= n)
            if (.not. is_digit(s(i:i))) return
            nexp = nexp + 1; i = i + 1
         end do
         if (nexp == 0) return
      end if
      ! checked: convert without Fortran internal I/O (the same correctly rounded value)
      value = decimal_real(s(1:n))
      ok = abs(value) <= huge(value)
      if (.not. ok) value = 0.0_wp
   end subroutine parse_real

   !> Strict integer: [sign] digits, within the default integer range.
   pure subroutine parse_int(s, value, ok)
      character(len=*), intent(in) :: s
      integer, intent(out) :: value
      logical, intent(out) :: ok
      integer :: i, n, i0
      value = 0
      ok = .false.
      n = trimmed_len(s)
      if (n == 0) return
      i0 = 1
      if (s(1:1) == '+' .or. s(1:1) == '-') i0 = 2
      if (i0 > n) return
      do i = i0, n
         if (.not. is_digit(s(i:i))) return
      end do
      if (n - i0 + 1 > 9) return
      value = int(decimal_int(s(1:n)))
      ok = .true.
   end subroutine parse_int

   !> len_trim without the library call (fields of mesh lines end in no blank: one test).
   pure integer function trimmed_len(s) result(n)
      character(len=*), intent(in) :: s
      n = len(s)
      do while (n > 0)
         if (iachar(s(n:n)) /= 32) exit  ! a test against ' ' would call len_trim
         n = n - 1
      end do
   end function trimmed_len

   !> Appends ' name' to a blank-separated list used in messages.
   pure subroutine add_name(list, name)
      character(len=:), allocatable, intent(inout) :: list
      character(len=*), intent(in) :: name
      if (.not. allocated(list)) list = ''
      list = list//' '//name
   end subroutine add_name

   !> Integer as text (messages).

   pure logical function is_digit(c)
      character(len=1), intent(in) :: c
      is_digit = c >= '0' .and. c <= '9'
   end function is_digit

end module pecplas_io_text_parse
