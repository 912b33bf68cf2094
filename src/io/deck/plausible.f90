!> Unit plausibility of material data (doc/deck.md, *UNITS): with *UNITS stated, a Young's
!> modulus or a unit weight far outside what soils and structural materials have in those
!> units is most likely typed in another unit (E in MPa in a kPa deck, a density in kg/m3 for
!> the unit weight). Such a value is a warning, not an error: the run goes on (`--strict`
!> makes it an input error, as every warning). The bounds are generous, a factor of about
!> 100 beyond the plausible ranges (every deck of the repository lies inside them by that
!> factor or more), except the soft end of E, where the softest soils (peat, 100-500 kPa)
!> leave no such room: below 50 kPa.
module pecplas_io_deck_plausible
   use pecplas_base_kinds, only: wp
   use pecplas_base_units, only: units_t
   use pecplas_base_strings, only: decimal_text
   use pecplas_base_warnings, only: warnings_t
   implicit none (type, external)
   private

   public :: check_plausible

   !> E below this (Pa) is softer than any soil; above, stiffer than any material (diamond
   !> 1.2e12 Pa, a rigid footing's 1e12 Pa, times 100).
   real(wp), parameter :: E_SOFTEST = 5.0e4_wp, E_STIFFEST = 1.0e14_wp
   !> A unit weight (N/m3) above this is heavier than any material (steel 78.5 kN/m3, times
   !> 13: a density in kg/m3 of soil, 1600-2200, typed in kN/m3 lies above it); a positive
   !> one below the lower bound lighter than any (EPS geofoam 200 N/m3, over 20).
   real(wp), parameter :: GAMMA_HEAVIEST = 1.0e6_wp, GAMMA_LIGHTEST = 10.0_wp
   !> The declared units in SI (pecplas_base_units: the stress unit is force/length2).
   character(len=*), parameter :: LENGTHS(3) = [character(len=2) :: 'm', 'cm', 'mm']
   real(wp), parameter :: LENGTH_SI(3) = [1.0_wp, 1.0e-2_wp, 1.0e-3_wp]
   character(len=*), parameter :: FORCES(3) = [character(len=2) :: 'N', 'kN', 'MN']
   real(wp), parameter :: FORCE_SI(3) = [1.0_wp, 1.0e3_wp, 1.0e6_wp]

contains

   !> Warns (file, line of the value) when parameter `key` = `value` of material `material`
   !> lies outside the plausible range in the deck's units. Only E and the unit weights
   !> (GAMMA, GAMMA_SAT, GAMMA_UNSAT) are checked, and only when the units are stated.
   subroutine check_plausible(units, material, key, value, file, line, warnings)
      type(units_t), intent(in) :: units
      character(len=*), intent(in) :: material, key, file
      real(wp), intent(in) :: value
      integer, intent(in) :: line
      type(warnings_t), intent(inout) :: warnings
      character(len=:), allocatable :: head, text
      real(wp) :: pa, npm3
      if (.not. units%stated) return
      pa = si(units%force, FORCES, FORCE_SI)/si(units%length, LENGTHS, LENGTH_SI)**2
      npm3 = pa/si(units%length, LENGTHS, LENGTH_SI)
      if (.not. (pa > 0.0_wp .and. pa < huge(pa))) return
      head = "[*MATERIAL] material '"//material//"': "//key//' = '//num(value)//' '
      text = ''
      select case (key)
      case ('E')
         if (value > 0.0_wp .and. value*pa < E_SOFTEST) then
            text = units%stress//' is softer than any soil (peat '//num(1.0e5_wp/pa)//'-'// &
               num(5.0e5_wp/pa)//' '//units%stress//', soft clay '//num(1.0e6_wp/pa)// &
               '-'//num(5.0e6_wp/pa)//' '//units%stress//', sand '//num(1.0e7_wp/pa)//'-'// &
               num(1.0e8_wp/pa)//' '//units%stress//')'//slip(value, pa, 1000.0_wp, units%stress)
         else if (value*pa > E_STIFFEST) then
            text = units%stress//' is stiffer than any material (steel '// &
               num(2.1e11_wp/pa)//' '//units%stress//', diamond '//num(1.2e12_wp/pa)//' '// &
               units%stress//')'//slip(value, pa, 1.0e-3_wp, units%stress)
         end if
      case ('GAMMA', 'GAMMA_SAT', 'GAMMA_UNSAT')
         if (value*npm3 > GAMMA_HEAVIEST) then
            text = weight()//' is heavier than any material (soils '//num(1.4e4_wp/npm3)// &
               '-'//num(2.3e4_wp/npm3)//', concrete '//num(2.4e4_wp/npm3)//', steel '// &
               num(7.85e4_wp/npm3)//' '//weight()//'); a density in kg/m3 (the unit weight '// &
               'is density times g: 2000 kg/m3 weigh '//num(1.962e4_wp/npm3)//' '// &
               weight()//')'//kn_slip()//'?'
         else if (value > 0.0_wp .and. value*npm3 < GAMMA_LIGHTEST) then
            text = weight()//' is lighter than any material (EPS geofoam '// &
               num(200.0_wp/npm3)//', soils '//num(1.4e4_wp/npm3)//'-'//num(2.3e4_wp/npm3)// &
               ' '//weight()//'); a density in t/m3 (2 t/m3 weigh '//num(1.962e4_wp/npm3)// &
               ' '//weight()//')?'
         end if
      end select
      if (len(text) > 0) call warnings%add(head//text, file, line)
   contains
      !> ' or typed in kN/m3 (18 kN/m3 is 1.8E-05 N/mm3)' when the deck's unit is another.
      function kn_slip() result(k)
         character(len=:), allocatable :: k
         k = ''
         if (abs(npm3 - 1.0e3_wp) > 1.0e-9_wp*npm3) k = ' or typed in kN/m3 ('// &
            num(value)//' kN/m3 is '//num(value*1.0e3_wp/npm3)//' '//weight()//')'
      end function kn_slip

      !> The unit weight's unit, force/length3.
      function weight() result(w)
         character(len=:), allocatable :: w
         w = units%force//'/'//units%length//'3'
      end function weight
   end subroutine check_plausible

   !> The SI value of unit `name` from its table (0: not in it, e.g. a path deck's force).
   pure real(wp) function si(name, names, values)
      character(len=*), intent(in) :: name, names(:)
      real(wp), intent(in) :: values(:)
      integer :: k
      si = 0.0_wp
      do k = 1, size(names)
         if (trim(names(k)) == name) si = values(k)
      end do
   end function si

   !> '; typed in MPa? (30 MPa is 30000 kPa)' for the stress unit `factor` times the
   !> declared one (`pa` Pa, named `unit`) when it has a name; otherwise '; typed in a unit
   !> N times larger (smaller)?'.
   function slip(value, pa, factor, unit) result(s)
      real(wp), intent(in) :: value, pa, factor
      character(len=*), intent(in) :: unit
      character(len=:), allocatable :: s
      character(len=*), parameter :: NAMES(4) = [character(len=3) :: 'Pa', 'kPa', 'MPa', 'GPa']
      real(wp), parameter :: SI(4) = [1.0_wp, 1.0e3_wp, 1.0e6_wp, 1.0e9_wp]
      integer :: k
      do k = 1, size(SI)
         if (abs(SI(k) - pa*factor) <= 1.0e-9_wp*SI(k)) then
            s = '; typed in '//trim(NAMES(k))//'? ('//num(value)//' '//trim(NAMES(k))// &
               ' is '//num(value*factor)//' '//unit//')'
            return
         end if
      end do
      if (factor > 1.0_wp) then
         s = '; typed in a unit '//num(factor)//' times larger?'
      else
         s = '; typed in a unit '//num(1.0_wp/factor)//' times smaller?'
      end if
   end function slip

   !> A number as an engineer writes it: three significant digits, no trailing zeros
   !> ("30", "0.5", "2.1E+08").
   function num(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=16) :: buf
      real(wp) :: ax
      ax = abs(x)
      if (ax >= 1.0e-3_wp .and. ax < 1.0e6_wp) then
         s = decimal_text(x, max(0, 2 - floor(log10(ax))))
      else if (ax == 0.0_wp) then
         s = '0'
      else
         write (buf, '(es10.2e2)') x
         s = trim(adjustl(buf))
      end if
   end function num

end module pecplas_io_deck_plausible
