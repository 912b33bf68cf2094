!> Checksum of the values of a real dataset, stored with it as the attribute `checksum` and
!> verified when the program reads the dataset back (a restart): HDF5 keeps no checksum of
!> raw data, so a damaged byte in a value would otherwise be read as a valid number.
!>
!> Fletcher's checksum over the IEEE bytes of the values taken as 32-bit words (the low then
!> the high word of each value): s1 = sum of the words, s2 = sum of the running s1, both
!> modulo the prime P = 67108859 < 2^26; the checksum is s2 * 2^26 + s1, below 2^52 and so
!> held exactly by a double. A change of one word changes s1; two changes that keep s1 (a
!> swap of words, equal and opposite changes) change s2 unless their positions balance.
module pecplas_io_results_checksum
   use, intrinsic :: iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: values_checksum, text_checksum, deck_identity, deck_checksum

   !> Name of the attribute that holds a dataset's checksum.
   character(len=*), parameter, public :: CHECKSUM_ATTR = 'checksum'

   integer(int64), parameter :: P = 67108859_int64, LOW32 = 4294967295_int64
   !> Words summed between two reductions modulo P: s2 stays below 2^63 (see values_checksum).
   integer, parameter :: SPAN = 4096

contains

   !> Checksum of v(1:n) (any contiguous real array, passed by sequence association).
   pure real(wp) function values_checksum(v, n) result(c)
      integer, intent(in) :: n
      real(wp), intent(in) :: v(n)
      integer(int64) :: s1, s2, w
      integer :: i, i0
      ! after SPAN values (2 SPAN words < 2^32 each): s1 < P + 2^45, s2 < P + 2 SPAN s1 < 2^59
      s1 = 0
      s2 = 0
      do i0 = 1, n, SPAN
         do i = i0, min(n, i0 + SPAN - 1)
            w = transfer(v(i), w)
            call add_word(s1, s2, iand(w, LOW32))
            call add_word(s1, s2, ishft(w, -32))
         end do
         call reduce(s1, s2)
      end do
      c = packed(s1, s2)
   end function values_checksum

   !> Checksum of the characters of `text` (the same sums over their codes, one word each),
   !> kept beside a text whose reading needs HDF5's global heap (the deck text), so that a
   !> restart can check the deck without reading that heap from a file that may be damaged.
   pure real(wp) function text_checksum(text) result(c)
      character(len=*), intent(in) :: text
      integer(int64) :: s1, s2
      integer :: i, i0
      s1 = 0
      s2 = 0
      do i0 = 1, len(text), SPAN
         do i = i0, min(len(text), i0 + SPAN - 1)
            call add_word(s1, s2, ichar(text(i:i), int64))
         end do
         call reduce(s1, s2)
      end do
      c = packed(s1, s2)
   end function text_checksum

   !> What identifies a deck for a restart: the checksum of its text without the paths of
   !> the files read (deck_identity); written as the results file's `deck_text_checksum`.
   pure real(wp) function deck_checksum(text) result(c)
      character(len=*), intent(in) :: text
      c = text_checksum(deck_identity(text))
   end function deck_checksum

   pure subroutine add_word(s1, s2, w)
      integer(int64), intent(inout) :: s1, s2
      integer(int64), intent(in) :: w
      s1 = s1 + w
      s2 = s2 + s1
   end subroutine add_word

   !> Both sums modulo P, every SPAN values (before they could overflow).
   pure subroutine reduce(s1, s2)
      integer(int64), intent(inout) :: s1, s2
      s1 = modulo(s1, P)
      s2 = modulo(s2, P)
   end subroutine reduce

   !> s2 * 2^26 + s1: below 2^52, exact in a double.
   pure real(wp) function packed(s1, s2) result(c)
      integer(int64), intent(in) :: s1, s2
      c = real(s2, wp)*67108864.0_wp + real(s1, wp)
   end function packed

   !> The deck text without the paths of its `** ---- file: <path>` lines (each file read
   !> starts with one): what identifies a deck for a restart, so that the same files read
   !> from another directory, or named by another path, are the same deck. The text may be
   !> large (a keyword mesh of 1e6 nodes: 40 MB): it is copied between markers, found by
   !> searching for them, into a heap buffer (an automatic one of that length overflowed
   !> the stack).
   pure function deck_identity(text) result(id)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: id
      character(len=*), parameter :: MARK = '** ---- file:'
      character(len=:), allocatable :: buf
      integer :: i, k, p, m, eol
      allocate (character(len=len(text)) :: buf)
      i = 1
      k = 0
      do while (i <= len(text))
         ! next marker at the start of a line, at or after i (0: none)
         p = i
         m = 0
         do
            m = index(text(p:), MARK)
            if (m == 0) exit
            m = p + m - 1
            if (m == 1) exit
            if (text(m - 1:m - 1) == new_line('a')) exit
            p = m + 1
            m = 0
         end do
         if (m == 0) then
            buf(k + 1:k + len(text) - i + 1) = text(i:)
            k = k + len(text) - i + 1
            exit
         end if
         ! the text before the marker, then the marker without its path
         buf(k + 1:k + m - i) = text(i:m - 1)
         k = k + m - i
         buf(k + 1:k + len(MARK)) = MARK
         k = k + len(MARK)
         eol = index(text(m:), new_line('a'))
         if (eol == 0) exit
         k = k + 1
         buf(k:k) = new_line('a')
         i = m + eol
      end do
      id = buf(:k)
   end function deck_identity

end module pecplas_io_results_checksum
