!> The command `pecplas-identify [options] CURVE.csv [CURVE.csv ...]`: identifies MODJOIN's
!> parameters from CNL test curves (pecplas_studies_identify_method), prints the table and writes
!> the CSV. Exit codes as `pecplas`: 0 done, 2 input error, 1 internal error.
module pecplas_cmd_identify
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, EXIT_OK, EXIT_INPUT
   use pecplas_base_version, only: VERSION
   use pecplas_base_files, only: make_directories, path_dir
   use pecplas_io_text_parse, only: parse_real
   use pecplas_studies_identify_curves, only: test_curve_t, read_test_curve
   use pecplas_studies_identify_method, only: identify_options_t, identification_t, identify, &
      VERSION_INITIAL, VERSION_IMPROVED
   use pecplas_studies_identify_report, only: print_identification, write_identification_csv
   use pecplas_cmd_command, only: command_error
   implicit none (type, external)
   private

   !> Program name in error messages.
   character(len=*), parameter :: COMMAND = 'pecplas-identify'

   public :: identify_main

   character(len=*), parameter :: USAGE = 'usage: pecplas-identify [--version initial|'// &
      'improved] [--secant MM] [--window MM] [--r0 R0] [--zero-cohesion] [--total-gamma] '// &
      '[--refine-alpha] [-o FILE.csv] [--quiet] CURVE.csv [CURVE.csv ...]'

contains

   !> Runs the command for the words `args`; returns the exit code.
   integer function identify_main(args) result(code)
      character(len=*), intent(in) :: args(:)
      type(identify_options_t) :: opt
      type(test_curve_t), allocatable :: curves(:)
      type(test_curve_t) :: curve
      type(identification_t) :: res
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, word
      logical :: quiet
      integer :: i

      out = 'output/identification.csv'
      quiet = .false.
      allocate (curves(0))
      i = 0
      do while (i < size(args))
         i = i + 1
         word = trim(args(i))
         select case (word)
         case ('-h', '--help')
            call help()
            code = EXIT_OK
            return
         case ('--quiet', '-q')
            quiet = .true.
         case ('--zero-cohesion')
            opt%zero_cohesion = .true.
         case ('--total-gamma')
            opt%total_gamma = .true.
         case ('--refine-alpha')
            opt%refine_alpha = .true.
         case ('--version', '--secant', '--window', '--r0', '-o', '--output')
            if (i == size(args)) then
               code = command_error(COMMAND, EXIT_INPUT, 'option '//word//' needs a value. '//USAGE)
               return
            end if
            i = i + 1
            select case (word)
            case ('--version')
               select case (trim(args(i)))
               case ('initial')
                  opt%version = VERSION_INITIAL
               case ('improved', 'cyclic')
                  opt%version = VERSION_IMPROVED
               case default
                  code = command_error(COMMAND, EXIT_INPUT, "--version must be 'initial' or 'improved', found '"// &
                     trim(args(i))//"'")
                  return
               end select
            case ('--secant')
               if (.not. number(args(i), opt%secant_at, code)) return
            case ('--window')
               if (.not. number(args(i), opt%window, code)) return
            case ('--r0')
               if (.not. number(args(i), opt%r0, code)) return
            case default
               out = trim(args(i))
            end select
         case default
            if (word(1:1) == '-') then
               code = command_error(COMMAND, EXIT_INPUT, 'unknown option '//word//'. '//USAGE)
               return
            end if
            call read_test_curve(word, curve, error)
            if (allocated(error)) then
               code = command_error(COMMAND, error%exit_code(), error%text())
               return
            end if
            curves = [curves, curve]
         end select
      end do
      if (size(curves) == 0) then
         code = command_error(COMMAND, EXIT_INPUT, 'no test curve given. '//USAGE)
         return
      end if
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

   subroutine help()
      write (*, '(a)') USAGE
      write (*, '(a)') '  Identifies the MODJOIN parameters (thesis III.17-III.20) from CNL '// &
         'test curves: CSV with columns'
      write (*, '(a)') '  eps_t, tau, eps_n (mm, kPa, closure-positive eps_n) and sigma_n or '// &
         'a "# sigma_n0 = value" line;'
      write (*, '(a)') "  the point driver's CSV is read as it is. See doc/identify.md."
      write (*, '(a)') '  --version initial|improved  model version (improved: G0 normalised '// &
         'by (sigma_n0/Pa)^0.5, peak, A, B)'
      write (*, '(a)') '  --secant MM       displacement of the secant shear modulus (0.2)'
      write (*, '(a)') '  --window MM       half-width of the parabolas fitted at the peak '// &
         'and at the turn of eps_n (0.5)'
      write (*, '(a)') '  --r0 R0           use R0 instead of detecting the end of the '// &
         'straight start'
      write (*, '(a)') '  --zero-cohesion   tau_peak = sigma_n0 tan(phi) (regression '// &
         'through the origin)'
      write (*, '(a)') '  --total-gamma     gamma = eps_t at the peak (the thesis: elastic '// &
         'part neglected)'
      write (*, '(a)') '  --refine-alpha    correct alpha = tau_lim/tau_peak for the '// &
         'hyperbola not yet at alpha'
      write (*, '(a)') '  -o FILE.csv       per-test and averaged values '// &
         '(output/identification.csv)'
   end subroutine help

   logical function number(text, value, code) result(ok)
      character(len=*), intent(in) :: text
      real(wp), intent(inout) :: value
      integer, intent(out) :: code
      call parse_real(trim(text), value, ok)
      code = EXIT_OK
      if (.not. ok) code = command_error(COMMAND, EXIT_INPUT, "expected a number, found '"//trim(text)//"'")
   end function number

end module pecplas_cmd_identify
