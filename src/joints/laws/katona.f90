!> Katona contact (thesis (I.12)–(I.14), doc/theory.md §6.5): the joints of a set whose law is
!> KATONA are not penalty elements but node-doublet constraints D U = d enforced by Lagrange
!> multipliers, solved by the bordered saddle-point solver (pecjoin_katona_*). This type only
!> carries the parameters; the penalty assembly skips its sets (`is_katona`), so `update` is
!> never called there (it returns zero stress for completeness).
!>
!> Contact law on a doublet of tributary measure A (force N normal, compression positive,
!> T tangential, both per doublet):
!>     bonded (stick): g_n = 0, no slip, |T| <= c A + mu N, N >= -T_ten A
!>     slipping:       g_n = 0, T = sign(slip) (c A + mu N)
!>     free (open):    N = T = 0, g_n >= 0
!> with mu = tan(PHI) (or MU), c = C, tensile strength T_ten = min(TENSION, c / mu), lost at
!> the first separation (as the Coulomb kernel of the penalty laws).
!>
!> Deck: PHI (degrees) or MU (>= 0, default 0: frictionless), C (>= 0, default 0), TENSION
!> (>= 0, default 0). KN, KT, PSI and E_RYG are accepted and ignored, so that a deck switches
!> between this method and a penalty law (MOHR_COULOMB, SPRING) by the one word TYPE=.
module pecplas_joints_laws_katona
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_type, only: interface_law_t, MODE_STICK
   use pecplas_joints_laws_checks, only: get_param, param_error, tan_deg
   implicit none (type, external)
   private

   public :: katona_law_t, build_katona_law, is_katona

   type, extends(interface_law_t) :: katona_law_t
      !> Friction coefficient, cohesion (stress) and tensile strength (stress).
      real(wp) :: mu = 0.0_wp, c = 0.0_wp, tension = 0.0_wp
   contains
      procedure :: nstate => katona_nstate
      procedure :: init_state => katona_init_state
      procedure :: elastic_tangent => katona_elastic_tangent
      procedure :: update => katona_update
      !> Tensile strength of an unbroken bond: min(TENSION, c / mu).
      procedure :: tensile_limit => katona_tensile_limit
   end type katona_law_t

contains

   subroutine build_katona_law(name, params, law, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(katona_law_t) :: k
      real(wp) :: phi, ignored
      call params%unknown_keys([character(len=7) :: 'PHI', 'MU', 'C', 'TENSION', 'KN', 'KT', &
         'PSI', 'E_RYG'], error)
      if (allocated(error)) return
      k%name = name
      if (params%has('PHI') .and. params%has('MU')) then
         call param_error(params, 'give the friction as PHI (degrees) or MU, not both', error)
         return
      end if
      if (params%has('PHI')) then
         call get_param(params, 'PHI', phi, error, ge=0.0_wp, lt=90.0_wp)
         if (allocated(error)) return
         k%mu = tan_deg(phi)
      else
         call get_param(params, 'MU', k%mu, error, default=0.0_wp, ge=0.0_wp)
         if (allocated(error)) return
      end if
      call get_param(params, 'C', k%c, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'TENSION', k%tension, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      ! penalty parameters: only range-checked, so a switched deck is still a valid deck
      call get_param(params, 'KN', ignored, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'KT', ignored, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      allocate (law, source=k)
   end subroutine build_katona_law

   !> True for a law whose joint sets are Katona constraints (skipped by penalty assembly).
   pure logical function is_katona(law)
      class(interface_law_t), intent(in) :: law
      is_katona = .false.
      select type (law)
      class is (katona_law_t)
         is_katona = .true.
      end select
   end function is_katona

   pure real(wp) function katona_tensile_limit(this) result(t)
      class(katona_law_t), intent(in) :: this
      t = this%tension
      if (this%mu > 0.0_wp) t = min(t, this%c/this%mu)
   end function katona_tensile_limit

   pure integer function katona_nstate(this) result(n)
      class(katona_law_t), intent(in) :: this
      n = 0
   end function katona_nstate

   subroutine katona_init_state(this, sigma0, state)
      class(katona_law_t), intent(in) :: this
      real(wp), intent(in) :: sigma0(2)
      real(wp), intent(out) :: state(:)
      state = 0.0_wp
   end subroutine katona_init_state

   !> No stiffness: the constraint is not a spring.
   subroutine katona_elastic_tangent(this, state, tangent)
      class(katona_law_t), intent(in) :: this
      real(wp), intent(in) :: state(:)
      real(wp), intent(out) :: tangent(2, 2)
      tangent = 0.0_wp
   end subroutine katona_elastic_tangent

   subroutine katona_update(this, sigma_old, deps, state, sigma, tangent, mode, error)
      class(katona_law_t), intent(in) :: this
      real(wp), intent(in) :: sigma_old(2), deps(2)
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: sigma(2), tangent(2, 2)
      integer, intent(out) :: mode
      type(error_t), allocatable, intent(out) :: error
      sigma = 0.0_wp
      tangent = 0.0_wp
      mode = MODE_STICK
   end subroutine katona_update

end module pecplas_joints_laws_katona
