!> The units a deck declares (*UNITS): one length, one force and one stress unit from a
!> known set, with stress = force / length**2 checked. They are never used to convert: the
!> program computes in whatever consistent units the deck's numbers are in; the names are
!> checked and written next to every results dataset (doc/deck.md, doc/results.md).
!>
!> Known names (matched without regard to case, stored in the spelling below):
!> length m, cm, mm; force N, kN, MN; stress Pa, kPa, MPa, GPa or FORCE/LENGTH2
!> (also FORCE/LENGTH^2, FORCE/LENGTH**2), e.g. kN/m2. Words are separated by commas,
!> semicolons or blanks and may come in any order; the stress unit may be left out (it is
!> then force/length**2, named Pa..GPa when one of those is equal).
module pecplas_base_units
   use pecplas_base_kinds, only: wp
   use pecplas_base_strings, only: same_name
   implicit none (type, external)
   private

   public :: units_t, parse_units, UNITS_NOT_STATED, UNITS_KNOWN

   !> Unit written for a dimensional quantity when the deck has no *UNITS.
   character(len=*), parameter :: UNITS_NOT_STATED = '(not stated)'
   !> The known names, for error messages and the documentation.
   character(len=*), parameter :: UNITS_KNOWN = 'length m, cm, mm; force N, kN, MN; '// &
      'stress Pa, kPa, MPa, GPa or FORCE/LENGTH2 (e.g. kN/m2)'

   character(len=*), parameter :: LENGTHS(3) = [character(len=2) :: 'm', 'cm', 'mm']
   real(wp), parameter :: LENGTH_SI(3) = [1.0_wp, 1.0e-2_wp, 1.0e-3_wp]
   character(len=*), parameter :: FORCES(3) = [character(len=2) :: 'N', 'kN', 'MN']
   real(wp), parameter :: FORCE_SI(3) = [1.0_wp, 1.0e3_wp, 1.0e6_wp]
   character(len=*), parameter :: STRESSES(4) = [character(len=3) :: 'Pa', 'kPa', 'MPa', 'GPa']
   real(wp), parameter :: STRESS_SI(4) = [1.0_wp, 1.0e3_wp, 1.0e6_wp, 1.0e9_wp]
   !> Spellings of the square in FORCE/LENGTH2.
   character(len=*), parameter :: POWERS(3) = [character(len=3) :: '**2', '^2', '2']

   !> The declared units; `stated` is false for a deck without *UNITS.
   type :: units_t
      logical :: stated = .false.
      character(len=:), allocatable :: length, force, stress
   contains
      !> Unit of a quantity: 'length', 'force', 'stress' or '1' (dimensionless).
      procedure :: of => units_of
   end type units_t

contains

   !> Reads `text` (the *UNITS data line). On success `message` is empty; otherwise it says
   !> what is wrong and what was expected, and `units` is not stated. With `no_force`
   !> (the point driver, which has no force), the line names a length and a stress unit only
   !> and the force is UNITS_NOT_STATED.
   subroutine parse_units(text, units, message, no_force)
      character(len=*), intent(in) :: text
      type(units_t), intent(out) :: units
      character(len=:), allocatable, intent(out) :: message
      logical, intent(in), optional :: no_force
      character(len=:), allocatable :: word, length, force, stress, expected
      real(wp) :: si_stress, si_length, si_force, si
      integer :: start, i, n
      logical :: sep
      message = ''
      n = len(text)
      start = 1
      do i = 1, n + 1
         sep = i > n
         if (.not. sep) sep = index(', ;'//achar(9), text(i:i)) > 0
         if (.not. sep) cycle
         if (i > start) then
            word = text(start:i - 1)
            call classify(word, length, force, stress, message)
            if (len(message) > 0) return
         end if
         start = i + 1
      end do
      if (present(no_force)) then
         if (no_force) then
            call lengths_and_stress(text, length, force, stress, units, message)
            return
         end if
      end if
      if (.not. allocated(length)) then
         message = 'no length unit in "'//trim(text)//'"; expected one of m, cm, mm'
      else if (.not. allocated(force)) then
         message = 'no force unit in "'//trim(text)//'"; expected one of N, kN, MN'
      end if
      if (len(message) > 0) return
      si_length = LENGTH_SI(findloc(LENGTHS, length, 1))
      si_force = FORCE_SI(findloc(FORCES, force, 1))
      expected = stress_name(force, length, si_force/si_length**2)
      if (allocated(stress)) then
         si = pascals(stress)
         si_stress = si_force/si_length**2
         if (abs(si - si_stress) > 1.0e-9_wp*si_stress) then
            message = 'stress unit '//stress//' is not force/length**2 = '//force//'/'// &
               length//'2; expected '//expected
            return
         end if
      else
         stress = expected
      end if
      units%stated = .true.
      units%length = length
      units%force = force
      units%stress = stress
   end subroutine parse_units

   !> The point driver's line: a length and a stress unit, no force.
   subroutine lengths_and_stress(text, length, force, stress, units, message)
      character(len=*), intent(in) :: text
      character(len=:), allocatable, intent(in) :: length, force, stress
      type(units_t), intent(inout) :: units
      character(len=:), allocatable, intent(inout) :: message
      if (allocated(force)) then
         message = 'a path deck has no force: give a length and a stress unit only, e.g. '// &
            '"mm, kPa"'
      else if (.not. allocated(length)) then
         message = 'no length unit in "'//trim(text)//'"; expected one of m, cm, mm'
      else if (.not. allocated(stress)) then
         message = 'no stress unit in "'//trim(text)//'"; expected one of Pa, kPa, MPa, GPa'
      end if
      if (len(message) > 0) return
      units%stated = .true.
      units%length = length
      units%force = UNITS_NOT_STATED
      units%stress = stress
   end subroutine lengths_and_stress

   !> Files `word` as a length, force or stress unit; message names a repeat or an unknown word.
   subroutine classify(word, length, force, stress, message)
      character(len=*), intent(in) :: word
      character(len=:), allocatable, intent(inout) :: length, force, stress
      character(len=:), allocatable, intent(inout) :: message
      character(len=:), allocatable :: name
      integer :: k
      k = known(LENGTHS, word)
      if (k > 0) then
         call take('length', trim(LENGTHS(k)), length, message)
         return
      end if
      k = known(FORCES, word)
      if (k > 0) then
         call take('force', trim(FORCES(k)), force, message)
         return
      end if
      name = stress_word(word)
      if (len(name) > 0) then
         call take('stress', name, stress, message)
         return
      end if
      message = 'unknown unit "'//word//'"; known units: '//UNITS_KNOWN
   end subroutine classify

   subroutine take(kind, name, slot, message)
      character(len=*), intent(in) :: kind, name
      character(len=:), allocatable, intent(inout) :: slot, message
      if (allocated(slot)) then
         message = 'two '//kind//' units ('//slot//' and '//name//'); give one'
      else
         slot = name
      end if
   end subroutine take

   !> Canonical spelling of a stress word: Pa..GPa or FORCE/LENGTH2; '' when not one.
   function stress_word(word) result(name)
      character(len=*), intent(in) :: word
      character(len=:), allocatable :: name
      character(len=:), allocatable :: below
      integer :: k, slash, f, l
      name = ''
      k = known(STRESSES, word)
      if (k > 0) then
         name = trim(STRESSES(k))
         return
      end if
      slash = index(word, '/')
      if (slash < 2) return
      below = word(slash + 1:)
      do k = 1, 3
         if (ends(below, trim(POWERS(k)))) exit
      end do
      if (k > 3) return
      below = below(1:len(below) - len_trim(POWERS(k)))
      f = known(FORCES, word(1:slash - 1))
      l = known(LENGTHS, below)
      if (f > 0 .and. l > 0) name = trim(FORCES(f))//'/'//trim(LENGTHS(l))//'2'
   contains
      pure logical function ends(s, tail)
         character(len=*), intent(in) :: s, tail
         ends = .false.
         if (len(s) > len(tail)) ends = s(len(s) - len(tail) + 1:) == tail
      end function ends
   end function stress_word

   !> Size in Pa of a canonical stress name.
   real(wp) function pascals(name) result(si)
      character(len=*), intent(in) :: name
      integer :: slash, k
      k = findloc(STRESSES, name, 1)
      if (k > 0) then
         si = STRESS_SI(k)
         return
      end if
      slash = index(name, '/')
      si = FORCE_SI(findloc(FORCES, name(1:slash - 1), 1))/ &
         LENGTH_SI(findloc(LENGTHS, name(slash + 1:len(name) - 1), 1))**2
   end function pascals

   !> Pa..GPa when one equals `si` Pa, else FORCE/LENGTH2 (e.g. N/cm2).
   function stress_name(force, length, si) result(name)
      character(len=*), intent(in) :: force, length
      real(wp), intent(in) :: si
      character(len=:), allocatable :: name
      integer :: k
      name = force//'/'//length//'2'
      do k = 1, size(STRESSES)
         if (abs(STRESS_SI(k) - si) <= 1.0e-9_wp*si) name = trim(STRESSES(k))
      end do
   end function stress_name

   !> Index of `word` in `names` (case-insensitive), 0 when absent.
   pure integer function known(names, word) result(k)
      character(len=*), intent(in) :: names(:), word
      do k = 1, size(names)
         if (same_name(names(k), word)) return
      end do
      k = 0
   end function known

   !> Unit of `quantity` ('length', 'force', 'stress'; anything else is dimensionless '1');
   !> UNITS_NOT_STATED for a dimensional quantity when the deck has no *UNITS.
   function units_of(this, quantity) result(name)
      class(units_t), intent(in) :: this
      character(len=*), intent(in) :: quantity
      character(len=:), allocatable :: name
      name = '1'
      select case (quantity)
      case ('length', 'force', 'stress')
         name = UNITS_NOT_STATED
         if (.not. this%stated) return
      end select
      select case (quantity)
      case ('length')
         name = this%length
      case ('force')
         name = this%force
      case ('stress')
         name = this%stress
      end select
   end function units_of

end module pecplas_base_units
