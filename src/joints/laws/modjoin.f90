!> MODJOIN, the interface law of thesis chapter III (doc/theory.md §6.4), in its three versions:
!> initial (III.4–III.11, linear elasticity, hardening III.5), improved (III.15 elasticity,
!> hardening with peak and softening III.16) and cyclic (kinematic hardening with discrete
!> memory, III.22–III.25 as corrected in doc/theory.md). Theory, corrections and the algorithm:
!> doc/theory.md §6.4. The parameters (`p`, model units: the builders of
!> pecplas_joints_laws_modjoin_build convert once at input), the history layout and the
!> integration are in pecplas_joints_laws_modjoin_step; this module binds them to interface_law_t.
module pecplas_joints_laws_modjoin
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, run_error
   use pecplas_joints_laws_type, only: interface_law_t, MODE_OPEN
   use pecplas_joints_laws_modjoin_kernel, only: mj_kmod, mj_gmod
   use pecplas_joints_laws_modjoin_step, only: mj_params_t, mj_integrate, mj_betap, mj_k0, MJ_CYCLIC, &
      MJ_SLIP, MJ_OPEN, MJ_GAP, MJ_SIGN0, MJ_K, MJ_SIGN, MJ_BETAC, MJ_PREV, NSTATE_MJ, &
      NSTATE_MJ_CYCLIC, MJ_STATE_NAMES
   implicit none (type, external)
   private

   public :: modjoin_law_t

   type, extends(interface_law_t) :: modjoin_law_t
      !> Parameters in model units.
      type(mj_params_t) :: p
      !> The line printed by the programs (values as given and as converted).
      character(len=:), allocatable :: summary
   contains
      procedure :: nstate => mj_nstate
      procedure :: init_state => mj_init_state
      procedure :: elastic_tangent => mj_elastic_tangent
      procedure :: update => mj_update
      procedure :: symmetric_tangent => mj_symmetric_tangent
      procedure :: strain_refusal => mj_strain_refusal
      procedure :: plastic_slip => mj_plastic_slip
      procedure :: state_names => mj_history_names
      procedure :: describe => mj_describe
      !> beta sigma_n0 / P_a for a beta and the sigma_n0 of a point (floored at SIGMA_MIN).
      procedure :: betap => mj_law_betap
      !> k0 of a point of initial normal stress sigma_n0: R_m(k0) = R0 ((III.6) when A = 0).
      procedure :: initial_k => mj_initial_k_of
   end type modjoin_law_t

contains

   pure integer function mj_nstate(this) result(n)
      class(modjoin_law_t), intent(in) :: this
      n = NSTATE_MJ
      if (this%p%version == MJ_CYCLIC) n = NSTATE_MJ_CYCLIC
   end function mj_nstate

   pure real(wp) function mj_law_betap(this, beta, sigma_n0) result(bp)
      class(modjoin_law_t), intent(in) :: this
      real(wp), intent(in) :: beta, sigma_n0
      bp = mj_betap(this%p, beta, sigma_n0)
   end function mj_law_betap

   pure real(wp) function mj_initial_k_of(this, sigma_n0) result(k0)
      class(modjoin_law_t), intent(in) :: this
      real(wp), intent(in) :: sigma_n0
      k0 = mj_k0(this%p, sigma_n0)
   end function mj_initial_k_of

   !> sigma_n0 = the initial normal stress of the point; k = k0; primary mechanism.
   subroutine mj_init_state(this, sigma0, state)
      class(modjoin_law_t), intent(in) :: this
      real(wp), intent(in) :: sigma0(2)
      real(wp), intent(out) :: state(:)
      state = 0.0_wp
      state(MJ_SIGN0) = sigma0(1)
      state(MJ_SIGN) = sigma0(1)
      state(MJ_K) = this%initial_k(sigma0(1))
      if (this%p%version == MJ_CYCLIC) then
         state(MJ_BETAC) = this%p%beta
         state(MJ_BETAC + MJ_PREV) = this%p%beta
      end if
   end subroutine mj_init_state

   !> K(sigma_n), G(sigma_n) at the converged normal stress.
   subroutine mj_elastic_tangent(this, state, tangent)
      class(modjoin_law_t), intent(in) :: this
      real(wp), intent(in) :: state(:)
      real(wp), intent(out) :: tangent(2, 2)
      tangent = 0.0_wp
      tangent(1, 1) = mj_kmod(this%p%el, state(MJ_SIGN))
      tangent(2, 2) = mj_gmod(this%p%el, state(MJ_SIGN))
   end subroutine mj_elastic_tangent

   pure logical function mj_symmetric_tangent(this) result(sym)
      class(modjoin_law_t), intent(in) :: this
      sym = .false.
   end function mj_symmetric_tangent

   !> A thin layer's strains (jump / thickness) have no consistent reading for MODJOIN.
   pure function mj_strain_refusal(this) result(why)
      class(modjoin_law_t), intent(in) :: this
      character(len=:), allocatable :: why
      why = 'MODJOIN works on displacement jumps: K0, G0, BETA, A, B, A_G, B_CYC are per '// &
         'length of relative displacement'
   end function mj_strain_refusal

   pure real(wp) function mj_plastic_slip(this, state) result(slip)
      class(modjoin_law_t), intent(in) :: this
      real(wp), intent(in) :: state(:)
      slip = state(MJ_SLIP)
   end function mj_plastic_slip

   pure subroutine mj_history_names(this, names)
      class(modjoin_law_t), intent(in) :: this
      character(len=16), allocatable, intent(out) :: names(:)
      allocate (names(this%nstate()))
      names = MJ_STATE_NAMES(1:this%nstate())
   end subroutine mj_history_names

   function mj_describe(this) result(text)
      class(modjoin_law_t), intent(in) :: this
      character(len=:), allocatable :: text
      text = ''
      if (allocated(this%summary)) text = this%summary
   end function mj_describe

   !> Open points stay open while the opening is not closed; re-contact loads the point with
   !> the part of the increment after contact (as the Coulomb laws).
   subroutine mj_update(this, sigma_old, deps, state, sigma, tangent, mode, error)
      class(modjoin_law_t), intent(in) :: this
      real(wp), intent(in) :: sigma_old(2), deps(2)
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: sigma(2), tangent(2, 2)
      integer, intent(out) :: mode
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: de(2), jac(2, 2), s0(2), local(2, 2), gap, a
      logical :: ok
      de = deps
      s0 = sigma_old
      if (state(MJ_OPEN) > 0.5_wp) then
         gap = state(MJ_GAP)
         if (deps(1) <= gap) then
            state(MJ_GAP) = gap - deps(1)
            sigma = 0.0_wp
            tangent = 0.0_wp
            mode = MODE_OPEN
            state(MJ_SIGN) = 0.0_wp
            return
         end if
         a = (deps(1) - gap)/deps(1)
         de = [deps(1) - gap, a*deps(2)]
         s0 = 0.0_wp
         state(MJ_OPEN) = 0.0_wp
         state(MJ_GAP) = 0.0_wp
         call mj_integrate(this%p, s0, de, state, sigma, local, mode, ok)
         jac = reshape([1.0_wp, deps(2)*gap/deps(1)**2, 0.0_wp, a], [2, 2])
         tangent = matmul(local, jac)
      else
         call mj_integrate(this%p, s0, de, state, sigma, tangent, mode, ok)
      end if
      if (.not. ok) then
         call run_error(error, 'MODJOIN law '//this%name//': the local return did not '// &
            'converge (increment too large or parameters out of range)')
         return
      end if
      state(MJ_SIGN) = sigma(1)
   end subroutine mj_update

end module pecplas_joints_laws_modjoin
