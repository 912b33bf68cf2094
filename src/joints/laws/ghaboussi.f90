!> Ghaboussi's thin-layer interface law (Ghaboussi, Wilson & Isenberg 1973; thesis §I.2.2,
!> fig. I.10; doc/theory.md §6.2), on the Coulomb kernel (pecplas_joints_laws_coulomb). The joint element
!> divides the relative displacements by the layer thickness e, so eps are strains and
!> KN, KT are the unit stiffnesses of the layer (stress per unit strain).
!>
!> Non-dilatant version (GAMMA = 0): stiffness adaptation with Mohr–Coulomb, exactly as
!> Goodman's law: |tau| <= c + sigma_n tan(phi), the stress capped on the criterion.
!>
!> Dilatant version (GAMMA > 0). The thesis (fig. I.10, text only, the figure is lost) says
!> the non-dilatant properties are defined in a frame (p, q) tied to the asperity and rotated
!> into (t, n) by the asperity angle gamma. The reading implemented here: the layer is elastic
!> with diag(K_n, K_t) in (n, t) while it sticks; it slips on the asperity face facing the
!> shear (a saw-tooth, so s = sign(tau) picks the face), along p_s = (-sin g, s cos g) in
!> (eps_n, eps_t), with the face normal q_s = (cos g, s sin g). With sigma_q = sigma.q_s and
!> tau_p = sigma.p_s the face obeys Mohr–Coulomb without dilatancy,
!>     tau_p <= c + sigma_q tan(phi)   <=>   |tau| <= c cos(phi)/cos(phi+g) + sigma_n tan(phi+g)
!> (Patton's first branch (I.8) with i = gamma), and the plastic flow along p_s is
!>     d eps^p = dlambda (-tan g, s)   (dilation d eps_n^p = -tan(gamma) |d eps_t^p|).
!> In (n, t) this is the Coulomb kernel with mu_f = tan(phi+gamma), c' = c cos(phi)/cos(phi+gamma)
!> and mu_g = tan(gamma): the coupling terms of the elastoplastic tangent, non-symmetric when
!> PHI > 0 (associated on the face, not in (n, t)). The second Ghaboussi method (cap model,
!> fig. I.11) and Patton's second branch (asperities sheared off) are not implemented.
!>
!> Deck: KN, KT (> 0), PHI (degrees, >= 0), C (>= 0, default 0), GAMMA (degrees, >= 0,
!> default 0), PHI + GAMMA < 90, TENSION (>= 0, default 0).
module pecplas_joints_laws_ghaboussi
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_joints_laws_coulomb, only: coulomb_law_t
   use pecplas_joints_laws_checks, only: get_param, param_error, tan_deg
   implicit none (type, external)
   private

   public :: ghaboussi_law_t, build_ghaboussi_law

   type, extends(coulomb_law_t) :: ghaboussi_law_t
      !> Friction angle of the asperity faces, asperity angle (degrees), cohesion as given.
      real(wp) :: phi = 0.0_wp, gamma = 0.0_wp, c_face = 0.0_wp
   end type ghaboussi_law_t

contains

   subroutine build_ghaboussi_law(name, params, law, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(ghaboussi_law_t) :: g
      real(wp), parameter :: DEG = acos(-1.0_wp)/180.0_wp
      call params%unknown_keys([character(len=7) :: 'KN', 'KT', 'PHI', 'C', 'GAMMA', &
         'TENSION'], error)
      if (allocated(error)) return
      g%name = name
      call get_param(params, 'KN', g%kn, error, gt=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'KT', g%kt, error, gt=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'PHI', g%phi, error, ge=0.0_wp, lt=90.0_wp)
      if (allocated(error)) return
      call get_param(params, 'C', g%c_face, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'GAMMA', g%gamma, error, default=0.0_wp, ge=0.0_wp, lt=90.0_wp)
      if (allocated(error)) return
      call get_param(params, 'TENSION', g%tension, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      if (.not. (g%phi + g%gamma < 90.0_wp)) then
         call param_error(params, 'PHI + GAMMA must be below 90 degrees (the asperity face '// &
            'would lock)', error)
         return
      end if
      g%mu_f = tan_deg(g%phi + g%gamma)
      g%mu_g = tan_deg(g%gamma)
      g%c = g%c_face
      if (g%gamma > 0.0_wp) g%c = g%c_face*cos(g%phi*DEG)/cos((g%phi + g%gamma)*DEG)
      allocate (law, source=g)
   end subroutine build_ghaboussi_law

end module pecplas_joints_laws_ghaboussi
