!> The command line of every program (pecplas, pecplas-path, pecplas-identify,
!> pecplas-sensitivity). A program declares its options — names, the value they take (none
!> for a flag, a word, an integer > 0, a number, a number > 0), whether they may repeat, a
!> help text — and its positional words; `parse` reads the words in order, answers -h/--help
!> (a text generated from the declarations) and --version (when the program has one), and
!> reports an unknown option, a missing or malformed value or a wrong number of positional
!> words as "<program>: error: <text>. usage: ..." with exit code 2, as every other input
!> error (pecplas_cmd_command). An option's value is the next word, whatever it looks like
!> (`-o --quiet` writes a file named --quiet); a word starting with '-' that is no option
!> is an unknown option. A non-repeatable option given twice keeps its last value.
module pecplas_cmd_args
   use, intrinsic :: iso_fortran_env, only: output_unit
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error, EXIT_OK, EXIT_INPUT
   use pecplas_io_text_parse, only: parse_real, parse_int
   use pecplas_cmd_command, only: command_error
   use pecplas_cmd_words, only: word_t, split, wrapped, wrapped_form
   use pecplas_cmd_option, only: option_t, option_label, find_option, valid, expected, &
      VALUE_NONE, VALUE_WORD, VALUE_POSITIVE_INTEGER, VALUE_REAL, VALUE_POSITIVE_REAL
   implicit none (type, external)
   private

   public :: arg_parser_t, lines_function
   public :: VALUE_WORD, VALUE_POSITIVE_INTEGER, VALUE_REAL, VALUE_POSITIVE_REAL

   !> What the words asked for besides a run.
   integer, parameter :: ASKED_RUN = 0, ASKED_HELP = 1, ASKED_VERSION = 2
   !> The widest option label kept beside its help in --help.
   integer, parameter :: LABEL_WIDTH = 24

   abstract interface
      !> Gives the lines --version prints (called only when asked: it may query libraries).
      subroutine lines_function(lines)
         character(len=:), allocatable, intent(out) :: lines(:)
      end subroutine lines_function
   end interface

   !> A program's command line: its declarations, then what `read` found.
   type :: arg_parser_t
      private
      character(len=:), allocatable :: program, summary
      !> Usage forms given by the program (several modes); generated when none.
      type(word_t), allocatable :: forms(:)
      !> Paragraphs printed after the options by --help (exit codes, notes).
      type(word_t), allocatable :: notes(:)
      type(option_t), allocatable :: options(:)
      procedure(lines_function), pointer, nopass :: version => null()
      !> The positional words: name in texts, noun in messages, help, count range (min 0
      !> or 1, max 0 when none are declared, 1, or -1: any number), and how many options are
      !> declared before them (their place in the generated usage line).
      character(len=:), allocatable :: pos_metavar, pos_noun, pos_help
      integer :: pos_min = 0, pos_max = 0, pos_at = 0
      type(word_t), allocatable :: words(:)
      integer :: asked = ASKED_RUN
   contains
      procedure :: init => parser_init
      procedure :: add_flag => parser_add_flag
      procedure :: add_option => parser_add_option
      procedure :: add_positional => parser_add_positional
      procedure :: add_usage => parser_add_usage
      procedure :: add_note => parser_add_note
      procedure :: read => parser_read
      procedure :: parse => parser_parse
      procedure :: asked_help => parser_asked_help
      procedure :: asked_version => parser_asked_version
      procedure :: given => parser_given
      procedure :: count => parser_count
      procedure :: text => parser_text
      procedure :: texts => parser_texts
      procedure :: int_value => parser_int_value
      procedure :: real_value => parser_real_value
      procedure :: npositional => parser_npositional
      procedure :: positional => parser_positional
      procedure :: usage => parser_usage
      procedure :: help_text => parser_help_text
      procedure :: usage_error => parser_usage_error
      procedure :: value_error => parser_value_error
      procedure, private :: usage_error_text
   end type arg_parser_t

contains

   !> Starts the declarations of `program` (its name in messages); `summary` opens --help;
   !> `version` gives the lines of --version (absent: the program has no --version).
   subroutine parser_init(this, program, summary, version)
      class(arg_parser_t), intent(out) :: this
      character(len=*), intent(in) :: program, summary
      procedure(lines_function), optional :: version
      this%program = program
      this%summary = summary
      if (present(version)) this%version => version
      allocate (this%forms(0), this%notes(0), this%options(0), this%words(0))
      this%pos_metavar = ''
      this%pos_noun = ''
      this%pos_help = ''
   end subroutine parser_init

   !> Declares a flag: `names` blank-separated ('--quiet -q'), the first one in the usage.
   subroutine parser_add_flag(this, names, help, hidden)
      class(arg_parser_t), intent(inout) :: this
      character(len=*), intent(in) :: names, help
      logical, intent(in), optional :: hidden
      call add(this, names, '', VALUE_NONE, help, .false., hidden)
   end subroutine parser_add_flag

   !> Declares an option that takes the next word as its value, named `metavar` in the
   !> texts; `kind` (default VALUE_WORD) is checked by `read`; a `repeatable` option keeps
   !> every value, in order.
   subroutine parser_add_option(this, names, metavar, help, kind, repeatable, hidden)
      class(arg_parser_t), intent(inout) :: this
      character(len=*), intent(in) :: names, metavar, help
      integer, intent(in), optional :: kind
      logical, intent(in), optional :: repeatable, hidden
      integer :: k
      k = VALUE_WORD
      if (present(kind)) k = kind
      call add(this, names, metavar, k, help, repeatable, hidden)
   end subroutine parser_add_option

   !> Declares the positional words: at least `min` (0 or 1) and at most `max` (1, or -1 for
   !> any number) of them, `metavar` in the texts, `noun` in the messages ("no deck given",
   !> "only one deck may be given"). Their place in the generated usage line is after the
   !> options declared so far.
   subroutine parser_add_positional(this, metavar, noun, help, min, max)
      class(arg_parser_t), intent(inout) :: this
      character(len=*), intent(in) :: metavar, noun, help
      integer, intent(in) :: min, max
      this%pos_metavar = metavar
      this%pos_noun = noun
      this%pos_help = help
      this%pos_min = merge(1, 0, min >= 1)
      this%pos_max = merge(1, -1, max == 1)
      this%pos_at = size(this%options)
   end subroutine parser_add_positional

   !> Adds a usage form written by the program ("pecplas --advise DECK ..."), for a program
   !> with several modes; without one the usage line is generated from the declarations.
   subroutine parser_add_usage(this, form)
      class(arg_parser_t), intent(inout) :: this
      character(len=*), intent(in) :: form
      this%forms = [this%forms, word_t(form)]
   end subroutine parser_add_usage

   !> Adds a paragraph printed after the options by --help.
   subroutine parser_add_note(this, paragraph)
      class(arg_parser_t), intent(inout) :: this
      character(len=*), intent(in) :: paragraph
      this%notes = [this%notes, word_t(paragraph)]
   end subroutine parser_add_note

   subroutine add(this, names, metavar, kind, help, repeatable, hidden)
      class(arg_parser_t), intent(inout) :: this
      character(len=*), intent(in) :: names, metavar, help
      integer, intent(in) :: kind
      logical, intent(in), optional :: repeatable, hidden
      type(option_t) :: opt
      opt%names = split(names)
      opt%metavar = metavar
      opt%kind = kind
      opt%help = help
      if (present(repeatable)) opt%repeatable = repeatable
      if (present(hidden)) opt%hidden = hidden
      allocate (opt%values(0))
      this%options = [this%options, opt]
   end subroutine add

   !> Reads the words `args` (blank-padded) in order. An error names the word and ends with
   !> the usage line; -h/--help and --version stop the reading (see asked_help,
   !> asked_version), so a word after them is not checked.
   subroutine parser_read(this, args, error)
      class(arg_parser_t), intent(inout) :: this
      character(len=*), intent(in) :: args(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: word, value
      integer :: i, k
      do k = 1, size(this%options)
         this%options(k)%values = [word_t ::]
      end do
      this%words = [word_t ::]
      this%asked = ASKED_RUN
      i = 0
      do while (i < size(args))
         i = i + 1
         word = trim(args(i))
         if (word == '-h' .or. word == '--help') then
            this%asked = ASKED_HELP
            return
         end if
         if (word == '--version' .and. associated(this%version)) then
            this%asked = ASKED_VERSION
            return
         end if
         k = find_option(this%options, word)
         if (k == 0) then
            if (word(1:min(1, len(word))) == '-') then
               call input_error(error, this%usage_error_text('unknown option '//word))
               return
            end if
            if (size(this%words) == this%pos_max) then
               if (this%pos_max == 0) then
                  call input_error(error, this%usage_error_text('unexpected word '''// &
                     word//''''))
               else
                  call input_error(error, this%usage_error_text('only one '// &
                     this%pos_noun//' may be given'))
               end if
               return
            end if
            this%words = [this%words, word_t(word)]
            cycle
         end if
         associate (opt => this%options(k))
            if (opt%kind == VALUE_NONE) then
               opt%values = [opt%values, word_t('')]
               cycle
            end if
            if (i == size(args)) then
               call input_error(error, this%usage_error_text('option '//word// &
                  ' needs a value ('//opt%metavar//')'))
               return
            end if
            i = i + 1
            value = trim(args(i))
            if (.not. valid(opt%kind, value)) then
               call input_error(error, this%usage_error_text('option '//word//': expected '// &
                  expected(opt%kind)//", got '"//value//"'"))
               return
            end if
            if (opt%repeatable) then
               opt%values = [opt%values, word_t(value)]
            else
               opt%values = [word_t(value)]
            end if
         end associate
      end do
      if (size(this%words) < this%pos_min) call input_error(error, &
         this%usage_error_text('no '//this%pos_noun//' given'))
   end subroutine parser_read

   !> Reads the words `args` as `read` does and answers what ends the program here:
   !> `done` is true when the program must return `code` at once (0 after --help or
   !> --version, printed on standard output; 2 after an error, printed on standard error).
   subroutine parser_parse(this, args, code, done)
      class(arg_parser_t), intent(inout) :: this
      character(len=*), intent(in) :: args(:)
      integer, intent(out) :: code
      logical, intent(out) :: done
      type(error_t), allocatable :: error
      character(len=:), allocatable :: lines(:)
      integer :: i
      call this%read(args, error)
      code = EXIT_OK
      done = .true.
      if (allocated(error)) then
         code = command_error(this%program, error%exit_code(), error%text())
      else if (this%asked == ASKED_HELP) then
         write (output_unit, '(a)') this%help_text()
      else if (this%asked == ASKED_VERSION) then
         call this%version(lines)
         do i = 1, size(lines)
            write (output_unit, '(a)') trim(lines(i))
         end do
      else
         done = .false.
      end if
   end subroutine parser_parse

   logical function parser_asked_help(this)
      class(arg_parser_t), intent(in) :: this
      parser_asked_help = this%asked == ASKED_HELP
   end function parser_asked_help

   logical function parser_asked_version(this)
      class(arg_parser_t), intent(in) :: this
      parser_asked_version = this%asked == ASKED_VERSION
   end function parser_asked_version

   !> True when the option named `name` (any of its names) was given.
   logical function parser_given(this, name)
      class(arg_parser_t), intent(in) :: this
      character(len=*), intent(in) :: name
      parser_given = this%count(name) > 0
   end function parser_given

   !> How many values the option `name` holds (for a flag: how often it was given).
   integer function parser_count(this, name)
      class(arg_parser_t), intent(in) :: this
      character(len=*), intent(in) :: name
      integer :: k
      parser_count = 0
      k = find_option(this%options, name)
      if (k > 0) parser_count = size(this%options(k)%values)
   end function parser_count

   !> The (last) value of option `name`, `default` (else '') when it was not given.
   function parser_text(this, name, default) result(value)
      class(arg_parser_t), intent(in) :: this
      character(len=*), intent(in) :: name
      character(len=*), intent(in), optional :: default
      character(len=:), allocatable :: value
      integer :: k
      value = ''
      if (present(default)) value = default
      k = find_option(this%options, name)
      if (k == 0) return
      associate (v => this%options(k)%values)
         if (size(v) > 0) value = v(size(v))%s
      end associate
   end function parser_text

   !> Every value of the repeatable option `name`, in order, blank-padded to the longest.
   function parser_texts(this, name) result(values)
      class(arg_parser_t), intent(in) :: this
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: values(:)
      integer :: k, i, n
      k = find_option(this%options, name)
      if (k == 0) then
         allocate (character(len=1) :: values(0))
         return
      end if
      associate (v => this%options(k)%values)
         n = 1
         do i = 1, size(v)
            n = max(n, len(v(i)%s))
         end do
         allocate (character(len=n) :: values(size(v)))
         do i = 1, size(v)
            values(i) = v(i)%s
         end do
      end associate
   end function parser_texts

   !> The value of the integer option `name` (checked by `read`), `default` when not given.
   integer function parser_int_value(this, name, default) result(value)
      class(arg_parser_t), intent(in) :: this
      character(len=*), intent(in) :: name
      integer, intent(in) :: default
      logical :: ok
      value = default
      if (.not. this%given(name)) return
      call parse_int(this%text(name), value, ok)
      if (.not. ok) value = default
   end function parser_int_value

   !> The value of the number option `name` (checked by `read`), `default` when not given.
   real(wp) function parser_real_value(this, name, default) result(value)
      class(arg_parser_t), intent(in) :: this
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: default
      logical :: ok
      value = default
      if (.not. this%given(name)) return
      call parse_real(this%text(name), value, ok)
      if (.not. ok) value = default
   end function parser_real_value

   integer function parser_npositional(this)
      class(arg_parser_t), intent(in) :: this
      parser_npositional = size(this%words)
   end function parser_npositional

   !> The i-th positional word ('' when there are fewer).
   function parser_positional(this, i) result(word)
      class(arg_parser_t), intent(in) :: this
      integer, intent(in) :: i
      character(len=:), allocatable :: word
      word = ''
      if (i >= 1 .and. i <= size(this%words)) word = this%words(i)%s
   end function parser_positional

   !> The usage line of messages: "usage: " and the forms, separated by " | ".
   function parser_usage(this) result(line)
      class(arg_parser_t), intent(in) :: this
      character(len=:), allocatable :: line
      integer :: i
      if (size(this%forms) == 0) then
         line = 'usage: '//generated_form(this)
         return
      end if
      line = 'usage: '//this%forms(1)%s
      do i = 2, size(this%forms)
         line = line//' | '//this%forms(i)%s
      end do
   end function parser_usage

   !> The --help text (lines separated by new_line): the usage forms, the summary, one
   !> entry per positional and visible option with its help, -h/--help, --version, the notes.
   function parser_help_text(this) result(text)
      class(arg_parser_t), intent(in) :: this
      character(len=:), allocatable :: text
      character(len=:), allocatable :: label
      character(len=1), parameter :: NL = new_line('a')
      integer :: i, width
      if (size(this%forms) == 0) then
         text = wrapped_form('usage: ', generated_form(this))//NL
      else
         text = wrapped_form('usage: ', this%forms(1)%s)//NL
         do i = 2, size(this%forms)
            text = text//wrapped_form('   or: ', this%forms(i)%s)//NL
         end do
      end if
      text = text//NL//wrapped(this%summary, '', 0)//NL//NL
      ! the help column: after the widest label that fits LABEL_WIDTH
      width = len('-h, --help')
      if (len(this%pos_metavar) > 0) width = max(width, len(this%pos_metavar))
      do i = 1, size(this%options)
         if (this%options(i)%hidden) cycle
         if (len(option_label(this%options(i))) <= LABEL_WIDTH) &
            width = max(width, len(option_label(this%options(i))))
      end do
      width = width + 4
      if (len(this%pos_metavar) > 0) text = text//wrapped(this%pos_help, &
         '  '//this%pos_metavar, width)//NL
      do i = 1, size(this%options)
         if (this%options(i)%hidden) cycle
         label = option_label(this%options(i))
         text = text//wrapped(this%options(i)%help, '  '//label, width)//NL
      end do
      text = text//wrapped('print this help and exit', '  -h, --help', width)
      if (associated(this%version)) text = text//NL// &
         wrapped('print the version and exit', '  --version', width)
      do i = 1, size(this%notes)
         text = text//NL//NL//wrapped(this%notes(i)%s, '', 0)
      end do
   end function parser_help_text

   !> Prints "<program>: error: <text>. <usage line>" on standard error; returns exit code 2.
   !> For the program's own checks after `parse` (options that do not go together).
   integer function parser_usage_error(this, text) result(code)
      class(arg_parser_t), intent(in) :: this
      character(len=*), intent(in) :: text
      code = command_error(this%program, EXIT_INPUT, this%usage_error_text(text))
   end function parser_usage_error

   !> As usage_error for a value of option `name` that the program's own check refused:
   !> "option NAME: expected EXPECTED, got 'VALUE'", the same words as `read`'s own checks.
   integer function parser_value_error(this, name, expected) result(code)
      class(arg_parser_t), intent(in) :: this
      character(len=*), intent(in) :: name, expected
      code = this%usage_error('option '//name//': expected '//expected//", got '"// &
         this%text(name)//"'")
   end function parser_value_error

   function usage_error_text(this, text) result(message)
      class(arg_parser_t), intent(in) :: this
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: message
      message = text//'. '//this%usage()
   end function usage_error_text

   !> The usage form generated from the declarations: each visible option in brackets
   !> (its first name and value; " ..." when repeatable), the positional words at their place.
   function generated_form(this) result(form)
      type(arg_parser_t), intent(in) :: this
      character(len=:), allocatable :: form
      integer :: i
      form = this%program
      do i = 1, size(this%options)
         if (i - 1 == this%pos_at) form = form//positional_form(this)
         if (this%options(i)%hidden) cycle
         associate (opt => this%options(i))
            form = form//' ['//opt%names(1)%s
            if (opt%kind /= VALUE_NONE) form = form//' '//opt%metavar
            if (opt%repeatable) form = form//' ...'
            form = form//']'
         end associate
      end do
      if (this%pos_at == size(this%options)) form = form//positional_form(this)
   end function generated_form

   !> " DECK", " [DECK]", " CURVE.csv [CURVE.csv ...]", " [X ...]" ('' without positionals).
   function positional_form(this) result(form)
      type(arg_parser_t), intent(in) :: this
      character(len=:), allocatable :: form
      associate (m => this%pos_metavar)
         form = ''
         if (len(m) == 0 .or. this%pos_max == 0) return
         if (this%pos_min >= 1) then
            form = ' '//m
            if (this%pos_max /= 1) form = form//' ['//m//' ...]'
         else
            form = ' ['//m
            if (this%pos_max /= 1) form = form//' ...'
            form = form//']'
         end if
      end associate
   end function positional_form

end module pecplas_cmd_args
