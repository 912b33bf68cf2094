!> Deck building blocks: strict number parsing (what Fortran writes is accepted, anything
!> else refused), keyword lines, data fields, include path folding and repeated ids.
module test_io_deck_fields
   use iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_text_fields, only: deck_line_t, keyword_line_t, field_t, parse_keyword_line, &
      split_fields, parse_real, parse_int
   use pecplas_io_text_lines, only: join_path, read_deck_lines
   use pecplas_io_deck_repeats, only: first_repeat
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_io_deck_fields

contains

   subroutine collect_io_deck_fields(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('numbers_accepted', test_numbers_ok), &
               new_unittest('numbers_refused', test_numbers_bad), &
               new_unittest('integers', test_integers), &
               new_unittest('keyword_line', test_keyword_line), &
               new_unittest('data_fields', test_fields), &
               new_unittest('include_paths', test_paths), &
               new_unittest('first_repeat', test_repeat), &
               new_unittest('numbers_as_fortran_read', test_numbers_as_read), &
               new_unittest('long_numbers_as_fortran_read', test_long_numbers_as_read), &
               new_unittest('deck_lines_cleaned', test_lines_cleaned), &
               new_unittest('deck_raw_text_exact', test_raw_text)]
   end subroutine collect_io_deck_fields

   subroutine test_numbers_ok(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=8), parameter :: text(8) = [character(len=8) :: '1e5', '1.0d-3', '-2.', &
         '.5', '+3', '2.5E+2', '0', '-0.125D1']
      real(wp), parameter :: expected(8) = [1.0e5_wp, 1.0e-3_wp, -2.0_wp, 0.5_wp, 3.0_wp, &
         250.0_wp, 0.0_wp, -1.25_wp]
      real(wp) :: v
      logical :: ok
      integer :: i
      do i = 1, size(text)
         call parse_real(text(i), v, ok)
         ! decimal text of a representable value reads back exactly, others to rounding
         call check(error, ok .and. abs(v - expected(i)) <= 1.0e-15_wp*abs(expected(i)), &
            'should read '//trim(text(i)))
         if (allocated(error)) return
      end do
   end subroutine test_numbers_ok

   subroutine test_numbers_bad(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=8), parameter :: text(12) = [character(len=8) :: '2.0e', 'abc', '1.2.3', &
         '', 'e5', '1e', '1+5', 'nan', 'inf', '.', '-', '1,0']
      real(wp) :: v
      logical :: ok
      integer :: i
      do i = 1, size(text)
         call parse_real(text(i), v, ok)
         call check(error, .not. ok, "should refuse '"//trim(text(i))//"'")
         if (allocated(error)) return
      end do
   end subroutine test_numbers_bad

   subroutine test_integers(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: v
      logical :: ok
      call parse_int('-42', v, ok)
      call check(error, ok .and. v == -42, '-42')
      if (allocated(error)) return
      call parse_int('123456789', v, ok)
      call check(error, ok .and. v == 123456789, 'nine digits')
      if (allocated(error)) return
      call parse_int('1.0', v, ok)
      call check(error, .not. ok, 'a real is not an integer')
      if (allocated(error)) return
      call parse_int('12345678901', v, ok)
      call check(error, .not. ok, 'out of range')
   end subroutine test_integers

   subroutine test_keyword_line(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(keyword_line_t) :: kw
      type(deck_line_t) :: line
      character(len=:), allocatable :: v
      logical :: found
      line = deck_line_t(file='x.inp', line=3, keyword='', &
         text='*elements ,  type = q4, Set=My_Soil, generate')
      call parse_keyword_line(line, kw, e)
      call check(error, .not. allocated(e), 'valid keyword line')
      if (allocated(error)) return
      call check(error, kw%name == '*ELEMENTS' .and. size(kw%params) == 3, 'name and 3 params')
      if (allocated(error)) return
      call kw%get('set', v, found)
      call check(error, found .and. v == 'My_Soil', 'value keeps its spelling')
      if (allocated(error)) return
      call check(error, kw%has('GENERATE') .and. .not. kw%params(3)%has_value, 'flag')
      if (allocated(error)) return
      line%text = '*end   step'
      call parse_keyword_line(line, kw, e)
      call check(error, kw%name == '*END STEP', 'inner blanks folded: '//kw%name)
      if (allocated(error)) return
      line%text = '*STEP, NAME=a b=c'
      call parse_keyword_line(line, kw, e)
      call check(error, .not. allocated(e), 'value may hold blanks and =')
      if (allocated(error)) return
      line%text = '*STEP, MY KEY=3'
      call parse_keyword_line(line, kw, e)
      call check(error, allocated(e), 'blank inside a key is an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'x.inp:3') > 0, 'error names file:line')
   end subroutine test_keyword_line

   subroutine test_fields(error)
      type(error_t), allocatable, intent(out) :: error
      type(field_t), allocatable :: f(:)
      allocate (f(0)) ! gives the descriptor bounds (silences a gfortran 12 false warning)
      call split_fields('1,2  3 ,, 4,', f)
      call check(error, size(f) == 4, 'commas and blanks separate, runs count once')
      if (allocated(error)) return
      call check(error, f(3)%s == '3' .and. f(4)%s == '4', 'field text')
      if (allocated(error)) return
      call split_fields('E=2e4, NU = 0.3', f)
      call check(error, size(f) == 6 .and. f(2)%s == '=' .and. f(5)%s == '=', '= is a field')
   end subroutine test_fields

   subroutine test_paths(error)
      type(error_t), allocatable, intent(out) :: error
      call check(error, join_path('a/b/', '../c.inp') == 'a/c.inp', '..: '// &
         join_path('a/b/', '../c.inp'))
      if (allocated(error)) return
      call check(error, join_path('', './x.inp') == 'x.inp', '.')
      if (allocated(error)) return
      call check(error, join_path('a/', '/abs/y.inp') == '/abs/y.inp', 'absolute kept')
      if (allocated(error)) return
      call check(error, join_path('', '../up.inp') == '../up.inp', 'leading .. kept')
      if (allocated(error)) return
      call check(error, join_path('d//', 'e/./f.inp') == 'd/e/f.inp', 'repeated / folded')
   end subroutine test_paths

   subroutine test_repeat(error)
      type(error_t), allocatable, intent(out) :: error
      call check(error, all(first_repeat([40, 7, 12, 3, 99, 8, 1]) == 0), 'distinct ids')
      if (allocated(error)) return
      call check(error, all(first_repeat([integer ::]) == 0), 'no ids')
      if (allocated(error)) return
      ! 7 repeats at 5, 3 repeats at 4: the repeat met first in reading order is reported
      call check(error, all(first_repeat([7, 3, 9, 3, 7]) == [2, 4]), &
         'first repeat in reading order')
      if (allocated(error)) return
      call check(error, all(first_repeat([5, 5, 5]) == [1, 2]), 'triple: first two')
   end subroutine test_repeat

   !> The reader converts numbers without Fortran I/O (exact short forms, strtod for the
   !> rest); every value must equal, bit for bit, what a list-directed read gives: edge
   !> cases (2**53 + 1, halfway cases, subnormals, 17-20 digits, underflow) and 20000
   !> pseudo-random decimals of every form (fixed seed: a failure is reproducible).
   subroutine test_numbers_as_read(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=24), parameter :: edge(14) = [character(len=24) :: '9007199254740993', &
         '9007199254740992.5', '0.1', '2.2250738585072011e-308', '4.9406564584124654d-324', &
         '1e-400', '1.7976931348623157e308', '123456789012345678901', '0.30000000000000004', &
         '-0.0', '1e22', '1e23', '8.5e-6', '70.71067811865476']
      character(len=40) :: s
      integer(int64) :: seed
      integer :: i
      do i = 1, size(edge)
         call same_as_read(trim(edge(i)), error)
         if (allocated(error)) return
      end do
      seed = 20240611_int64
      do i = 1, 20000
         call random_decimal(seed, s)
         call same_as_read(trim(s), error)
         if (allocated(error)) return
      end do
   end subroutine test_numbers_as_read

   !> The extended-precision path (16-18 significant digits, |decimal exponent| <= 27, the
   !> form of 17-digit mesh coordinates): bit for bit what a list-directed read gives, on
   !> exact halfway cases between doubles (2**53 + 1, + 3: the path must hand them to
   !> strtod) and 20000 pseudo-random mantissas of 16 to 18 digits (fixed seed).
   subroutine test_long_numbers_as_read(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=28), parameter :: edge(8) = [character(len=28) :: '9007199254740993', &
         '9007199254740995', '18014398509481986', '4.4843049327354258E-02', &
         '123456789012345678', '1e27', '9.99999999999999999e26', &
         '0.000000000000000000000000001']
      character(len=40) :: s
      character(len=4) :: ex
      integer(int64) :: seed
      integer :: i, k, nd
      do i = 1, size(edge)
         call same_as_read(trim(edge(i)), error)
         if (allocated(error)) return
      end do
      seed = 20261124_int64
      do i = 1, 20000
         nd = 16 + next(seed, 3)
         s = achar(49 + next(seed, 9))//'.'
         do k = 2, nd
            s = trim(s)//achar(48 + next(seed, 10))
         end do
         write (ex, '(i0)') next(seed, 21) - 10
         s = trim(s)//'E'//trim(ex)
         if (next(seed, 2) == 0) s = '-'//trim(s)
         call same_as_read(trim(s), error)
         if (allocated(error)) return
      end do
   end subroutine test_long_numbers_as_read

   subroutine same_as_read(s, error)
      character(len=*), intent(in) :: s
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: v, r
      logical :: ok
      integer :: ios
      call parse_real(s, v, ok)
      read (s, *, iostat=ios) r
      if (ios == 0) ios = merge(0, 1, abs(r) <= huge(r))
      call check(error, ok .eqv. (ios == 0), "accepted/refused differently from a read: '"// &
         s//"'")
      if (allocated(error) .or. .not. ok) return
      call check(error, transfer(v, 0_int64) == transfer(r, 0_int64), &
         "not the value a Fortran read gives: '"//s//"'")
   end subroutine same_as_read

   !> A decimal with 1..20 digits, a point anywhere (or none), maybe an exponent e/E/d/D.
   subroutine random_decimal(seed, s)
      integer(int64), intent(inout) :: seed
      character(len=*), intent(out) :: s
      integer :: nd, dot, k, p
      s = ''
      p = 0
      if (next(seed, 3) == 0) call put('-')
      nd = 1 + next(seed, 20)
      dot = next(seed, nd + 2)
      do k = 1, nd
         if (k == dot) call put('.')
         call put(achar(48 + next(seed, 10)))
      end do
      select case (next(seed, 4))
      case (0)
      case default
         k = next(seed, 4) + 1
         call put('eEdD'(k:k))
         if (next(seed, 2) == 0) call put('-')
         call put_int(next(seed, 330))
      end select
   contains
      subroutine put(c)
         character(len=*), intent(in) :: c
         s(p + 1:p + len(c)) = c
         p = p + len(c)
      end subroutine put
      subroutine put_int(v)
         integer, intent(in) :: v
         character(len=8) :: buf
         write (buf, '(i0)') v
         call put(trim(buf))
      end subroutine put_int
   end subroutine random_decimal

   !> Integer in 0..m-1 from a xorshift64 generator (no integer overflow; 0 if m <= 0).
   integer function next(seed, m)
      integer(int64), intent(inout) :: seed
      integer, intent(in) :: m
      seed = ieor(seed, ishft(seed, 13))
      seed = ieor(seed, ishft(seed, -7))
      seed = ieor(seed, ishft(seed, 17))
      next = 0
      if (m > 0) next = int(modulo(ishft(seed, -33), int(m, int64)))
   end function next

   !> Logical lines of a deck written with a byte order mark, CRLF ends, tabs, comments of
   !> every kind and blank lines: exactly the texts, line numbers and keywords in force
   !> that the deck language defines (doc/deck.md), over more lines than the first
   !> capacity of the list (its growth keeps every line).
   subroutine test_lines_cleaned(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: path = 'build/test_io_deck_lines.inp'
      character(len=*), parameter :: crlf = achar(13)//achar(10), tab = achar(9)
      type(deck_line_t), allocatable :: lines(:)
      character(len=:), allocatable :: text, raw
      character(len=12) :: buf
      integer :: u, k
      text = achar(239)//achar(187)//achar(191)//'** header comment'//crlf// &
         '  *Nodes'//tab//crlf// &
         tab//'1,'//tab//'0.0, 0.0   # a comment'//crlf// &
         crlf//'   '//crlf// &
         '2, 1.0, 0.0 ! another'//crlf
      do k = 3, 100
         write (buf, '(i0)') k
         text = text//trim(buf)//', 2.0, 0.0'//achar(10)
      end do
      text = text//'*elements, type=Q4, set=s # end'
      open (newunit=u, file=path, access='stream', form='unformatted', status='replace', &
         action='write')
      write (u) text
      close (u)
      call read_deck_lines(path, lines, raw, error)
      if (allocated(error)) return
      call check(error, size(lines) == 102, 'a keyword, 100 nodes and a keyword: 102 lines')
      if (allocated(error)) return
      call check(error, lines(1)%text == '*Nodes' .and. lines(1)%line == 2 .and. &
         lines(1)%keyword == '*NODES' .and. lines(1)%file == path, &
         "line 1: '*Nodes' at line 2 under *NODES, found '"//lines(1)%text//"'")
      if (allocated(error)) return
      call check(error, lines(2)%text == '1,'//' '//'0.0, 0.0' .and. lines(2)%line == 3 .and. &
         lines(2)%keyword == '*NODES', "tab as blank, comment cut: found '"//lines(2)%text//"'")
      if (allocated(error)) return
      call check(error, lines(3)%text == '2, 1.0, 0.0' .and. lines(3)%line == 6, &
         "blank lines skipped, '!' comment cut: found '"//lines(3)%text//"'")
      if (allocated(error)) return
      call check(error, lines(101)%text == '100, 2.0, 0.0' .and. lines(101)%line == 104, &
         "line 101 after the list grew: found '"//lines(101)%text//"'")
      if (allocated(error)) return
      call check(error, lines(102)%text == '*elements, type=Q4, set=s' .and. &
         lines(102)%keyword == '*ELEMENTS' .and. lines(102)%line == 105, &
         "last line without a line end: found '"//lines(102)%text//"'")
   end subroutine test_lines_cleaned

   !> The raw deck text kept for provenance is each file's bytes after a `** ---- file:`
   !> line (a line end added to a file without one, a byte order mark dropped), in reading
   !> order with an include after its parent: taken from the line buffer when no file holds
   !> a tab or carriage return, copied before the cleaning otherwise (here the include
   !> holds both: the raw text keeps them, the lines do not).
   subroutine test_raw_text(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: main = 'build/test_io_deck_raw.inp', &
         inc = 'build/test_io_deck_raw_inc.inp', NL = achar(10)
      character(len=*), parameter :: crlf = achar(13)//achar(10), tab = achar(9)
      type(deck_line_t), allocatable :: lines(:)
      character(len=:), allocatable :: raw, main_text, inc_text, expected
      integer :: pass
      main_text = '*NODES'//NL//'1, 0.0, 0.0'//NL//'*INCLUDE, FILE=test_io_deck_raw_inc.inp'// &
         NL//'3, 2.0, 0.0'
      do pass = 1, 2
         if (pass == 1) then
            inc_text = '2, 1.0, 0.0'//NL
         else
            inc_text = achar(239)//achar(187)//achar(191)//'2,'//tab//'1.0, 0.0'//crlf
         end if
         call write_text(main, main_text)
         call write_text(inc, inc_text)
         call read_deck_lines(main, lines, raw, error)
         if (allocated(error)) return
         expected = '** ---- file: '//main//NL//main_text//NL//'** ---- file: '//inc//NL
         if (pass == 1) then
            expected = expected//inc_text
         else
            expected = expected//inc_text(4:)
         end if
         call check(error, raw == expected, 'raw text exact, '// &
            merge('clean files (from the buffer)   ', 'tab and CR in the include (copy)', &
            pass == 1)//": got '"//raw//"'")
         if (allocated(error)) return
         call check(error, size(lines) == 4, 'four lines read')
         if (allocated(error)) return
         call check(error, lines(3)%text == '2, 1.0, 0.0' .and. lines(3)%file == inc .and. &
            lines(4)%text == '3, 2.0, 0.0' .and. lines(4)%line == 4, "include's line "// &
            "cleaned, the main deck's last line after it: '"//lines(3)%text//"', '"// &
            lines(4)%text//"'")
         if (allocated(error)) return
      end do
   contains
      subroutine write_text(path, text)
         character(len=*), intent(in) :: path, text
         integer :: u
         open (newunit=u, file=path, access='stream', form='unformatted', &
            status='replace', action='write')
         write (u) text
         close (u)
      end subroutine write_text
   end subroutine test_raw_text

end module test_io_deck_fields
