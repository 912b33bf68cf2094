!> *UNITS: the known names, stress = force / length**2, and the messages for bad lines.
module test_model_units
   use pecplas_base_error, only: error_t
   use pecplas_base_units, only: units_t, parse_units, UNITS_NOT_STATED
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_model_units

contains

   subroutine collect_model_units(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('consistent', test_consistent), &
               new_unittest('mismatch', test_mismatch), &
               new_unittest('unknown', test_unknown), &
               new_unittest('not_stated', test_not_stated)]
   end subroutine collect_model_units

   !> Lines whose stress unit is force/length**2 (1 kN/m2 = 1 kPa, 1 N/mm2 = 1 MPa,
   !> 1 MN/m2 = 1 MPa, 1 kN/mm2 = 1 GPa), in any order, any case, compound or omitted.
   subroutine test_consistent(error)
      type(error_t), allocatable, intent(out) :: error
      call expect('kN, m, kPa', 'm', 'kN', 'kPa')
      call expect('N, mm, MPa', 'mm', 'N', 'MPa')
      call expect('m kN', 'm', 'kN', 'kPa')
      call expect('MPa; MN; m', 'm', 'MN', 'MPa')
      call expect('kn, MM, gpa', 'mm', 'kN', 'GPa')
      call expect('kN, m, kN/m2', 'm', 'kN', 'kN/m2')
      call expect('N, m, N/m^2', 'm', 'N', 'N/m2')
      call expect('N, cm, N/cm**2', 'cm', 'N', 'N/cm2')
      call expect('N, cm', 'cm', 'N', 'N/cm2')
      call expect('N, m', 'm', 'N', 'Pa')
   contains
      subroutine expect(text, length, force, stress)
         character(len=*), intent(in) :: text, length, force, stress
         type(units_t) :: u
         character(len=:), allocatable :: message
         if (allocated(error)) return
         call parse_units(text, u, message)
         call check(error, len(message) == 0, '"'//text//'" refused: '//message)
         if (allocated(error)) return
         call check(error, u%stated .and. u%of('length') == length .and. &
            u%of('force') == force .and. u%of('stress') == stress .and. u%of('1') == '1', &
            '"'//text//'" read as '//u%of('length')//', '//u%of('force')//', '// &
            u%of('stress')//'; expected '//length//', '//force//', '//stress)
      end subroutine expect
   end subroutine test_consistent

   !> A stress unit that is not force/length**2 is refused, naming the expected unit.
   subroutine test_mismatch(error)
      type(error_t), allocatable, intent(out) :: error
      call refuse('kN, m, MPa', 'expected kPa')
      call refuse('N, mm, kPa', 'expected MPa')
      call refuse('N, cm, Pa', 'expected N/cm2')
      call refuse('kN, mm, kN/m2', 'expected GPa')
      call refuse('kN, m, mm', 'two length units (m and mm)')
      call refuse('kN, kPa', 'no length unit')
      call refuse('m, kPa', 'no force unit')
   contains
      subroutine refuse(text, part)
         character(len=*), intent(in) :: text, part
         type(units_t) :: u
         character(len=:), allocatable :: message
         if (allocated(error)) return
         call parse_units(text, u, message)
         call check(error, index(message, part) > 0 .and. .not. u%stated, '"'//text// &
            '" gave "'//message//'", expected a message with "'//part//'"')
      end subroutine refuse
   end subroutine test_mismatch

   !> An unknown word is refused with the list of the known names.
   subroutine test_unknown(error)
      type(error_t), allocatable, intent(out) :: error
      type(units_t) :: u
      character(len=:), allocatable :: message
      call parse_units('kip, in, ksi', u, message)
      call check(error, index(message, 'unknown unit "kip"') > 0 .and. &
         index(message, 'length m, cm, mm; force N, kN, MN') > 0, &
         'unknown unit message: "'//message//'"')
      if (allocated(error)) return
      call parse_units('kN, m, kN/in2', u, message)
      call check(error, index(message, 'unknown unit "kN/in2"') > 0, &
         'compound with an unknown length: "'//message//'"')
   end subroutine test_unknown

   !> Without *UNITS: dimensional quantities are "(not stated)", dimensionless ones "1".
   subroutine test_not_stated(error)
      type(error_t), allocatable, intent(out) :: error
      type(units_t) :: u
      call check(error, u%of('length') == UNITS_NOT_STATED .and. &
         u%of('stress') == UNITS_NOT_STATED .and. u%of('1') == '1', &
         'a model without *UNITS')
   end subroutine test_not_stated

end module test_model_units
