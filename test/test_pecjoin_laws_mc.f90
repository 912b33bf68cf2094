!> Mohr–Coulomb interface details (hand-derived exact returns): dilatancy under constrained
!> normal displacement, tension cut-off with opening and re-contact, the apex and cut-off
!> corner, the tensile strength lost at separation; Goodman's slip stiffness; the spring
!> penalty; Ghaboussi's asperity (Patton) strength and dilation.
module test_pecjoin_laws_mc
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use pecplas_joints_laws_type, only: interface_law_t, MODE_STICK, MODE_SLIP, MODE_OPEN
   use pecplas_joints_laws_coulomb, only: ST_SLIP, ST_GAP, ST_EPS_NP, ST_EPS_TP
   use pecplas_joints_laws_spring, only: spring_law_t
   use pecplas_studies_path_deck, only: PATH_CNL
   use pecplas_studies_path_driver, only: path_result_t, run_path
   use fixtures_pecjoin, only: make_law
   implicit none (type, external)
   private
   public :: collect_pecjoin_laws_mc

   real(wp), parameter :: PI = acos(-1.0_wp), DEG = PI/180.0_wp
   real(wp), parameter :: KN = 1000.0_wp, KT = 500.0_wp

contains

   subroutine collect_pecjoin_laws_mc(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('dilatancy_constrained_normal', test_dilatancy), &
               new_unittest('psi0_sigma_n_constant', test_psi0), &
               new_unittest('open_and_recontact', test_open_recontact), &
               new_unittest('tensile_strength_then_broken', test_tensile_strength), &
               new_unittest('apex_and_cutoff_corner', test_apex), &
               new_unittest('goodman_slip_stiffness', test_goodman_tangent), &
               new_unittest('spring_penalty', test_spring_penalty), &
               new_unittest('spring_smooth', test_spring_smooth), &
               new_unittest('ghaboussi_asperity', test_ghaboussi)]
   end subroutine collect_pecjoin_laws_mc

   !> Constrained normal displacement (d eps_n = 0) from sigma_n0 = 100, phi = 30, psi = 10.
   !> On the cone, an increment d of eps_t has the trial f = K_t d, so (module header of
   !> pecplas_joints_laws_coulomb) dlambda = K_t d / (K_t + K_n tan(psi) tan(phi)); the plastic
   !> normal displacement is -tan(psi) dlambda (dilation) and, eps_n being fixed, the elastic
   !> one is +tan(psi) dlambda: d sigma_n = K_n tan(psi) dlambda, and tau = sigma_n tan(phi).
   subroutine test_dilatancy(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp) :: state(6), sigma(2), old(2), t(2, 2), d, dl, slip_old, tp, tf
      integer :: mode, i
      tf = tan(30.0_wp*DEG)
      tp = tan(10.0_wp*DEG)
      call make_law('MOHR_COULOMB', ['KN ', 'KT ', 'PHI', 'PSI'], [KN, KT, 30.0_wp, 10.0_wp], &
         law, error)
      if (allocated(error)) return
      call law%init_state([100.0_wp, 0.0_wp], state)
      sigma = [100.0_wp, 0.0_wp]
      d = 0.01_wp
      do i = 1, 40
         old = sigma
         slip_old = state(ST_SLIP)
         call law%update(old, [0.0_wp, d], state, sigma, t, mode, error)
         if (allocated(error)) return
         if (i <= 12) cycle ! elastic up to tau = 57.7 at eps_t = 0.115, then the first slip
         call check(error, mode == MODE_SLIP, 'slip on the cone')
         if (allocated(error)) return
         dl = KT*d/(KT + KN*tp*tf)
         call check_close(error, state(ST_SLIP) - slip_old, dl, 1.0e-12_wp, 'dlambda closed form')
         if (allocated(error)) return
         call check_close(error, sigma(1) - old(1), KN*tp*(state(ST_SLIP) - slip_old), &
            1.0e-10_wp, 'd sigma_n = K_n tan(psi) |d eps_t^p|')
         if (allocated(error)) return
         call check_close(error, sigma(2), sigma(1)*tf, 1.0e-12_wp, 'tau on the cone')
         if (allocated(error)) return
      end do
      call check(error, state(ST_SLIP) > 0.2_wp .and. state(ST_EPS_NP) < 0.0_wp, &
         'slipped over 28 increments, eps_n^p < 0 (dilation)')
      if (allocated(error)) return
      call check_close(error, sigma(1) - 100.0_wp, KN*tp*state(ST_SLIP), 1.0e-12_wp, &
         'total rise of sigma_n = K_n tan(psi) * plastic slip')
      if (allocated(error)) return
      call check_close(error, state(ST_EPS_NP), -tp*state(ST_SLIP), 1.0e-12_wp, &
         'eps_n^p = -tan(psi) * plastic slip')
      if (allocated(error)) return
      call check_close(error, state(ST_EPS_TP), state(ST_SLIP), 1.0e-12_wp, &
         'monotonic slip: signed eps_t^p = accumulated slip')
   end subroutine test_dilatancy

   !> psi = 0: slip at fixed eps_n leaves sigma_n exactly unchanged.
   subroutine test_psi0(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp) :: state(6), sigma(2), old(2), t(2, 2)
      integer :: mode, i
      call make_law('MOHR_COULOMB', ['KN ', 'KT ', 'PHI', 'C  '], [KN, KT, 30.0_wp, 5.0_wp], &
         law, error)
      if (allocated(error)) return
      call law%init_state([100.0_wp, 0.0_wp], state)
      sigma = [100.0_wp, 0.0_wp]
      do i = 1, 40
         old = sigma
         call law%update(old, [0.0_wp, 0.01_wp], state, sigma, t, mode, error)
         if (allocated(error)) return
         call check(error, sigma(1) == 100.0_wp, 'sigma_n constant with psi = 0')
         if (allocated(error)) return
      end do
      call check(error, mode == MODE_SLIP .and. state(ST_EPS_NP) == 0.0_wp, &
         'slipping without dilation')
   end subroutine test_psi0

   !> From (50, 10): opening by 0.1 gives the trial -50 < 0 -> open, sigma = 0, tangent 0,
   !> gap = 0.1 - 50/K_n = 0.05. Further opening 0.02 (gap 0.07), closing 0.05 (gap 0.02,
   !> still open), closing 0.03 = gap + 0.01: contact again with sigma_n = K_n 0.01 = 10 and
   !> tau = K_t * (1/3) * d eps_t (only the third of the increment after contact loads it).
   subroutine test_open_recontact(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp) :: state(6), sigma(2), old(2), t(2, 2)
      integer :: mode
      call make_law('MOHR_COULOMB', ['KN ', 'KT ', 'PHI'], [KN, KT, 30.0_wp], law, error)
      if (allocated(error)) return
      call law%init_state([50.0_wp, 10.0_wp], state)
      call law%update([50.0_wp, 10.0_wp], [-0.1_wp, 0.0_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_OPEN .and. all(sigma == 0.0_wp) .and. all(t == 0.0_wp), &
         'opening: zero stress, zero tangent, mode open')
      if (allocated(error)) return
      call check_close(error, state(ST_GAP), 0.05_wp, 1.0e-12_wp, 'gap after separation')
      if (allocated(error)) return
      old = sigma
      call law%update(old, [-0.02_wp, 0.3_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      old = sigma
      call law%update(old, [0.05_wp, 0.0_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_OPEN .and. all(sigma == 0.0_wp), 'still open')
      if (allocated(error)) return
      call check_close(error, state(ST_GAP), 0.02_wp, 1.0e-12_wp, 'gap while open')
      if (allocated(error)) return
      old = sigma
      call law%update(old, [0.03_wp, 0.006_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_STICK, 're-closing returns to contact')
      if (allocated(error)) return
      call check_close(error, sigma(1), KN*0.01_wp, 1.0e-12_wp, 'sigma_n after re-contact')
      if (allocated(error)) return
      call check_close(error, sigma(2), KT*0.006_wp/3.0_wp, 1.0e-12_wp, 'tau after re-contact')
   end subroutine test_open_recontact

   !> TENSION = 5 (below the apex 20/tan 30 = 34.6): sigma_n = -4 is carried; -6 opens; after
   !> re-contact the bond is broken and the smallest tension opens again.
   subroutine test_tensile_strength(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp) :: state(6), sigma(2), old(2), t(2, 2)
      integer :: mode
      call make_law('MOHR_COULOMB', ['KN     ', 'KT     ', 'PHI    ', 'C      ', 'TENSION'], &
         [KN, KT, 30.0_wp, 20.0_wp, 5.0_wp], law, error)
      if (allocated(error)) return
      call law%init_state([0.0_wp, 0.0_wp], state)
      sigma = 0.0_wp
      old = sigma
      call law%update(old, [-0.004_wp, 0.0_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_STICK, 'tension below the strength is carried')
      if (allocated(error)) return
      call check_close(error, sigma(1), -4.0_wp, 1.0e-12_wp, 'sigma_n = -4')
      if (allocated(error)) return
      old = sigma
      call law%update(old, [-0.002_wp, 0.0_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_OPEN .and. all(sigma == 0.0_wp), 'beyond TENSION: open')
      if (allocated(error)) return
      old = sigma
      call law%update(old, [0.01_wp, 0.0_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_STICK .and. sigma(1) > 0.0_wp, 're-contact')
      if (allocated(error)) return
      old = sigma
      call law%update(old, [-old(1)/KN - 1.0e-6_wp, 0.0_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_OPEN, 'broken bond: no tensile strength left')
   end subroutine test_tensile_strength

   !> phi = 30, c = 10. (a) TENSION = 1e6 > apex 10/tan 30 = 17.32: a trial at sigma_n = -20
   !> would return across the apex -> open. (b) Same trial region but associated (psi = 30)
   !> with a large shear: the return raises sigma_n by K_n tan(psi) dlambda above the apex
   !> onto the cone: slip with f = 0 (the decision is made on the returned stress).
   !> (c) TENSION = 0, trial (-1, 25): with psi = 0 the return keeps sigma_n = -1 < 0 -> open;
   !> with psi = 30 it dilates into compression and slips.
   subroutine test_apex(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp) :: state(6), sigma(2), t(2, 2), tf, f, dl
      integer :: mode
      character(len=8), parameter :: KEYS(6) = [character(len=8) :: 'KN', 'KT', 'PHI', 'PSI', &
         'C', 'TENSION']
      tf = tan(30.0_wp*DEG)
      ! (a)
      call make_law('MOHR_COULOMB', KEYS, [KN, KT, 30.0_wp, 0.0_wp, 10.0_wp, 1.0e6_wp], law, error)
      if (allocated(error)) return
      call law%init_state([0.0_wp, 0.0_wp], state)
      call law%update([0.0_wp, 0.0_wp], [-0.02_wp, 0.0_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_OPEN .and. all(sigma == 0.0_wp), 'beyond the apex: open')
      if (allocated(error)) return
      ! just above the apex: still carried (elastic, f < 0)
      call law%init_state([0.0_wp, 0.0_wp], state)
      call law%update([0.0_wp, 0.0_wp], [-0.017_wp, 0.0_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_STICK, 'tension inside the cone is carried')
      if (allocated(error)) return
      ! (b)
      call make_law('MOHR_COULOMB', KEYS, [KN, KT, 30.0_wp, 30.0_wp, 10.0_wp, 1.0e6_wp], law, &
         error)
      if (allocated(error)) return
      call law%init_state([0.0_wp, 0.0_wp], state)
      call law%update([0.0_wp, 0.0_wp], [-0.018_wp, 0.2_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_SLIP .and. sigma(1) > -10.0_wp/tf, &
         'returned above the apex: slip')
      if (allocated(error)) return
      f = abs(sigma(2)) - sigma(1)*tf - 10.0_wp
      call check_close(error, f, 0.0_wp, 0.0_wp, 'returned stress on the cone', atol=1.0e-12_wp)
      if (allocated(error)) return
      dl = (100.0_wp + 18.0_wp*tf - 10.0_wp)/(KT + KN*tf*tf)
      call check_close(error, sigma(1), -18.0_wp + KN*tf*dl, 1.0e-12_wp, 'sigma_n of the return')
      if (allocated(error)) return
      ! (c)
      call make_law('MOHR_COULOMB', KEYS, [KN, KT, 30.0_wp, 0.0_wp, 10.0_wp, 0.0_wp], law, error)
      if (allocated(error)) return
      call law%init_state([0.0_wp, 0.0_wp], state)
      call law%update([0.0_wp, 0.0_wp], [-0.001_wp, 0.05_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_OPEN, 'cut-off corner, psi = 0: open')
      if (allocated(error)) return
      call make_law('MOHR_COULOMB', KEYS, [KN, KT, 30.0_wp, 30.0_wp, 10.0_wp, 0.0_wp], law, error)
      if (allocated(error)) return
      call law%init_state([0.0_wp, 0.0_wp], state)
      call law%update([0.0_wp, 0.0_wp], [-0.001_wp, 0.05_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      dl = (25.0_wp + tf - 10.0_wp)/(KT + KN*tf*tf)
      call check(error, mode == MODE_SLIP, 'cut-off corner, psi = 30: dilates into contact')
      if (allocated(error)) return
      call check_close(error, sigma(1), -1.0_wp + KN*tf*dl, 1.0e-12_wp, 'sigma_n of the return')
   end subroutine test_apex

   !> Goodman in slip: d tau/d eps_t = K_t KT_RATIO (stiffness adaptation), d tau/d eps_n =
   !> tan(phi) K_n (the cap follows sigma_n), no coupling in the normal row.
   subroutine test_goodman_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp) :: state(6), sigma(2), t(2, 2)
      integer :: mode
      call make_law('GOODMAN', ['KN      ', 'KT      ', 'PHI     ', 'KT_RATIO'], [KN, KT, &
         30.0_wp, 0.01_wp], law, error)
      if (allocated(error)) return
      call law%init_state([100.0_wp, 0.0_wp], state)
      call law%update([100.0_wp, 0.0_wp], [0.0_wp, 1.0_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_SLIP .and. .not. law%symmetric_tangent(), 'slip')
      if (allocated(error)) return
      call check_close(error, t(2, 2), KT*0.01_wp, 1.0e-12_wp, 'K_t becomes K_t * KT_RATIO')
      if (allocated(error)) return
      call check_close(error, t(2, 1), KN*tan(30.0_wp*DEG), 1.0e-12_wp, 'd tau / d eps_n')
      if (allocated(error)) return
      call check(error, t(1, 1) == KN .and. t(1, 2) == 0.0_wp, 'normal row K_n, 0')
      if (allocated(error)) return
      call law%update([100.0_wp, 0.0_wp], [-1.0_wp, 0.0_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_OPEN .and. all(t == 0.0_wp), 'tension: K_n = K_t = 0')
   end subroutine test_goodman_tangent

   !> Without KN/KT the spring waits for its penalty: update refuses; set_penalty with
   !> Frank's 1e5 E_RYG R_max (I.10) fills both stiffnesses and keeps the ones given.
   subroutine test_spring_penalty(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      type(error_t), allocatable :: e
      real(wp) :: state(6), sigma(2), t(2, 2)
      integer :: mode
      call make_law('SPRING', ['E_RYG', 'PHI  ', 'KT   '], [0.5_wp, 20.0_wp, 3.0_wp], law, error)
      if (allocated(error)) return
      select type (law)
      type is (spring_law_t)
         call check(error, law%needs_penalty, 'KN absent: needs_penalty')
         if (allocated(error)) return
         call law%init_state([0.0_wp, 0.0_wp], state)
         call law%update([0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp], state, sigma, t, mode, e)
         call check(error, allocated(e), 'update before set_penalty must fail')
         if (allocated(error)) return
         call check_close(error, law%default_penalty(2.0e6_wp), 1.0e5_wp*0.5_wp*2.0e6_wp, &
            1.0e-15_wp, 'Frank penalty 1e5 E_ryg R_max')
         if (allocated(error)) return
         call law%set_penalty(law%default_penalty(2.0e6_wp), law%default_penalty(2.0e6_wp))
         call check(error, .not. law%needs_penalty .and. law%kn == 1.0e11_wp .and. &
            law%kt == 3.0_wp, 'penalty fills KN only (KT was given)')
         if (allocated(error)) return
         call law%update([0.0_wp, 0.0_wp], [1.0e-9_wp, 0.0_wp], state, sigma, t, mode, error)
         if (allocated(error)) return
         call check_close(error, sigma(1), 100.0_wp, 1.0e-12_wp, 'normal spring force')
      class default
         call check(error, .false., 'SPRING must build a spring_law_t')
      end select
   end subroutine test_spring_penalty

   !> Neither PHI nor C: the tangential spring never carries a force once the doublet moves.
   subroutine test_spring_smooth(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp) :: state(6), sigma(2), t(2, 2)
      integer :: mode
      call make_law('SPRING', ['KN', 'KT'], [KN, KT], law, error)
      if (allocated(error)) return
      call law%init_state([10.0_wp, 0.0_wp], state)
      call law%update([10.0_wp, 0.0_wp], [0.001_wp, 0.2_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_SLIP .and. abs(sigma(2)) <= 1.0e-12_wp .and. &
         t(2, 2) == 0.0_wp .and. t(2, 1) == 0.0_wp, &
         'smooth: tau = 0, one continuity (normal spring only)')
      if (allocated(error)) return
      call check_close(error, sigma(1), 11.0_wp, 1.0e-12_wp, 'normal spring still acts')
      if (allocated(error)) return
      call law%update([10.0_wp, 0.0_wp], [0.001_wp, 0.0_wp], state, sigma, t, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_STICK, 'no tangential motion: two continuities')
   end subroutine test_spring_smooth

   !> Ghaboussi with asperities (gamma = 10, phi = 25, c = 4) under constant sigma_n = 100:
   !> plateau c cos(phi)/cos(phi+gamma) + sigma_n tan(phi+gamma) (Patton's first branch),
   !> dilation d eps_n = -tan(gamma) d(plastic slip); gamma = 0 gives Goodman's plateau.
   subroutine test_ghaboussi(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      type(path_result_t) :: res
      real(wp) :: plateau
      integer :: n, k
      call make_law('GHABOUSSI', ['KN   ', 'KT   ', 'PHI  ', 'C    ', 'GAMMA'], [KN, KT, &
         25.0_wp, 4.0_wp, 10.0_wp], law, error)
      if (allocated(error)) return
      call run_path(law, PATH_CNL, [100.0_wp, 0.0_wp], 0.0_wp, [1.0_wp], 100, res, error)
      if (allocated(error)) return
      n = ubound(res%tau, 1)
      plateau = 4.0_wp*cos(25.0_wp*DEG)/cos(35.0_wp*DEG) + 100.0_wp*tan(35.0_wp*DEG)
      call check_close(error, res%tau(n), plateau, 1.0e-10_wp, 'asperity plateau')
      if (allocated(error)) return
      k = n - 10
      call check_close(error, (res%eps_n(n) - res%eps_n(k))/(res%slip(n) - res%slip(k)), &
         -tan(10.0_wp*DEG), 1.0e-8_wp, 'dilation at the asperity angle')
      if (allocated(error)) return
      call check(error, .not. law%symmetric_tangent(), 'phi > 0: non-symmetric tangent')
      if (allocated(error)) return
      call make_law('GHABOUSSI', ['KN ', 'KT ', 'PHI', 'C  '], [KN, KT, 25.0_wp, 4.0_wp], law, &
         error)
      if (allocated(error)) return
      call run_path(law, PATH_CNL, [100.0_wp, 0.0_wp], 0.0_wp, [1.0_wp], 100, res, error)
      if (allocated(error)) return
      call check_close(error, res%tau(n), 4.0_wp + 100.0_wp*tan(25.0_wp*DEG), 1.0e-12_wp, &
         'gamma = 0: Mohr-Coulomb plateau')
      if (allocated(error)) return
      call check(error, all(res%eps_n == 0.0_wp), 'gamma = 0: no dilation')
   end subroutine test_ghaboussi

end module test_pecjoin_laws_mc
