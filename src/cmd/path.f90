!> The command `pecplas-path DECK [-o BASE] [--quiet]`: reads a path deck, runs the law on
!> the path and writes BASE.csv and BASE.h5 (default: the deck's *OUTPUT file, else
!> output/<deck>). Exit codes as `pecplas`: 0 done, 2 input error (file:line message),
!> 3 path stopped early (the converged rows are written), 1 internal error.
module pecplas_cmd_path
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, EXIT_OK, EXIT_INPUT, EXIT_STOPPED
   use pecplas_base_version, only: VERSION
   use pecplas_base_run_status, only: RUN_COMPLETED, RUN_STOPPED
   use pecplas_base_files, only: make_directories, path_stem, path_dir
   use pecplas_joints_laws_type, only: MODE_NAMES
   use pecplas_studies_path_deck, only: path_deck_t, read_path_deck, PATH_NAMES
   use pecplas_studies_path_driver, only: path_result_t, run_path
   use pecplas_studies_path_writers, only: write_path_csv, write_path_h5
   use pecplas_cmd_command, only: command_error
   use pecplas_cmd_args, only: arg_parser_t, VALUE_POSITIVE_REAL
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private

   !> Program name in error messages.
   character(len=*), parameter :: COMMAND = 'pecplas-path'

   public :: path_main, run_path_deck, path_command_line

contains

   !> The options of pecplas-path.
   subroutine path_command_line(cli)
      type(arg_parser_t), intent(out) :: cli
      call cli%init(COMMAND, 'Integrates one interface law on a CNL/CND/CNS path (doc/path.md) '// &
         'and writes BASE.csv and BASE.h5. A progress line with the time left is printed '// &
         'every 5 s.', path_version)
      call cli%add_positional('DECK', 'deck', 'the path deck: *INTERFACE_LAW and *PATH', 1, 1)
      call cli%add_option('-o --output', 'BASE', 'writes BASE.csv and BASE.h5 (default: the '// &
         '*OUTPUT file of the deck, else output/<deck>)')
      call cli%add_flag('--quiet -q', 'no header, progress or summary lines')
      call cli%add_option('--max-seconds', 'S', 'stop after S seconds of wall time (exit 3, '// &
         'files written with status "stopped", complete = 0)', VALUE_POSITIVE_REAL)
      call cli%add_note('Exit codes: 0 completed, 2 input error, 3 path stopped early.')
   end subroutine path_command_line

   !> Runs the command for the words `args`; returns the exit code.
   integer function path_main(args) result(code)
      character(len=*), intent(in) :: args(:)
      type(arg_parser_t) :: cli
      type(path_result_t) :: res
      logical :: done
      call path_command_line(cli)
      call cli%parse(args, code, done)
      if (done) return
      code = run_path_deck(cli%positional(1), cli%text('-o'), cli%given('--quiet'), res, &
         cli%real_value('--max-seconds', 0.0_wp))
   end function path_main

   !> What --version prints.
   subroutine path_version(lines)
      character(len=:), allocatable, intent(out) :: lines(:)
      lines = [COMMAND//' '//VERSION]
   end subroutine path_version

   !> Runs the path deck `deck`, writing `base_in`.csv/.h5 (empty: *OUTPUT or
   !> output/<deck>); returns the exit code and the rows computed (for tests).
   integer function run_path_deck(deck, base_in, quiet, res, max_seconds) result(code)
      character(len=*), intent(in) :: deck, base_in
      logical, intent(in) :: quiet
      type(path_result_t), intent(out) :: res
      !> Wall-time limit (seconds, 0 or absent: none): the path then stops with status
      !> 'stopped' (exit 3) and its files hold the increments done.
      real(wp), intent(in), optional :: max_seconds
      type(path_deck_t) :: d
      type(error_t), allocatable :: error, run_err
      character(len=:), allocatable :: base
      integer :: n

      call read_path_deck(deck, d, error)
      if (allocated(error)) then
         code = command_error(COMMAND, error%exit_code(), error%text())
         return
      end if
      base = base_in
      if (len(base) == 0) base = d%output
      if (len(base) == 0) base = 'output/'//path_stem(deck)
      call make_directories(path_dir(base))
      if (.not. quiet) write (*, '(a)') 'pecplas-path '//VERSION//'  deck '//deck//'  ->  '// &
         base//'.csv, '//base//'.h5'
      if (.not. quiet) write (*, '(a,i0,a,i0,a)') ' law '//d%law%name//' ('//d%law_type// &
         ')   path '//PATH_NAMES(d%control)//'  sigma_n0 '//num(d%sigma_n0)//'  targets ', &
         size(d%targets), '  x ', d%steps, ' increments'
      if (.not. quiet .and. len(d%law%describe()) > 0) write (*, '(a)') ' '//d%law%describe()

      ! an output that cannot be created is an input error, found before the path runs
      ! (exit 2, as pecplas does with its results file)
      if (.not. can_create(base//'.csv')) then
         code = command_error(COMMAND, EXIT_INPUT, 'cannot write results: cannot create '// &
            base//'.csv (does its directory exist?)')
         return
      end if
      call run_path(d%law, d%control, [d%sigma_n0, d%tau0], d%ks, d%targets, d%steps, res, &
         run_err, progress=.not. quiet, max_seconds=limit(max_seconds))
      call write_path_csv(base//'.csv', res, error)
      if (.not. allocated(error)) then
         if (allocated(run_err)) then
            call write_path_h5(base//'.h5', d, res, VERSION, error, RUN_STOPPED, run_err%text())
         else
            call write_path_h5(base//'.h5', d, res, VERSION, error, RUN_COMPLETED, '')
         end if
      end if
      if (allocated(error)) then
         ! the output was created above: what failed is the writing (disk full)
         code = command_error(COMMAND, EXIT_STOPPED, 'cannot write results: '//error%text())
         return
      end if
      n = ubound(res%step, 1)
      if (allocated(run_err)) then
         code = command_error(COMMAND, EXIT_STOPPED, 'path stopped after increment '//itoa(n)//': '// &
            run_err%text())
         return
      end if
      if (.not. quiet) write (*, '(a)') ' done: '//itoa(n)//' increments, '// &
         itoa(res%iterations)//' law updates; final sigma_n '//num(res%sigma_n(n))// &
         '  tau '//num(res%tau(n))//'  eps_n '//num(res%eps_n(n))//'  mode '// &
         trim(MODE_NAMES(res%mode(n)))
      code = EXIT_OK
   end function run_path_deck

   !> True when `path` can be created (or replaced) for writing; it is left empty, to be
   !> written after the path has run.
   logical function can_create(path)
      character(len=*), intent(in) :: path
      integer :: u, ios
      open (newunit=u, file=path, status='replace', action='write', iostat=ios)
      can_create = ios == 0
      if (can_create) close (u)
   end function can_create

   pure real(wp) function limit(x)
      real(wp), intent(in), optional :: x
      limit = 0.0_wp
      if (present(x)) limit = x
   end function limit

   function num(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=32) :: buf
      write (buf, '(g0.8)') x
      s = trim(adjustl(buf))
   end function num


end module pecplas_cmd_path
