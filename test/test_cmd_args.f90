!> The command-line layer (pecplas_cmd_args): what a declared option reads, the messages of
!> every usage error (the same words for every program), the usage line and --help text
!> generated from the declarations, and the declarations of the four programs (their usage
!> lines are those quoted by README.md, doc/path.md and doc/identify.md).
module test_cmd_args
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, ERR_INPUT
   use pecplas_base_strings, only: itoa
   use pecplas_cmd_args, only: arg_parser_t, VALUE_POSITIVE_INTEGER, VALUE_REAL, &
      VALUE_POSITIVE_REAL
   use pecplas_cmd_pecplas, only: pecplas_command_line
   use pecplas_cmd_path, only: path_command_line
   use pecplas_cmd_identify, only: identify_command_line
   use pecplas_cmd_sensitivity, only: sensitivity_command_line
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_cmd_args

   !> The usage line of the example program `demo` (see declare_demo).
   character(len=*), parameter :: DEMO_USAGE = 'usage: demo DECK [-o FILE] [--quiet] '// &
      '[--steps N] [--scale X] [--tag T ...]'

contains

   subroutine collect_cmd_args(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('values', test_values), &
               new_unittest('value_looks_like_option', test_value_word), &
               new_unittest('usage_errors', test_usage_errors), &
               new_unittest('positional_counts', test_positional_counts), &
               new_unittest('help_and_version', test_help_version), &
               new_unittest('help_text', test_help_text), &
               new_unittest('program_usage_lines', test_program_usage), &
               new_unittest('program_options', test_program_options)]
   end subroutine collect_cmd_args

   !> demo DECK [-o FILE] [--quiet] [--steps N] [--scale X] [--tag T ...] (+ a hidden hook).
   subroutine declare_demo(cli, with_version)
      type(arg_parser_t), intent(out) :: cli
      logical, intent(in) :: with_version
      if (with_version) then
         call cli%init('demo', 'Runs a demo deck.', demo_version)
      else
         call cli%init('demo', 'Runs a demo deck.')
      end if
      call cli%add_positional('DECK', 'deck', 'the deck', 1, 1)
      call cli%add_option('-o --output', 'FILE', 'results file')
      call cli%add_flag('--quiet -q', 'say nothing')
      call cli%add_option('--steps', 'N', 'increments', VALUE_POSITIVE_INTEGER)
      call cli%add_option('--scale', 'X', 'a factor', VALUE_REAL)
      call cli%add_option('--tag', 'T', 'a label, repeatable', repeatable=.true.)
      call cli%add_option('--hook', 'S', 'a test hook', VALUE_POSITIVE_REAL, hidden=.true.)
   end subroutine declare_demo

   subroutine demo_version(lines)
      character(len=:), allocatable, intent(out) :: lines(:)
      lines = [character(len=12) :: 'demo 1.0', 'commit: x']
   end subroutine demo_version

   !> Reads `words` with the demo declarations; `message`: the error's text ('' if none).
   subroutine read_demo(words, cli, message, with_version)
      character(len=*), intent(in) :: words(:)
      type(arg_parser_t), intent(out) :: cli
      character(len=:), allocatable, intent(out) :: message
      logical, intent(in), optional :: with_version
      type(error_t), allocatable :: error
      logical :: v
      v = .false.
      if (present(with_version)) v = with_version
      call declare_demo(cli, v)
      call cli%read(words, error)
      message = ''
      if (allocated(error)) then
         message = error%text()
         if (error%kind /= ERR_INPUT) message = 'not an input error: '//message
      end if
   end subroutine read_demo

   !> Long and short names, typed values, a repeatable option in order, the last value of a
   !> non-repeatable one, defaults when an option is absent.
   subroutine test_values(error)
      type(error_t), allocatable, intent(out) :: error
      type(arg_parser_t) :: cli
      character(len=:), allocatable :: message, tags(:)
      call read_demo([character(len=8) :: '-q', 'd.inp', '--output', 'a.h5', '-o', 'b.h5', &
         '--steps', '12', '--scale', '-2.5e1', '--tag', 'x', '--tag', 'yy', '--hook', '.5'], &
         cli, message)
      call check(error, message == '', 'no error: '//message)
      if (allocated(error)) return
      tags = cli%texts('--tag')
      call check(error, cli%given('--quiet') .and. cli%given('-q') .and. &
         cli%count('--quiet') == 1 .and. cli%text('--output') == 'b.h5' .and. &
         cli%text('-o') == 'b.h5' .and. cli%int_value('--steps', 0) == 12 .and. &
         cli%real_value('--scale', 0.0_wp) == -25.0_wp .and. &
         cli%real_value('--hook', 0.0_wp) == 0.5_wp .and. size(tags) == 2 .and. &
         cli%npositional() == 1 .and. cli%positional(1) == 'd.inp', &
         'every value read, the last -o kept')
      if (allocated(error)) return
      call check(error, tags(1) == 'x' .and. tags(2) == 'yy' .and. cli%count('--tag') == 2, &
         'repeatable option: both values, in order')
      if (allocated(error)) return
      call read_demo([character(len=8) :: 'd.inp'], cli, message)
      tags = cli%texts('--tag')
      call check(error, message == '' .and. .not. cli%given('-q') .and. &
         cli%text('-o') == '' .and. cli%text('-o', 'def.h5') == 'def.h5' .and. &
         cli%int_value('--steps', 7) == 7 .and. cli%real_value('--scale', 1.5_wp) == 1.5_wp &
         .and. size(tags) == 0 .and. cli%positional(2) == '', 'defaults when absent')
   end subroutine test_values

   !> An option's value is the next word, whatever it looks like (as before the layer).
   subroutine test_value_word(error)
      type(error_t), allocatable, intent(out) :: error
      type(arg_parser_t) :: cli
      character(len=:), allocatable :: message
      call read_demo([character(len=8) :: '-o', '--quiet', 'd.inp', '--tag', '-h'], cli, &
         message)
      call check(error, message == '' .and. cli%text('-o') == '--quiet' .and. &
         .not. cli%given('--quiet') .and. cli%text('--tag') == '-h' .and. &
         .not. cli%asked_help(), '-o --quiet: a file named --quiet; --tag -h: no help')
   end subroutine test_value_word

   !> Every usage error: "<text>. usage: ...", an input error (exit code 2).
   subroutine test_usage_errors(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error([character(len=8) :: 'd.inp', '--bogus'], 'unknown option --bogus', &
         error)
      if (allocated(error)) return
      call expect_error([character(len=8) :: 'd.inp', '-'], 'unknown option -', error)
      if (allocated(error)) return
      call expect_error([character(len=8) :: 'd.inp', '-o'], 'option -o needs a value (FILE)', &
         error)
      if (allocated(error)) return
      call expect_error([character(len=8) :: 'd.inp', '--steps', '0'], &
         "option --steps: expected an integer > 0, got '0'", error)
      if (allocated(error)) return
      call expect_error([character(len=8) :: 'd.inp', '--steps', '2.5'], &
         "option --steps: expected an integer > 0, got '2.5'", error)
      if (allocated(error)) return
      call expect_error([character(len=8) :: 'd.inp', '--scale', '1,5'], &
         "option --scale: expected a number, got '1,5'", error)
      if (allocated(error)) return
      call expect_error([character(len=8) :: 'd.inp', '--hook', '-1'], &
         "option --hook: expected a number > 0, got '-1'", error)
      if (allocated(error)) return
      ! no --version declared: an unknown option like any other
      call expect_error([character(len=9) :: 'd.inp', '--version'], &
         'unknown option --version', error)
   end subroutine test_usage_errors

   subroutine expect_error(words, text, error)
      character(len=*), intent(in) :: words(:), text
      type(error_t), allocatable, intent(out) :: error
      type(arg_parser_t) :: cli
      character(len=:), allocatable :: message
      call read_demo(words, cli, message)
      call check(error, message == text//'. '//DEMO_USAGE, 'expected "'//text//'. '// &
         DEMO_USAGE//'", got "'//message//'"')
   end subroutine expect_error

   !> One deck exactly; from one to any number of curves; none or one optional deck.
   subroutine test_positional_counts(error)
      type(error_t), allocatable, intent(out) :: error
      type(arg_parser_t) :: cli
      type(error_t), allocatable :: e
      call expect_error([character(len=8) :: '-q'], 'no deck given', error)
      if (allocated(error)) return
      call expect_error([character(len=8) :: 'a.inp', 'b.inp'], 'only one deck may be given', &
         error)
      if (allocated(error)) return
      call cli%init('many', 'Reads curves.')
      call cli%add_positional('C', 'test curve', 'a curve', 1, -1)
      call cli%read([character(len=1) :: 'a', 'b', 'c'], e)
      call check(error, .not. allocated(e) .and. cli%npositional() == 3 .and. &
         cli%positional(3) == 'c' .and. cli%usage() == 'usage: many C [C ...]', &
         'any number of curves: '//cli%usage())
      if (allocated(error)) return
      call cli%read([character(len=1) :: ], e)
      call check(error, allocated(e), 'no curve: an error')
      if (allocated(error)) return
      call check(error, e%text() == 'no test curve given. usage: many C [C ...]', e%text())
      if (allocated(error)) return
      call cli%init('opt', 'An optional deck.')
      call cli%add_flag('--quiet', 'quiet')
      call cli%add_positional('DECK', 'deck', 'a deck', 0, 1)
      call cli%read([character(len=1) :: ], e)
      call check(error, .not. allocated(e) .and. cli%npositional() == 0 .and. &
         cli%usage() == 'usage: opt [--quiet] [DECK]', 'an optional deck: '//cli%usage())
      if (allocated(error)) return
      call cli%init('none', 'No words.')
      call cli%read([character(len=1) :: 'x'], e)
      call check(error, allocated(e), 'a word where none is declared: an error')
      if (allocated(error)) return
      call check(error, e%text() == "unexpected word 'x'. usage: none", e%text())
   end subroutine test_positional_counts

   !> -h/--help and --version (when declared) stop the reading wherever they stand: no error
   !> for the words after them, and no "no deck given".
   subroutine test_help_version(error)
      type(error_t), allocatable, intent(out) :: error
      type(arg_parser_t) :: cli
      character(len=:), allocatable :: message
      call read_demo([character(len=8) :: '-h', '--bogus'], cli, message)
      call check(error, message == '' .and. cli%asked_help(), '-h before a bad word: help')
      if (allocated(error)) return
      call read_demo([character(len=8) :: '--help'], cli, message)
      call check(error, message == '' .and. cli%asked_help(), '--help alone: help')
      if (allocated(error)) return
      call read_demo([character(len=9) :: '--version', 'x', 'y'], cli, message, .true.)
      call check(error, message == '' .and. cli%asked_version() .and. .not. cli%asked_help(), &
         '--version declared: version')
      if (allocated(error)) return
      call read_demo([character(len=8) :: '--bogus', '-h'], cli, message)
      call check(error, index(message, 'unknown option --bogus') == 1, &
         'a bad word before -h: its error, in the order of the words')
   end subroutine test_help_version

   !> --help: the usage, the summary, every visible option once with its help, -h and
   !> --version, nothing of a hidden option, no line wider than 80 columns.
   subroutine test_help_text(error)
      type(error_t), allocatable, intent(out) :: error
      type(arg_parser_t) :: cli
      character(len=:), allocatable :: text
      character(len=1), parameter :: NL = new_line('a')
      integer :: i, j, widest
      call declare_demo(cli, .true.)
      text = cli%help_text()
      call check(error, index(text, DEMO_USAGE//NL) == 1 .and. &
         index(text, NL//'Runs a demo deck.'//NL) > 0 .and. &
         index(text, NL//'  DECK ') > 0 .and. index(text, NL//'  -o, --output FILE ') > 0 &
         .and. index(text, NL//'  -q, --quiet ') > 0 .and. &
         index(text, NL//'  --tag T ') > 0 .and. index(text, 'a label, repeatable') > 0 .and. &
         index(text, NL//'  -h, --help ') > 0 .and. index(text, NL//'  --version ') > 0 .and. &
         index(text, 'hook') == 0, 'help text:'//NL//text)
      if (allocated(error)) return
      ! the help column is the same for every entry
      call check(error, index(text, '  -o, --output FILE  results file') > 0 .and. &
         index(text, '  DECK               the deck') > 0, 'help column:'//NL//text)
      if (allocated(error)) return
      call pecplas_command_line(cli)
      text = cli%help_text()
      widest = 0
      i = 1
      do while (i <= len(text))
         j = index(text(i:), NL)
         if (j == 0) j = len(text) - i + 2
         widest = max(widest, j - 1)
         i = i + j
      end do
      call check(error, widest <= 80 .and. index(text, NL//'   or: pecplas --advise DECK') > 0 &
         .and. index(text, 'stop-after') == 0, 'pecplas --help: lines <= 80 columns '// &
         '(widest: '//itoa(widest)//'), three forms, no test hook:'//NL//text)
   end subroutine test_help_text

   !> The usage lines of the four programs, as the docs quote them (README.md, doc/path.md,
   !> doc/identify.md) and as every usage error ends.
   subroutine test_program_usage(error)
      type(error_t), allocatable, intent(out) :: error
      type(arg_parser_t) :: cli
      call pecplas_command_line(cli)
      call check(error, cli%usage() == 'usage: pecplas DECK [-o FILE.h5] [--quiet] '// &
         '[--restart OLD.h5] [--strict] | pecplas --advise DECK [--goal node:N:x|y | '// &
         '--advise-node N] [--max-dofs N] | pecplas DECK --target-error E% [--goal '// &
         'node:N:x|y | reaction:SET[:x|y] | limit] [--max-dofs N] [-o FILE.h5]', cli%usage())
      if (allocated(error)) return
      call path_command_line(cli)
      call check(error, cli%usage() == 'usage: pecplas-path DECK [-o BASE] [--quiet] '// &
         '[--max-seconds S]', cli%usage())
      if (allocated(error)) return
      call identify_command_line(cli)
      call check(error, cli%usage() == 'usage: pecplas-identify [--version initial|improved] '// &
         '[--secant MM] [--window MM] [--r0 R0] [--zero-cohesion] [--total-gamma] '// &
         '[--refine-alpha] [-o FILE.csv] [--quiet] CURVE.csv [CURVE.csv ...]', cli%usage())
      if (allocated(error)) return
      call sensitivity_command_line(cli)
      call check(error, cli%usage() == 'usage: pecplas-sensitivity [DECK] [--sigma-n0 S] '// &
         '[--to MM] [--steps N] [--table III.3|III.4] [--perturb KEY=PERCENT ...] '// &
         '[-o FILE.csv] [--quiet]', cli%usage())
   end subroutine test_program_usage

   !> The programs read their options as before: pecplas's three modes and its hidden test
   !> hook, pecplas-identify's --version (the model version: no program --version).
   subroutine test_program_options(error)
      type(error_t), allocatable, intent(out) :: error
      type(arg_parser_t) :: cli
      type(error_t), allocatable :: e
      call pecplas_command_line(cli)
      call cli%read([character(len=24) :: 'd.inp', '--restart', 'old.h5', '-o', 'new.h5', &
         '--strict', '--stop-after-increments', '3', '-q'], e)
      call check(error, .not. allocated(e) .and. cli%text('--restart') == 'old.h5' .and. &
         cli%text('--output') == 'new.h5' .and. cli%given('--strict') .and. &
         cli%int_value('--stop-after-increments', 0) == 3 .and. cli%given('--quiet'), &
         'pecplas: a restart with the test hook')
      if (allocated(error)) return
      call cli%read([character(len=16) :: '--advise', 'd.inp', '--advise-node', 'x'], e)
      call check(error, allocated(e), 'pecplas --advise-node x: an error')
      if (allocated(error)) return
      call check(error, index(e%text(), "option --advise-node: expected an integer > 0, "// &
         "got 'x'. usage: pecplas DECK") == 1, e%text())
      if (allocated(error)) return
      call cli%read([character(len=16) :: '--version'], e)
      call check(error, .not. allocated(e) .and. cli%asked_version(), 'pecplas --version')
      if (allocated(error)) return
      call identify_command_line(cli)
      call cli%read([character(len=16) :: '--version', 'initial', 'a.csv', 'b.csv'], e)
      call check(error, .not. allocated(e) .and. .not. cli%asked_version() .and. &
         cli%text('--version') == 'initial' .and. cli%npositional() == 2, &
         'pecplas-identify --version initial: the model version')
      if (allocated(error)) return
      call sensitivity_command_line(cli)
      call cli%read([character(len=16) :: '--perturb', 'KN=30', '--perturb', 'PHI=5', &
         '--steps', 'many'], e)
      call check(error, allocated(e), 'pecplas-sensitivity --steps many: an error')
      if (allocated(error)) return
      call check(error, index(e%text(), "option --steps: expected an integer > 0, got "// &
         "'many'. usage: pecplas-sensitivity [DECK]") == 1, e%text())
   end subroutine test_program_options

end module test_cmd_args
