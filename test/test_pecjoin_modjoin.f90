!> MODJOIN (thesis chapter III) point checks: the closed forms of the hardening law, the
!> invariants of constant-normal-load paths, the consistent tangent against central
!> differences of the update in hardening, softening and kinematic (cyclic) flow, the unit
!> conversion at input and the deck errors.
module test_pecjoin_modjoin
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use pecplas_joints_laws_type, only: interface_law_t, MODE_SLIP, MODE_OPEN, MODE_STICK
   use pecplas_joints_laws_modjoin, only: modjoin_law_t
   use pecplas_joints_laws_modjoin_step, only: MJ_K, MJ_MECH
   use pecplas_joints_laws_modjoin_kernel, only: mj_hardening, mj_hardening_slope, mj_gmod, mj_psi
   use pecplas_studies_path_driver, only: path_result_t, path_increment
   use pecplas_studies_path_deck, only: PATH_CNL, PATH_CND
   use fixtures_pecjoin, only: fd_tangent, max_rel_diff, make_law
   use pecplas_cmd_path, only: run_path_deck
   use pecplas_base_files, only: make_directories
   use fixtures_modjoin, only: table_law, run_table_path
   implicit none (type, external)
   private
   public :: collect_pecjoin_modjoin

   real(wp), parameter :: DEG = acos(-1.0_wp)/180.0_wp, PA = 100.0_wp
   real(wp), parameter :: SIGMAS(3) = [31.0_wp, 56.0_wp, 122.0_wp]

contains

   subroutine collect_pecjoin_modjoin(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('k0_initial_closed_form', test_k0_initial), &
               new_unittest('k0_improved_root', test_k0_improved), &
               new_unittest('hardening_modulus_fd', test_modulus_fd), &
               new_unittest('cnl_tangent_modulus', test_cnl_modulus), &
               new_unittest('cnl_k0_no_effect', test_k0_no_effect), &
               new_unittest('cnl_psi_ag_no_shear_effect', test_psi_ag), &
               new_unittest('tangent_initial', test_tangent_initial), &
               new_unittest('tangent_improved', test_tangent_improved), &
               new_unittest('tangent_cyclic', test_tangent_cyclic), &
               new_unittest('units_mm_to_m', test_units), &
               new_unittest('opening_and_recontact', test_opening), &
               new_unittest('deck_errors', test_deck_errors), &
               new_unittest('example_path_deck', test_example)]
   end subroutine collect_pecjoin_modjoin

   !> (III.6): k0 = R0 beta (sigma_n0/P_a)/(1 - R0), and R_m(k0) = R0 (III.5).
   subroutine test_k0_initial(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp) :: k0, bp
      integer :: i
      call table_law('III.1', law, error)
      if (allocated(error)) return
      select type (law)
      type is (modjoin_law_t)
         do i = 1, size(SIGMAS)
            k0 = law%initial_k(SIGMAS(i))
            bp = 9.0_wp*SIGMAS(i)/PA
            call check_close(error, k0, 0.3_wp*bp/0.7_wp, 1.0e-14_wp, '(III.6) k0')
            if (allocated(error)) return
            call check_close(error, mj_hardening(k0, bp, 1.0_wp, 0.0_wp, 0.0_wp), 0.3_wp, &
               1.0e-14_wp, 'R_m(k0) = R0')
            if (allocated(error)) return
         end do
      end select
   end subroutine test_k0_initial

   !> Improved and cyclic versions: k0 solves R_m(k0) = R0 (III.16) on the rising branch.
   subroutine test_k0_improved(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      character(len=6), parameter :: TABLES(3) = [character(len=6) :: 'III.2', 'III.5', 'III.6D']
      real(wp) :: k0, bp
      integer :: i, t
      do t = 1, size(TABLES)
         call table_law(trim(TABLES(t)), law, error)
         if (allocated(error)) return
         select type (law)
         type is (modjoin_law_t)
            do i = 1, size(SIGMAS)
               k0 = law%initial_k(SIGMAS(i))
               bp = law%betap(law%p%beta, SIGMAS(i))
               associate (p => law%p)
                  call check_close(error, mj_hardening(k0, bp, p%alpha, p%a, p%b), p%r0, &
                     1.0e-13_wp, trim(TABLES(t))//': R_m(k0) = R0')
                  if (allocated(error)) return
                  call check(error, mj_hardening_slope(k0, bp, p%alpha, p%a, p%b) > 0.0_wp, &
                     trim(TABLES(t))//': k0 on the rising branch')
               end associate
               if (allocated(error)) return
            end do
         end select
      end do
   end subroutine test_k0_improved

   !> H = M_f (sigma_n + C) dR_m/dk against central differences of R_m (hardening and, past
   !> the peak of table III.2, softening H < 0): truncation h^2 R''' ~ 1e-10.
   subroutine test_modulus_fd(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: BP = 1.5_wp*0.56_wp, H = 1.0e-5_wp, MF = 0.8692867378162267_wp
      real(wp) :: k, hm, fd
      integer :: i
      logical :: soft
      soft = .false.
      do i = 1, 40
         k = 0.25_wp*i
         hm = MF*56.0_wp*mj_hardening_slope(k, BP, 0.7_wp, 0.6_wp, 0.96_wp)
         fd = MF*56.0_wp*(mj_hardening(k + H, BP, 0.7_wp, 0.6_wp, 0.96_wp) - &
            mj_hardening(k - H, BP, 0.7_wp, 0.6_wp, 0.96_wp))/(2.0_wp*H)
         call check_close(error, hm, fd, 0.0_wp, 'H = M_f sigma_n dR_m/dk', atol=1.0e-8_wp)
         if (allocated(error)) return
         soft = soft .or. hm < -1.0_wp
      end do
      call check(error, soft, 'table III.2 softens past its peak (H < 0)')
   end subroutine test_modulus_fd

   !> Constant normal load: d tau = G (d eps_t - d lambda) and d tau = H d lambda give the
   !> slope d tau/d eps_t = G H/(G + H) with H = M_f (sigma_n + C) dR_m/dk at the current k.
   !> The law's tangent condensed on d sigma_n = 0 must give it, up to the backward-Euler
   !> step (one 0.001 mm substep: H varies by < 1e-3 over it).
   subroutine test_cnl_modulus(error)
      type(error_t), allocatable, intent(out) :: error
      call cnl_modulus('III.1', 1.0_wp, error)
      if (allocated(error)) return
      call cnl_modulus('III.2', 1.0_wp, error)
      if (allocated(error)) return
      call cnl_modulus('III.2', 5.0_wp, error)
   end subroutine test_cnl_modulus

   subroutine cnl_modulus(table, at, error)
      character(len=*), intent(in) :: table
      real(wp), intent(in) :: at
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp), allocatable :: state(:)
      real(wp) :: sigma(2), s1(2), t(2, 2), slope, g, hm, kk
      integer :: mode
      call table_law(table, law, error)
      if (allocated(error)) return
      call advance(law, PATH_CNL, 56.0_wp, [at], 400, sigma, state, error)
      if (allocated(error)) return
      select type (law)
      type is (modjoin_law_t)
         call law%update(sigma, [0.0_wp, 1.0e-3_wp], state, s1, t, mode, error)
         if (allocated(error)) return
         slope = t(2, 2) - t(2, 1)*t(1, 2)/t(1, 1)
         g = mj_gmod(law%p%el, 56.0_wp)
         kk = state(MJ_K)
         hm = law%p%mu_f*56.0_wp*mj_hardening_slope(kk, law%betap(law%p%beta, 56.0_wp), &
            law%p%alpha, law%p%a, law%p%b)
         call check(error, mode == MODE_SLIP, table//': slip on the CNL path')
         if (allocated(error)) return
         call check_close(error, slope, g*hm/(g + hm), 2.0e-3_wp, table// &
            ': condensed tangent = G H/(G + H)')
      end select
   end subroutine cnl_modulus

   !> Under constant normal load sigma_n never changes, so K0 has no effect at all (neither on
   !> tau nor on eps_n = eps_n^p). Increments of one substep (0.001 mm) so that sigma_n is
   !> held at every backward-Euler step: then the discrete law keeps the invariance to
   !> round-off (asserted 1e-9: measured 1e-14 on tau, 1e-10 on eps_n, a sum of 4000 Newton
   !> roots). With several substeps per increment d eps_n is
   !> spread evenly over them, sigma_n wanders by O(K d eps_n / n) inside the increment and
   !> K0 enters at the 1e-8 level.
   subroutine test_k0_no_effect(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=6), parameter :: TABLES(3) = [character(len=6) :: 'III.1', 'III.2', 'III.6D']
      class(interface_law_t), allocatable :: law
      type(path_result_t) :: r0, r1
      integer :: t
      do t = 1, size(TABLES)
         call table_law(trim(TABLES(t)), law, error)
         if (.not. allocated(error)) call run_table_path(law, PATH_CNL, 56.0_wp, &
            [3.0_wp, 1.0_wp], 3000, r0, error)
         if (.not. allocated(error)) call table_law(trim(TABLES(t)), law, error, 'K0', 240.0_wp)
         if (.not. allocated(error)) call run_table_path(law, PATH_CNL, 56.0_wp, &
            [3.0_wp, 1.0_wp], 3000, r1, error)
         if (allocated(error)) return
         call check_close(error, maxval(abs(r1%tau - r0%tau))/maxval(abs(r0%tau)), 0.0_wp, &
            0.0_wp, trim(TABLES(t))//': K0 x 3 leaves tau unchanged', atol=1.0e-9_wp)
         if (allocated(error)) return
         call check_close(error, maxval(abs(r1%eps_n - r0%eps_n))/maxval(abs(r0%eps_n)), &
            0.0_wp, 0.0_wp, trim(TABLES(t))//': K0 x 3 leaves eps_n unchanged', atol=1.0e-9_wp)
         if (allocated(error)) return
      end do
   end subroutine test_k0_no_effect

   !> Under constant normal load the shear curve involves neither psi nor a_g (they only
   !> enter the normal flow); eps_n does change (checked, so the test cannot pass vacuously).
   !> One substep per increment, as for K0.
   subroutine test_psi_ag(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      type(path_result_t) :: r0, r1, r2
      call table_law('III.2', law, error)
      if (.not. allocated(error)) call run_table_path(law, PATH_CNL, 122.0_wp, [5.0_wp], &
         5000, r0, error)
      if (.not. allocated(error)) call table_law('III.2', law, error, 'PSI', 35.0_wp)
      if (.not. allocated(error)) call run_table_path(law, PATH_CNL, 122.0_wp, [5.0_wp], &
         5000, r1, error)
      if (.not. allocated(error)) call table_law('III.2', law, error, 'A_G', 1.2_wp)
      if (.not. allocated(error)) call run_table_path(law, PATH_CNL, 122.0_wp, [5.0_wp], &
         5000, r2, error)
      if (allocated(error)) return
      call check_close(error, maxval(abs(r1%tau - r0%tau))/maxval(abs(r0%tau)), 0.0_wp, &
         0.0_wp, 'PSI 27 -> 35 leaves tau unchanged', atol=1.0e-9_wp)
      if (allocated(error)) return
      call check_close(error, maxval(abs(r2%tau - r0%tau))/maxval(abs(r0%tau)), 0.0_wp, &
         0.0_wp, 'A_G 0.4 -> 1.2 leaves tau unchanged', atol=1.0e-9_wp)
      if (allocated(error)) return
      call check(error, maxval(abs(r1%eps_n - r0%eps_n)) > 1.0e-2_wp*maxval(abs(r0%eps_n)) &
         .and. maxval(abs(r2%eps_n - r0%eps_n)) > 1.0e-2_wp*maxval(abs(r0%eps_n)), &
         'PSI and A_G do change eps_n')
   end subroutine test_psi_ag

   subroutine test_tangent_initial(error)
      type(error_t), allocatable, intent(out) :: error
      call tangent_at('III.1', PATH_CNL, [1.0_wp], [0.002_wp, 0.0105_wp], 0, error)
      if (allocated(error)) return
      call tangent_at('III.1', PATH_CND, [3.0_wp], [-0.001_wp, 0.0105_wp], 0, error)
   end subroutine test_tangent_initial

   !> Hardening (1 mm), softening (5 mm, past the peak of table III.2), on CNL and CND states.
   subroutine test_tangent_improved(error)
      type(error_t), allocatable, intent(out) :: error
      call tangent_at('III.2', PATH_CNL, [1.0_wp], [0.002_wp, 0.0105_wp], 0, error)
      if (allocated(error)) return
      call tangent_at('III.2', PATH_CNL, [5.0_wp], [0.002_wp, 0.0105_wp], 0, error)
      if (allocated(error)) return
      call tangent_at('III.2', PATH_CND, [5.0_wp], [-0.001_wp, 0.0105_wp], 0, error)
      if (allocated(error)) return
      call tangent_at('III.5', PATH_CND, [1.0_wp], [0.001_wp, 0.0105_wp], 0, error)
   end subroutine test_tangent_improved

   !> Primary mechanism (first loading), then kinematic flow after a reversal at 2 mm.
   subroutine test_tangent_cyclic(error)
      type(error_t), allocatable, intent(out) :: error
      call tangent_at('III.6D', PATH_CNL, [1.0_wp], [0.002_wp, 0.0105_wp], 0, error)
      if (allocated(error)) return
      call tangent_at('III.6D', PATH_CNL, [2.0_wp, 1.0_wp], [0.002_wp, -0.0105_wp], 1, error)
      if (allocated(error)) return
      call tangent_at('III.6L', PATH_CNL, [2.0_wp, 1.6_wp], [0.002_wp, -0.0105_wp], 1, error)
      if (allocated(error)) return
      call tangent_at('III.6D', PATH_CND, [2.0_wp, 0.5_wp], [-0.001_wp, -0.0105_wp], 1, error)
   end subroutine test_tangent_cyclic

   !> Brings a point of table `table` along a path to the last target, then compares the
   !> tangent of one more increment `deps` (10.5 substeps of 0.001 mm: away from a change
   !> of the substep count) with central differences of the update (step 1e-7 mm:
   !> truncation and round-off both below 1e-7 relative). `mech`: mechanism expected.
   subroutine tangent_at(table, control, targets, deps, mech, error)
      character(len=*), intent(in) :: table
      integer, intent(in) :: control, mech
      real(wp), intent(in) :: targets(:), deps(2)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp), allocatable :: state(:), st(:)
      real(wp) :: sigma(2), s1(2), t(2, 2), fd(2, 2)
      integer :: mode
      character(len=64) :: what
      call table_law(table, law, error)
      if (allocated(error)) return
      call advance(law, control, 56.0_wp, targets, 300, sigma, state, error)
      if (allocated(error)) return
      st = state
      call law%update(sigma, deps, st, s1, t, mode, error)
      if (allocated(error)) return
      write (what, '(a,a,f4.1,a)') table, ' at ', targets(size(targets)), ' mm'
      call check(error, mode == MODE_SLIP, trim(what)//': the increment is plastic')
      if (allocated(error)) return
      if (size(state) >= MJ_MECH) then
         call check(error, nint(st(MJ_MECH)) == mech, trim(what)//': mechanism as expected')
         if (allocated(error)) return
      end if
      call fd_tangent(law, sigma, state, deps, 1.0e-7_wp, fd, error)
      if (allocated(error)) return
      call check(error, max_rel_diff(t, fd) < 1.0e-6_wp, trim(what)// &
         ': tangent = central differences of the update (1e-6)')
   end subroutine tangent_at

   !> Runs the point driver's increments from (sigma_n0, 0) through `targets` (`steps` per
   !> segment) and returns the converged stress and state.
   subroutine advance(law, control, sigma_n0, targets, steps, sigma, state, error)
      class(interface_law_t), intent(in) :: law
      integer, intent(in) :: control, steps
      real(wp), intent(in) :: sigma_n0, targets(:)
      real(wp), intent(out) :: sigma(2)
      real(wp), allocatable, intent(out) :: state(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: eps_t, deps_t, deps_n, s_new(2)
      integer :: seg, i, mode, iters
      allocate (state(law%nstate()))
      sigma = [sigma_n0, 0.0_wp]
      call law%init_state(sigma, state)
      eps_t = 0.0_wp
      do seg = 1, size(targets)
         deps_t = (targets(seg) - eps_t)/steps
         do i = 1, steps
            call path_increment(law, control, 0.0_wp, sigma, state, deps_t, deps_n, s_new, &
               mode, iters, error)
            if (allocated(error)) return
            sigma = s_new
         end do
         eps_t = targets(seg)
      end do
   end subroutine advance

   !> LENGTH_UNIT=MM with MODEL_UNIT=M: the law in metres is the law in mm with every
   !> displacement scaled by 1e-3 (same stresses at eps_m = 1e-3 eps_mm), to round-off.
   subroutine test_units(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: lmm, lm
      type(path_result_t) :: rmm, rm
      call table_law('III.2', lmm, error)
      if (.not. allocated(error)) call table_law('III.2', lm, error, 'MODEL_UNIT', 1.0_wp)
      if (.not. allocated(error)) call run_table_path(lmm, PATH_CND, 56.0_wp, [3.0_wp], 150, &
         rmm, error)
      if (.not. allocated(error)) call run_table_path(lm, PATH_CND, 56.0_wp, [3.0e-3_wp], &
         150, rm, error)
      if (allocated(error)) return
      call check_close(error, maxval(abs(rm%tau - rmm%tau))/maxval(abs(rmm%tau)), 0.0_wp, &
         0.0_wp, 'tau(eps in m) = tau(eps in mm)', atol=1.0e-9_wp)
      if (allocated(error)) return
      call check_close(error, maxval(abs(rm%sigma_n - rmm%sigma_n))/maxval(rmm%sigma_n), &
         0.0_wp, 0.0_wp, 'sigma_n(eps in m) = sigma_n(eps in mm)', atol=1.0e-9_wp)
      if (allocated(error)) return
      select type (lm)
      type is (modjoin_law_t)
         call check_close(error, lm%p%el%k0, 8.0e4_wp, 1.0e-15_wp, 'K0 = 80 kPa/mm = 8e4 kPa/m')
         if (allocated(error)) return
         call check_close(error, lm%p%beta, 1.5e-3_wp, 1.0e-15_wp, 'BETA = 1.5 mm = 1.5e-3 m')
         if (allocated(error)) return
         call check_close(error, lm%p%a, 0.6e6_wp, 1.0e-15_wp, 'A = 0.6 mm^-2 = 6e5 m^-2')
         if (allocated(error)) return
         call check(error, index(lm%describe(), 'parameters in mm, model in m') > 0, &
            'the summary line states the conversion')
      end select
   end subroutine test_units

   !> No tensile strength: opening by 2.5 mm from 56 kPa (improved version: the elastic
   !> closure from 0 to 56 kPa is Psi(56) - Psi(0) = 1.75 mm) separates the point (zero
   !> stress and tangent) with the opening beyond zero stress, 2.5 - (Psi(56) - Psi(0)),
   !> Psi the exact elastic compliance potential (III.15); closing it plus 0.1 mm re-contacts
   !> and loads the point from zero stress, to Psi(s) = Psi(0) + 0.1 (round-off of the
   !> potential differences, 1e-10).
   subroutine test_opening(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp), allocatable :: state(:)
      real(wp) :: sigma(2), s0(2), t(2, 2), gap
      integer :: mode
      call table_law('III.2', law, error)
      if (allocated(error)) return
      select type (law)
      type is (modjoin_law_t)
         allocate (state(law%nstate()))
         call law%init_state([56.0_wp, 0.0_wp], state)
         call law%update([56.0_wp, 0.0_wp], [-2.5_wp, 0.0_wp], state, sigma, t, mode, error)
         if (allocated(error)) return
         call check(error, mode == MODE_OPEN .and. all(sigma == 0.0_wp) .and. all(t == 0.0_wp), &
            'opening: mode open, zero stress and tangent')
         if (allocated(error)) return
         gap = 2.5_wp - (mj_psi(law%p%el, 56.0_wp) - mj_psi(law%p%el, 0.0_wp))
         call check_close(error, state(3), gap, 1.0e-12_wp, 'opening beyond zero stress')
         if (allocated(error)) return
         s0 = sigma
         call law%update(s0, [gap + 0.1_wp, 0.0_wp], state, sigma, t, mode, error)
         if (allocated(error)) return
         call check(error, mode == MODE_STICK, 're-contact')
         if (allocated(error)) return
         call check_close(error, mj_psi(law%p%el, sigma(1)) - mj_psi(law%p%el, 0.0_wp), &
            0.1_wp, 1.0e-10_wp, 'loaded from zero stress by the closure after contact')
      end select
   end subroutine test_opening

   !> Units are never guessed; parameters out of range name the key.
   subroutine test_deck_errors(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      type(error_t), allocatable :: e
      type(path_result_t) :: res
      character(len=*), parameter :: DIR = 'build/test_out/modjoin'
      integer :: u, code
      call make_law('MODJOIN_INITIAL', [character(len=4) :: 'K0', 'G0', 'PHI', 'R0', 'BETA', &
         'PSI', 'A_G'], [80.0_wp, 40.0_wp, 41.0_wp, 0.3_wp, 9.0_wp, 27.0_wp, 0.5_wp], law, e)
      call check(error, allocated(e), 'no LENGTH_UNIT: deck error')
      if (allocated(error)) return
      call check(error, index(e%message, 'LENGTH_UNIT=MM') > 0, 'the message says how: '// &
         e%message)
      if (allocated(error)) return
      call table_law('III.2', law, e, 'R0', 0.8_wp)
      call check(error, allocated(e), 'R0 = 0.8 >= ALPHA = 0.7: deck error')
      if (allocated(error)) return
      call check(error, index(e%message, 'R0') > 0, 'the message names R0: '//e%message)
      if (allocated(error)) return
      call make_law('MOHR_COULOMB', [character(len=11) :: 'KN', 'KT', 'PHI', 'LENGTH_UNIT'], &
         [1.0e3_wp, 5.0e2_wp, 30.0_wp, 1.0e-3_wp], law, e)
      call check(error, allocated(e), 'LENGTH_UNIT on a law that does not convert: error')
      if (allocated(error)) return
      call make_directories(DIR)
      open (newunit=u, file=DIR//'/bad_unit.inp', status='replace', action='write')
      write (u, '(a)') '*INTERFACE_LAW, NAME=j, TYPE=MODJOIN_INITIAL, LENGTH_UNIT=FT'
      write (u, '(a)') 'K0 = 80, G0 = 40, PHI = 41, R0 = 0.3, BETA = 9, PSI = 27, A_G = 0.5'
      write (u, '(a)') '*PATH, TYPE=CNL, SIGMA_N0=56'
      write (u, '(a)') '2.0'
      close (u)
      code = run_path_deck(DIR//'/bad_unit.inp', DIR//'/bad_unit', .true., res)
      call check(error, code == 2, 'LENGTH_UNIT=FT: input error (exit code 2)')
   end subroutine test_deck_errors

   !> input/paths/cnl_modjoin.inp runs and shows the peak the deck announces (~42 kPa).
   subroutine test_example(error)
      type(error_t), allocatable, intent(out) :: error
      type(path_result_t) :: res
      integer :: code
      call make_directories('build/test_out/modjoin')
      code = run_path_deck('input/paths/cnl_modjoin.inp', 'build/test_out/modjoin/cnl', &
         .true., res)
      call check(error, code == 0, 'input/paths/cnl_modjoin.inp completes')
      if (allocated(error)) return
      call check(error, abs(maxval(res%tau) - 42.0_wp) < 1.0_wp .and. &
         res%tau(ubound(res%tau, 1)) < 0.9_wp*maxval(res%tau), 'peak near 42 kPa, then softening')
   end subroutine test_example

end module test_pecjoin_modjoin
