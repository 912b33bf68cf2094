!> Reads a deck and its `*INCLUDE` files into one list of logical lines (file, line number,
!> keyword in force, text without comments: offsets into one buffer, see
!> pecplas_io_text_line_store), and keeps the raw text of every file read for provenance.
!> An *INCLUDE is replaced by the lines of its file, so an included file may hold only
!> data lines that continue the keyword in force (a generated node list).
module pecplas_io_text_lines
   use pecplas_base_error, only: error_t, deck_error, input_error
   use pecplas_io_text_fields, only: deck_line_t, keyword_line_t, parse_keyword_line, &
      keyword_name
   use pecplas_io_text_line_store, only: deck_lines_t, add_name, next_line, find_byte
   implicit none (type, external)
   private

   public :: deck_line_t, deck_lines_t, read_deck_lines, read_deck_store, read_text_file
   public :: join_path, dir_name

   character(len=*), parameter :: NL = new_line('a')
   character(len=*), parameter :: BOM = achar(239)//achar(187)//achar(191)
   integer, parameter :: TAB = 9, CR = 13, LF = 10

contains

   !> Logical lines of the deck `path` with includes expanded, and the raw text of all
   !> files read, each preceded by a `** ---- file: <path>` line (one record per line: for
   !> small decks; the deck reader keeps them in a deck_lines_t).
   subroutine read_deck_lines(path, lines, raw, error)
      character(len=*), intent(in) :: path
      type(deck_line_t), allocatable, intent(out) :: lines(:)
      character(len=:), allocatable, intent(out) :: raw
      type(error_t), allocatable, intent(out) :: error
      type(deck_lines_t) :: store
      integer :: i
      call read_deck_store(path, store, raw, error)
      if (allocated(error)) return
      allocate (lines(store%n))
      do i = 1, store%n
         lines(i) = store%get(i)
      end do
      call store%take_text(raw)
   end subroutine read_deck_lines

   !> Logical lines of the deck `path` with includes expanded, in one text buffer, and the
   !> raw text of all files read as in read_deck_lines: in `raw`, or, when the buffer is that
   !> text (store%raw_in_buf), still in the buffer, for store%take_text once the lines have
   !> been read (a mesh deck of 40 MB is then held once, not twice).
   subroutine read_deck_store(path, store, raw, error)
      character(len=*), intent(in) :: path
      type(deck_lines_t), intent(out) :: store
      character(len=:), allocatable, intent(out) :: raw
      type(error_t), allocatable, intent(out) :: error
      integer :: kw_id
      raw = ''
      store%buf = ''
      allocate (store%i1(0), store%i2(0), store%num(0), store%file_of(0), store%kw_of(0))
      allocate (store%files(0), store%keywords(0))
      kw_id = 0
      call read_one(join_path('', path), '', '', 0, store, raw, kw_id, error)
      if (allocated(error)) return
   end subroutine read_deck_store

   !> Appends the lines of `path`; `stack` holds the files being read (newline separated)
   !> to detect recursion; `origin_file`:`origin_line` is the *INCLUDE line (line 0 for the
   !> main deck); `kw_id` the keyword in force (index in store%keywords, 0 before any).
   recursive subroutine read_one(path, stack, origin_file, origin_line, store, raw, kw_id, &
         error)
      character(len=*), intent(in) :: path, stack, origin_file
      integer, intent(in) :: origin_line
      type(deck_lines_t), intent(inout) :: store
      character(len=:), allocatable, intent(inout) :: raw
      integer, intent(inout) :: kw_id
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text, line, name, incl
      type(deck_line_t) :: here
      type(keyword_line_t) :: kw
      integer :: lineno, i1, i2, nt, pos, base, file_id, ahead(4), head
      logical :: found, cr_only

      ! the file's text after its `** ---- file:` line, read in place behind it
      call read_text_file(path, text, found, '** ---- file: '//path//NL)
      if (.not. found) then
         if (origin_line == 0) then
            call input_error(error, "cannot read deck file '"//path//"'")
         else
            call deck_error(error, origin_file, origin_line, '*INCLUDE', &
               "cannot read include file '"//path//"'")
         end if
         return
      end if
      head = len('** ---- file: '//path//NL)
      ! a UTF-8 byte order mark (written by some Windows editors) is not part of the text
      if (len(text) >= head + 3) then
         if (text(head + 1:head + 3) == BOM) text = text(1:head)//text(head + 4:)
      end if
      ! lines ended by a carriage return alone (classic Mac OS editors): those are the line
      ! ends of the file (else each became a blank and the deck one line, "empty")
      cr_only = .false.
      if (len(text) > head) cr_only = find_byte(text, head + 1, LF) > len(text) .and. &
                                      find_byte(text, head + 1, CR) <= len(text)
      if (len(text) > head) then
         if (text(len(text):len(text)) /= NL) text = text//NL
      end if
      file_id = size(store%files) + 1
      call add_name(store%files, path)
      ! the raw text for provenance: the buffer itself while no file read holds a tab or a
      ! carriage return (the only bytes the line sweep below changes), else a copy
      if (store%raw_in_buf .and. (find_byte(text, head + 1, TAB) <= len(text) .or. &
                                  find_byte(text, head + 1, CR) <= len(text))) then
         raw = store%buf
         store%raw_in_buf = .false.
      end if
      if (.not. store%raw_in_buf) raw = raw//text
      if (cr_only) then  ! the raw text keeps them
         do i1 = head + 1, len(text)
            if (iachar(text(i1:i1)) == CR) text(i1:i1) = NL
         end do
      end if

      ! the text joins the buffer whole: lines are offsets into it, found in one sweep
      ! that also turns tabs and carriage returns into blanks (the raw text keeps them)
      nt = len(text) - head
      base = len(store%buf) + head
      if (len(store%buf) == 0) then
         call move_alloc(text, store%buf)
      else
         store%buf = store%buf//text
         deallocate (text)
      end if
      ! room for the lines at once when they hold 16 characters or more on average (mesh
      ! lines do): no copies as the arrays grow; room not used is never touched
      if (store%n + nt/16 + 64 > size(store%i1)) call store%resize(store%n + nt/16 + 64)
      pos = 1
      lineno = 0
      ahead = 0
      do while (pos <= nt)
         lineno = lineno + 1
         call next_line(store%buf(base + 1:base + nt), pos, i1, i2, ahead)
         if (i2 < i1) cycle
         if (store%buf(base + i1:base + i1) /= '*') then
            ! a data line (most of a mesh deck): offsets only
            call store%push(base + i1, base + i2, lineno, file_id, kw_id)
            cycle
         end if
         line = store%buf(base + i1:base + i2)
         name = keyword_name(line)
         if (name == '*INCLUDE') then
            here = deck_line_t(file=path, line=lineno, keyword=name, text=line)
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
            call read_one(incl, stack//NL//path, path, lineno, store, raw, kw_id, error)
            if (allocated(error)) return
            cycle
         end if
         if (len(name) > 0) then
            call add_name(store%keywords, name)
            kw_id = size(store%keywords)
         end if
         call store%push(base + i1, base + i2, lineno, file_id, kw_id)
      end do
   end subroutine read_one

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

   !> Whole content of a text file, after `prefix` if given (read in place behind it, no
   !> copy); found = .false. if it cannot be opened or read.
   subroutine read_text_file(path, text, found, prefix)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: text
      logical, intent(out) :: found
      character(len=*), intent(in), optional :: prefix
      integer :: u, ios, nbytes, lp
      logical :: exists
      lp = 0
      if (present(prefix)) lp = len(prefix)
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
      allocate (character(len=lp + nbytes) :: text)
      if (lp > 0) text(1:lp) = prefix
      if (nbytes > 0) read (u, iostat=ios) text(lp + 1:)
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

end module pecplas_io_text_lines
