!> The command `pecplas-sensitivity [DECK] [options]`: the sensitivity study of table III.4
!> (pecplas_studies_sensitivity_core) for the law of a path deck (its *INTERFACE_LAW; its *PATH is
!> not used), by default table III.2's improved MODJOIN set, on CNL and CND paths at
!> sigma_n0 = 56 kPa from 0 to 6 mm. Exit codes as `pecplas`: 0 done, 2 input error,
!> 3 a reference path stopped, 1 internal error.
module pecplas_cmd_sensitivity
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, EXIT_OK, EXIT_INPUT
   use pecplas_base_files, only: make_directories, path_dir
   use pecplas_base_strings, only: upper
   use pecplas_base_params, only: params_t
   use pecplas_io_text_parse, only: parse_real
   use pecplas_base_version, only: VERSION
   use pecplas_joints_laws_factory, only: default_law_registry
   use pecplas_studies_path_deck, only: path_deck_t, read_path_deck
   use pecplas_studies_sensitivity_core, only: law_path_runner_t, sensitivity_t, sensitivity_study
   use pecplas_studies_sensitivity_thesis, only: THESIS_KEYS, FRACTIONS_III3, FRACTIONS_III4, &
      CURVE_LABELS, thesis_curves, table_iii2_params, THESIS_SIGMA_N0, THESIS_EPS_T
   use pecplas_studies_sensitivity_report, only: print_sensitivity, write_sensitivity_csv
   use pecplas_cmd_command, only: command_error
   use pecplas_cmd_args, only: arg_parser_t, VALUE_POSITIVE_REAL, VALUE_POSITIVE_INTEGER
   use pecplas_base_strings, only: decimal_text
   implicit none (type, external)
   private

   !> Program name in error messages.
   character(len=*), parameter :: COMMAND = 'pecplas-sensitivity'

   public :: sensitivity_main, sensitivity_command_line

contains

   !> The options of pecplas-sensitivity.
   subroutine sensitivity_command_line(cli)
      type(arg_parser_t), intent(out) :: cli
      call cli%init(COMMAND, 'Sensitivity of an interface law to its parameters (thesis '// &
         'III.21, table III.4): each parameter perturbed by +/- a percentage, Q_p on the CNL '// &
         '(tau, eps_n) and CND (tau, sigma_n) curves, normalised by the largest per curve, '// &
         'beside the thesis. See doc/identify.md.', sensitivity_version)
      call cli%add_positional('DECK', 'deck', 'a path deck whose *INTERFACE_LAW is the '// &
         'reference set (default: table III.2, MODJOIN)', 0, 1)
      call cli%add_option('--sigma-n0', 'S', 'initial normal stress, kPa (56)', &
         VALUE_POSITIVE_REAL)
      call cli%add_option('--to', 'MM', 'largest eps_t of the paths (6) in --steps '// &
         'increments', VALUE_POSITIVE_REAL)
      call cli%add_option('--steps', 'N', 'increments of each path (600)', &
         VALUE_POSITIVE_INTEGER)
      call cli%add_option('--table', 'III.3|III.4', 'perturbations of that table (III.4: '// &
         'beta +/-15 %, III.3: +/-50 %)')
      call cli%add_option('--perturb', 'KEY=PERCENT', 'set the perturbation of a parameter '// &
         '(deck key, in %), or add one', repeatable=.true.)
      call cli%add_option('-o --output', 'FILE.csv', 'raw and normalised Q_p '// &
         '(output/sensitivity.csv)')
      call cli%add_flag('--quiet -q', 'no table, no "written:" line')
      call cli%add_note('Exit codes: 0 done, 2 input error, 3 a reference path stopped.')
   end subroutine sensitivity_command_line

   !> Runs the command for the words `args`; returns the exit code.
   integer function sensitivity_main(args) result(code)
      character(len=*), intent(in) :: args(:)
      type(arg_parser_t) :: cli
      type(law_path_runner_t) :: runner
      type(params_t) :: base
      type(path_deck_t) :: deck
      type(sensitivity_t) :: res
      type(error_t), allocatable :: error
      character(len=32), allocatable :: keys(:)
      character(len=:), allocatable :: perturb(:)
      real(wp), allocatable :: fractions(:)
      character(len=:), allocatable :: out, word, deck_file
      real(wp) :: sigma_n0, eps_max, pct
      integer :: i, steps, k, eq
      logical :: quiet, ok, with_thesis, done

      call sensitivity_command_line(cli)
      call cli%parse(args, code, done)
      if (done) return
      out = cli%text('-o', 'output/sensitivity.csv')
      deck_file = cli%positional(1)
      sigma_n0 = cli%real_value('--sigma-n0', THESIS_SIGMA_N0)
      eps_max = cli%real_value('--to', THESIS_EPS_T)
      steps = cli%int_value('--steps', 600)
      quiet = cli%given('--quiet')
      keys = THESIS_KEYS
      fractions = FRACTIONS_III4
      if (cli%given('--table')) then
         select case (upper(cli%text('--table')))
         case ('III.3', 'III3')
            fractions = FRACTIONS_III3
         case ('III.4', 'III4')
            fractions = FRACTIONS_III4
         case default
            code = cli%value_error('--table', 'III.3 or III.4')
            return
         end select
      end if
      perturb = cli%texts('--perturb')
      do i = 1, size(perturb)
         word = trim(perturb(i))
         eq = index(word, '=')
         ok = eq > 1
         if (ok) call parse_real(word(eq + 1:), pct, ok)
         if (.not. ok) then
            code = cli%usage_error("option --perturb: expected KEY=PERCENT, got '"//word//"'")
            return
         end if
         k = findloc(keys, upper(word(1:eq - 1)), dim=1)
         if (k == 0) then
            keys = [character(len=32) :: keys, upper(word(1:eq - 1))]
            fractions = [fractions, pct/100.0_wp]
         else
            fractions(k) = pct/100.0_wp
         end if
      end do

      runner%registry = default_law_registry()
      if (len(deck_file) > 0) then
         call read_path_deck(deck_file, deck, error)
         if (allocated(error)) then
            code = command_error(COMMAND, error%exit_code(), error%text())
            return
         end if
         runner%law_type = deck%law_type
         base = deck%params
      else
         runner%law_type = 'MODJOIN'
         base = table_iii2_params()
      end if
      ! the table's parameters that this law has, then those added by --perturb (which must)
      do k = size(keys), 1, -1
         if (base%has(keys(k))) cycle
         if (k > size(THESIS_KEYS)) then
            code = command_error(COMMAND, EXIT_INPUT, 'option --perturb: the law '// &
               runner%law_type//' has no parameter '//trim(keys(k)))
            return
         end if
         keys = [keys(:k - 1), keys(k + 1:)]
         fractions = [fractions(:k - 1), fractions(k + 1:)]
      end do
      with_thesis = index(upper(runner%law_type), 'MODJOIN') == 1
      call sensitivity_study(runner, base, keys, fractions, thesis_curves(), sigma_n0, &
         [eps_max], steps, res, error)
      if (allocated(error)) then
         code = command_error(COMMAND, error%exit_code(), error%text())
         return
      end if
      word = 'table III.2'
      if (len(deck_file) > 0) word = 'deck '//deck_file
      if (.not. quiet) call print_sensitivity(6, res, CURVE_LABELS, 'Sensitivity of '// &
         runner%law_type//' ('//word//') at sigma_n0 = '//decimal_text(sigma_n0, 3)// &
         ' kPa, eps_t 0 -> '//decimal_text(eps_max, 3)//' mm', with_thesis)
      call make_directories(path_dir(out))
      call write_sensitivity_csv(out, res, CURVE_LABELS, with_thesis, error)
      if (allocated(error)) then
         ! an output that cannot be written (-o in a missing or read-only place): input error
         code = command_error(COMMAND, EXIT_INPUT, error%text())
         return
      end if
      if (.not. quiet) write (*, '(a)') 'written: '//out
      code = EXIT_OK
   end function sensitivity_main

   !> What --version prints.
   subroutine sensitivity_version(lines)
      character(len=:), allocatable, intent(out) :: lines(:)
      lines = [COMMAND//' '//VERSION]
   end subroutine sensitivity_version

end module pecplas_cmd_sensitivity
