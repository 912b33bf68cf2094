!> The options a program declares on its command line (pecplas_cmd_args): the kinds of
!> value they take, their names, help and the values given, their label in --help, and the
!> check of a value against its kind.
module pecplas_cmd_option
   use pecplas_base_kinds, only: wp
   use pecplas_io_text_parse, only: parse_real, parse_int
   use pecplas_cmd_words, only: word_t
   implicit none (type, external)
   private

   public :: option_t, option_label, find_option, valid, expected
   public :: VALUE_NONE, VALUE_WORD, VALUE_POSITIVE_INTEGER, VALUE_REAL, VALUE_POSITIVE_REAL

   !> The value an option takes, checked by `read`: any word, an integer > 0, a number
   !> (strict Fortran form, pecplas_io_text_parse), a number > 0.
   integer, parameter :: VALUE_WORD = 1, VALUE_POSITIVE_INTEGER = 2, VALUE_REAL = 3, &
      VALUE_POSITIVE_REAL = 4
   !> A flag takes no value.
   integer, parameter :: VALUE_NONE = 0

   !> One declared option and the values the command line gave it.
   type :: option_t
      !> Its names, the first one shown in the usage line ('-o', '--output').
      type(word_t), allocatable :: names(:)
      !> The value's name in the usage and help texts ('' for a flag).
      character(len=:), allocatable :: metavar
      character(len=:), allocatable :: help
      integer :: kind = VALUE_NONE
      logical :: repeatable = .false.
      !> Left out of the usage line and --help (test hooks).
      logical :: hidden = .false.
      !> One entry per occurrence ('' for a flag); a non-repeatable option keeps the last.
      type(word_t), allocatable :: values(:)
   end type option_t

contains

   !> "-o, --output FILE.h5": short names first, then the value.
   function option_label(opt) result(label)
      type(option_t), intent(in) :: opt
      character(len=:), allocatable :: label
      integer :: i, pass
      label = ''
      do pass = 1, 2
         do i = 1, size(opt%names)
            associate (name => opt%names(i)%s)
               if ((pass == 1) .neqv. (name(1:min(2, len(name))) /= '--')) cycle
               if (len(label) > 0) label = label//', '
               label = label//name
            end associate
         end do
      end do
      if (opt%kind /= VALUE_NONE) label = label//' '//opt%metavar
   end function option_label

   !> The declared option one of whose names is `word` (0: none).
   integer function find_option(options, word) result(k)
      type(option_t), intent(in) :: options(:)
      character(len=*), intent(in) :: word
      integer :: i
      do k = 1, size(options)
         do i = 1, size(options(k)%names)
            if (options(k)%names(i)%s == word) return
         end do
      end do
      k = 0
   end function find_option

   !> True when `value` is a value of `kind` (VALUE_*).
   logical function valid(kind, value)
      integer, intent(in) :: kind
      character(len=*), intent(in) :: value
      integer :: n
      real(wp) :: x
      select case (kind)
      case (VALUE_POSITIVE_INTEGER)
         call parse_int(value, n, valid)
         valid = valid .and. n > 0
      case (VALUE_REAL)
         call parse_real(value, x, valid)
      case (VALUE_POSITIVE_REAL)
         call parse_real(value, x, valid)
         valid = valid .and. x > 0.0_wp
      case default
         valid = .true.
      end select
   end function valid

   !> What a value of `kind` must be, in messages ('an integer > 0', ...).
   function expected(kind) result(text)
      integer, intent(in) :: kind
      character(len=:), allocatable :: text
      select case (kind)
      case (VALUE_POSITIVE_INTEGER)
         text = 'an integer > 0'
      case (VALUE_REAL)
         text = 'a number'
      case (VALUE_POSITIVE_REAL)
         text = 'a number > 0'
      case default
         text = 'a value'
      end select
   end function expected

end module pecplas_cmd_option
