!> Goodman's interface law by stiffness adaptation (Goodman, Taylor & Brekke 1968; thesis
!> §I.2.1.1, (I.6)–(I.7), fig. I.5), on the Coulomb kernel (pecplas_joints_laws_coulomb):
!>
!> - compression: d sigma = diag(K_n, K_t) d eps (stick while |tau| < tau_bar);
!> - |tau| reaching tau_bar = c + sigma_n tan(phi): the stress is capped at tau_bar (the excess
!>   of the elastic trial goes back to the solver as residual force) and the tangential
!>   stiffness becomes small, K_t * KT_RATIO (mode slip). No dilatancy (psi = 0), so the cap is
!>   the Mohr–Coulomb return with mu_g = 0; the tangent is the consistent one, whose
!>   d tau / d eps_n = sign(tau) tan(phi) K_n makes it non-symmetric when PHI > 0, plus the
!>   adaptation stiffness K_t KT_RATIO on d tau / d eps_t (so a fully slipping joint does not
!>   make the global matrix singular);
!> - tension (sigma_n below -TENSION): K_n = K_t = 0 and zero stress (mode open), re-contact
!>   when the opening is closed again.
!>
!> Deck: KN, KT (> 0), PHI (degrees, 0 <= PHI < 90), C (>= 0, default 0),
!> KT_RATIO (0 <= KT_RATIO <= 1, default 1e-3), TENSION (>= 0, default 0).
module pecplas_joints_laws_goodman
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_joints_laws_coulomb, only: coulomb_law_t
   use pecplas_joints_laws_checks, only: get_param, tan_deg
   implicit none (type, external)
   private

   public :: goodman_law_t, build_goodman_law

   type, extends(coulomb_law_t) :: goodman_law_t
      !> Friction angle (degrees) and slip stiffness ratio as given.
      real(wp) :: phi = 0.0_wp, kt_ratio = 1.0e-3_wp
   end type goodman_law_t

contains

   subroutine build_goodman_law(name, params, law, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(goodman_law_t) :: g
      call params%unknown_keys([character(len=8) :: 'KN', 'KT', 'PHI', 'C', 'KT_RATIO', &
         'TENSION'], error)
      if (allocated(error)) return
      g%name = name
      call get_param(params, 'KN', g%kn, error, gt=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'KT', g%kt, error, gt=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'PHI', g%phi, error, ge=0.0_wp, lt=90.0_wp)
      if (allocated(error)) return
      call get_param(params, 'C', g%c, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'KT_RATIO', g%kt_ratio, error, default=1.0e-3_wp, ge=0.0_wp, &
         le=1.0_wp)
      if (allocated(error)) return
      call get_param(params, 'TENSION', g%tension, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      g%mu_f = tan_deg(g%phi)
      g%mu_g = 0.0_wp
      g%kt_slip = g%kt*g%kt_ratio
      allocate (law, source=g)
   end subroutine build_goodman_law

end module pecplas_joints_laws_goodman
