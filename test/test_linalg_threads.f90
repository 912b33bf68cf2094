!> Thread setting of a run: the deck's THREADS= wins over the environment, applying it sets
!> the OpenMP team size, and a deck value below 1 is refused with the deck line.
module test_linalg_threads
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_linalg_threads, only: thread_setting_t, resolve_threads, apply_threads, &
      openmp_threads
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_linalg_threads

contains

   subroutine collect_linalg_threads(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('deck_wins', test_deck_wins), &
               new_unittest('apply', test_apply), &
               new_unittest('deck_threads_keyword', test_deck_keyword)]
   end subroutine collect_linalg_threads

   subroutine test_deck_wins(error)
      type(error_t), allocatable, intent(out) :: error
      type(thread_setting_t) :: s
      s = resolve_threads(3)
      call check(error, s%n == 3 .and. s%source == 'deck', 'THREADS=3 in the deck gives 3, '// &
         'source deck, whatever OMP_NUM_THREADS says')
      if (allocated(error)) return
      s = resolve_threads(0)
      call check(error, s%n >= 1 .and. (s%source == 'default' .or. &
         s%source == 'OMP_NUM_THREADS'), 'no deck value: the environment or 1')
   end subroutine test_deck_wins

   subroutine test_apply(error)
      type(error_t), allocatable, intent(out) :: error
      type(thread_setting_t) :: s
      integer :: n
      s = resolve_threads(2)
      call apply_threads(s)
      n = openmp_threads()
      s = resolve_threads(1)
      call apply_threads(s)
      ! without OpenMP every region has one thread; with it the team is the setting
      call check(error, (s%openmp .and. n == 2 .and. openmp_threads() == 1) .or. &
         (.not. s%openmp .and. n == 1), 'OpenMP team follows the setting (2, then 1)')
      if (allocated(error)) return
      ! Debian links CHOLMOD against OpenBLAS; a BLAS without a thread setter gives ''
      call check(error, any(s%blas == [character(len=8) :: '', 'OpenBLAS', 'BLIS', 'MKL']), &
         'BLAS name: '//s%blas)
   end subroutine test_apply

   subroutine test_deck_keyword(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(model_t) :: model
      integer :: unit
      character(len=*), parameter :: PATH = 'build/test_threads_bad.inp'
      open (newunit=unit, file=PATH, status='replace', action='write')
      write (unit, '(a)') '*NODES', '1, 0, 0', '2, 1, 0', '3, 1, 1', '4, 0, 1', &
         '*ELEMENTS, TYPE=Q4, SET=a', '1, 1, 2, 3, 4', '*MATERIAL, NAME=m', 'E = 1, NU = 0.3', &
         '*SECTION, SET=a, MATERIAL=m', '*SOLVER, THREADS=0'
      close (unit)
      call read_deck(PATH, model, e)
      open (newunit=unit, file=PATH, status='old')
      close (unit, status='delete')
      call check(error, allocated(e), 'THREADS=0 refused')
      if (allocated(error)) return
      call check(error, index(e%text(), ':11: ') > 0 .and. index(e%text(), 'THREADS must be >= 1') &
         > 0, 'message names line 11 and the bound: '//e%text())
   end subroutine test_deck_keyword

end module test_linalg_threads
