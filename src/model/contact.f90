!> Katona contact (thesis (I.12)–(I.14), doc/theory.md §6.5): the parameters of an
!> *INTERFACE_LAW, TYPE=KATONA. Such a law is no constitutive law of the joint points: the
!> joint sets that use it are held by Lagrange multipliers on their node doublets
!> (pecplas_joints_katona_*, solved by pecplas_solve_katona_increment), and the deck reader
!> marks them so (joint_set_t%is_katona); these parameters give the doublets' contact law.
!>
!> Contact law on a doublet of tributary measure A (force N normal, compression positive,
!> T tangential, both per doublet):
!>     bonded (stick): g_n = 0, no slip, |T| <= c A + mu N, N >= -T_ten A
!>     slipping:       g_n = 0, T = sign(slip) (c A + mu N)
!>     free (open):    N = T = 0, g_n >= 0
!> with mu = tan(PHI) (or MU), c = C, tensile strength T_ten = min(TENSION, c / mu), lost when
!> an increment ends with the doublet open (as the Coulomb kernel of the penalty laws).
!>
!> Deck: PHI (degrees) or MU (>= 0, default 0: frictionless), C (>= 0, default 0), TENSION
!> (>= 0, default 0). KN, KT, PSI and E_RYG are accepted and ignored, so that a deck switches
!> between this method and a penalty law (MOHR_COULOMB, SPRING) by the one word TYPE=.
module pecplas_model_contact
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_checks, only: get_param, param_error, tan_deg
   implicit none (type, external)
   private

   public :: katona_contact_t, build_katona_contact, KATONA_TYPE

   !> The *INTERFACE_LAW type name of Katona contact.
   character(len=*), parameter :: KATONA_TYPE = 'KATONA'

   type :: katona_contact_t
      !> The law's deck name (NAME=).
      character(len=:), allocatable :: name
      !> Friction coefficient, cohesion (stress) and tensile strength (stress).
      real(wp) :: mu = 0.0_wp, c = 0.0_wp, tension = 0.0_wp
   contains
      !> Tensile strength of an unbroken bond: min(TENSION, c / mu).
      procedure :: tensile_limit => contact_tensile_limit
   end type katona_contact_t

contains

   !> The contact `name` from its deck parameters (checked).
   subroutine build_katona_contact(name, params, contact, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      type(katona_contact_t), intent(out) :: contact
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: phi, ignored
      call params%unknown_keys([character(len=7) :: 'PHI', 'MU', 'C', 'TENSION', 'KN', 'KT', &
         'PSI', 'E_RYG'], error)
      if (allocated(error)) return
      contact%name = name
      if (params%has('PHI') .and. params%has('MU')) then
         call param_error(params, 'give the friction as PHI (degrees) or MU, not both', error)
         return
      end if
      if (params%has('PHI')) then
         call get_param(params, 'PHI', phi, error, ge=0.0_wp, lt=90.0_wp)
         if (allocated(error)) return
         contact%mu = tan_deg(phi)
      else
         call get_param(params, 'MU', contact%mu, error, default=0.0_wp, ge=0.0_wp)
         if (allocated(error)) return
      end if
      call get_param(params, 'C', contact%c, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'TENSION', contact%tension, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      ! penalty parameters: only range-checked, so a switched deck is still a valid deck
      call get_param(params, 'KN', ignored, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'KT', ignored, error, default=0.0_wp, ge=0.0_wp)
   end subroutine build_katona_contact

   pure real(wp) function contact_tensile_limit(this) result(t)
      class(katona_contact_t), intent(in) :: this
      t = this%tension
      if (this%mu > 0.0_wp) t = min(t, this%c/this%mu)
   end function contact_tensile_limit

end module pecplas_model_contact
