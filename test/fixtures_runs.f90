!> Runs of test decks shared by the suites: a deck that must complete, the default penalty
!> its spring joints get, whether a run left a file; reading and writing a deck's text.
module fixtures_runs
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_strings, only: itoa
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_model_type, only: model_t
   use pecplas_problem_type, only: problem_t
   use pecplas_joints_laws_spring, only: spring_law_t
   use pecplas_testing, only: check, check_close
   implicit none (type, external)
   private
   public :: run_completes, check_default_penalty, file_exists, read_text, write_text

contains

   !> Runs `deck` (quiet) into the results file `results` and checks that it completes
   !> (exit 0); the message names the run `label`.
   subroutine run_completes(error, deck, results, model, problem, label)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: deck, results, label
      type(model_t), intent(out) :: model
      type(problem_t), intent(out) :: problem
      integer :: code
      code = run_deck(deck, results, .true., model, problem)
      call check(error, code == 0, label//' runs (exit '//itoa(code)//')')
   end subroutine run_completes

   !> The default penalty of the spring law 1 of `model` (a deck giving neither KN nor KT,
   !> E_RYG = 0.5, the springs' tributaries 1/2, 1, 1/2): set, KN = 1e5 E_RYG R_max / (2/3)
   !> with R_max = `rmax` (1e-12: a few floating-point operations on the same numbers), and
   !> KT = KN (the same value). `what` ends the message of KN.
   subroutine check_default_penalty(error, model, rmax, what)
      type(error_t), allocatable, intent(out) :: error
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: rmax
      character(len=*), intent(in) :: what
      select type (law => model%laws(1)%law)
      class is (spring_law_t)
         call check(error, .not. law%needs_penalty, 'the penalty was set')
         if (allocated(error)) return
         call check_close(error, law%kn, 1.0e5_wp*0.5_wp*rmax/(2.0_wp/3.0_wp), 1.0e-12_wp, &
            'KN = 1e5 E_RYG R_max / mean tributary'//what)
         if (allocated(error)) return
         call check_close(error, law%kt, law%kn, 1.0e-15_wp, 'KT = KN')
      class default
         call check(error, .false., 'the law is the spring law')
      end select
   end subroutine check_default_penalty

   !> Whether the file `path` exists (a run that fails must leave no results file; stale
   !> files are removed first with remove_file).
   logical function file_exists(path)
      character(len=*), intent(in) :: path
      inquire (file=path, exist=file_exists)
   end function file_exists

   !> The whole text of file `path`.
   subroutine read_text(path, text)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: text
      integer :: u, n
      open (newunit=u, file=path, access='stream', form='unformatted', status='old', &
         action='read')
      inquire (unit=u, size=n)
      allocate (character(len=n) :: text)
      read (u) text
      close (u)
   end subroutine read_text

   !> Writes `text` and a line end to `path` (replaced).
   subroutine write_text(path, text)
      character(len=*), intent(in) :: path, text
      integer :: u
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') text
      close (u)
   end subroutine write_text

end module fixtures_runs
