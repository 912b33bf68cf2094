!> Errors as values: every fallible routine ends with
!> `type(error_t), allocatable, intent(out) :: error` and callers
!> write `if (allocated(error)) return`. Only `app/` turns an error into an exit code.
module pecplas_error
   implicit none (type, external)
   private

   public :: error_t, fatal_error, deck_error, input_error, run_error, singular_error
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
      error%message = message
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
      error%message = message
   end subroutine deck_error

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

end module pecplas_error
