!> The logical lines of a deck held as offsets into one text buffer: each line is a slice
!> buf(i1:i2) with its line number, file and keyword in force as small integers. A mesh
!> block of a million lines thus costs no allocation per line; `get` builds the one-line
!> record (deck_line_t) that messages and keyword handlers use.
module pecplas_io_text_line_store
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_size_t, c_intptr_t, c_loc, &
      c_associated
   use pecplas_io_text_fields, only: deck_line_t
   implicit none (type, external)
   private

   public :: deck_lines_t, name_t, add_name, next_line, find_byte

   !> One name of a table (a file path, a keyword).
   type :: name_t
      character(len=:), allocatable :: s
   end type name_t

   !> Lines 1..n of a deck with its includes expanded.
   type :: deck_lines_t
      !> Text of every file read, back to back, each after a `** ---- file: <path>` line;
      !> cleaned: tabs and carriage returns of the lines read become blanks.
      character(len=:), allocatable :: buf
      !> Whether buf is also the raw text of the files (none held a tab or carriage
      !> return, so the cleaning changed nothing): the deck text for provenance is then
      !> taken from buf (take_text) instead of being kept as a second copy.
      logical :: raw_in_buf = .true.
      integer :: n = 0
      !> Line k is buf(i1(k):i2(k)), line num(k) of files(file_of(k)), under the keyword
      !> keywords(kw_of(k)) (kw_of = 0 before the first keyword).
      integer, allocatable :: i1(:), i2(:), num(:), file_of(:), kw_of(:)
      type(name_t), allocatable :: files(:), keywords(:)
   contains
      procedure :: text => lines_text
      procedure :: file => lines_file
      procedure :: keyword => lines_keyword
      procedure :: line => lines_line
      procedure :: get => lines_get
      procedure :: is_keyword => lines_is_keyword
      procedure :: push => lines_push
      procedure :: resize => lines_resize
      procedure :: take_text => lines_take_text
   end type deck_lines_t

   interface
      !> C library memchr: first byte c in s(1:n), or a null pointer.
      function c_memchr(s, c, n) bind(c, name='memchr') result(hit)
         import :: c_ptr, c_int, c_size_t
         type(c_ptr), value :: s
         integer(c_int), value :: c
         integer(c_size_t), value :: n
         type(c_ptr) :: hit
      end function c_memchr
   end interface

contains

   !> Text of line k (comments and outer blanks removed).
   function lines_text(this, k) result(s)
      class(deck_lines_t), intent(in) :: this
      integer, intent(in) :: k
      character(len=:), allocatable :: s
      s = this%buf(this%i1(k):this%i2(k))
   end function lines_text

   !> File holding line k (the include file when inside one).
   function lines_file(this, k) result(s)
      class(deck_lines_t), intent(in) :: this
      integer, intent(in) :: k
      character(len=:), allocatable :: s
      s = this%files(this%file_of(k))%s
   end function lines_file

   !> Keyword in force on line k (upper case), '' before the first one.
   function lines_keyword(this, k) result(s)
      class(deck_lines_t), intent(in) :: this
      integer, intent(in) :: k
      character(len=:), allocatable :: s
      if (this%kw_of(k) == 0) then
         s = ''
      else
         s = this%keywords(this%kw_of(k))%s
      end if
   end function lines_keyword

   !> Line number of line k in its file.
   pure integer function lines_line(this, k) result(num)
      class(deck_lines_t), intent(in) :: this
      integer, intent(in) :: k
      num = this%num(k)
   end function lines_line

   !> Line k as a record of its own.
   function lines_get(this, k) result(line)
      class(deck_lines_t), intent(in) :: this
      integer, intent(in) :: k
      type(deck_line_t) :: line
      line%file = this%file(k)
      line%line = this%num(k)
      line%keyword = this%keyword(k)
      line%text = this%buf(this%i1(k):this%i2(k))
   end function lines_get

   !> Whether line k is a keyword line (starts with '*').
   pure logical function lines_is_keyword(this, k) result(yes)
      class(deck_lines_t), intent(in) :: this
      integer, intent(in) :: k
      yes = this%buf(this%i1(k):this%i1(k)) == '*'
   end function lines_is_keyword

   !> Appends line buf(i1:i2); the arrays double when full.
   pure subroutine lines_push(this, i1, i2, num, file_id, kw_id)
      class(deck_lines_t), intent(inout) :: this
      integer, intent(in) :: i1, i2, num, file_id, kw_id
      if (this%n == size(this%i1)) call this%resize(max(2*this%n, 64))
      this%n = this%n + 1
      this%i1(this%n) = i1
      this%i2(this%n) = i2
      this%num(this%n) = num
      this%file_of(this%n) = file_id
      this%kw_of(this%n) = kw_id
   end subroutine lines_push

   !> The raw text of the files read: `raw` as read_deck_store left it, or, when buf holds
   !> it (raw_in_buf), buf itself, moved into `raw` without a copy; the lines of the store
   !> are no longer readable after that.
   subroutine lines_take_text(this, raw)
      class(deck_lines_t), intent(inout) :: this
      character(len=:), allocatable, intent(inout) :: raw
      if (.not. this%raw_in_buf) return
      call move_alloc(this%buf, raw)
      this%buf = ''
      this%n = 0
      this%raw_in_buf = .false.
   end subroutine lines_take_text

   !> Room for `capacity` lines (>= n).
   pure subroutine lines_resize(this, capacity)
      class(deck_lines_t), intent(inout) :: this
      integer, intent(in) :: capacity
      call resize_int(this%i1, this%n, capacity)
      call resize_int(this%i2, this%n, capacity)
      call resize_int(this%num, this%n, capacity)
      call resize_int(this%file_of, this%n, capacity)
      call resize_int(this%kw_of, this%n, capacity)
   end subroutine lines_resize

   pure subroutine resize_int(a, n, capacity)
      integer, allocatable, intent(inout) :: a(:)
      integer, intent(in) :: n, capacity
      integer, allocatable :: tmp(:)
      allocate (tmp(capacity))
      tmp(1:n) = a(1:n)
      call move_alloc(tmp, a)
   end subroutine resize_int

   !> Bounds text(i1:i2) of the line that starts at `pos`, without comments ('**' lines,
   !> '#' or '!' to the end of the line) and outer blanks; i2 < i1 for a line left empty.
   !> Tabs and carriage returns of the line become blanks; `pos` moves past its line end.
   !> `ahead` (0 at the start of a text) keeps the next place of a tab, carriage return,
   !> '#' and '!' (found by memchr): a line without any of them is cut without looking at
   !> its characters one by one.
   subroutine next_line(text, pos, i1, i2, ahead)
      character(len=*), intent(inout), target :: text
      integer, intent(inout) :: pos
      integer, intent(out) :: i1, i2
      integer, intent(inout) :: ahead(4)
      integer, parameter :: SPECIAL(4) = [9, 13, 35, 33]
      integer :: p, lf, k, j1, j2
      p = pos
      do k = 1, 4
         if (ahead(k) < p) ahead(k) = find_byte(text, p, SPECIAL(k))
      end do
      lf = find_byte(text, p, 10)
      if (minval(ahead) < lf) then
         call cut_line(text, pos, i1, i2)
         return
      end if
      ! character codes: gfortran turns a test against ' ' into a len_trim call
      do while (p < lf)
         if (iachar(text(p:p)) /= 32) exit
         p = p + 1
      end do
      j1 = p
      j2 = lf - 1
      if (p + 1 < lf) then
         if (text(p:p + 1) == '**') j2 = j1 - 1
      end if
      do while (j2 >= j1)
         if (iachar(text(j2:j2)) /= 32) exit
         j2 = j2 - 1
      end do
      i1 = j1
      i2 = j2
      pos = lf + 1
   end subroutine next_line

   !> Position of the first byte `code` in text(p:), len(text) + 1 when there is none.
   integer function find_byte(text, p, code) result(k)
      character(len=*), intent(in), target :: text
      integer, intent(in) :: p, code
      type(c_ptr) :: hit
      k = len(text) + 1
      if (p > len(text)) return
      hit = c_memchr(c_loc(text(p:p)), int(code, c_int), int(len(text) - p + 1, c_size_t))
      if (.not. c_associated(hit)) return
      k = p + int(transfer(hit, 0_c_intptr_t) - transfer(c_loc(text(p:p)), 0_c_intptr_t))
   end function find_byte

   !> next_line character by character (lines holding a tab, carriage return or comment).
   pure subroutine cut_line(text, pos, i1, i2)
      character(len=*), intent(inout) :: text
      integer, intent(inout) :: pos
      integer, intent(out) :: i1, i2
      integer :: p, c, k, j1, j2
      logical :: comment
      p = pos
      do while (p <= len(text))
         c = iachar(text(p:p))
         if (c == 9 .or. c == 13) then
            text(p:p) = ' '
         else if (c /= 32) then
            exit
         end if
         p = p + 1
      end do
      j1 = p
      comment = .false.
      if (p < len(text)) comment = text(p:p + 1) == '**'
      if (.not. comment) then
         do while (p <= len(text))
            c = iachar(text(p:p))
            if (c == 10) exit
            if (c == 9 .or. c == 13) text(p:p) = ' '
            if (c == 33 .or. c == 35) then
               comment = .true.
               exit
            end if
            p = p + 1
         end do
      end if
      ! the line ends at p - 1 (line end or comment): trailing blanks off
      j2 = p - 1
      do while (j2 >= j1)
         if (iachar(text(j2:j2)) /= 32) exit
         j2 = j2 - 1
      end do
      if (comment) then
         ! the rest of the line is dropped
         k = index(text(p:), achar(10))
         if (k > 0) then
            p = p + k - 1
         else
            p = len(text) + 1
         end if
      end if
      i1 = j1
      i2 = j2
      pos = p + 1
   end subroutine cut_line

   !> Appends `s` to a name table.
   pure subroutine add_name(list, s)
      type(name_t), allocatable, intent(inout) :: list(:)
      character(len=*), intent(in) :: s
      type(name_t), allocatable :: tmp(:)
      integer :: k
      k = size(list)
      allocate (tmp(k + 1))
      tmp(1:k) = list
      tmp(k + 1)%s = s
      call move_alloc(tmp, list)
   end subroutine add_name

end module pecplas_io_text_line_store
