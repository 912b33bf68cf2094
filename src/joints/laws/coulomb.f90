!> The Coulomb kernel shared by the classical frictional interface laws (Goodman, spring,
!> Ghaboussi, Mohr–Coulomb): linear elasticity C = diag(K_n, K_t), a linear slip criterion,
!> a linear flow direction and a brittle tension cut-off, integrated exactly in one step.
!>
!>     f(sigma) = |tau| - sigma_n mu_f - c              (I.11 with mu_f = tan(phi))
!>     d eps^p = dlambda m,  m = (-mu_g, sign(tau))    (g = |tau| - sigma_n mu_g, mu_g = tan(psi))
!>
!> Signs (pecplas_joints_laws_type): eps_n closure positive, sigma_n compression positive, so the
!> plastic normal displacement d eps_n^p = -mu_g dlambda <= 0 is a dilation and, with
!> d eps_n = 0, d sigma_n = K_n mu_g dlambda > 0. The accumulated plastic slip is
!> sum |d eps_t^p| = sum dlambda.
!>
!> Return (exact: f is linear on each side tau > 0, tau < 0 and the elastic map is linear):
!> trial s_tr = sigma_old + C deps; if f(s_tr) > 0, s = sign(tau_tr),
!>     dlambda = f(s_tr) / (K_t + K_n mu_g mu_f),
!>     sigma_n = sigma_n,tr + K_n mu_g dlambda,  tau = s (|tau_tr| - K_t dlambda),
!> and the consistent tangent is (C.15 as corrected in doc/theory.md, H = 0)
!>     C_ep = C - (C m)(n^T C) / (n^T C m),  n = (-mu_f, s),
!> non-symmetric when mu_g /= mu_f. Stiffness adaptation laws add `kt_slip` to C_ep(2,2) in slip
!> (Goodman's small K_t): the update does not contain it, the returned stress stays capped.
!>
!> Separation: the tensile strength is T_eff = min(TENSION, c/mu_f) (the cone apex
!> sigma_n = -c/mu_f is the most tensile state a Mohr–Coulomb interface can carry). When the
!> stress of the step (elastic trial, or the return above) has sigma_n < -T_eff the point opens:
!> sigma = 0, tangent = 0, mode open; this also covers a return that would cross the apex
!> (|tau| < 0 there), which therefore never happens. After the first separation the bond is
!> broken: T_eff = 0. While open the law stores the opening `gap` (eps units) measured from the
!> zero-stress position (-sigma_n/K_n of the separating stress); re-contact happens within the
!> increment that closes more than the gap, and only the part after contact loads the point
!> (fraction a = (d eps_n - gap)/d eps_n of the increment, tau restarting from 0).
module pecplas_joints_laws_coulomb
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_joints_laws_type, only: interface_law_t, MODE_STICK, MODE_SLIP, MODE_OPEN
   implicit none (type, external)
   private

   public :: coulomb_law_t, coulomb_update, plastic_slip
   public :: ST_SLIP, ST_OPEN, ST_GAP, ST_BROKEN, ST_EPS_NP, ST_EPS_TP, NSTATE_COULOMB
   public :: COULOMB_STATE_NAMES

   !> History layout of every Coulomb-family law: accumulated plastic slip sum |d eps_t^p|,
   !> open flag (1 = separated), opening since separation, broken-bond flag, plastic normal
   !> displacement eps_n^p (<= 0: dilation), signed plastic tangential displacement eps_t^p.
   integer, parameter :: ST_SLIP = 1, ST_OPEN = 2, ST_GAP = 3, ST_BROKEN = 4, ST_EPS_NP = 5, &
      ST_EPS_TP = 6, NSTATE_COULOMB = 6
   character(len=*), parameter :: COULOMB_STATE_NAMES(NSTATE_COULOMB) = [character(len=12) :: &
      'plastic_slip', 'open', 'gap', 'broken', 'eps_n_p', 'eps_t_p']

   !> Elastic–perfectly-plastic Coulomb interface point; concrete laws set the coefficients
   !> from their own deck parameters (see each law's module).
   type, abstract, extends(interface_law_t) :: coulomb_law_t
      !> Elastic normal and tangential stiffnesses.
      real(wp) :: kn = 0.0_wp, kt = 0.0_wp
      !> Criterion f = |tau| - sigma_n mu_f - c and flow m = (-mu_g, sign tau).
      real(wp) :: mu_f = 0.0_wp, c = 0.0_wp, mu_g = 0.0_wp
      !> Tensile strength (>= 0) before the first separation.
      real(wp) :: tension = 0.0_wp
      !> Stiffness added to the tangential tangent in slip (stiffness adaptation), 0 if none.
      real(wp) :: kt_slip = 0.0_wp
   contains
      procedure :: nstate => coulomb_nstate
      procedure :: init_state => coulomb_init_state
      procedure :: elastic_tangent => coulomb_elastic_tangent
      procedure :: update => coulomb_update
      procedure :: symmetric_tangent => coulomb_symmetric_tangent
      procedure :: plastic_slip => coulomb_plastic_slip
      procedure :: state_names => coulomb_history_names
      !> Current tensile strength T_eff of a point with history `state`.
      procedure :: tensile_limit => coulomb_tensile_limit
      !> c and mu_f = tan(phi) divided by msf, mu_g = min(mu_g, mu_f / msf) (psi follows phi
      !> when phi_r falls below it); K_n, K_t and the tensile strength kept.
      procedure :: reduced_strength => coulomb_reduced_strength
   end type coulomb_law_t

contains

   pure integer function coulomb_nstate(this) result(n)
      class(coulomb_law_t), intent(in) :: this
      n = NSTATE_COULOMB
   end function coulomb_nstate

   !> Starts bonded and in contact; the initial stress itself is the caller's sigma_old.
   subroutine coulomb_init_state(this, sigma0, state)
      class(coulomb_law_t), intent(in) :: this
      real(wp), intent(in) :: sigma0(2)
      real(wp), intent(out) :: state(:)
      state = 0.0_wp
   end subroutine coulomb_init_state

   subroutine coulomb_elastic_tangent(this, state, tangent)
      class(coulomb_law_t), intent(in) :: this
      real(wp), intent(in) :: state(:)
      real(wp), intent(out) :: tangent(2, 2)
      tangent = reshape([this%kn, 0.0_wp, 0.0_wp, this%kt], [2, 2])
   end subroutine coulomb_elastic_tangent

   !> Symmetric iff the flow is associated (mu_g = mu_f, e.g. PSI = PHI, or both 0).
   pure logical function coulomb_symmetric_tangent(this) result(sym)
      class(coulomb_law_t), intent(in) :: this
      sym = this%mu_g == this%mu_f
   end function coulomb_symmetric_tangent

   pure real(wp) function coulomb_tensile_limit(this, state) result(t)
      class(coulomb_law_t), intent(in) :: this
      real(wp), intent(in) :: state(:)
      t = this%tension
      if (state(ST_BROKEN) > 0.5_wp) t = 0.0_wp
      if (this%mu_f > 0.0_wp) t = min(t, this%c/this%mu_f)
   end function coulomb_tensile_limit

   subroutine coulomb_update(this, sigma_old, deps, state, sigma, tangent, mode, error)
      class(coulomb_law_t), intent(in) :: this
      real(wp), intent(in) :: sigma_old(2), deps(2)
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: sigma(2), tangent(2, 2)
      integer, intent(out) :: mode
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: de(2), jac(2, 2), s0(2), local(2, 2), gap, a

      de = deps
      s0 = sigma_old
      jac = reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2])
      if (state(ST_OPEN) > 0.5_wp) then
         gap = state(ST_GAP)
         if (deps(1) <= gap) then
            state(ST_GAP) = gap - deps(1)
            sigma = 0.0_wp
            tangent = 0.0_wp
            mode = MODE_OPEN
            return
         end if
         ! re-contact: only the part of the increment after closing the gap loads the point
         a = (deps(1) - gap)/deps(1)
         de = [deps(1) - gap, a*deps(2)]
         jac(2, 1) = deps(2)*gap/deps(1)**2
         jac(2, 2) = a
         s0 = 0.0_wp
         state(ST_OPEN) = 0.0_wp
         state(ST_GAP) = 0.0_wp
      end if
      call contact_step(this, s0, de, state, sigma, local, mode)
      tangent = matmul(local, jac)
   end subroutine coulomb_update

   !> Accumulated plastic slip sum |d eps_t^p| of a point with history `state` (what the
   !> results report): the law's own plastic_slip (state(ST_SLIP) for the Coulomb family,
   !> state(1) for MODJOIN, 0 for laws without one).
   pure real(wp) function plastic_slip(law, state) result(slip)
      class(interface_law_t), intent(in) :: law
      real(wp), intent(in) :: state(:)
      slip = law%plastic_slip(state)
   end function plastic_slip

   pure real(wp) function coulomb_plastic_slip(this, state) result(slip)
      class(coulomb_law_t), intent(in) :: this
      real(wp), intent(in) :: state(:)
      slip = state(ST_SLIP)
   end function coulomb_plastic_slip

   pure subroutine coulomb_history_names(this, names)
      class(coulomb_law_t), intent(in) :: this
      character(len=16), allocatable, intent(out) :: names(:)
      allocate (names(NSTATE_COULOMB))
      names = COULOMB_STATE_NAMES
   end subroutine coulomb_history_names

   !> Elastic trial, exact return on the cone side, separation check (module header).
   subroutine contact_step(this, s0, de, state, sigma, tangent, mode)
      class(coulomb_law_t), intent(in) :: this
      real(wp), intent(in) :: s0(2), de(2)
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: sigma(2), tangent(2, 2)
      integer, intent(out) :: mode
      real(wp) :: trial(2), f, s, dl, d
      associate (kn => this%kn, kt => this%kt, mu_f => this%mu_f, mu_g => this%mu_g)
         trial = s0 + [kn*de(1), kt*de(2)]
         f = abs(trial(2)) - trial(1)*mu_f - this%c
         if (f <= 0.0_wp) then
            dl = 0.0_wp
            s = 0.0_wp
            sigma = trial
            tangent = reshape([kn, 0.0_wp, 0.0_wp, kt], [2, 2])
            mode = MODE_STICK
         else
            s = sign(1.0_wp, trial(2))
            d = kt + kn*mu_g*mu_f
            dl = f/d
            sigma = [trial(1) + kn*mu_g*dl, s*(abs(trial(2)) - kt*dl)]
            tangent(1, 1) = kn - kn*kn*mu_g*mu_f/d
            tangent(1, 2) = s*kn*kt*mu_g/d
            tangent(2, 1) = s*kn*kt*mu_f/d
            tangent(2, 2) = kt - kt*kt/d + this%kt_slip
            mode = MODE_SLIP
         end if
      end associate
      if (sigma(1) < -this%tensile_limit(state)) then
         state(ST_OPEN) = 1.0_wp
         state(ST_BROKEN) = 1.0_wp
         state(ST_GAP) = -sigma(1)/this%kn
         sigma = 0.0_wp
         tangent = 0.0_wp
         mode = MODE_OPEN
         return
      end if
      state(ST_SLIP) = state(ST_SLIP) + dl
      state(ST_EPS_NP) = state(ST_EPS_NP) - this%mu_g*dl
      state(ST_EPS_TP) = state(ST_EPS_TP) + s*dl
   end subroutine contact_step

   subroutine coulomb_reduced_strength(this, msf, reduced)
      class(coulomb_law_t), intent(in) :: this
      real(wp), intent(in) :: msf
      class(interface_law_t), allocatable, intent(out) :: reduced
      allocate (reduced, source=this)
      select type (r => reduced)
      class is (coulomb_law_t)
         r%c = this%c/msf
         r%mu_f = this%mu_f/msf
         r%mu_g = min(this%mu_g, r%mu_f)
      end select
   end subroutine coulomb_reduced_strength

end module pecplas_joints_laws_coulomb
