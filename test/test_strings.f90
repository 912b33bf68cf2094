!> Name folding and the short number texts shared by messages and tables.
module test_strings
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_strings, only: upper, same_name, itoa, decimal_text, g6
   use pecplas_base_run_status, only: RUN_NOT_RUN, RUN_COMPLETED, RUN_LIMIT_LOAD, RUN_DIVERGED, &
      RUN_STOPPED, RUN_FAILED, RUN_INTERRUPTED, status_name, is_run_status
   use pecplas_base_suggest, only: did_you_mean, with_suggestion
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_strings

contains

   subroutine collect_strings(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('names', test_names), &
               new_unittest('integers', test_integers), &
               new_unittest('decimals', test_decimals), &
               new_unittest('run_status_words', test_run_status_words), &
               new_unittest('did_you_mean', test_suggest)]
   end subroutine collect_strings

   !> The closest known names of a misspelt one (pecplas_base_suggest): a typo (one letter
   !> wrong, missing or swapped), a missing digit, '-' for '_', any letter case; nothing for a
   !> name written as it is (letter case aside) or for a word that is no typo of any name.
   subroutine test_suggest(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: KNOWN = ' E NU C PHI PSI GAMMA TENSION'
      call check(error, did_you_mean('PHY', KNOWN) == ' (did you mean PHI?)', 'PHY -> PHI')
      if (allocated(error)) return
      call check(error, did_you_mean('gamam', KNOWN) == ' (did you mean GAMMA?)', &
         'swapped letters, lower case')
      if (allocated(error)) return
      call check(error, did_you_mean('GOODMAN', 'SPRING GOODMAN4 GOODMAN6 THIN_LAYER') == &
         ' (did you mean GOODMAN4 or GOODMAN6?)', 'missing digit: both')
      if (allocated(error)) return
      call check(error, did_you_mean('mohr-coulomb', 'ELASTIC MOHR_COULOMB') == &
         ' (did you mean MOHR_COULOMB?)', "'-' for '_'")
      if (allocated(error)) return
      call check(error, did_you_mean('phi', KNOWN) == '', 'the name itself: nothing')
      if (allocated(error)) return
      call check(error, did_you_mean('INTERFACE', 'SPRING GOODMAN4 GOODMAN6 THIN_LAYER') == &
         '', 'no typo of any name: nothing')
      if (allocated(error)) return
      call check(error, with_suggestion("undefined node set 'bsae'; known node sets: base "// &
         "top (or ALL)") == "undefined node set 'bsae' (did you mean base?); known node "// &
         "sets: base top (or ALL)", 'inserted before the list, the remark not a name')
      if (allocated(error)) return
      call check(error, index(with_suggestion('unknown parameter GAMA_SAT; known parameters: '// &
         'E NU GAMMA; water parameters: GAMMA_UNSAT GAMMA_SAT'), &
         'GAMA_SAT (did you mean GAMMA_SAT?); known') > 0, 'the names of a second list too')
      if (allocated(error)) return
      call check(error, with_suggestion('cannot read mesh file') == 'cannot read mesh file', &
         'a message without a list is kept')
   end subroutine test_suggest

   subroutine test_names(error)
      type(error_t), allocatable, intent(out) :: error
      call check(error, upper('  Mohr_coulomb ') == 'MOHR_COULOMB', 'upper trims and folds')
      if (allocated(error)) return
      call check(error, same_name('Shaft', 'SHAFT ') .and. .not. same_name('a', 'b'), &
         'same_name ignores case and blanks')
   end subroutine test_names

   subroutine test_integers(error)
      type(error_t), allocatable, intent(out) :: error
      call check(error, itoa(0) == '0' .and. itoa(-42) == '-42' .and. &
         itoa(huge(1)) == '2147483647', 'itoa: no blanks, sign, largest integer')
      if (allocated(error)) return
      call check(error, g6(0.990099_wp) == '0.990099' .and. g6(-2.5_wp) == '-2.50000', &
         'g6: six significant digits, no blanks, got '//g6(0.990099_wp)//' '//g6(-2.5_wp))
      if (allocated(error)) return
      ! below 0.1 in fixed notation with six significant digits (the round-off of the
      ! decimal values is far below the seventh digit), scientific outside 1e-4 .. 1e6
      call check(error, g6(0.0942241_wp) == '0.0942241' .and. g6(-0.00123_wp) == &
         '-0.00123000' .and. g6(4.38107e-5_wp) == '4.38107E-05' .and. &
         g6(1234567.0_wp) == '1.23457E+06' .and. g6(0.0_wp) == '0.00000', &
         'g6 small and large: '//g6(0.0942241_wp)//' '//g6(-0.00123_wp)//' '// &
         g6(4.38107e-5_wp)//' '//g6(1234567.0_wp)//' '//g6(0.0_wp))
   end subroutine test_integers

   !> Each case is a text a person reads in a table: no trailing zeros, a leading 0, no '-0'.
   subroutine test_decimals(error)
      type(error_t), allocatable, intent(out) :: error
      call expect(0.5_wp, 2, '0.5')
      call expect(1.0_wp, 2, '1')
      call expect(2.0_wp, 2, '2')
      call expect(56.0_wp, 3, '56')
      call expect(2.25_wp, 3, '2.25')
      call expect(-0.125_wp, 3, '-0.125')
      call expect(0.0_wp, 3, '0')
      call expect(-1.0e-9_wp, 3, '0')
      call expect(1.0e-4_wp, 2, '0')
      call expect(100.0_wp, 2, '100')
   contains
      subroutine expect(x, d, text)
         real(wp), intent(in) :: x
         integer, intent(in) :: d
         character(len=*), intent(in) :: text
         if (allocated(error)) return
         call check(error, decimal_text(x, d) == text, 'decimal_text gives '''// &
            decimal_text(x, d)//''', expected '''//text//'''')
      end subroutine expect
   end subroutine test_decimals

   !> The words written to results files and read by the tools (pecplas_py.results, the
   !> docs' status table): one per status, distinct, and no word for a value that is none.
   subroutine test_run_status_words(error)
      type(error_t), allocatable, intent(out) :: error
      call check(error, status_name(RUN_COMPLETED) == 'completed' .and. &
         status_name(RUN_LIMIT_LOAD) == 'limit load' .and. &
         status_name(RUN_DIVERGED) == 'diverged' .and. status_name(RUN_STOPPED) == 'stopped' &
         .and. status_name(RUN_FAILED) == 'failed' .and. &
         status_name(RUN_INTERRUPTED) == 'interrupted' .and. status_name(RUN_NOT_RUN) == &
         'not run', 'status words as documented in doc/deck.md and read by the tools')
      if (allocated(error)) return
      call check(error, .not. is_run_status(RUN_NOT_RUN) .and. .not. is_run_status(99) .and. &
         status_name(99) == 'unknown' .and. all(is_run_status([RUN_COMPLETED, RUN_LIMIT_LOAD, &
         RUN_DIVERGED, RUN_STOPPED, RUN_FAILED, RUN_INTERRUPTED])), &
         'only the six ends of a run are run statuses')
   end subroutine test_run_status_words

end module test_strings
