!> Splitting deck lines: keyword lines (`*ELEMENTS, TYPE=Q4, SET=soil`) into a keyword
!> and `KEY=value` parameters, data lines into fields (separated by commas and/or blanks,
!> `=` being a field of its own), and number fields with errors that say what was
!> expected and what was found, at the line where it was found.
module pecplas_io_text_fields
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_io_text_parse, only: parse_real, parse_int, upper, same_name, add_name, itoa
   implicit none (type, external)
   private

   public :: deck_line_t, param_t, keyword_line_t, field_t
   public :: parse_keyword_line, keyword_name, split_fields
   public :: field_real, field_int, check_count
   ! re-exported so that handlers need one module for fields and their text
   public :: parse_real, parse_int, upper, same_name, add_name, itoa

   !> Most parameters one keyword line may carry (the most any keyword knows is about 10).
   integer, parameter, public :: MAX_PARAMS = 64

   !> One logical line of a deck, comments stripped, with where it came from.
   type :: deck_line_t
      !> File holding the line (the include file when inside one) and line number in it.
      character(len=:), allocatable :: file
      integer :: line = 0
      !> Keyword in force on this line (upper case, e.g. '*NODES'); '' before the first one.
      character(len=:), allocatable :: keyword
      character(len=:), allocatable :: text
   end type deck_line_t

   !> One `KEY=value` (or bare `KEY` flag) parameter of a keyword line.
   type :: param_t
      !> Upper-case key; value as written (case kept), '' for a flag.
      character(len=:), allocatable :: key, value
      logical :: has_value = .false.
   end type param_t

   !> A parsed keyword line.
   type :: keyword_line_t
      !> Upper-case keyword with its star and single inner blanks, e.g. '*END STEP'.
      character(len=:), allocatable :: name
      type(param_t), allocatable :: params(:)
   contains
      procedure :: has => keyword_has
      procedure :: get => keyword_get
      procedure :: check_keys => keyword_check_keys
      procedure :: require => keyword_require
   end type keyword_line_t

   !> One field of a data line.
   type :: field_t
      character(len=:), allocatable :: s
   end type field_t

contains

   !> Upper-case keyword of a keyword line (text before the first comma), '' otherwise.
   pure function keyword_name(text) result(name)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: name
      integer :: i, k, n
      character(len=:), allocatable :: raw, buf
      name = ''
      if (len_trim(text) == 0) return
      if (text(1:1) /= '*') return
      k = index(text, ',')
      if (k == 0) k = len(text) + 1
      raw = upper(text(2:k - 1))
      ! collapse blanks: '* end   step' -> '*END STEP' (in place: a keyword may be as long
      ! as a line, and growing the name a character at a time took quadratic time)
      allocate (character(len=len(raw) + 1) :: buf)
      buf(1:1) = '*'
      n = 1
      do i = 1, len(raw)
         if (raw(i:i) == ' ') then
            if (n > 1 .and. buf(n:n) /= ' ') then
               n = n + 1
               buf(n:n) = ' '
            end if
         else
            n = n + 1
            buf(n:n) = raw(i:i)
         end if
      end do
      name = trim(buf(1:n))
   end function keyword_name

   !> Parses `*KEYWORD, KEY=value, FLAG, ...`; errors on empty keys, empty values, duplicates.
   subroutine parse_keyword_line(line, kw, error)
      type(deck_line_t), intent(in) :: line
      type(keyword_line_t), intent(out) :: kw
      type(error_t), allocatable, intent(out) :: error
      integer :: start, comma, eq, i, n
      character(len=:), allocatable :: part, key
      type(param_t), allocatable :: tmp(:)
      kw%name = keyword_name(line%text)
      allocate (kw%params(0))
      start = index(line%text, ',')
      if (start == 0) return
      do
         comma = index(line%text(start + 1:), ',')
         if (comma == 0) then
            part = trim(adjustl(line%text(start + 1:)))
         else
            part = trim(adjustl(line%text(start + 1:start + comma - 1)))
         end if
         if (len(part) > 0) then
            eq = index(part, '=')
            if (eq > 0) then
               key = upper(adjustl(part(1:eq - 1)))
            else
               key = upper(part)
            end if
            if (len(key) == 0 .or. index(key, ' ') > 0) then
               call deck_error(error, line%file, line%line, kw%name, "bad parameter '"//part// &
                  "': expected KEY=value")
               return
            end if
            do i = 1, size(kw%params)
               if (kw%params(i)%key == key) then
                  call deck_error(error, line%file, line%line, kw%name, 'parameter '//key// &
                     ' given twice')
                  return
               end if
            end do
            n = size(kw%params)
            if (n >= MAX_PARAMS) then
               ! no keyword has nearly as many; the checks above are quadratic in the count
               call deck_error(error, line%file, line%line, kw%name, 'more than '// &
                  itoa(MAX_PARAMS)//' parameters on one keyword line')
               return
            end if
            allocate (tmp(n + 1))
            tmp(1:n) = kw%params
            call move_alloc(tmp, kw%params)
            kw%params(n + 1)%key = key
            kw%params(n + 1)%value = ''
            kw%params(n + 1)%has_value = eq > 0
            if (eq > 0) then
               kw%params(n + 1)%value = trim(adjustl(part(eq + 1:)))
               if (len(kw%params(n + 1)%value) == 0) then
                  call deck_error(error, line%file, line%line, kw%name, 'missing value for '// &
                     key//'= (expected '//key//'=<value>)')
                  return
               end if
            end if
         end if
         if (comma == 0) exit
         start = start + comma
      end do
   end subroutine parse_keyword_line

   logical function keyword_has(this, key)
      class(keyword_line_t), intent(in) :: this
      character(len=*), intent(in) :: key
      integer :: i
      keyword_has = .false.
      do i = 1, size(this%params)
         if (this%params(i)%key == upper(key)) keyword_has = .true.
      end do
   end function keyword_has

   !> Value of parameter `key` ('' and found = .false. when absent).
   subroutine keyword_get(this, key, value, found)
      class(keyword_line_t), intent(in) :: this
      character(len=*), intent(in) :: key
      character(len=:), allocatable, intent(out) :: value
      logical, intent(out) :: found
      integer :: i
      value = ''
      found = .false.
      do i = 1, size(this%params)
         if (this%params(i)%key == upper(key)) then
            value = this%params(i)%value
            found = .true.
         end if
      end do
   end subroutine keyword_get

   !> Error naming the first parameter not in `known`, with the list of known keys.
   subroutine keyword_check_keys(this, line, known, error)
      class(keyword_line_t), intent(in) :: this
      type(deck_line_t), intent(in) :: line
      character(len=*), intent(in) :: known(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: i, j
      character(len=:), allocatable :: list
      do i = 1, size(this%params)
         if (any([(upper(known(j)) == this%params(i)%key, j=1, size(known))])) cycle
         list = ''
         do j = 1, size(known)
            call add_name(list, upper(known(j)))
         end do
         if (size(known) == 0) list = ' (none)'
         call deck_error(error, line%file, line%line, this%name, 'unknown parameter '// &
            this%params(i)%key//' on '//this%name//'; known parameters:'//list)
         return
      end do
   end subroutine keyword_check_keys

   !> Value of a required parameter; error "missing required parameter KEY=" otherwise.
   subroutine keyword_require(this, line, key, value, error)
      class(keyword_line_t), intent(in) :: this
      type(deck_line_t), intent(in) :: line
      character(len=*), intent(in) :: key
      character(len=:), allocatable, intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      logical :: found
      call this%get(key, value, found)
      if (.not. found .or. len(value) == 0) call deck_error(error, line%file, line%line, &
         this%name, 'missing required parameter '//upper(key)//'= (expected '//this%name// &
         ', '//upper(key)//'=<value>)')
   end subroutine keyword_require

   !> Fields of a data line; commas and blanks separate, `=` is a field of its own.
   pure subroutine split_fields(text, fields)
      character(len=*), intent(in) :: text
      type(field_t), allocatable, intent(out) :: fields(:)
      integer :: pass, i, start, n
      ! pass 1 counts the fields, pass 2 stores them
      do pass = 1, 2
         n = 0
         start = 0
         do i = 1, len(text) + 1
            if (i <= len(text)) then
               if (text(i:i) /= ',' .and. text(i:i) /= ' ' .and. text(i:i) /= '=') then
                  if (start == 0) start = i
                  cycle
               end if
            end if
            if (start > 0) then
               n = n + 1
               if (pass == 2) fields(n)%s = text(start:i - 1)
            end if
            start = 0
            if (i <= len(text)) then
               if (text(i:i) == '=') then
                  n = n + 1
                  if (pass == 2) fields(n)%s = '='
               end if
            end if
         end do
         if (pass == 1) allocate (fields(n))
      end do
   end subroutine split_fields

   !> Field k as a real; errors name `what` and show the offending text.
   subroutine field_real(line, fields, k, what, value, error)
      type(deck_line_t), intent(in) :: line
      type(field_t), intent(in) :: fields(:)
      integer, intent(in) :: k
      character(len=*), intent(in) :: what
      real(wp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      logical :: ok
      value = 0.0_wp
      if (k > size(fields)) then
         call deck_error(error, line%file, line%line, line%keyword, 'missing value: expected '// &
            what//' in field '//itoa(k)//', found only '//itoa(size(fields))//' field(s)')
         return
      end if
      call parse_real(fields(k)%s, value, ok)
      if (.not. ok) call deck_error(error, line%file, line%line, line%keyword, 'expected '// &
         what//' as a number in field '//itoa(k)//", found '"//fields(k)%s//"'")
   end subroutine field_real

   !> Field k as an integer; errors name `what` and show the offending text.
   subroutine field_int(line, fields, k, what, value, error)
      type(deck_line_t), intent(in) :: line
      type(field_t), intent(in) :: fields(:)
      integer, intent(in) :: k
      character(len=*), intent(in) :: what
      integer, intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      logical :: ok
      value = 0
      if (k > size(fields)) then
         call deck_error(error, line%file, line%line, line%keyword, 'missing value: expected '// &
            what//' in field '//itoa(k)//', found only '//itoa(size(fields))//' field(s)')
         return
      end if
      call parse_int(fields(k)%s, value, ok)
      if (.not. ok) call deck_error(error, line%file, line%line, line%keyword, 'expected '// &
         what//' as an integer in field '//itoa(k)//", found '"//fields(k)%s//"'")
   end subroutine field_int

   !> Error unless nmin <= size(fields) <= nmax; `form` shows the expected line.
   subroutine check_count(line, fields, nmin, nmax, form, error)
      type(deck_line_t), intent(in) :: line
      type(field_t), intent(in) :: fields(:)
      integer, intent(in) :: nmin, nmax
      character(len=*), intent(in) :: form
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: count
      if (size(fields) >= nmin .and. size(fields) <= nmax) return
      if (nmin == nmax) then
         count = itoa(nmin)
      else
         count = itoa(nmin)//' to '//itoa(nmax)
      end if
      if (size(fields) < nmin) then
         call deck_error(error, line%file, line%line, line%keyword, 'too few fields: expected "'// &
            form//'" ('//count//' fields), found '//itoa(size(fields)))
      else
         call deck_error(error, line%file, line%line, line%keyword, 'too many fields: '// &
            'expected "'//form//'" ('//count//' fields), found '//itoa(size(fields)))
      end if
   end subroutine check_count

end module pecplas_io_text_fields
