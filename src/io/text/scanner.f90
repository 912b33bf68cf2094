!> Fast whitespace tokenizer over a whole text file held in memory, tracking line numbers
!> for messages. Made for large mesh files: one read of the file, no per-line records,
!> integers and most reals parsed without Fortran internal I/O.
module pecplas_io_text_scanner
   use iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error, input_error
   use pecplas_io_text_parse, only: parse_real
   use pecplas_io_text_number, only: decimal_value
   implicit none (type, external)
   private

   public :: scanner_t

   !> A file's text and a cursor. Tokens are maximal runs of characters > ' '.
   type :: scanner_t
      character(len=:), allocatable :: path
      character(len=:), allocatable :: buf
      !> Next character to look at, and its line.
      integer(int64) :: pos = 1
      integer :: line = 1
      !> Last token: buf(t1:t2), on line tok_line.
      integer(int64) :: t1 = 1, t2 = 0
      integer :: tok_line = 1
   contains
      procedure :: open => scanner_open
      procedure :: next => scanner_next
      procedure :: token => scanner_token
      procedure :: get_int => scanner_get_int
      procedure :: get_real => scanner_get_real
      procedure :: get_word => scanner_get_word
      procedure :: get_name => scanner_get_name
      procedure :: skip_lines => scanner_skip_lines
      procedure :: remaining => scanner_remaining
      procedure :: fail => scanner_fail
   end type scanner_t

contains

   !> Reads the whole file `path` into memory.
   subroutine scanner_open(this, path, error)
      class(scanner_t), intent(out) :: this
      character(len=*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios
      integer(int64) :: n
      character(len=256) :: msg
      this%path = path
      open (newunit=u, file=path, access='stream', form='unformatted', status='old', &
            action='read', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call input_error(error, 'cannot open '''//path//''': '//trim(msg))
         return
      end if
      inquire (unit=u, size=n)
      allocate (character(len=max(n, 0_int64)) :: this%buf)
      if (n > 0) read (u, iostat=ios, iomsg=msg) this%buf
      close (u)
      if (ios /= 0) call input_error(error, 'cannot read '''//path//''': '//trim(msg))
      ! skip a UTF-8 byte order mark
      if (n >= 3) then
         if (this%buf(1:3) == achar(239)//achar(187)//achar(191)) this%pos = 4
      end if
   end subroutine scanner_open

   !> Moves to the next token; .false. at end of file.
   logical function scanner_next(this) result(ok)
      class(scanner_t), intent(inout) :: this
      integer(int64) :: p, n
      integer :: c
      n = len(this%buf, kind=int64)
      p = this%pos
      do while (p <= n)
         c = iachar(this%buf(p:p))
         if (c > 32) exit
         if (c == 10) this%line = this%line + 1
         ! a carriage return alone ends a line too (files of classic Mac OS editors)
         if (c == 13) then
            if (p == n) then
               this%line = this%line + 1
            else if (iachar(this%buf(p + 1:p + 1)) /= 10) then
               this%line = this%line + 1
            end if
         end if
         p = p + 1
      end do
      ok = p <= n
      ! at end of file the last token's line stays, the most useful place to point at
      if (ok) this%tok_line = this%line
      this%t1 = p
      do while (p <= n)
         if (iachar(this%buf(p:p)) <= 32) exit
         p = p + 1
      end do
      this%t2 = p - 1
      this%pos = p
   end function scanner_next

   !> Copy of the last token.
   function scanner_token(this) result(s)
      class(scanner_t), intent(in) :: this
      character(len=:), allocatable :: s
      s = this%buf(this%t1:this%t2)
   end function scanner_token

   !> Error at the line of the last token: "path:line: [keyword] message".
   subroutine scanner_fail(this, error, keyword, message)
      class(scanner_t), intent(in) :: this
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: keyword, message
      call deck_error(error, this%path, this%tok_line, keyword, message)
   end subroutine scanner_fail

   !> Next token as a default integer.
   subroutine scanner_get_int(this, v, keyword, error)
      class(scanner_t), intent(inout) :: this
      integer, intent(out) :: v
      character(len=*), intent(in) :: keyword
      type(error_t), allocatable, intent(out) :: error
      integer(int64) :: p, acc
      integer :: c
      logical :: neg
      v = 0
      if (.not. this%next()) then
         call this%fail(error, keyword, 'unexpected end of file (truncated?)')
         return
      end if
      p = this%t1
      neg = this%buf(p:p) == '-'
      if (neg .or. this%buf(p:p) == '+') p = p + 1
      acc = 0
      if (p > this%t2 .or. this%t2 - p > 10) then
         call this%fail(error, keyword, 'expected an integer, got '''//this%token()//'''')
         return
      end if
      do while (p <= this%t2)
         c = iachar(this%buf(p:p)) - 48
         if (c < 0 .or. c > 9) then
            call this%fail(error, keyword, 'expected an integer, got '''//this%token()//'''')
            return
         end if
         acc = 10*acc + c
         p = p + 1
      end do
      if (acc > huge(v)) then
         call this%fail(error, keyword, 'integer '//this%token()//' is too large')
         return
      end if
      v = int(acc)
      if (neg) v = -v
   end subroutine scanner_get_int

   !> Next token as a real. Plain decimals of up to 18 significant digits are converted from
   !> the digits read here (pecplas_io_text_number%decimal_value: the value a Fortran read gives);
   !> other plain decimals by strtod (the same value again); other forms fall back to a
   !> Fortran read.
   subroutine scanner_get_real(this, v, keyword, error)
      class(scanner_t), intent(inout) :: this
      real(wp), intent(out) :: v
      character(len=*), intent(in) :: keyword
      type(error_t), allocatable, intent(out) :: error
      integer(int64) :: p, mant
      integer :: c, nd, e10, ex, ios
      logical :: neg, negx, dot, digits, fast
      v = 0.0_wp
      if (.not. this%next()) then
         call this%fail(error, keyword, 'unexpected end of file (truncated?)')
         return
      end if
      p = this%t1
      neg = this%buf(p:p) == '-'
      if (neg .or. this%buf(p:p) == '+') p = p + 1
      mant = 0; nd = 0; e10 = 0; dot = .false.; digits = .false.; fast = .true.
      do while (p <= this%t2)
         c = iachar(this%buf(p:p))
         if (c >= 48 .and. c <= 57) then
            digits = .true.
            if (mant > 0 .or. c > 48) nd = nd + 1
            if (nd > 18) then
               fast = .false.
               exit
            end if
            mant = 10*mant + (c - 48)
            if (dot) e10 = e10 - 1
         else if (c == 46 .and. .not. dot) then
            dot = .true.
         else
            exit
         end if
         p = p + 1
      end do
      fast = fast .and. digits
      if (fast .and. p <= this%t2) then
         c = iachar(this%buf(p:p))
         fast = c == 69 .or. c == 101 .or. c == 68 .or. c == 100
         p = p + 1
         negx = .false.
         if (fast .and. p <= this%t2) then
            negx = this%buf(p:p) == '-'
            if (negx .or. this%buf(p:p) == '+') p = p + 1
         end if
         ! one to three exponent digits, up to the end of the token
         fast = fast .and. p <= this%t2 .and. this%t2 - p < 3
         ex = 0
         do while (fast .and. p <= this%t2)
            c = iachar(this%buf(p:p)) - 48
            fast = c >= 0 .and. c <= 9
            ex = 10*ex + c
            p = p + 1
         end do
         if (negx) ex = -ex
         e10 = e10 + ex
      end if
      ! a whole plain decimal of at most 18 significant digits: exact conversion from its
      ! digits (long 17-digit coordinates included, pecplas_io_text_number)
      fast = fast .and. p > this%t2
      if (fast) call decimal_value(mant, nd, e10, neg, v, fast)
      if (.not. fast) then
         ! other forms: strtod when the form is a plain decimal, else a Fortran read
         call parse_real(this%buf(this%t1:this%t2), v, fast)
         if (fast) return
         read (this%buf(this%t1:this%t2), *, iostat=ios) v
         if (ios /= 0) then
            call this%fail(error, keyword, 'expected a real number, got '''//this%token()//'''')
            return
         end if
         if (.not. ieee_is_finite(v)) then
            call this%fail(error, keyword, 'not a finite number: '''//this%token()//'''')
            return
         end if
      end if
   end subroutine scanner_get_real

   !> Next token as a string.
   subroutine scanner_get_word(this, w, keyword, error)
      class(scanner_t), intent(inout) :: this
      character(len=:), allocatable, intent(out) :: w
      character(len=*), intent(in) :: keyword
      type(error_t), allocatable, intent(out) :: error
      if (.not. this%next()) then
         call this%fail(error, keyword, 'unexpected end of file (truncated?)')
         return
      end if
      w = this%token()
   end subroutine scanner_get_word

   !> Next token, or a "double-quoted string" (may hold blanks, ends on the same line).
   subroutine scanner_get_name(this, w, keyword, error)
      class(scanner_t), intent(inout) :: this
      character(len=:), allocatable, intent(out) :: w
      character(len=*), intent(in) :: keyword
      type(error_t), allocatable, intent(out) :: error
      integer(int64) :: p
      if (.not. this%next()) then
         call this%fail(error, keyword, 'unexpected end of file (truncated?)')
         return
      end if
      if (this%buf(this%t1:this%t1) /= '"') then
         w = this%token()
         return
      end if
      p = this%t1 + 1
      do while (p <= len(this%buf, kind=int64))
         if (this%buf(p:p) == '"' .or. this%buf(p:p) == achar(10)) exit
         p = p + 1
      end do
      if (p > len(this%buf, kind=int64)) then
         call this%fail(error, keyword, 'unterminated quoted name')
         return
      end if
      if (this%buf(p:p) /= '"') then
         call this%fail(error, keyword, 'unterminated quoted name')
         return
      end if
      w = this%buf(this%t1 + 1:p - 1)
      this%pos = p + 1
   end subroutine scanner_get_name

   !> Bytes of the file after the cursor: a bound on what a count announced in a header
   !> can hold, checked before allocating for it.
   pure integer(int64) function scanner_remaining(this) result(n)
      class(scanner_t), intent(in) :: this
      n = max(len(this%buf, kind=int64) - this%pos + 1, 0_int64)
   end function scanner_remaining

   !> Skips the rest of the current line, then `n` more lines.
   subroutine scanner_skip_lines(this, n, keyword, error)
      class(scanner_t), intent(inout) :: this
      integer, intent(in) :: n
      character(len=*), intent(in) :: keyword
      type(error_t), allocatable, intent(out) :: error
      integer(int64) :: p, last, i
      integer :: k
      last = len(this%buf, kind=int64)
      p = this%pos
      do k = 0, n
         i = index(this%buf(p:last), achar(10), kind=int64)
         if (i == 0) then
            this%pos = last + 1
            this%tok_line = this%line
            if (k < n) call this%fail(error, keyword, 'unexpected end of file (truncated?)')
            return
         end if
         p = p + i
         this%line = this%line + 1
      end do
      this%pos = p
   end subroutine scanner_skip_lines

end module pecplas_io_text_scanner
