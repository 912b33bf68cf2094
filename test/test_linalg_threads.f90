!> Thread setting of a run: the deck's THREADS= wins over the environment, applying it sets
!> the OpenMP team size, and a deck value below 1 is refused with the deck line. The parts
!> each get their rule's threads (or PECPLAS_THREAD_PARTS's), and a BLAS call under CHOLMOD's
!> begin/end passes through the program's definition to the BLAS, with its share of threads.
module test_linalg_threads
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_reader, only: read_deck
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_null_char
   use pecplas_base_kinds, only: wp
   use pecplas_linalg_lapack, only: dgemm
   use pecplas_linalg_threads, only: thread_setting_t, resolve_threads, apply_threads, &
      openmp_threads, parts_text
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_linalg_threads

   interface
      integer(c_int) function pecplas_threads_configure(loops, regions, blas, work) bind(C)
         import :: c_int, c_double
         integer(c_int), value :: loops, regions, blas
         real(c_double), value :: work
      end function
      subroutine pecplas_threads_calls_begin() bind(C)
      end subroutine
      subroutine pecplas_threads_calls_end() bind(C)
      end subroutine
      subroutine pecplas_threads_calls_stats(out, reset) bind(C)
         import :: c_int, c_double
         real(c_double), intent(out) :: out(4)
         integer(c_int), value :: reset
      end subroutine
      integer(c_int) function setenv(name, value, overwrite) bind(C)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: name(*), value(*)
         integer(c_int), value :: overwrite
      end function
      integer(c_int) function unsetenv(name) bind(C)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: name(*)
      end function
   end interface

   character(len=*), parameter :: PARTS = 'PECPLAS_THREAD_PARTS'//c_null_char

contains

   subroutine collect_linalg_threads(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('deck_wins', test_deck_wins), &
               new_unittest('apply', test_apply), &
               new_unittest('deck_threads_keyword', test_deck_keyword), &
               new_unittest('parts_rule', test_parts_rule), &
               new_unittest('parts_override', test_parts_override), &
               new_unittest('blas_call_share', test_blas_call_share)]
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

   !> n threads: the element loops n, CHOLMOD's regions 1 (plain code), every BLAS call n.
   subroutine test_parts_rule(error)
      type(error_t), allocatable, intent(out) :: error
      type(thread_setting_t) :: s
      integer(c_int) :: rc
      rc = unsetenv(PARTS)
      s = resolve_threads(3)
      call check(error, s%loops == 3 .and. s%regions == 1 .and. s%blas_threads == 3 .and. &
         s%blas_work == 0.0 .and. s%parts_source == 'rule', 'parts of 3 threads: '// &
         parts_text(s))
   end subroutine test_parts_rule

   !> PECPLAS_THREAD_PARTS="R,B,W" replaces the rule's parts (not the loops); a malformed or
   !> out-of-range value is ignored.
   subroutine test_parts_override(error)
      type(error_t), allocatable, intent(out) :: error
      type(thread_setting_t) :: s, bad, negative
      integer(c_int) :: rc
      rc = setenv(PARTS, '2,3,1e6'//c_null_char, 1_c_int)
      s = resolve_threads(4)
      rc = setenv(PARTS, 'two'//c_null_char, 1_c_int)
      bad = resolve_threads(4)
      rc = setenv(PARTS, '1,0,0'//c_null_char, 1_c_int)
      negative = resolve_threads(4)
      rc = unsetenv(PARTS)
      call check(error, s%loops == 4 .and. s%regions == 2 .and. s%blas_threads == 3 .and. &
         s%blas_work == 1.0e6 .and. s%parts_source == 'PECPLAS_THREAD_PARTS', &
         'override 2,3,1e6: '//parts_text(s))
      if (allocated(error)) return
      call check(error, bad%parts_source == 'rule' .and. bad%blas_threads == 4 .and. &
         negative%parts_source == 'rule', 'malformed "two" or B = 0 ignored: '// &
         parts_text(bad)//'; '//parts_text(negative))
   end subroutine test_parts_override

   !> With a work of one flop per BLAS thread and at most 2 threads, a 2x2x2 product (16
   !> flops) made between begin and end is counted as one call given 2 threads, and passed
   !> on to the BLAS: the product of small integers is exact. Outside begin/end nothing is
   !> counted. The configuration is set back to the process's thread count afterwards.
   subroutine test_blas_call_share(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: a(2, 2), b(2, 2), c(2, 2)
      real(c_double) :: stats(4)
      integer(c_int) :: k, before
      before = int(openmp_threads(), c_int)
      a = reshape([1.0_wp, 2.0_wp, 3.0_wp, 4.0_wp], [2, 2])
      b = reshape([5.0_wp, 6.0_wp, 7.0_wp, 8.0_wp], [2, 2])
      k = pecplas_threads_configure(1_c_int, 1_c_int, 2_c_int, 1.0_c_double)
      call pecplas_threads_calls_stats(stats, 1_c_int)
      c = 0.0_wp
      call dgemm('N', 'N', 2, 2, 2, 1.0_wp, a, 2, b, 2, 0.0_wp, c, 2)
      call pecplas_threads_calls_stats(stats, 1_c_int)
      call check(error, all(stats == 0.0_c_double), 'nothing counted outside begin/end')
      if (allocated(error)) return
      call pecplas_threads_calls_begin()
      call dgemm('N', 'N', 2, 2, 2, 1.0_wp, a, 2, b, 2, 0.0_wp, c, 2)
      call pecplas_threads_calls_end()
      call pecplas_threads_calls_stats(stats, 1_c_int)
      k = pecplas_threads_configure(before, before, before, 0.0_c_double)
      call check(error, all(c == matmul(a, b)), 'the product passed through to the BLAS')
      if (allocated(error)) return
      ! without a BLAS thread setter (k = 0) no share is given and nothing is counted
      call check(error, k == 0 .or. all(stats == [1.0_c_double, 1.0_c_double, 16.0_c_double, &
         16.0_c_double]), 'one call of 16 flops given 2 threads')
   end subroutine test_blas_call_share

end module test_linalg_threads
