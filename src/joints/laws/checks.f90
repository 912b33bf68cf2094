!> Reading and range-checking interface-law parameters: every error names the deck file,
!> line and keyword carried by params_t, the key, the value found and the range expected.
module pecplas_joints_laws_checks
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_base_params, only: params_t
   implicit none (type, external)
   private

   public :: get_param, param_error, tan_deg, num, length_unit_metres, LENGTH_UNIT_KEYS

   real(wp), parameter :: PI = acos(-1.0_wp)

   !> Keyword-line options of *INTERFACE_LAW giving the unit of the law's length parameters
   !> and of the model's displacements; the readers pass them to the law as parameters of
   !> the same names whose value is the size of the unit in metres.
   character(len=*), parameter :: LENGTH_UNIT_KEYS(2) = [character(len=11) :: 'LENGTH_UNIT', &
      'MODEL_UNIT']

contains

   !> Value of `key` (or `default` when absent) checked against the bounds given:
   !> gt/ge (value > gt, value >= ge) and lt/le (value < lt, value <= le).
   subroutine get_param(params, key, value, error, default, gt, ge, lt, le)
      type(params_t), intent(in) :: params
      character(len=*), intent(in) :: key
      real(wp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: default, gt, ge, lt, le
      character(len=:), allocatable :: expected
      logical :: ok
      call params%get(key, value, error, default)
      if (allocated(error)) return
      ok = .true.
      expected = ''
      if (present(gt)) then
         ok = ok .and. value > gt
         expected = expected//' > '//num(gt)
      end if
      if (present(ge)) then
         ok = ok .and. value >= ge
         expected = expected//' >= '//num(ge)
      end if
      if (present(lt)) then
         ok = ok .and. value < lt
         if (len(expected) > 0) expected = expected//' and'
         expected = expected//' < '//num(lt)
      end if
      if (present(le)) then
         ok = ok .and. value <= le
         if (len(expected) > 0) expected = expected//' and'
         expected = expected//' <= '//num(le)
      end if
      ! written so that a NaN fails too
      if (.not. ok) call param_error(params, key//' = '//num(value)//' is out of range: '// &
         'expected '//key//expected, error)
   end subroutine get_param

   !> Size in metres of a length unit named in a deck: MM (1e-3) or M (1); ok = .false. else.
   pure subroutine length_unit_metres(text, metres, ok)
      character(len=*), intent(in) :: text
      real(wp), intent(out) :: metres
      logical, intent(out) :: ok
      ok = .true.
      select case (trim(adjustl(text)))
      case ('MM', 'mm', 'Mm', 'mM')
         metres = 1.0e-3_wp
      case ('M', 'm')
         metres = 1.0_wp
      case default
         metres = 0.0_wp
         ok = .false.
      end select
   end subroutine length_unit_metres

   !> Deck error at the parameters' position.
   subroutine param_error(params, message, error)
      type(params_t), intent(in) :: params
      character(len=*), intent(in) :: message
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: file, keyword
      file = ''
      keyword = ''
      if (allocated(params%file)) file = params%file
      if (allocated(params%keyword)) keyword = params%keyword
      call deck_error(error, file, params%line, keyword, message)
   end subroutine param_error

   !> tan of an angle in degrees (exactly 0 for 0).
   elemental real(wp) function tan_deg(deg)
      real(wp), intent(in) :: deg
      tan_deg = tan(deg*PI/180.0_wp)
   end function tan_deg

   !> Shortest readable form of a number ('90', '0.001', '-5').
   function num(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=32) :: buf
      if (x == aint(x) .and. abs(x) < 1.0e15_wp) then
         write (buf, '(i0)') int(x, kind=selected_int_kind(18))
      else
         write (buf, '(g0.6)') x
      end if
      s = trim(adjustl(buf))
   end function num

end module pecplas_joints_laws_checks
