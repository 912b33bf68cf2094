!> The command `pecplas-identify [options] CURVE.csv [CURVE.csv ...]`: identifies MODJOIN's
!> parameters from CNL test curves (pecplas_studies_identify_method), prints the table and writes
!> the CSV. Exit codes as `pecplas`: 0 done, 2 input error, 1 internal error.
module pecplas_cmd_identify
   use pecplas_base_error, only: error_t, EXIT_OK, EXIT_INPUT
   use pecplas_base_files, only: make_directories, path_dir
   use pecplas_studies_identify_curves, only: test_curve_t, read_test_curve
   use pecplas_studies_identify_method, only: identify_options_t, identification_t, identify, &
      VERSION_INITIAL, VERSION_IMPROVED
   use pecplas_studies_identify_report, only: print_identification, write_identification_csv
   use pecplas_cmd_command, only: command_error
   use pecplas_cmd_args, only: arg_parser_t, VALUE_REAL
   implicit none (type, external)
   private

   !> Program name in error messages.
   character(len=*), parameter :: COMMAND = 'pecplas-identify'

   public :: identify_main, identify_command_line

contains

   !> The options of pecplas-identify (its --version is MODJOIN's: the program has none).
   subroutine identify_command_line(cli)
      type(arg_parser_t), intent(out) :: cli
      call cli%init(COMMAND, 'Identifies the MODJOIN parameters (thesis III.17-III.20) from '// &
         'CNL test curves: CSV with columns eps_t, tau, eps_n (mm, kPa, closure-positive '// &
         'eps_n) and sigma_n or a "# sigma_n0 = value" line; the point driver''s CSV is read '// &
         'as it is. See doc/identify.md.')
      call cli%add_option('--version', 'initial|improved', 'model version (improved: G0 '// &
         'normalised by (sigma_n0/Pa)^0.5, peak, A, B)')
      call cli%add_option('--secant', 'MM', 'displacement of the secant shear modulus (0.2)', &
         VALUE_REAL)
      call cli%add_option('--window', 'MM', 'half-width of the parabolas fitted at the peak '// &
         'and at the turn of eps_n (0.5)', VALUE_REAL)
      call cli%add_option('--r0', 'R0', 'use R0 instead of detecting the end of the '// &
         'straight start', VALUE_REAL)
      call cli%add_flag('--zero-cohesion', 'tau_peak = sigma_n0 tan(phi) (regression '// &
         'through the origin)')
      call cli%add_flag('--total-gamma', 'gamma = eps_t at the peak (the thesis: elastic '// &
         'part neglected)')
      call cli%add_flag('--refine-alpha', 'correct alpha = tau_lim/tau_peak for the '// &
         'hyperbola not yet at alpha')
      call cli%add_option('-o --output', 'FILE.csv', 'per-test and averaged values '// &
         '(output/identification.csv)')
      call cli%add_flag('--quiet -q', 'no table, no "written:" line')
      call cli%add_positional('CURVE.csv', 'test curve', 'one CNL test curve', 1, -1)
      call cli%add_note('Exit codes: 0 done, 2 input error.')
   end subroutine identify_command_line

   !> Runs the command for the words `args`; returns the exit code.
   integer function identify_main(args) result(code)
      character(len=*), intent(in) :: args(:)
      type(arg_parser_t) :: cli
      type(identify_options_t) :: opt
      type(test_curve_t), allocatable :: curves(:)
      type(identification_t) :: res
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out
      logical :: quiet, done
      integer :: i

      call identify_command_line(cli)
      call cli%parse(args, code, done)
      if (done) return
      select case (cli%text('--version', 'improved'))
      case ('initial')
         opt%version = VERSION_INITIAL
      case ('improved', 'cyclic')
         opt%version = VERSION_IMPROVED
      case default
         code = cli%value_error('--version', 'initial or improved')
         return
      end select
      opt%secant_at = cli%real_value('--secant', opt%secant_at)
      opt%window = cli%real_value('--window', opt%window)
      opt%r0 = cli%real_value('--r0', opt%r0)
      opt%zero_cohesion = cli%given('--zero-cohesion')
      opt%total_gamma = cli%given('--total-gamma')
      opt%refine_alpha = cli%given('--refine-alpha')
      out = cli%text('-o', 'output/identification.csv')
      quiet = cli%given('--quiet')
      allocate (curves(cli%npositional()))
      do i = 1, size(curves)
         call read_test_curve(cli%positional(i), curves(i), error)
         if (allocated(error)) then
            code = command_error(COMMAND, error%exit_code(), error%text())
            return
         end if
      end do
      call identify(curves, opt, res, error)
      if (allocated(error)) then
         code = command_error(COMMAND, error%exit_code(), error%text())
         return
      end if
      if (.not. quiet) call print_identification(6, res)
      call make_directories(path_dir(out))
      call write_identification_csv(out, res, error)
      if (allocated(error)) then
         ! an output that cannot be written (-o in a missing or read-only place): input error
         code = command_error(COMMAND, EXIT_INPUT, error%text())
         return
      end if
      if (.not. quiet) write (*, '(a)') 'written: '//out
      code = EXIT_OK
   end function identify_main

end module pecplas_cmd_identify
