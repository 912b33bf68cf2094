!> Deck builders of the three MODJOIN versions (pecplas_joints_laws_modjoin):
!>
!>     *INTERFACE_LAW, NAME=n, TYPE=MODJOIN_INITIAL|MODJOIN|MODJOIN_CYCLIC, LENGTH_UNIT=MM|M
!>                     [, MODEL_UNIT=MM|M]
!>     K0 = 80, G0 = 40, PHI = 41, C = 0, R0 = 0.3, BETA = 1.5, PSI = 27, A_G = 0.4
!>     ALPHA = 0.7, A = 0.6, B = 0.96                ! MODJOIN, MODJOIN_CYCLIC
!>     B_CYC = 0.9                                   ! MODJOIN_CYCLIC (b of III.25)
!>     [PA = 100] [SIGMA_MIN = 1] [SUBSTEP = 0.001]
!>
!> Units (doc/theory.md §6.4, "Units of the thesis tables"): every length-dimensioned parameter is
!> given in LENGTH_UNIT (required: never guessed): BETA, B_CYC, SUBSTEP in it, K0, G0 in
!> stress/LENGTH_UNIT, A in LENGTH_UNIT^-2, B and A_G in LENGTH_UNIT^-1. With LENGTH_UNIT=MM
!> the thesis tables read K0 = 80 (printed "80 MPa" = kPa/mm) and BETA = 1.5 (printed 0.0015,
!> in metres). The law works in MODEL_UNIT, the length unit of the model's displacements
!> (default: LENGTH_UNIT; the model-deck reader requires it): the conversion is applied here,
!> once, and the summary line that the programs print shows the converted values. Stresses (C, PA, SIGMA_MIN) are in the
!> deck's stress unit; PA = 100 is P_a in kPa. The readers pass LENGTH_UNIT and MODEL_UNIT as
!> the size of the unit in metres (1e-3 for MM, 1 for M).
module pecplas_joints_laws_modjoin_build
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_strings, only: decimal_text
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_joints_laws_checks, only: get_param, param_error, tan_deg
   use pecplas_joints_laws_modjoin, only: modjoin_law_t
   use pecplas_joints_laws_modjoin_step, only: MJ_INITIAL, MJ_IMPROVED, MJ_CYCLIC, MJ_VERSION_NAMES
   implicit none (type, external)
   private

   public :: build_modjoin_initial_law, build_modjoin_law, build_modjoin_cyclic_law

   !> Default largest substep: 0.001 mm, in metres.
   real(wp), parameter :: SUBSTEP_M = 1.0e-6_wp

contains

   subroutine build_modjoin_initial_law(name, params, law, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      call build(MJ_INITIAL, name, params, law, error)
   end subroutine build_modjoin_initial_law

   subroutine build_modjoin_law(name, params, law, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      call build(MJ_IMPROVED, name, params, law, error)
   end subroutine build_modjoin_law

   subroutine build_modjoin_cyclic_law(name, params, law, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      call build(MJ_CYCLIC, name, params, law, error)
   end subroutine build_modjoin_cyclic_law

   subroutine build(version, name, params, law, error)
      integer, intent(in) :: version
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(modjoin_law_t) :: m
      character(len=11), allocatable :: known(:)
      real(wp) :: lu, mu, f, phi, psi, c, k0, g0, beta, a, b, a_g, b_cyc, h
      character(len=:), allocatable :: vname

      vname = trim(MJ_VERSION_NAMES(version))
      known = [character(len=11) :: 'K0', 'G0', 'PHI', 'C', 'R0', 'BETA', 'PSI', 'A_G', 'PA', &
         'SIGMA_MIN', 'SUBSTEP', 'LENGTH_UNIT', 'MODEL_UNIT']
      if (version /= MJ_INITIAL) known = [known, [character(len=11) :: 'ALPHA', 'A', 'B']]
      if (version == MJ_CYCLIC) known = [known, [character(len=11) :: 'B_CYC']]
      call params%unknown_keys(known, error)
      if (allocated(error)) return
      if (.not. params%has('LENGTH_UNIT')) then
         call param_error(params, vname//' needs the unit of its parameters on the keyword '// &
            'line: LENGTH_UNIT=MM (thesis tables: kPa, mm, kPa/mm) or LENGTH_UNIT=M', error)
         return
      end if
      m%name = name
      m%p%version = version
      call get_param(params, 'LENGTH_UNIT', lu, error, gt=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'MODEL_UNIT', mu, error, default=lu, gt=0.0_wp)
      if (allocated(error)) return
      ! f = size of the parameter length unit in model length units
      f = lu/mu
      call get_param(params, 'K0', k0, error, gt=0.0_wp)
      if (.not. allocated(error)) call get_param(params, 'G0', g0, error, gt=0.0_wp)
      if (.not. allocated(error)) call get_param(params, 'PHI', phi, error, gt=0.0_wp, &
         lt=90.0_wp)
      if (.not. allocated(error)) call get_param(params, 'C', c, error, default=0.0_wp, &
         ge=0.0_wp)
      if (.not. allocated(error)) call get_param(params, 'BETA', beta, error, gt=0.0_wp)
      if (.not. allocated(error)) call get_param(params, 'PSI', psi, error, ge=0.0_wp, &
         lt=90.0_wp)
      if (.not. allocated(error)) call get_param(params, 'A_G', a_g, error, ge=0.0_wp)
      if (.not. allocated(error)) call get_param(params, 'PA', m%p%el%pa, error, &
         default=100.0_wp, gt=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'SIGMA_MIN', m%p%el%smin, error, default=0.01_wp*m%p%el%pa, &
         gt=0.0_wp, lt=m%p%el%pa)
      if (.not. allocated(error)) call get_param(params, 'SUBSTEP', h, error, &
         default=SUBSTEP_M/lu, gt=0.0_wp)
      if (allocated(error)) return
      a = 0.0_wp
      b = 0.0_wp
      b_cyc = 0.0_wp
      m%p%alpha = 1.0_wp
      if (version == MJ_IMPROVED) then
         call get_param(params, 'ALPHA', m%p%alpha, error, gt=0.0_wp)
         if (.not. allocated(error)) call get_param(params, 'A', a, error, ge=0.0_wp)
      else if (version == MJ_CYCLIC) then
         call get_param(params, 'ALPHA', m%p%alpha, error, default=1.0_wp, gt=0.0_wp)
         if (.not. allocated(error)) call get_param(params, 'A', a, error, default=0.0_wp, &
            ge=0.0_wp)
         if (.not. allocated(error)) call get_param(params, 'B_CYC', b_cyc, error, gt=0.0_wp)
      end if
      if (allocated(error)) return
      if (a > 0.0_wp) then
         call get_param(params, 'B', b, error, gt=0.0_wp)
      else if (version /= MJ_INITIAL) then
         call get_param(params, 'B', b, error, default=0.0_wp, ge=0.0_wp)
      end if
      if (allocated(error)) return
      if (version == MJ_INITIAL) then
         call get_param(params, 'R0', m%p%r0, error, gt=0.0_wp, lt=1.0_wp)
      else
         call get_param(params, 'R0', m%p%r0, error, gt=0.0_wp, lt=m%p%alpha)
      end if
      if (allocated(error)) return

      m%p%el%nonlinear = version /= MJ_INITIAL
      m%p%el%k0 = k0/f
      m%p%el%g0 = g0/f
      m%p%mu_f = tan_deg(phi)
      m%p%cc = c/m%p%mu_f
      m%p%mu_g = tan_deg(psi)
      m%p%a_g = a_g/f
      m%p%beta = beta*f
      m%p%a = a/f**2
      m%p%b = b/f
      m%p%b_cyc = b_cyc*f
      m%p%substep = h*f
      m%summary = vname//' '//name//': parameters in '//unit_name(lu)//', model in '// &
         unit_name(mu)//' (x'//num(f)//'); in model units K0 = '//num(m%p%el%k0)//', G0 = '// &
         num(m%p%el%g0)//', BETA = '//num(m%p%beta)//', A = '//num(m%p%a)//', B = '//num(m%p%b)// &
         ', A_G = '//num(m%p%a_g)
      if (version == MJ_CYCLIC) m%summary = m%summary//', B_CYC = '//num(m%p%b_cyc)
      m%summary = m%summary//', SUBSTEP = '//num(m%p%substep)//'; P_a = '//num(m%p%el%pa)// &
         ', SIGMA_MIN = '//num(m%p%el%smin)//'; (III.18) alpha tan(phi) P_a/G0 = '// &
         num(m%p%alpha*m%p%mu_f*m%p%el%pa/m%p%el%g0)//' vs BETA'
      allocate (law, source=m)
   end subroutine build

   !> Six significant digits, without trailing zeros: 0.0015, 80000, 1.52125, 6e-07.
   function num(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=40) :: buf
      integer :: e, i, d
      if (x == 0.0_wp) then
         s = '0'
         return
      end if
      e = floor(log10(abs(x)))
      if (e >= -4 .and. e <= 6) then
         ! 5 - e decimals: six significant digits (never a value rounded to zero)
         s = decimal_text(x, max(0, 5 - e))
      else
         write (buf, '(es12.5e2)') x
         s = trim(adjustl(buf))
         i = index(s, 'E')
         d = i - 1
         do while (s(d:d) == '0')
            d = d - 1
         end do
         if (s(d:d) == '.') d = d - 1
         s = s(1:d)//'e'//s(i + 1:)
      end if
   end function num

   !> 'mm' / 'm' / '<x> m'.
   function unit_name(metres) result(s)
      real(wp), intent(in) :: metres
      character(len=:), allocatable :: s
      if (metres == 1.0e-3_wp) then
         s = 'mm'
      else if (metres == 1.0_wp) then
         s = 'm'
      else
         s = num(metres)//' m'
      end if
   end function unit_name

end module pecplas_joints_laws_modjoin_build
