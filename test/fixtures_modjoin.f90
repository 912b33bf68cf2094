!> Shared fixtures of the MODJOIN tests: the parameter sets of the thesis tables (doc/theory.md §6.4,
!> "Parameter sets", in kPa and mm: LENGTH_UNIT=MM) built through the factory as a deck
!> would, optionally with one parameter changed; and paths run by the point driver.
module fixtures_modjoin
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_studies_path_driver, only: path_result_t, run_path
   use fixtures_pecjoin, only: make_law
   implicit none (type, external)
   private

   public :: table_law, run_table_path, rel_curve_diff

contains

   !> Law of table `table` ('III.1' initial, 'III.2', 'III.5' improved, 'III.6D' cyclic
   !> Dr = 80 %, 'III.6L' cyclic Dr = 15 %), with key `key` set to `value` when given, and
   !> `type_name` instead of the table's own version when given.
   subroutine table_law(table, law, error, key, value, type_name)
      character(len=*), intent(in) :: table
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in), optional :: key, type_name
      real(wp), intent(in), optional :: value
      character(len=11), allocatable :: keys(:)
      real(wp), allocatable :: values(:)
      character(len=:), allocatable :: tname
      character(len=11) :: kpad
      integer :: k
      keys = [character(len=11) :: 'LENGTH_UNIT', 'K0', 'G0', 'PHI', 'C', 'R0', 'BETA', &
         'PSI', 'A_G']
      select case (table)
      case ('III.1')
         tname = 'MODJOIN_INITIAL'
         values = [1.0e-3_wp, 80.0_wp, 40.0_wp, 41.0_wp, 0.0_wp, 0.3_wp, 9.0_wp, 27.0_wp, &
            0.5_wp]
      case ('III.2')
         tname = 'MODJOIN'
         values = [1.0e-3_wp, 80.0_wp, 40.0_wp, 41.0_wp, 0.0_wp, 0.3_wp, 1.5_wp, 27.0_wp, &
            0.4_wp, 0.7_wp, 0.6_wp, 0.96_wp]
      case ('III.5')
         tname = 'MODJOIN'
         values = [1.0e-3_wp, 70.0_wp, 35.0_wp, 37.0_wp, 0.0_wp, 0.2_wp, 1.8_wp, 30.0_wp, &
            0.4_wp, 0.84_wp, 0.15_wp, 0.7_wp]
      case ('III.6D')
         tname = 'MODJOIN_CYCLIC'
         values = [1.0e-3_wp, 90.0_wp, 45.0_wp, 37.0_wp, 0.0_wp, 0.3_wp, 1.2_wp, 27.0_wp, &
            0.4_wp, 0.75_wp, 0.25_wp, 0.73_wp, 0.9_wp]
      case ('III.6L')
         tname = 'MODJOIN_CYCLIC'
         values = [1.0e-3_wp, 70.0_wp, 35.0_wp, 28.0_wp, 0.0_wp, 0.1_wp, 8.0_wp, 30.0_wp, &
            0.4_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.5_wp]
      case default
         values = [real(wp) ::]
      end select
      if (size(values) >= 12) keys = [keys, [character(len=11) :: 'ALPHA', 'A', 'B']]
      if (size(values) == 13) keys = [keys, [character(len=11) :: 'B_CYC']]
      if (present(type_name)) tname = type_name
      if (present(key) .and. present(value)) then
         k = findloc(keys, key, dim=1)
         if (k > 0) then
            values(k) = value
         else
            kpad = key
            keys = [keys, kpad]
            values = [values, value]
         end if
      end if
      call make_law(tname, keys, values, law, error)
   end subroutine table_law

   !> Runs `law` on a path (pecplas_studies_path_driver: control PATH_CNL/CND/CNS) from
   !> (sigma_n0, 0) through `targets` with `steps` increments per segment.
   subroutine run_table_path(law, control, sigma_n0, targets, steps, res, error)
      class(interface_law_t), intent(in) :: law
      integer, intent(in) :: control, steps
      real(wp), intent(in) :: sigma_n0, targets(:)
      type(path_result_t), intent(out) :: res
      type(error_t), allocatable, intent(out) :: error
      call run_path(law, control, [sigma_n0, 0.0_wp], 0.0_wp, targets, steps, res, error)
   end subroutine run_table_path

   !> max_i |y(i) - y_ref(r i)| / max |y_ref|: a coarse curve against a fine one computed
   !> on the same path with r times more increments per segment (so that coarse row i and
   !> fine row r i are the same eps_t).
   pure real(wp) function rel_curve_diff(y, yref, r) result(d)
      real(wp), intent(in) :: y(0:), yref(0:)
      integer, intent(in) :: r
      integer :: i
      d = 0.0_wp
      do i = 0, ubound(y, 1)
         d = max(d, abs(y(i) - yref(r*i)))
      end do
      d = d/max(maxval(abs(yref)), tiny(1.0_wp))
   end function rel_curve_diff

end module fixtures_modjoin
