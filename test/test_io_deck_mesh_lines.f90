!> The one-pass readers of mesh data lines and of deck lines against the general path they
!> shortcut: a line they accept must be one split_fields/parse_int/parse_real accept, with
!> the same values bit for bit (else error messages or coordinates would change), and the
!> usual forms must take the short path (else there is no speed-up).
module test_io_deck_mesh_lines
   use iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_text_fields, only: field_t, split_fields, parse_real, parse_int, itoa
   use pecplas_io_deck_mesh_lines, only: quick_node, quick_ids
   use pecplas_io_text_line_store, only: next_line
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private

   public :: collect_io_deck_mesh_lines

contains

   subroutine collect_io_deck_mesh_lines(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('node_lines_as_general_path', test_node_cases), &
               new_unittest('random_node_lines', test_node_random), &
               new_unittest('element_lines_as_general_path', test_id_cases), &
               new_unittest('line_bounds_and_comments', test_next_line)]
   end subroutine collect_io_deck_mesh_lines

   !> The general path's reading of a node line: ok, id, x, y.
   subroutine general_node(text, ok, id, x, y)
      character(len=*), intent(in) :: text
      logical, intent(out) :: ok
      integer, intent(out) :: id
      real(wp), intent(out) :: x, y
      type(field_t), allocatable :: f(:)
      id = 0; x = 0.0_wp; y = 0.0_wp
      call split_fields(text, f)
      ok = size(f) == 3
      if (ok) call parse_int(f(1)%s, id, ok)
      if (ok) ok = id > 0
      if (ok) call parse_real(f(2)%s, x, ok)
      if (ok) call parse_real(f(3)%s, y, ok)
   end subroutine general_node

   !> quick_node agrees with the general path on `text`; `fast`: it must also accept it.
   subroutine check_node(error, text, fast)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: text
      logical, intent(in) :: fast
      logical :: ok_q, ok_g
      integer :: id_q, id_g
      real(wp) :: x_q, y_q, x_g, y_g
      ok_q = quick_node(text, id_q, x_q, y_q)
      call general_node(text, ok_g, id_g, x_g, y_g)
      if (ok_q) then
         ! same bits: -0.0 and 0.0 differ, and no rounding difference is allowed
         call check(error, ok_g .and. id_q == id_g .and. &
            transfer(x_q, 1_int64) == transfer(x_g, 1_int64) .and. &
            transfer(y_q, 1_int64) == transfer(y_g, 1_int64), &
            "quick path accepts '"//text//"' differently from the general path")
      else if (fast) then
         call check(error, .false., "quick path should accept '"//text//"'")
      end if
   end subroutine check_node

   subroutine test_node_cases(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=40), parameter :: usual(12) = [character(len=40) :: &
         '1, 0.0, 0.0', '12 1.5 -2.25', '3,4.0,5.0', '7, 1e5, 1.0d-3', '8, -2., .5', &
         '9, +3, 2.5E+2', '10, -0.0, 0.125D1', '000000011, 1, 2', &
         '5, 0.33333333333333331, 0.66666666666666663', '6, 1.2345678901234567e-3, 7', &
         '13 , 1.0 , 2.0 ,', '14,,1.0,,2.0']
      character(len=48), parameter :: other(27) = [character(len=48) :: &
         '0, 1.0, 2.0', '-1, 1.0, 2.0', '+1, 1.0, 2.0', '1234567890, 1.0, 2.0', &
         '1.0, 1.0, 2.0', '1, 1.0', '1, 1.0, 2.0, 3.0', '1, 1.0, 2.0e', '1, 1.0, e5', &
         '1, ., 2.0', '1, -, 2.0', '1, 1.2.3, 2.0', '1, 1e999, 2.0', '1, 1.0, nan', &
         '1, 1.0 = 2.0', 'id=1, 1.0, 2.0', '1, 1+5, 2.0', '1, 1.0d, 2', &
         '1, 12345678901234567890123, 2', '1, 0.1234567890123456789012e-5, 2', &
         '1, 1e-400, 2', '1, 4.9e-324, 2.2250738585072014e-308', '1, 1.0, 2.0x', &
         '1a, 1.0, 2.0', '1, 1.0e+, 2.0', '', ',,,']
      integer :: i
      do i = 1, size(usual)
         call check_node(error, trim(usual(i)), .true.)
         if (allocated(error)) return
      end do
      do i = 1, size(other)
         call check_node(error, trim(other(i)), .false.)
         if (allocated(error)) return
      end do
   end subroutine test_node_cases

   !> 20000 node lines of random numbers (1 to 22 digits, a dot anywhere, an exponent of
   !> any letter e/E/d/D, blanks and commas between fields) of which one in five has a
   !> random character changed: whatever the short path accepts, the general path reads
   !> the same way, and the short path takes most well-formed lines.
   subroutine test_node_random(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: stray = '+-.eEdD,, =x0'
      character(len=:), allocatable :: text
      real(wp) :: r(8)
      integer :: k, n, c, nquick
      integer, allocatable :: seed(:)
      integer :: id
      real(wp) :: x, y
      call random_seed(size=n)
      allocate (seed(n))
      seed = 20260415
      call random_seed(put=seed)
      nquick = 0
      do k = 1, 20000
         call random_number(r)
         text = itoa(1 + int(r(1)*1.0e6_wp))//sep(r(2))//random_number_text()// &
            sep(r(3))//random_number_text()
         if (r(4) < 0.2_wp) then
            ! one character changed at random
            n = 1 + int(r(5)*len(text))
            c = 1 + int(r(6)*len(stray))
            text(n:n) = stray(c:c)
         end if
         call check_node(error, text, .false.)
         if (allocated(error)) return
         if (quick_node(text, id, x, y)) nquick = nquick + 1
      end do
      ! 80 % of the lines are well formed; a short path taking fewer would gain nothing
      call check(error, nquick > 14000, 'random lines on the short path: '// &
         itoa(nquick)//' of 20000, expected more than 14000')
   end subroutine test_node_random

   !> A separator: ', ', ',' or blanks.
   function sep(r) result(s)
      real(wp), intent(in) :: r
      character(len=:), allocatable :: s
      if (r < 0.4_wp) then
         s = ', '
      else if (r < 0.7_wp) then
         s = ','
      else
         s = '   '
      end if
   end function sep

   !> A decimal: optional sign, 1 to 22 digits with a dot at a random place (or none),
   !> optional exponent.
   function random_number_text() result(s)
      character(len=:), allocatable :: s
      character(len=*), parameter :: letters = 'eEdD'
      real(wp) :: r(30)
      integer :: nd, dot, i
      call random_number(r)
      s = ''
      if (r(1) < 0.3_wp) s = '-'
      if (r(1) > 0.9_wp) s = '+'
      nd = 1 + int(r(2)*22)
      dot = int(r(3)*(nd + 2))
      do i = 1, nd
         if (i == dot) s = s//'.'
         s = s//achar(48 + int(r(5 + i)*10))
      end do
      if (r(4) < 0.4_wp) then
         i = 1 + int(r(28)*4)
         s = s//letters(i:i)
         if (r(29) < 0.5_wp) s = s//'-'
         s = s//itoa(int(r(30)*40))
      end if
   end function random_number_text

   subroutine test_id_cases(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=40), parameter :: lines(12) = [character(len=40) :: '1, 2, 3, 4, 5', &
         '1 2 3 4 5', '1,2,3,4,5,', '001, 2, 3, 4, 5', '1, 2, 3, 4', '1, 2, 3, 4, 5, 6', &
         '1, 2, 3, -4, 5', '1, 2, 0, 4, 5', '1, 2, 3.0, 4, 5', '1, 2, 3, 4, 5 = 6', &
         '1, 2, 3, 4, 1234567890', '+1, 2, 3, 4, 5']
      logical, parameter :: fast(12) = [.true., .true., .true., .true., .false., .false., &
         .false., .false., .false., .false., .false., .false.]
      type(field_t), allocatable :: f(:)
      integer :: i, k, ids(5), gen(5)
      logical :: ok_q, ok_g
      do i = 1, size(lines)
         ok_q = quick_ids(trim(lines(i)), ids)
         call split_fields(trim(lines(i)), f)
         ok_g = size(f) == 5
         do k = 1, size(f)
            if (.not. ok_g) exit
            call parse_int(f(k)%s, gen(k), ok_g)
            if (ok_g) ok_g = gen(k) > 0
         end do
         if (ok_q) then
            call check(error, ok_g .and. all(ids == gen), "quick ids differ on '"// &
               trim(lines(i))//"'")
         else
            call check(error, .not. fast(i), "quick ids should accept '"//trim(lines(i))//"'")
         end if
         if (allocated(error)) return
      end do
   end subroutine test_id_cases

   !> Line bounds by the deck's comment rules: '**' at the start drops the line, '#' and
   !> '!' cut it, tabs and carriage returns are blanks, outer blanks go; lines with and
   !> without such characters (the two ways next_line cuts a line) alternate.
   subroutine test_next_line(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: nl = achar(10), tab = achar(9), cr = achar(13)
      character(len=:), allocatable :: text
      character(len=16), parameter :: expected(9) = [character(len=16) :: '*NODES', '', &
         '1, 2', '* *', '"a"', '', 'x y', '', 'end']
      integer :: pos, i1, i2, k, ahead(4)
      text = '  *NODES'//cr//nl//'  ** comment'//nl//tab//'1, 2 # c'//nl//'* *'//nl// &
         '"a"!'//nl//'#'//nl//'x'//tab//'y '//cr//nl//'**'//nl//'end'
      pos = 1
      ahead = 0
      do k = 1, size(expected)
         call check(error, pos <= len(text), 'text ended before line '//itoa(k))
         if (allocated(error)) return
         call next_line(text, pos, i1, i2, ahead)
         if (i2 < i1) then
            call check(error, len_trim(expected(k)) == 0, 'line '//itoa(k)// &
               ' should be '//trim(expected(k))//', found empty')
         else
            ! tabs inside a line are blanks in the buffer
            call check(error, text(i1:i2) == trim(expected(k)), 'line '// &
               itoa(k)//": expected '"//trim(expected(k))//"', found '"// &
               text(i1:i2)//"'")
         end if
         if (allocated(error)) return
      end do
      call check(error, pos > len(text), 'all lines read')
   end subroutine test_next_line

end module test_io_deck_mesh_lines
