!> Errors as values: every fallible routine ends with
!> `type(error_t), allocatable, intent(out) :: error` and callers
!> write `if (allocated(error)) return`. Only the command layer (`src/cmd/`) turns an error
!> into an exit code (`exit_code`); the programs of `app/` hand that code to the system.
module pecplas_base_error
   use pecplas_base_suggest, only: with_suggestion
   implicit none (type, external)
   private

   public :: error_t, fatal_error, deck_error, input_error, run_error, singular_error, shortened
   public :: EXIT_OK, EXIT_INPUT, EXIT_STOPPED, EXIT_INTERNAL, EXIT_INTERRUPTED

   !> Exit codes of the batch executable (4: stopped by SIGTERM, SIGINT or SIGHUP).
   integer, parameter :: EXIT_OK = 0, EXIT_INPUT = 2, EXIT_STOPPED = 3, EXIT_INTERNAL = 1, &
      EXIT_INTERRUPTED = 4

   !> Kinds of error (decide the exit code).
   integer, parameter, public :: ERR_INTERNAL = 1, ERR_INPUT = 2, ERR_RUN = 3, ERR_SINGULAR = 4

   !> An error with an optional deck position.
   type :: error_t
      !> One of ERR_INTERNAL, ERR_INPUT, ERR_RUN, ERR_SINGULAR.
      integer :: kind = ERR_INTERNAL
      character(len=:), allocatable :: message
      !> Deck file and line (line = 0 when unknown), keyword being read.
      character(len=:), allocatable :: file
      integer :: line = 0
      character(len=:), allocatable :: keyword
   contains
      procedure :: text => error_text
      procedure :: exit_code => error_exit_code
   end type error_t

contains

   !> Internal or unclassified failure.
   subroutine fatal_error(error, message)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: message
      allocate (error)
      error%kind = ERR_INTERNAL
      error%message = message
   end subroutine fatal_error

   !> Input error without a deck position (bad command line, unreadable file).
   subroutine input_error(error, message)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: message
      allocate (error)
      error%kind = ERR_INPUT
      error%message = with_suggestion(message)
   end subroutine input_error

   !> Deck error naming file, line and keyword.
   subroutine deck_error(error, file, line, keyword, message)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: file, keyword, message
      integer, intent(in) :: line
      allocate (error)
      error%kind = ERR_INPUT
      error%file = file
      error%line = line
      error%keyword = keyword
      ! a misspelt name: the closest known names (pecplas_base_suggest)
      error%message = with_suggestion(message)
   end subroutine deck_error

   !> `text` with every word (run of characters without a blank) longer than LONG_WORD cut
   !> to its first KEPT characters and '...(n characters)': a message quoting a token of a
   !> deck line of megabytes stays a readable line (applied where errors are printed,
   !> pecplas_cmd_command).
   pure function shortened(text) result(out)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: out
      integer, parameter :: LONG_WORD = 256, KEPT = 60
      character(len=24) :: count
      integer :: i, j, k
      if (len(text) <= LONG_WORD) then
         out = text
         return
      end if
      allocate (character(len=len(text)) :: out)
      i = 1
      k = 0
      do while (i <= len(text))
         j = index(text(i:), ' ')
         if (j == 0) then
            j = len(text)
         else
            j = i + j - 1
         end if
         ! text(i:j): a word and the blank after it (none at the end)
         if (j - i + 1 > LONG_WORD) then
            write (count, '(a,i0,a)') '...(', j - i + merge(0, 1, text(j:j) == ' '), &
               ' characters)'
            out(k + 1:k + KEPT) = text(i:i + KEPT - 1)
            k = k + KEPT
            out(k + 1:k + len_trim(count)) = trim(count)
            k = k + len_trim(count)
            if (text(j:j) == ' ') then
               k = k + 1
               out(k:k) = ' '
            end if
         else
            out(k + 1:k + j - i + 1) = text(i:j)
            k = k + j - i + 1
         end if
         i = j + 1
      end do
      out = out(1:k)
   end function shortened

   !> A run that cannot go on (divergence, limit load).
   subroutine run_error(error, message)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: message
      allocate (error)
      error%kind = ERR_RUN
      error%message = message
   end subroutine run_error

   !> A singular (or not positive definite) system.
   subroutine singular_error(error, message)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: message
      allocate (error)
      error%kind = ERR_SINGULAR
      error%message = message
   end subroutine singular_error

   !> Human-readable text: "file:line: [KEYWORD] message".
   function error_text(this) result(text)
      class(error_t), intent(in) :: this
      character(len=:), allocatable :: text
      character(len=16) :: buf
      text = ''
      if (allocated(this%file)) then
         text = this%file
         if (this%line > 0) then
            write (buf, '(i0)') this%line
            text = text//':'//trim(buf)
         end if
         text = text//': '
      end if
      if (allocated(this%keyword)) then
         if (len(this%keyword) > 0) text = text//'['//this%keyword//'] '
      end if
      if (allocated(this%message)) text = text//this%message
   end function error_text

   !> Exit code of the batch executable for this error.
   pure integer function error_exit_code(this) result(code)
      class(error_t), intent(in) :: this
      select case (this%kind)
      case (ERR_INPUT, ERR_SINGULAR)
         code = EXIT_INPUT
      case (ERR_RUN)
         code = EXIT_STOPPED
      case default
         code = EXIT_INTERNAL
      end select
   end function error_exit_code

end module pecplas_base_error
