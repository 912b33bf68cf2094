!> Non-associated Mohr–Coulomb interface (Meimon et al.; thesis (I.11), fig. I.9, Annex C
!> (C.11)–(C.16) with the correction of doc/theory.md §6.1), on the Coulomb kernel
!> (pecplas_joints_laws_coulomb, which holds the return and the tangent):
!>
!>     elastic   d sigma_n = K_n d eps_n^e,  d tau = K_t d eps_t^e
!>     criterion f = |tau| - sigma_n tan(phi) - c           (sigma_n compression positive)
!>     potential g = |tau| - sigma_n tan(psi),  0 <= psi <= phi
!>     tangent   C_ep = C_e - (C_e m)(n^T C_e) / (n^T C_e m),  n = df/dsigma, m = dg/dsigma
!>
!> The return is exact in one step (piecewise-linear law). Under constrained normal
!> displacement (d eps_n = 0) a plastic slip dlambda dilates (d eps_n^p = -tan(psi) dlambda)
!> and raises the normal stress by exactly d sigma_n = K_n tan(psi) dlambda.
!> Separation: when sigma_n would fall below -TENSION (or below the apex -c/tan(phi) if that
!> is higher) the stress drops to zero, mode open; contact is recovered when the opening
!> closes. The tensile strength is lost at the first separation.
!>
!> Deck: KN, KT (> 0), PHI (degrees, 0 <= PHI < 90), PSI (degrees, 0 <= PSI <= PHI,
!> default 0), C (>= 0, default 0), TENSION (>= 0, default 0).
module pecplas_joints_laws_mohr_coulomb
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_joints_laws_coulomb, only: coulomb_law_t
   use pecplas_joints_laws_checks, only: get_param, param_error, tan_deg, num
   implicit none (type, external)
   private

   public :: mohr_coulomb_law_t, build_mohr_coulomb_law

   type, extends(coulomb_law_t) :: mohr_coulomb_law_t
      !> Friction and dilatancy angles (degrees) as given.
      real(wp) :: phi = 0.0_wp, psi = 0.0_wp
   end type mohr_coulomb_law_t

contains

   subroutine build_mohr_coulomb_law(name, params, law, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(mohr_coulomb_law_t) :: m
      call params%unknown_keys([character(len=7) :: 'KN', 'KT', 'PHI', 'PSI', 'C', 'TENSION'], &
         error)
      if (allocated(error)) return
      m%name = name
      call get_param(params, 'KN', m%kn, error, gt=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'KT', m%kt, error, gt=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'PHI', m%phi, error, ge=0.0_wp, lt=90.0_wp)
      if (allocated(error)) return
      call get_param(params, 'PSI', m%psi, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      if (m%psi > m%phi) then
         call param_error(params, 'PSI = '//num(m%psi)//' must not exceed PHI = '// &
            num(m%phi)//' (dilatancy angle above the friction angle)', error)
         return
      end if
      call get_param(params, 'C', m%c, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'TENSION', m%tension, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      m%mu_f = tan_deg(m%phi)
      m%mu_g = tan_deg(m%psi)
      allocate (law, source=m)
   end subroutine build_mohr_coulomb_law

end module pecplas_joints_laws_mohr_coulomb
