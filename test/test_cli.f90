!> The batch program end to end (`run_deck`, as `pecplas DECK -o FILE` runs it): exit codes,
!> no results file after an input error, singular systems named by node and direction, a
!> stopped run that keeps its converged increments, and an exact oedometer.
module test_cli
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error, ERR_SINGULAR
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories, remove_file
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_problem_type, only: problem_t, setup_problem
   use pecplas_solve_stiffness, only: factorise_stiffness
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_runs, only: file_exists
   implicit none (type, external)
   private
   public :: collect_cli

   character(len=*), parameter :: DIR = 'build/test_out/cli'
   character(len=*), parameter :: DATA = 'test/data/cli/'

contains

   subroutine collect_cli(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('oedometer_exact', test_oedometer), &
               new_unittest('bad_decks_exit_2_no_file', test_bad_decks), &
               new_unittest('floating_body_singular', test_floating), &
               new_unittest('rollers_name_direction', test_rollers), &
               new_unittest('divergence_keeps_increments', test_diverge)]
   end subroutine collect_cli

   !> Oedometer, p = 100 then 50: eps_yy = -p/M, sigma_xx = nu/(1-nu) sigma_yy, reactions of
   !> the base balance the load; every increment converges in one iteration (linear).
   subroutine test_oedometer(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: rd
      character(len=:), allocatable :: out, status
      real(wp) :: m, p, nu, e
      integer :: code, n, complete
      real(wp), allocatable :: reac(:, :)

      call make_directories(DIR)
      out = DIR//'/oedometer.h5'
      call remove_file(out)
      code = run_deck(DATA//'oedometer.inp', out, .true., model, problem)
      call check(error, code == 0, 'oedometer run exits 0')
      if (allocated(error)) return
      e = 1.0e4_wp; nu = 0.3_wp; p = 50.0_wp
      m = e*(1.0_wp - nu)/((1.0_wp + nu)*(1.0_wp - 2.0_wp*nu))
      call check_close(error, problem%state%sets(1)%strain(2, 1, 1), -p/m, 1.0e-12_wp, &
         'eps_yy = -p/M at the end of unloading')
      if (allocated(error)) return
      call check_close(error, problem%state%u(2, 3), -p/m, 1.0e-12_wp, 'top settlement = -p H/M')
      if (allocated(error)) return
      call check_close(error, problem%state%sets(1)%stress(1, 4, 1), &
         nu/(1.0_wp - nu)*problem%state%sets(1)%stress(2, 4, 1), 1.0e-12_wp, 'K0 = nu/(1-nu)')
      if (allocated(error)) return
      call check(error, problem%stats%iterations == problem%stats%increments .and. problem%stats%increments == 6 &
         .and. problem%stats%factorisations == 1, 'linear: 6 increments, 1 iteration each, 1 factorisation')
      if (allocated(error)) return
      ! the law updates are timed inside the residual computation (a nanosecond clock: each
      ! timed update adds at least one clock read)
      call check(error, problem%stats%time%laws > 0.0_wp .and. &
         problem%stats%time%laws <= problem%stats%time%residual, 'law-update time is part of residual time')
      if (allocated(error)) return
      call rd%open(out, error)
      if (allocated(error)) return
      call rd%attribute('/', 'status', status, error)
      if (allocated(error)) return
      call rd%attribute('/', 'complete', complete, error)
      if (allocated(error)) return
      call rd%history_length(n, error)
      if (allocated(error)) return
      call rd%dataset('/increments/000006/reaction', reac, error)
      if (allocated(error)) return
      call rd%close()
      call check(error, status == 'completed' .and. complete == 1 .and. n == 6, &
         'file says completed with 6 rows, got '//status)
      if (allocated(error)) return
      ! base reactions (nodes 1, 2, y) carry the whole load p * width (1 m)
      call check_close(error, reac(2, 1) + reac(2, 2), p, 1.0e-12_wp, 'vertical reactions = p B')
   end subroutine test_oedometer

   !> Every bad deck of the reader's suite: exit code 2 and no results file at all.
   subroutine test_bad_decks(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      character(len=256) :: name
      character(len=:), allocatable :: out
      integer :: u, ios, code, count
      call make_directories(DIR)
      call execute_command_line('ls test/data/decks/bad_*.inp > '//DIR//'/bad_list.txt', &
         exitstat=code)
      call check(error, code == 0, 'listing the bad decks')
      if (allocated(error)) return
      count = 0
      open (newunit=u, file=DIR//'/bad_list.txt', status='old', action='read')
      do
         read (u, '(a)', iostat=ios) name
         if (ios /= 0) exit
         out = DIR//'/bad.h5'
         call remove_file(out)
         code = run_deck(trim(name), out, .true., model, problem)
         if (code /= 2 .or. file_exists(out)) then
            call fatal_error(error, trim(name)//': expected exit 2 and no results file')
            close (u)
            return
         end if
         count = count + 1
      end do
      close (u)
      call check(error, count >= 15, 'at least 15 bad decks were run')
   end subroutine test_bad_decks

   !> Message of the first factorisation of `deck` (an empty string when it succeeds).
   subroutine factorise_message(deck, kind, text, error)
      character(len=*), intent(in) :: deck
      integer, intent(out) :: kind
      character(len=:), allocatable, intent(out) :: text
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(error_t), allocatable :: e
      call read_deck(deck, model, error)
      if (allocated(error)) return
      call setup_problem(model, problem, error)
      if (allocated(error)) return
      call factorise_stiffness(model, problem, .false., e)
      kind = 0; text = ''
      if (allocated(e)) then
         kind = e%kind; text = e%text()
      end if
   end subroutine factorise_message

   subroutine test_floating(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      character(len=:), allocatable :: text
      integer :: kind, code
      call factorise_message(DATA//'floating.inp', kind, text, error)
      if (allocated(error)) return
      call check(error, kind == ERR_SINGULAR .and. index(text, 'singular') > 0 .and. &
         index(text, 'node ') > 0 .and. index(text, 'direction') > 0, &
         'floating block: singular, node and direction named: '//text)
      if (allocated(error)) return
      call remove_file(DIR//'/floating.h5')
      code = run_deck(DATA//'floating.inp', DIR//'/floating.h5', .true., model, problem)
      call check(error, code == 2 .and. .not. file_exists(DIR//'/floating.h5'), &
         'singular model: exit 2, no results file')
   end subroutine test_floating

   !> Supported vertically only: the free mechanism is a horizontal slide, so the named
   !> direction must be x.
   subroutine test_rollers(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      integer :: kind
      call factorise_message(DATA//'roller_only.inp', kind, text, error)
      if (allocated(error)) return
      call check(error, kind == ERR_SINGULAR .and. index(text, 'direction x') > 0, &
         'rollers: direction x named: '//text)
   end subroutine test_rollers

   !> Step 2 cannot converge: exit 3, status 'diverged', complete = 0, step 1 kept.
   subroutine test_diverge(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: rd
      character(len=:), allocatable :: out, status, message
      integer :: code, n, complete
      call make_directories(DIR)
      out = DIR//'/diverge.h5'
      call remove_file(out)
      code = run_deck(DATA//'diverge.inp', out, .true., model, problem)
      call check(error, code == 3, 'a stopped run exits 3')
      if (allocated(error)) return
      call rd%open(out, error)
      if (allocated(error)) return
      call rd%attribute('/', 'status', status, error)
      if (allocated(error)) return
      call rd%attribute('/', 'status_message', message, error)
      if (allocated(error)) return
      call rd%attribute('/', 'complete', complete, error)
      if (allocated(error)) return
      call rd%history_length(n, error)
      if (allocated(error)) return
      call rd%close()
      call check(error, status == 'diverged' .and. complete == 0 .and. n == 2 .and. &
         index(message, 'step 2') > 0, 'diverged, not complete, 2 rows kept, message names '// &
         'the step: '//status//' / '//message)
      if (allocated(error)) return
      ! MAX_CUTS = 2 halvings, then the arc-length probe (which cuts its own lengths)
      call check(error, problem%stats%cuts >= 2, 'MAX_CUTS = 2 cuts were tried')
   end subroutine test_diverge

end module test_cli
