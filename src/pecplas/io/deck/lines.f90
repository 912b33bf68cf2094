!> Reads a deck and its `*INCLUDE` files into one list of logical lines (file, line number,
!> keyword in force, text without comments), and keeps the raw text of every file read for
!> provenance. An *INCLUDE is replaced by the lines of its file, so an included file may
!> hold only data lines that continue the keyword in force (a generated node list).
module pecplas_io_deck_lines
   use pecplas_error, only: error_t, deck_error, input_error
   use pecplas_io_deck_fields, only: deck_line_t, keyword_line_t, parse_keyword_line, &
      keyword_name
   implicit none (type, external)
   private

   public :: deck_line_t, read_deck_lines, read_text_file, join_path, dir_name

   character(len=*), parameter :: NL = new_line('a')
   character(len=*), parameter :: BOM = achar(239)//achar(187)//achar(191)

contains

   !> Logical lines of the deck `path` with includes expanded, and the raw text of all
   !> files read, each preceded by a `** ---- file: <path>` line.
   subroutine read_deck_lines(path, lines, raw, error)
      character(len=*), intent(in) :: path
      type(deck_line_t), allocatable, intent(out) :: lines(:)
      character(len=:), allocatable, intent(out) :: raw
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t), allocatable :: buf(:)
      character(len=:), allocatable :: keyword
      type(deck_line_t) :: origin
      integer :: n
      allocate (buf(0))
      n = 0
      raw = ''
      keyword = ''
      call read_one(join_path('', path), '', origin, buf, n, raw, keyword, error)
      if (allocated(error)) return
      ! exact already unless includes took places
      if (size(buf) /= n) call resize(buf, n, n)
      call move_alloc(buf, lines)
   end subroutine read_deck_lines

   !> Appends the lines of `path`; `stack` holds the files being read (newline separated)
   !> to detect recursion; `origin` is the *INCLUDE line (line 0 for the main deck).
   recursive subroutine read_one(path, stack, origin, lines, n, raw, keyword, error)
      character(len=*), intent(in) :: path, stack
      type(deck_line_t), intent(in) :: origin
      type(deck_line_t), allocatable, intent(inout) :: lines(:)
      integer, intent(inout) :: n
      character(len=:), allocatable, intent(inout) :: raw, keyword
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text, line, name, incl
      type(deck_line_t) :: here
      type(keyword_line_t) :: kw
      integer :: start, stop_, lineno, i1, i2, nkeep
      integer, allocatable :: bounds(:, :)
      logical :: found

      call read_text_file(path, text, found)
      if (.not. found) then
         if (origin%line == 0) then
            call input_error(error, "cannot read deck file '"//path//"'")
         else
            call deck_error(error, origin%file, origin%line, '*INCLUDE', &
               "cannot read include file '"//path//"'")
         end if
         return
      end if
      ! a UTF-8 byte order mark (written by some Windows editors) is not part of the text
      if (len(text) >= 3) then
         if (text(1:3) == BOM) text = text(4:)
      end if
      raw = raw//'** ---- file: '//path//NL//text
      if (len(text) > 0) then
         if (text(len(text):len(text)) /= NL) raw = raw//NL
      end if

      ! pass 1: the text bounds of every line, tabs and carriage returns turned into blanks
      ! (the raw text above keeps them); then room for the lines kept, at once
      allocate (bounds(2, count_lines(text)))
      nkeep = 0
      start = 1
      lineno = 0
      do while (start <= len(text))
         stop_ = start
         do while (stop_ <= len(text))
            if (text(stop_:stop_) == NL) exit
            if (text(stop_:stop_) == achar(9) .or. text(stop_:stop_) == achar(13)) &
               text(stop_:stop_) = ' '
            stop_ = stop_ + 1
         end do
         lineno = lineno + 1
         call clean_bounds(text, start, stop_ - 1, bounds(1, lineno), bounds(2, lineno))
         if (bounds(2, lineno) >= bounds(1, lineno)) nkeep = nkeep + 1
         start = stop_ + 1
      end do
      if (n + nkeep > size(lines)) call resize(lines, n, size(lines) + nkeep)

      do lineno = 1, size(bounds, 2)
         i1 = bounds(1, lineno)
         i2 = bounds(2, lineno)
         if (i2 < i1) cycle

         if (text(i1:i1) /= '*') then
            ! a data line (most of a mesh deck): stored in place, no temporaries
            call push(lines, n, path, lineno, keyword, text(i1:i2))
            cycle
         end if
         line = text(i1:i2)
         here = deck_line_t(file=path, line=lineno, keyword=keyword, text=line)
         name = keyword_name(line)
         if (name == '*INCLUDE') then
            here%keyword = name
            call parse_keyword_line(here, kw, error)
            if (allocated(error)) return
            call kw%check_keys(here, ['FILE'], error)
            if (allocated(error)) return
            call kw%require(here, 'FILE', incl, error)
            if (allocated(error)) return
            incl = join_path(dir_name(path), incl)
            if (index(NL//stack//NL//path//NL, NL//incl//NL) > 0) then
               call deck_error(error, path, lineno, name, "recursive include: '"//incl// &
                  "' is already being read (include chain: "//chain(stack, path)//')')
               return
            end if
            call read_one(incl, stack//NL//path, here, lines, n, raw, keyword, error)
            if (allocated(error)) return
            cycle
         end if
         if (len(name) > 0) keyword = name
         call push(lines, n, path, lineno, keyword, line)
      end do
   end subroutine read_one

   !> Number of lines of a text (the last one may lack its line end).
   pure integer function count_lines(text) result(k)
      character(len=*), intent(in) :: text
      integer :: i
      k = 0
      do i = 1, len(text)
         if (text(i:i) == NL) k = k + 1
      end do
      if (len(text) > 0) then
         if (text(len(text):len(text)) /= NL) k = k + 1
      end if
   end function count_lines

   !> Bounds i1:i2 of the text of line text(first:last) without comments ('**' lines, '#' or
   !> '!' to end of line) and without blanks on both sides (tabs and carriage returns are
   !> already blanks); i2 < i1 for a line left empty.
   pure subroutine clean_bounds(text, first, last, i1, i2)
      character(len=*), intent(in) :: text
      integer, intent(in) :: first, last
      integer, intent(out) :: i1, i2
      integer :: k
      i1 = first
      i2 = last
      ! character codes: gfortran turns a test against ' ' into a len_trim call
      do while (i1 <= i2)
         if (iachar(text(i1:i1)) /= 32) exit
         i1 = i1 + 1
      end do
      if (i2 - i1 >= 1) then
         if (text(i1:i1 + 1) == '**') then
            i2 = i1 - 1
            return
         end if
      end if
      do k = i1, i2
         if (text(k:k) == '#' .or. text(k:k) == '!') then
            i2 = k - 1
            exit
         end if
      end do
      do while (i2 >= i1)
         if (iachar(text(i2:i2)) /= 32) exit
         i2 = i2 - 1
      end do
   end subroutine clean_bounds

   !> 'a.inp -> b.inp -> c.inp' from the newline-separated stack and the current file.
   pure function chain(stack, path) result(s)
      character(len=*), intent(in) :: stack, path
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, len(stack)
         if (stack(i:i) == NL) then
            if (len(s) > 0) s = s//' -> '
         else
            s = s//stack(i:i)
         end if
      end do
      if (len(s) > 0) s = s//' -> '
      s = s//path
   end function chain

   !> Appends a line; the list doubles when full, its strings moved, not copied.
   subroutine push(lines, n, file, lineno, keyword, text)
      type(deck_line_t), allocatable, intent(inout) :: lines(:)
      integer, intent(inout) :: n
      character(len=*), intent(in) :: file, keyword, text
      integer, intent(in) :: lineno
      if (n == size(lines)) call resize(lines, n, max(2*n, 64))
      n = n + 1
      lines(n)%file = file
      lines(n)%line = lineno
      lines(n)%keyword = keyword
      lines(n)%text = text
   end subroutine push

   !> lines(1:n) into a list of `capacity` entries (>= n), moving the strings.
   subroutine resize(lines, n, capacity)
      type(deck_line_t), allocatable, intent(inout) :: lines(:)
      integer, intent(in) :: n, capacity
      type(deck_line_t), allocatable :: tmp(:)
      integer :: i
      allocate (tmp(capacity))
      do i = 1, n
         call move_alloc(lines(i)%file, tmp(i)%file)
         tmp(i)%line = lines(i)%line
         call move_alloc(lines(i)%keyword, tmp(i)%keyword)
         call move_alloc(lines(i)%text, tmp(i)%text)
      end do
      call move_alloc(tmp, lines)
   end subroutine resize

   !> Whole content of a text file; found = .false. if it cannot be opened or read.
   subroutine read_text_file(path, text, found)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: text
      logical, intent(out) :: found
      integer :: u, ios, nbytes
      logical :: exists
      text = ''
      found = .false.
      inquire (file=path, exist=exists)
      if (.not. exists) return
      open (newunit=u, file=path, access='stream', form='unformatted', status='old', &
         action='read', iostat=ios)
      if (ios /= 0) return
      inquire (unit=u, size=nbytes)
      if (nbytes < 0) then
         close (u)
         return
      end if
      deallocate (text)
      allocate (character(len=nbytes) :: text)
      if (nbytes > 0) read (u, iostat=ios) text
      close (u)
      found = ios == 0
   end subroutine read_text_file

   !> Directory part of a path with its trailing '/', '' when none.
   pure function dir_name(path) result(dir)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: dir
      integer :: k
      k = index(path, '/', back=.true.)
      dir = path(1:k)
   end function dir_name

   !> `rel` relative to directory `dir` (absolute `rel` kept), with '.', '..' and repeated
   !> '/' folded so that one file always gets one spelling (used to detect recursion).
   pure function join_path(dir, rel) result(path)
      character(len=*), intent(in) :: dir, rel
      character(len=:), allocatable :: path, full, part, kept
      integer :: start, k, last
      if (len(rel) > 0) then
         if (rel(1:1) == '/') then
            full = rel
         else
            full = dir//rel
         end if
      else
         full = dir
      end if
      kept = ''
      start = 1
      do while (start <= len(full) + 1)
         k = index(full(start:), '/')
         if (k == 0) then
            part = full(start:)
            k = len(full) + 2
         else
            part = full(start:start + k - 2)
            k = start + k
         end if
         start = k
         if (part == '' .or. part == '.') cycle
         last = index(kept, '/', back=.true.)
         if (part == '..' .and. len(kept) > 0 .and. kept(last + 1:) /= '..') then
            kept = kept(1:max(last - 1, 0))
            cycle
         end if
         if (len(kept) > 0) then
            kept = kept//'/'//part
         else
            kept = part
         end if
      end do
      path = kept
      if (len(full) > 0) then
         if (full(1:1) == '/') path = '/'//kept
      end if
   end function join_path

end module pecplas_io_deck_lines
