!> One MODJOIN increment (pecplas_joints_laws_modjoin; doc/theory.md §6.4): the parameters in model
!> units, the history layout, and the integration of an increment from a converged state.
!>
!> An increment is split into n = ceil(max|d eps| / SUBSTEP) equal substeps, each a
!> backward-Euler step (pecplas_joints_laws_modjoin_kernel) with a local Newton on the consistency
!> condition; the tangent is the exact derivative of this composition (chain rule through the
!> substeps), so it is consistent with the update wherever n and the mechanism sequence do not
!> switch. A wholly elastic increment is one exact step.
!>
!> Cyclic memory (the algorithmic reading of III.22–III.25):
!> - a reversal is registered at the start of an increment whose d eps_t opposes the
!>   direction of the last plastic flow (state LOAD): R_i = tau/((sigma_n + C) M_f), n_c =
!>   LOAD, beta_c = beta (1 - eps_bar/(b + eps_bar)) with eps_bar the accumulated plastic slip,
!>   kappa_c restarts where R_c = R0; the mechanism that was active is kept one level deep;
!> - the kinematic surface yields on its active side (flow s = -n_c); reloading through its
!>   passive side (the reversal point) restores the mechanism kept before the reversal;
!> - reaching the primary surface f_m resumes the primary mechanism (memory erased).
!> Opening: no tensile strength. When sigma_n would become negative the point separates
!> (sigma = 0, tangent = 0, mode open), as the Coulomb laws with TENSION = 0, and the cyclic
!> memory is cleared; the hardening variables are kept.
module pecplas_joints_laws_modjoin_step
   use pecplas_base_kinds, only: wp
   use pecplas_joints_laws_type, only: MODE_STICK, MODE_SLIP, MODE_OPEN
   use pecplas_joints_laws_modjoin_kernel, only: mj_elastic_t, mj_mech_t, mj_hardening, &
      mj_initial_k, mj_psi, mj_elastic_step, mj_plastic_step
   implicit none (type, external)
   private

   public :: mj_params_t, mj_integrate, mj_betap, mj_k0
   public :: MJ_INITIAL, MJ_IMPROVED, MJ_CYCLIC, MJ_VERSION_NAMES
   public :: MJ_SLIP, MJ_OPEN, MJ_GAP, MJ_EPS_NP, MJ_EPS_TP, MJ_SIGN0, MJ_K, MJ_SIGN, MJ_LOAD, &
      MJ_MECH, MJ_KC, MJ_RI, MJ_NC, MJ_BETAC, MJ_PREV, NSTATE_MJ, NSTATE_MJ_CYCLIC, MJ_STATE_NAMES

   integer, parameter :: MJ_INITIAL = 1, MJ_IMPROVED = 2, MJ_CYCLIC = 3
   !> Substeps of one increment beyond which it is refused (the caller cuts it).
   integer, parameter :: MAX_SUBSTEPS = 100000
   character(len=*), parameter :: MJ_VERSION_NAMES(3) = [character(len=15) :: &
      'MODJOIN_INITIAL', 'MODJOIN', 'MODJOIN_CYCLIC']

   !> History: accumulated plastic slip (= eps_bar), open flag, opening, plastic normal and
   !> signed tangential displacements, sigma_n0, primary hardening variable k (from k0),
   !> current sigma_n (for the elastic tangent), direction of the last plastic flow (+-1, 0);
   !> cyclic: active mechanism (0 primary, 1 kinematic), kappa_c, R_i, n_c, beta_c, and the
   !> same five for the mechanism kept one level deep.
   integer, parameter :: MJ_SLIP = 1, MJ_OPEN = 2, MJ_GAP = 3, MJ_EPS_NP = 4, MJ_EPS_TP = 5, &
      MJ_SIGN0 = 6, MJ_K = 7, MJ_SIGN = 8, MJ_LOAD = 9, NSTATE_MJ = 9
   integer, parameter :: MJ_MECH = 10, MJ_KC = 11, MJ_RI = 12, MJ_NC = 13, MJ_BETAC = 14, &
      MJ_PREV = 5, NSTATE_MJ_CYCLIC = 19
   character(len=*), parameter :: MJ_STATE_NAMES(NSTATE_MJ_CYCLIC) = [character(len=16) :: &
      'plastic_slip', 'open', 'gap', 'eps_n_p', 'eps_t_p', 'sigma_n0', 'k', 'sigma_n', &
      'load_dir', 'mechanism', 'k_c', 'r_i', 'n_c', 'beta_c', 'prev_mechanism', 'prev_k_c', &
      'prev_r_i', 'prev_n_c', 'prev_beta_c']

   !> The parameters of a MODJOIN law, in model units.
   type :: mj_params_t
      integer :: version = MJ_IMPROVED
      type(mj_elastic_t) :: el
      !> M_f = tan(phi), C = c cot(phi), M_g = tan(psi), a_g.
      real(wp) :: mu_f = 0.0_wp, cc = 0.0_wp, mu_g = 0.0_wp, a_g = 0.0_wp
      !> R0, beta, alpha, A, B of (III.16); b of (III.25).
      real(wp) :: r0 = 0.0_wp, beta = 0.0_wp, alpha = 1.0_wp, a = 0.0_wp, b = 0.0_wp
      real(wp) :: b_cyc = 0.0_wp
      !> Largest substep of relative displacement.
      real(wp) :: substep = 1.0e-3_wp
   end type mj_params_t

contains

   !> beta sigma_n0 / P_a for a beta and the sigma_n0 of a point (floored at SIGMA_MIN).
   pure real(wp) function mj_betap(this, beta, sigma_n0) result(bp)
      type(mj_params_t), intent(in) :: this
      real(wp), intent(in) :: beta, sigma_n0
      bp = beta*max(sigma_n0, this%el%smin)/this%el%pa
   end function mj_betap

   !> k0 of a point of initial normal stress sigma_n0: R_m(k0) = R0 ((III.6) when A = 0).
   pure real(wp) function mj_k0(this, sigma_n0) result(k0)
      type(mj_params_t), intent(in) :: this
      real(wp), intent(in) :: sigma_n0
      k0 = mj_initial_k(this%r0, mj_betap(this, this%beta, sigma_n0), this%alpha, this%a, &
         this%b)
   end function mj_k0

   !> One increment from the converged (s0, state): reversal (cyclic version), fast elastic
   !> path, then substeps (refined on failure). ok = .false.: the local return failed.
   subroutine mj_integrate(this, s0, de, state, sigma, tangent, mode, ok)
      type(mj_params_t), intent(in) :: this
      real(wp), intent(in) :: s0(2), de(2)
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: sigma(2), tangent(2, 2)
      integer, intent(out) :: mode
      logical, intent(out) :: ok
      real(wp) :: saved(size(state)), trial(2), jac(3, 5)
      integer :: n, attempt
      if (this%version == MJ_CYCLIC) then
         if (state(MJ_LOAD) /= 0.0_wp .and. de(2)*state(MJ_LOAD) < 0.0_wp) &
            call register_reversal(this, s0, state)
      end if
      call mj_elastic_step(this%el, s0, de, trial, jac)
      if (trial(1) >= 0.0_wp) then
         if (elastic_inside(this, trial, state)) then
            sigma = trial
            tangent = jac(1:2, 4:5)
            mode = MODE_STICK
            ok = .true.
            return
         end if
      end if
      saved = state
      ! an increment of more than MAX_SUBSTEPS substeps (100 mm at the default 0.001 mm) is
      ! refused at once: the caller cuts it, instead of integrating for hours
      ok = .false.
      sigma = s0
      tangent = jac(1:2, 4:5)
      mode = MODE_STICK
      if (.not. (maxval(abs(de))/this%substep <= real(MAX_SUBSTEPS, wp))) return
      ! the slack keeps n the same when the units are scaled (0.02/0.001 vs 2e-5/1e-6)
      n = max(1, ceiling(maxval(abs(de))/this%substep*(1.0_wp - 1.0e-10_wp)))
      do attempt = 1, 4
         call substeps(this, s0, de, n, state, sigma, tangent, mode, ok)
         if (ok) return
         state = saved
         n = min(8*n, 80000000)
      end do
   end subroutine mj_integrate

   !> True when the stress is inside every active surface (no yield, no passive crossing).
   logical function elastic_inside(this, s, state) result(inside)
      type(mj_params_t), intent(in) :: this
      real(wp), intent(in) :: s(2)
      real(wp), intent(in) :: state(:)
      inside = primary_f(this, s, state(MJ_SIGN0), state(MJ_K)) <= 0.0_wp
      if (.not. inside .or. this%version /= MJ_CYCLIC) return
      if (state(MJ_MECH) > 0.5_wp) inside = kinematic_f(this, s, state) <= 0.0_wp
   end function elastic_inside

   !> f_m = |tau| - M_f (sigma_n + C) R_m(k) (III.4).
   pure real(wp) function primary_f(this, s, sigma_n0, k) result(f)
      type(mj_params_t), intent(in) :: this
      real(wp), intent(in) :: s(2), sigma_n0, k
      f = abs(s(2)) - this%mu_f*(s(1) + this%cc)* &
         mj_hardening(k, mj_betap(this, this%beta, sigma_n0), this%alpha, this%a, this%b)
   end function primary_f

   !> f_c = |tau - T_c| - (sigma_n + C) M_f R_c, T_c = (R_i - n_c R_c)(sigma_n + C) M_f
   !> (III.22 corrected, III.24); `side` = sign(tau - T_c).
   real(wp) function kinematic_f(this, s, state, side) result(f)
      type(mj_params_t), intent(in) :: this
      real(wp), intent(in) :: s(2), state(:)
      real(wp), intent(out), optional :: side
      real(wp) :: rc, sm, tc
      rc = mj_hardening(state(MJ_KC), mj_betap(this, state(MJ_BETAC), state(MJ_SIGN0)), &
         this%alpha, this%a, this%b)
      sm = this%mu_f*(s(1) + this%cc)
      tc = (state(MJ_RI) - state(MJ_NC)*rc)*sm
      f = abs(s(2) - tc) - sm*rc
      if (present(side)) side = sign(1.0_wp, s(2) - tc)
   end function kinematic_f

   !> New kinematic surface through the stress s0 (module header); the active mechanism is
   !> kept one level deep.
   subroutine register_reversal(this, s0, state)
      type(mj_params_t), intent(in) :: this
      real(wp), intent(in) :: s0(2)
      real(wp), intent(inout) :: state(:)
      real(wp) :: sm, ebar
      state(MJ_MECH + MJ_PREV:MJ_BETAC + MJ_PREV) = state(MJ_MECH:MJ_BETAC)
      sm = this%mu_f*(s0(1) + this%cc)
      state(MJ_RI) = 0.0_wp
      if (sm > 0.0_wp) state(MJ_RI) = s0(2)/sm
      state(MJ_NC) = state(MJ_LOAD)
      ebar = state(MJ_SLIP)
      state(MJ_BETAC) = this%beta*(1.0_wp - ebar/(this%b_cyc + ebar))
      state(MJ_KC) = mj_initial_k(this%r0, mj_betap(this, state(MJ_BETAC), state(MJ_SIGN0)), &
         this%alpha, this%a, this%b)
      state(MJ_MECH) = 1.0_wp
      state(MJ_LOAD) = 0.0_wp
   end subroutine register_reversal

   !> n equal substeps from s0; d = d(sigma_n, tau, k, kappa_c)/d(deps) chained through them.
   !> ok = .false. when a local return failed (the caller refines).
   subroutine substeps(this, s0, de, n, state, sigma, tangent, mode, ok)
      type(mj_params_t), intent(in) :: this
      real(wp), intent(in) :: s0(2), de(2)
      integer, intent(in) :: n
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: sigma(2), tangent(2, 2)
      integer, intent(out) :: mode
      logical, intent(out) :: ok
      real(wp) :: y(4), d(4, 2), dnew(4, 2), des(2), trial(2), jac(3, 5), snew(2)
      real(wp) :: kappa, dlam, mn, side
      type(mj_mech_t) :: mc
      integer :: j, ik, pass
      logical :: plastic, any_plastic
      ok = .true.
      any_plastic = .false.
      des = de/real(n, wp)
      y = [s0(1), s0(2), state(MJ_K), 0.0_wp]
      if (this%version == MJ_CYCLIC) y(4) = state(MJ_KC)
      d = 0.0_wp
      do j = 1, n
         call mj_elastic_step(this%el, y(1:2), des, trial, jac)
         if (trial(1) < 0.0_wp) then
            call open_point(this, y(1), des(1)*real(n - j + 1, wp), state, sigma, tangent, mode)
            return
         end if
         ik = 3
         plastic = .false.
         do pass = 1, 3
            if (primary_f(this, trial, state(MJ_SIGN0), y(3)) > 0.0_wp) then
               if (this%version == MJ_CYCLIC) state(MJ_MECH) = 0.0_wp
               mc = mechanism(this, state, 0, sign(1.0_wp, trial(2)))
               plastic = .true.
               exit
            end if
            if (this%version /= MJ_CYCLIC) exit
            if (state(MJ_MECH) < 0.5_wp) exit
            state(MJ_KC) = y(4)
            if (kinematic_f(this, trial, state, side) <= 0.0_wp) exit
            if (side == -state(MJ_NC)) then
               mc = mechanism(this, state, 1, side)
               ik = 4
               plastic = .true.
               exit
            end if
            ! through the reversal point: back to the mechanism kept before the reversal
            state(MJ_MECH:MJ_BETAC) = state(MJ_MECH + MJ_PREV:MJ_BETAC + MJ_PREV)
            state(MJ_MECH + MJ_PREV) = 0.0_wp
            y(4) = state(MJ_KC)
            d(4, :) = 0.0_wp
         end do
         if (.not. plastic) then
            y(1:2) = trial
            call chain(d, jac, 3, n, dnew)
            d = dnew
            cycle
         end if
         call mj_plastic_step(this%el, mc, y(1:2), y(ik), des, trial, snew, kappa, dlam, mn, &
            jac, ok)
         if (.not. ok) then
            ! contraction at a vanishing normal stress (|tau|/sigma_n -> infinity in m_n):
            ! no return with sigma_n > 0 exists, the point loses contact (S6 near the surface)
            if (y(1) <= 2.0_wp*this%el%smin) then
               call open_point(this, y(1), des(1)*real(n - j + 1, wp), state, sigma, tangent, &
                  mode)
               ok = .true.
            end if
            return
         end if
         if (snew(1) < 0.0_wp) then
            call open_point(this, snew(1), des(1)*real(n - j, wp), state, sigma, tangent, mode)
            return
         end if
         call chain(d, jac, ik, n, dnew)
         d = dnew
         y(1:2) = snew
         y(ik) = kappa
         any_plastic = .true.
         state(MJ_SLIP) = state(MJ_SLIP) + dlam
         state(MJ_EPS_TP) = state(MJ_EPS_TP) + mc%s*dlam
         state(MJ_EPS_NP) = state(MJ_EPS_NP) + mn*dlam
         if (dlam > 0.0_wp) state(MJ_LOAD) = mc%s
      end do
      state(MJ_K) = y(3)
      if (this%version == MJ_CYCLIC) state(MJ_KC) = y(4)
      sigma = y(1:2)
      tangent = d(1:2, :)
      mode = MODE_STICK
      if (any_plastic) mode = MODE_SLIP
   end subroutine substeps

   !> Mechanism data for a substep: 0 primary (III.4, III.16), 1 kinematic (III.22–III.24).
   pure function mechanism(this, state, kind, s) result(mc)
      type(mj_params_t), intent(in) :: this
      real(wp), intent(in) :: state(:), s
      integer, intent(in) :: kind
      type(mj_mech_t) :: mc
      mc%mu_f = this%mu_f
      mc%cc = this%cc
      mc%mu_g = this%mu_g
      mc%a_g = this%a_g
      mc%alpha = this%alpha
      mc%a = this%a
      mc%b = this%b
      mc%s = s
      if (kind == 0) then
         mc%betap = mj_betap(this, this%beta, state(MJ_SIGN0))
         mc%shift = 0.0_wp
         mc%factor = 1.0_wp
      else
         mc%betap = mj_betap(this, state(MJ_BETAC), state(MJ_SIGN0))
         mc%shift = s*state(MJ_RI)
         mc%factor = 2.0_wp
      end if
      ! A_g counts the plastic slip of this mechanism (kappa - kappa at its start), so the
      ! flow starts undamped whatever sigma_n0: the contraction then grows with sigma_n0 as
      ! the thesis reports (fig. III.9b, III.11b; doc/theory.md §6.4)
      mc%k_ref = mj_initial_k(this%r0, mc%betap, this%alpha, this%a, this%b)
   end function mechanism

   !> d <- A d + B / n for a substep Jacobian jac(3, 5) whose hardening variable is y(ik).
   pure subroutine chain(d, jac, ik, n, dnew)
      real(wp), intent(in) :: d(4, 2), jac(3, 5)
      integer, intent(in) :: ik, n
      real(wp), intent(out) :: dnew(4, 2)
      integer :: r, ir
      dnew = d
      do r = 1, 3
         ir = r
         if (r == 3) ir = ik
         dnew(ir, :) = jac(r, 1)*d(1, :) + jac(r, 2)*d(2, :) + jac(r, 3)*d(ik, :) + &
            jac(r, 4:5)/real(n, wp)
      end do
   end subroutine chain

   !> Separation from normal stress s_n with the closure `rest` still to come (negative):
   !> the opening is what the elastic relation gives beyond zero stress.
   subroutine open_point(this, s_n, rest, state, sigma, tangent, mode)
      type(mj_params_t), intent(in) :: this
      real(wp), intent(in) :: s_n, rest
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: sigma(2), tangent(2, 2)
      integer, intent(out) :: mode
      state(MJ_OPEN) = 1.0_wp
      state(MJ_GAP) = max(mj_psi(this%el, 0.0_wp) - mj_psi(this%el, s_n) - rest, 0.0_wp)
      state(MJ_LOAD) = 0.0_wp
      if (this%version == MJ_CYCLIC) then
         state(MJ_MECH) = 0.0_wp
         state(MJ_MECH + MJ_PREV) = 0.0_wp
      end if
      sigma = 0.0_wp
      tangent = 0.0_wp
      mode = MODE_OPEN
   end subroutine open_point

end module pecplas_joints_laws_modjoin_step
