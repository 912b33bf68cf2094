!> Pure numerical kernel of the MODJOIN interface law (thesis chapter III; doc/theory.md §6.4):
!> the hardening function, the elastic relations and one backward-Euler substep with its
!> full Jacobian (the law module pecplas_joints_laws_modjoin chains substeps and mechanisms).
!>
!> Hardening (III.16; III.5 is alpha = 1, A = 0), with betap = beta sigma_n0 / P_a:
!>     R(k) = alpha k / (betap + k) + A k^2 exp(-B k)
!> Elasticity (III.15, or constant K0, G0 for the initial version), floored at SIGMA_MIN so
!> that a point with no compression keeps a stiffness:
!>     K(s) = K0 sqrt(max(s, s_min)/P_a),   G(s) = G0 sqrt(max(s, s_min)/P_a)
!> The normal part is integrated exactly through the compliance potential Psi (dPsi/ds = 1/K):
!> Psi(s_n) - Psi(s_n,old) = d eps_n^e. The tangential part uses the mean of G at both ends,
!> exact on a proportional elastic step (sqrt(s_n) is then linear along the step).
!>
!> One plastic substep (backward Euler), unknowns x = (s_n, tau, dlambda), kappa = kappa_old +
!> dlambda the hardening variable of the active mechanism, s = +-1 the flow direction:
!>     r1 = Psi(s_n) - Psi(s_n,old) - d eps_n + dlambda m_n(s_n, tau, kappa)
!>     r2 = tau - tau_old - Gbar (d eps_t - dlambda s)
!>     r3 = s tau - M_f (s_n + C) (shift + factor R(kappa))
!> with m_n = (M_g - |tau|/max(s_n, s_min)) exp(-a_g (kappa - k_ref)) (III.9–III.11; k_ref =
!> the start of kappa, so A_g = 1 when the mechanism starts to flow). The primary
!> surface (III.4) is shift = 0, factor = 1; the active side of the kinematic surface
!> (III.22–III.24 as corrected in doc/theory.md) is shift = s R_i, factor = 2.
module pecplas_joints_laws_modjoin_kernel
   use pecplas_base_kinds, only: wp
   use pecplas_base_matrix3, only: inverse3
   implicit none (type, external)
   private

   public :: mj_elastic_t, mj_mech_t
   public :: mj_hardening, mj_hardening_slope, mj_initial_k
   public :: mj_psi, mj_kmod, mj_gmod, mj_elastic_step, mj_plastic_step

   !> Elastic constants (model units).
   type :: mj_elastic_t
      !> .true.: (III.15) K, G proportional to sqrt(sigma_n / P_a); .false.: K0, G0.
      logical :: nonlinear = .false.
      real(wp) :: k0 = 0.0_wp, g0 = 0.0_wp, pa = 100.0_wp, smin = 1.0_wp
   end type mj_elastic_t

   !> One mechanism as seen by a substep.
   type :: mj_mech_t
      !> M_f = tan(phi), C = c cot(phi), M_g = tan(psi), a_g.
      real(wp) :: mu_f = 0.0_wp, cc = 0.0_wp, mu_g = 0.0_wp, a_g = 0.0_wp
      !> Hardening: beta sigma_n0 / P_a (or beta_c ...), alpha, A, B.
      real(wp) :: betap = 1.0_wp, alpha = 1.0_wp, a = 0.0_wp, b = 0.0_wp
      !> Flow direction s and surface R_tot = shift + factor R(kappa).
      real(wp) :: s = 1.0_wp, shift = 0.0_wp, factor = 1.0_wp
      !> Start of the mechanism's hardening variable (k0, or kappa_c0 at the last reversal):
      !> the flow damping A_g = exp(-a_g (kappa - k_ref)) counts the plastic slip produced.
      real(wp) :: k_ref = 0.0_wp
   end type mj_mech_t

   integer, parameter :: MAX_ITER = 40
   real(wp), parameter :: RTOL = 1.0e-13_wp

contains

   !> R(k) of (III.16).
   pure real(wp) function mj_hardening(k, betap, alpha, a, b) result(r)
      real(wp), intent(in) :: k, betap, alpha, a, b
      r = alpha*k/(betap + k)
      if (a /= 0.0_wp) r = r + a*k*k*exp(-b*k)
   end function mj_hardening

   !> dR/dk of (III.16).
   pure real(wp) function mj_hardening_slope(k, betap, alpha, a, b) result(dr)
      real(wp), intent(in) :: k, betap, alpha, a, b
      dr = alpha*betap/(betap + k)**2
      if (a /= 0.0_wp) dr = dr + a*k*(2.0_wp - b*k)*exp(-b*k)
   end function mj_hardening_slope

   !> The k0 with R(k0) = r0 on the rising branch ((III.6) in closed form when A = 0);
   !> needs 0 < r0 < alpha. Safeguarded Newton in [0, r0 betap/(alpha - r0)], where the
   !> hyperbolic term alone reaches r0 (A >= 0 so R is above it).
   pure real(wp) function mj_initial_k(r0, betap, alpha, a, b) result(k)
      real(wp), intent(in) :: r0, betap, alpha, a, b
      real(wp) :: lo, hi, f, df
      integer :: it
      k = r0*betap/(alpha - r0)
      if (a == 0.0_wp) return
      lo = 0.0_wp
      hi = k
      do it = 1, 200
         f = mj_hardening(k, betap, alpha, a, b) - r0
         if (abs(f) <= 1.0e-15_wp*r0) exit
         if (f > 0.0_wp) then
            hi = k
         else
            lo = k
         end if
         df = mj_hardening_slope(k, betap, alpha, a, b)
         k = k - f/df
         if (.not. (k > lo .and. k < hi)) k = 0.5_wp*(lo + hi)
      end do
   end function mj_initial_k

   !> Compliance potential Psi(s), dPsi/ds = 1/K(s).
   pure real(wp) function mj_psi(el, s) result(p)
      type(mj_elastic_t), intent(in) :: el
      real(wp), intent(in) :: s
      if (.not. el%nonlinear) then
         p = s/el%k0
      else if (s >= el%smin) then
         p = 2.0_wp*sqrt(el%pa*s)/el%k0
      else
         p = 2.0_wp*sqrt(el%pa*el%smin)/el%k0 + (s - el%smin)/mj_kmod(el, el%smin)
      end if
   end function mj_psi

   !> Inverse of Psi.
   pure real(wp) function psi_inverse(el, p) result(s)
      type(mj_elastic_t), intent(in) :: el
      real(wp), intent(in) :: p
      real(wp) :: pmin
      if (.not. el%nonlinear) then
         s = p*el%k0
         return
      end if
      pmin = 2.0_wp*sqrt(el%pa*el%smin)/el%k0
      if (p >= pmin) then
         s = (el%k0*p)**2/(4.0_wp*el%pa)
      else
         s = el%smin + (p - pmin)*mj_kmod(el, el%smin)
      end if
   end function psi_inverse

   !> Normal stiffness K(s).
   pure real(wp) function mj_kmod(el, s) result(k)
      type(mj_elastic_t), intent(in) :: el
      real(wp), intent(in) :: s
      k = el%k0
      if (el%nonlinear) k = el%k0*sqrt(max(s, el%smin)/el%pa)
   end function mj_kmod

   !> Tangential stiffness G(s).
   pure real(wp) function mj_gmod(el, s) result(g)
      type(mj_elastic_t), intent(in) :: el
      real(wp), intent(in) :: s
      g = el%g0
      if (el%nonlinear) g = el%g0*sqrt(max(s, el%smin)/el%pa)
   end function mj_gmod

   !> dG/ds.
   pure real(wp) function gslope(el, s) result(dg)
      type(mj_elastic_t), intent(in) :: el
      real(wp), intent(in) :: s
      dg = 0.0_wp
      if (el%nonlinear .and. s > el%smin) dg = 0.5_wp*mj_gmod(el, s)/s
   end function gslope

   !> Elastic step from so = (s_n, tau) by de = (d eps_n, d eps_t); jac(3, 5) =
   !> d(s_n, tau, kappa)/d(s_n,old, tau_old, kappa_old, d eps_n, d eps_t).
   pure subroutine mj_elastic_step(el, so, de, s, jac)
      type(mj_elastic_t), intent(in) :: el
      real(wp), intent(in) :: so(2), de(2)
      real(wp), intent(out) :: s(2), jac(3, 5)
      real(wp) :: kn, ko, dsn_dso
      s(1) = psi_inverse(el, mj_psi(el, so(1)) + de(1))
      s(2) = so(2) + 0.5_wp*(mj_gmod(el, so(1)) + mj_gmod(el, s(1)))*de(2)
      jac = 0.0_wp
      jac(3, 3) = 1.0_wp
      jac(2, 2) = 1.0_wp
      if (.not. el%nonlinear) then
         jac(1, 1) = 1.0_wp
         jac(1, 4) = el%k0
         jac(2, 5) = el%g0
         return
      end if
      kn = mj_kmod(el, s(1))
      ko = mj_kmod(el, so(1))
      dsn_dso = kn/ko
      jac(1, 1) = dsn_dso
      jac(1, 4) = kn
      jac(2, 1) = 0.5_wp*de(2)*(gslope(el, so(1)) + gslope(el, s(1))*dsn_dso)
      jac(2, 4) = 0.5_wp*de(2)*gslope(el, s(1))*kn
      jac(2, 5) = 0.5_wp*(mj_gmod(el, so(1)) + mj_gmod(el, s(1)))
   end subroutine mj_elastic_step

   !> Backward-Euler plastic substep of mechanism `mc` (module header) from so, kappa_o,
   !> starting at the elastic trial `trial`. Returns the stress s, kappa, dlambda, the plastic
   !> normal direction m_n and jac(3, 5) as mj_elastic_step. ok = .false. when Newton fails
   !> or the result leaves the admissible range (s_n + C <= 0, dlambda < 0).
   pure subroutine mj_plastic_step(el, mc, so, kappa_o, de, trial, s, kappa, dlam, mn, jac, ok)
      type(mj_elastic_t), intent(in) :: el
      type(mj_mech_t), intent(in) :: mc
      real(wp), intent(in) :: so(2), kappa_o, de(2), trial(2)
      real(wp), intent(out) :: s(2), kappa, dlam, mn, jac(3, 5)
      logical, intent(out) :: ok
      real(wp) :: x(3), r(3), jm(3, 3), ji(3, 3), p(3, 5), dx(3)
      real(wp) :: ag, sh, ratio, dm_ds, dm_dt, dm_dk, rk, drk, gbar, kn, sref, det, base
      integer :: it
      x = [trial(1), trial(2), 0.0_wp]
      ok = .false.
      sref = max(abs(so(1)), abs(so(2)), abs(trial(1)), abs(trial(2)), el%smin)
      do it = 1, MAX_ITER
         kappa = kappa_o + x(3)
         ag = exp(-mc%a_g*(kappa - mc%k_ref))
         sh = max(x(1), el%smin)
         ratio = abs(x(2))/sh
         mn = (mc%mu_g - ratio)*ag
         dm_ds = 0.0_wp
         if (x(1) > el%smin) dm_ds = ratio/sh*ag
         dm_dt = -sign(1.0_wp, x(2))/sh*ag
         dm_dk = -mc%a_g*mn
         rk = mc%shift + mc%factor*mj_hardening(kappa, mc%betap, mc%alpha, mc%a, mc%b)
         drk = mc%factor*mj_hardening_slope(kappa, mc%betap, mc%alpha, mc%a, mc%b)
         gbar = 0.5_wp*(mj_gmod(el, so(1)) + mj_gmod(el, x(1)))
         kn = mj_kmod(el, x(1))
         base = de(2) - x(3)*mc%s
         r(1) = mj_psi(el, x(1)) - mj_psi(el, so(1)) - de(1) + x(3)*mn
         r(2) = x(2) - so(2) - gbar*base
         r(3) = mc%s*x(2) - mc%mu_f*(x(1) + mc%cc)*rk
         jm(1, :) = [1.0_wp/kn + x(3)*dm_ds, x(3)*dm_dt, mn + x(3)*dm_dk]
         jm(2, :) = [-0.5_wp*gslope(el, x(1))*base, 1.0_wp, gbar*mc%s]
         jm(3, :) = [-mc%mu_f*rk, mc%s, -mc%mu_f*(x(1) + mc%cc)*drk]
         if (abs(r(1))*kn + abs(r(2)) + abs(r(3)) <= RTOL*sref) then
            ok = .true.
            exit
         end if
         call inverse3(jm, ji, det)
         if (det == 0.0_wp) return
         dx = -matmul(ji, r)
         x = x + dx
         ! keep the normal stress in the range where the law is defined while iterating
         if (x(1) <= -mc%cc) x(1) = 0.5_wp*(x(1) - dx(1) - mc%cc)
      end do
      if (.not. ok) return
      call inverse3(jm, ji, det)
      if (det == 0.0_wp .or. x(3) < 0.0_wp .or. x(1) + mc%cc <= 0.0_wp) then
         ok = .false.
         return
      end if
      s = x(1:2)
      dlam = x(3)
      kappa = kappa_o + dlam
      ! implicit function theorem: dx/dp = -J^-1 dr/dp, p = (s_n,o, tau_o, kappa_o, de_n, de_t)
      p = 0.0_wp
      p(1, 1) = -1.0_wp/mj_kmod(el, so(1))
      p(1, 3) = dlam*dm_dk
      p(1, 4) = -1.0_wp
      p(2, 1) = -0.5_wp*gslope(el, so(1))*(de(2) - dlam*mc%s)
      p(2, 2) = -1.0_wp
      p(2, 5) = -gbar
      p(3, 3) = -mc%mu_f*(s(1) + mc%cc)*drk
      jac = -matmul(ji, p)
      jac(3, 3) = jac(3, 3) + 1.0_wp
   end subroutine mj_plastic_step

end module pecplas_joints_laws_modjoin_kernel
