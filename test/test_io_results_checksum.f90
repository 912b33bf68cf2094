!> The checksum kept with every real dataset and beside the deck text
!> (pecplas_io_results_checksum): it must change when any one value changes by one unit in
!> the last place, when two different values swap, and when the text changes by one
!> character or two lines swap; it is an integer below 2^52 (held exactly by the double
!> attribute) and needs more than one reduction span (4096 values) to be exercised.
module test_io_results_checksum
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_results_checksum, only: values_checksum, text_checksum, deck_identity
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_io_results_checksum

contains

   subroutine collect_io_results_checksum(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('one_ulp_anywhere', test_one_ulp), &
               new_unittest('swap_and_range', test_swap_and_range), &
               new_unittest('text', test_text), &
               new_unittest('deck_identity', test_deck_identity), &
               new_unittest('deck_identity_long', test_deck_identity_long)]
   end subroutine collect_io_results_checksum

   !> 10 000 values (three reduction spans): one ulp up or down at any of 60 positions spread
   !> over the array, the first and the last included, changes the checksum.
   subroutine test_one_ulp(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: v(:), w(:)
      real(wp) :: c0
      integer :: i, k
      allocate (v(10000))
      v = [(sin(real(i, wp))*10.0_wp**mod(i, 7), i = 1, size(v))]
      c0 = values_checksum(v, size(v))
      do k = 0, 59
         i = 1 + (k*(size(v) - 1))/59
         w = v
         w(i) = nearest(w(i), merge(1.0_wp, -1.0_wp, mod(k, 2) == 0))
         call check(error, values_checksum(w, size(w)) /= c0, 'one ulp at a value changes it')
         if (allocated(error)) return
      end do
      call check(error, values_checksum(v, size(v)) == c0, 'the same values, the same sum')
   end subroutine test_one_ulp

   subroutine test_swap_and_range(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: v(5000), w(5000), c
      integer :: i
      v = [(1.0_wp/real(i, wp), i = 1, size(v))]
      w = v
      w([17, 4500]) = v([4500, 17])
      call check(error, values_checksum(w, size(w)) /= values_checksum(v, size(v)), &
         'two values swapped change it')
      if (allocated(error)) return
      ! the largest doubles and negative values: an integer in [0, 2^52)
      v = -huge(1.0_wp)
      c = values_checksum(v, size(v))
      call check(error, c >= 0.0_wp .and. c < 2.0_wp**52 .and. c == aint(c), &
         'an integer below 2^52')
      if (allocated(error)) return
      call check(error, values_checksum(v, 0) == 0.0_wp, 'no values: 0')
   end subroutine test_swap_and_range

   subroutine test_text(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: a = '*NODES'//new_line('a')//'1, 0, 0'//new_line('a'), &
         b = '1, 0, 0'//new_line('a')//'*NODES'//new_line('a')
      call check(error, text_checksum(a) /= text_checksum(b), 'two lines swapped change it')
      if (allocated(error)) return
      call check(error, text_checksum(a) /= text_checksum('*NODES'//new_line('a')// &
         '1, 0, 1'//new_line('a')), 'one character changes it')
      if (allocated(error)) return
      call check(error, text_checksum(a) == text_checksum(a(1:len(a))) .and. &
         text_checksum('') == 0.0_wp, 'the same text, the same sum; empty: 0')
   end subroutine test_text

   !> The paths of the `** ---- file:` lines do not count, everything else does.
   subroutine test_deck_identity(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=1), parameter :: nl = new_line('a')
      character(len=*), parameter :: a = '** ---- file: /home/u/run/deck.inp'//nl//'*TITLE'// &
         nl//'** ---- file: mesh.inp'//nl//'*NODES'//nl//'1, 0, 0'
      character(len=*), parameter :: b = '** ---- file: deck.inp'//nl//'*TITLE'//nl// &
         '** ---- file: ../run/mesh.inp'//nl//'*NODES'//nl//'1, 0, 0'
      call check(error, deck_identity(a) == '** ---- file:'//nl//'*TITLE'//nl// &
         '** ---- file:'//nl//'*NODES'//nl//'1, 0, 0', 'marker paths dropped, the rest kept')
      if (allocated(error)) return
      call check(error, deck_identity(a) == deck_identity(b), 'other paths, the same deck')
      if (allocated(error)) return
      call check(error, deck_identity(a) /= deck_identity(a(:len(a) - 1)//'1'), &
         'an edited line counts')
      if (allocated(error)) return
      call check(error, deck_identity('** ---- file: x') == '** ---- file:' .and. &
         deck_identity('') == '' .and. deck_identity('** -') == '** -', &
         'a last line without newline; short lines')
      if (allocated(error)) return
      call check(error, deck_identity('*TITLE x ** ---- file: y'//nl//'** ---- file: z'// &
         nl) == '*TITLE x ** ---- file: y'//nl//'** ---- file:'//nl, &
         'a marker inside a line is text')
   end subroutine test_deck_identity

   !> A deck text longer than the stack (16 MB; a keyword mesh of 1e6 nodes is 40 MB): the
   !> identity was built in an automatic buffer of the text's length and crashed on it.
   subroutine test_deck_identity_long(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=1), parameter :: nl = new_line('a')
      character(len=*), parameter :: line = '1, 0.125, 0.250'//nl
      character(len=:), allocatable :: text, id
      integer :: i, n
      n = 16*1024*1024/len(line)
      allocate (character(len=len('** ---- file: /a/deck.inp'//nl) + n*len(line)) :: text)
      text(1:len('** ---- file: /a/deck.inp'//nl)) = '** ---- file: /a/deck.inp'//nl
      do i = 1, n
         text(len(text) - (n - i + 1)*len(line) + 1:len(text) - (n - i)*len(line)) = line
      end do
      id = deck_identity(text)
      call check(error, len(id) == len(text) - len(' /a/deck.inp'), 'the path dropped')
      if (allocated(error)) return
      call check(error, id(len('** ---- file:') + 2:) == text(len('** ---- file: /a/deck.inp') + &
         2:), 'the rest kept')
   end subroutine test_deck_identity_long

end module test_io_results_checksum
