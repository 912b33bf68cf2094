!> The safety step (strength reduction, doc/theory.md, Factor of safety) against closed forms
!> and charts, on the decks of test/data/safety (tools/pecplas_py/decks/make_safety_decks.py):
!> - a block on a Mohr-Coulomb joint (c and tan(phi) reduced) pushed by T below its sliding
!>   resistance R = c L + N tan(phi): factor R / T within 1 %;
!> - an infinite slope (a periodic column, gravity inclined by beta), associated flow:
!>   cohesionless tan(phi) / tan(beta) within 2 %; with cohesion the closed form at the base
!>   (c + gamma z cos^2(beta) tan(phi)) / (gamma z sin(beta) cos(beta)), z = H / cos(beta) the
!>   vertical depth of the base under a layer H thick, within 3 %; with psi = 0 Davis's
!>   strength in simple shear, tan(phi) / tan(asin(tan(beta))), within 2 %; under a water
!>   table parallel to it (seepage parallel to the slope) the closed form with
!>   (gamma - m gamma_w) within 3 %;
!> - Prandtl's footing on weightless Tresca soil under a pressure q (Mohr-Coulomb and
!>   Drucker-Prager): Msf = (2 + pi) c / q within 2 % (the collapse pressure is proportional
!>   to c);
!> - an undrained slope of 60 degrees on a firm base at the toe: Taylor's stability number
!>   c / (gamma H F) = 0.191 within 5 %;
!> - the reduction of each material and law type; the results file (/safety, the XDMF);
!> - honesty: a budget too small gives a lower bound (exit 3), a model that fails before the
!>   reduction reports "unstable before reduction" and no factor (exit 3);
!> - bad decks (a safety step first, *REDUCE of a material without strength): exit 2 with
!>   file:line.
module test_safety
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_problem_safety, only: SAFETY_FACTOR, SAFETY_LOWER_BOUND, SAFETY_UNSTABLE
   use pecplas_base_strings, only: itoa, g6
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_bad_decks, only: check_refused
   use pecplas_io_results_reader, only: results_reader_t
   use doc_report, only: report
   use pecplas_massif_materials_type, only: material_t
   use pecplas_massif_materials_mohr_coulomb, only: mohr_coulomb_t
   use pecplas_massif_materials_drucker_prager, only: drucker_prager_t, drucker_prager_constants
   use pecplas_massif_materials_elastic, only: elastic_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_joints_laws_mohr_coulomb, only: mohr_coulomb_law_t
   use pecplas_joints_laws_modjoin, only: modjoin_law_t
   implicit none (type, external)
   private
   public :: collect_safety

   character(len=*), parameter :: DATA = 'test/data/safety/', OUT = 'build/test_out/safety/'
   real(wp), parameter :: PI = acos(-1.0_wp), DEG = PI/180.0_wp

contains

   subroutine collect_safety(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('reduced_strengths', test_reduced), &
               new_unittest('block_on_joint', test_block), &
               new_unittest('infinite_slope_dry', test_infinite_dry), &
               new_unittest('infinite_slope_cohesion', test_infinite_c), &
               new_unittest('infinite_slope_non_associated', test_infinite_psi0), &
               new_unittest('infinite_slope_water', test_infinite_water), &
               new_unittest('prandtl_footing', test_footing), &
               new_unittest('prandtl_footing_drucker_prager', test_footing_dp), &
               new_unittest('taylor_undrained_slope', test_taylor), &
               new_unittest('results_file', test_results_file), &
               new_unittest('lower_bound', test_lower_bound), &
               new_unittest('unstable_before_reduction', test_unstable), &
               new_unittest('bad_decks', test_bad_decks)]
   end subroutine collect_safety

   !> The reduction of each type: Mohr-Coulomb soil c / M, tan(phi) / M, psi kept while below
   !> phi_r and equal to it after; Drucker-Prager the same on its Mohr-Coulomb parameters and
   !> its cone fitted again; the Coulomb joint law the same on c, mu_f, mu_g; an elastic
   !> material and MODJOIN have none. Tolerance 1e-14: a few roundings of tan and atan.
   subroutine test_reduced(error)
      type(error_t), allocatable, intent(out) :: error
      type(mohr_coulomb_t) :: mc
      type(drucker_prager_t) :: dp
      type(elastic_t) :: el
      type(mohr_coulomb_law_t) :: law
      type(modjoin_law_t) :: mj
      class(material_t), allocatable :: r
      class(interface_law_t), allocatable :: rl
      real(wp) :: eta, xi, etabar
      mc%soil%cohesion = 10.0_wp
      mc%soil%phi = 30.0_wp*DEG
      mc%soil%psi = 10.0_wp*DEG
      call mc%reduced_strength(1.5_wp, r)
      select type (r)
      type is (mohr_coulomb_t)
         call check(error, abs(r%soil%cohesion - 10.0_wp/1.5_wp) <= 1.0e-14_wp*10.0_wp .and. &
            abs(tan(r%soil%phi) - tan(30.0_wp*DEG)/1.5_wp) <= 1.0e-14_wp .and. &
            r%soil%psi == mc%soil%psi, 'Mohr-Coulomb, M = 1.5: c, tan(phi) divided, psi kept')
      class default
         call check(error, .false., 'Mohr-Coulomb reduces to a Mohr-Coulomb soil')
      end select
      if (allocated(error)) return
      call mc%reduced_strength(4.0_wp, r)
      select type (r)
      type is (mohr_coulomb_t)
         call check(error, r%soil%psi == r%soil%phi .and. r%soil%phi < mc%soil%psi, &
            'Mohr-Coulomb, M = 4: phi_r < psi, so psi_r = phi_r')
      end select
      if (allocated(error)) return
      dp%soil = mc%soil
      dp%match = 3
      call dp%reduced_strength(2.0_wp, r)
      select type (r)
      type is (drucker_prager_t)
         call drucker_prager_constants(3, atan(tan(30.0_wp*DEG)/2.0_wp), 10.0_wp*DEG, eta, xi, &
            etabar)
         call check(error, abs(r%soil%cohesion - 5.0_wp) <= 1.0e-14_wp*5.0_wp .and. &
            abs(r%eta - eta) <= 1.0e-14_wp .and. abs(r%xi - xi) <= 1.0e-14_wp .and. &
            abs(r%etabar - etabar) <= 1.0e-14_wp, 'Drucker-Prager: the cone of the reduced '// &
            'Mohr-Coulomb parameters')
      class default
         call check(error, .false., 'Drucker-Prager reduces to a Drucker-Prager soil')
      end select
      if (allocated(error)) return
      call el%reduced_strength(2.0_wp, r)
      call check(error, .not. allocated(r), 'an elastic material has no strength to reduce')
      if (allocated(error)) return
      law%c = 6.0_wp
      law%mu_f = 0.6_wp
      law%mu_g = 0.2_wp
      call law%reduced_strength(2.0_wp, rl)
      select type (rl)
      type is (mohr_coulomb_law_t)
         call check(error, rl%c == 3.0_wp .and. rl%mu_f == 0.3_wp .and. rl%mu_g == 0.2_wp, &
            'Mohr-Coulomb joint law, M = 2: c and mu_f halved, mu_g kept (below mu_f / 2)')
      class default
         call check(error, .false., 'the joint law reduces to its own type')
      end select
      if (allocated(error)) return
      call law%reduced_strength(4.0_wp, rl)
      select type (rl)
      class is (mohr_coulomb_law_t)
         call check(error, rl%mu_g == rl%mu_f, 'joint law, M = 4: mu_g follows mu_f / 4')
      end select
      if (allocated(error)) return
      call mj%reduced_strength(2.0_wp, rl)
      call check(error, .not. allocated(rl), 'MODJOIN is not reduced')
   end subroutine test_reduced

   !> Runs deck `name`; the factor found (kind SAFETY_FACTOR, exit 0) in `f`.
   subroutine run_factor(name, f, error)
      character(len=*), intent(in) :: name
      real(wp), intent(out) :: f
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call make_directories(OUT)
      code = run_deck(DATA//name//'.inp', OUT//name//'.h5', .true., model, problem)
      f = problem%safety%factor
      call check(error, code == 0 .and. problem%safety%kind == SAFETY_FACTOR, name// &
         ': a factor is found (exit '//itoa(code)//', kind '//itoa(problem%safety%kind)//')')
      if (allocated(error)) return
      ! the resolution is the last Msf step, RESOLUTION of the decks
      call check(error, problem%safety%resolution <= 0.005_wp*(1.0_wp + 1.0e-9_wp), name// &
         ': resolution '//g6(problem%safety%resolution))
   end subroutine run_factor

   !> Runs deck `name` (run_factor), reports [factor, expected] as safety/`key` and checks the
   !> factor against `expected` within the relative tolerance `rel` (each test says why).
   subroutine check_factor(error, name, key, expected, rel, what)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: name, key, what
      real(wp), intent(in) :: expected, rel
      real(wp) :: f
      call run_factor(name, f, error)
      if (allocated(error)) return
      call report('safety/'//key, [f, expected])
      call check_close(error, f, expected, rel, what)
   end subroutine check_factor

   !> R = c L + N tan(phi) = 5 x 2 + 200 x 0.3 = 70, T = 30: the joint alone fails, at
   !> 7/3. 1 %: the resolution (0.002) and the penalty joint's exact return leave less.
   subroutine test_block(error)
      type(error_t), allocatable, intent(out) :: error
      call check_factor(error, 'block', 'block', 70.0_wp/30.0_wp, 0.01_wp, &
         'block on a joint: R / T')
   end subroutine test_block

   !> beta = 20, phi = psi = 35, c = 0: associated flow in the simple shear of the infinite
   !> slope gives the strength c + sigma_n tan(phi) on planes parallel to it (Davis 1968), so
   !> F = tan(phi) / tan(beta) = 1.9238. 2 %: the resolution and the tolerance of equilibrium.
   subroutine test_infinite_dry(error)
      type(error_t), allocatable, intent(out) :: error
      call check_factor(error, 'infinite_slope_dry', 'infinite_slope_dry', &
         tan(35.0_wp*DEG)/tan(20.0_wp*DEG), 0.02_wp, &
         'infinite slope, dry, cohesionless: tan(phi) / tan(beta)')
   end subroutine test_infinite_dry

   !> The same slope with psi = 0: the strength on planes parallel to it in simple shear is
   !> sigma_n sin(phi) cos(psi) / (1 - sin(phi) sin(psi)) (Davis 1968), sigma_n sin(phi_r) here,
   !> so the factor is tan(phi) / tan(asin(tan(beta))) = 1.7919, not tan(phi) / tan(beta).
   !> 2 %: as above.
   subroutine test_infinite_psi0(error)
      type(error_t), allocatable, intent(out) :: error
      call check_factor(error, 'infinite_slope_psi0', 'infinite_slope_psi0', &
         tan(35.0_wp*DEG)/tan(asin(tan(20.0_wp*DEG))), 0.02_wp, &
         'infinite slope, psi = 0: Davis''s strength in simple shear')
   end subroutine test_infinite_psi0

   !> beta = 25, phi = psi = 30, c = 10, gamma = 20, H = 5: the closed form is lowest at the
   !> base, F = (c + gamma z cos^2 tan(phi)) / (gamma z sin cos) with z = H / cos(beta) the
   !> vertical depth of the base (the layer is H thick normal to the slope): 1.4748. 3 %: the
   !> lowest Gauss points are 0.106 normal to the slope above the base (F = 1.4796 there) and
   !> the resolution.
   subroutine test_infinite_c(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: b, p, fc
      b = 25.0_wp*DEG
      p = 30.0_wp*DEG
      ! gamma z = 20 x 5 / cos(beta)
      fc = (10.0_wp + 100.0_wp/cos(b)*cos(b)**2*tan(p))/(100.0_wp/cos(b)*sin(b)*cos(b))
      call check_factor(error, 'infinite_slope_c', 'infinite_slope_c', fc, 0.03_wp, &
         'infinite slope with cohesion: closed form')
   end subroutine test_infinite_c

   !> The slope of test_infinite_c under a water table parallel to it at half its thickness
   !> (m = 0.5), seepage parallel to the slope (doc/deck.md Groundwater: a horizontal level
   !> with GAMMA_W = gamma_w cos(beta) in the column turned horizontal, the K0 procedure with
   !> the normal weight, then the weight along the slope as a body force): the closed form
   !> (c' + (gamma - m gamma_w) z cos^2 tan(phi')) / (gamma z sin cos), z = H / cos(beta),
   !> gamma_w = 10: 1.1652. 3 %: the lowest Gauss points lie 0.053 above the base (20
   !> elements: +1.2 %; 10 and 40 elements give +2.4 % and +0.5 %).
   subroutine test_infinite_water(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: b, p, z, fc
      b = 25.0_wp*DEG
      p = 30.0_wp*DEG
      z = 5.0_wp/cos(b)
      fc = (10.0_wp + (20.0_wp - 0.5_wp*10.0_wp)*z*cos(b)**2*tan(p))/(20.0_wp*z*sin(b)*cos(b))
      call check_factor(error, 'infinite_slope_water', 'infinite_slope_water', fc, 0.03_wp, &
         'infinite slope with a water table: closed form')
   end subroutine test_infinite_water

   !> Weightless Tresca soil, c = 10, flexible strip of half-width 1 under q = 25: the
   !> collapse pressure is proportional to c, so Msf = (2 + pi) c / q = 2.0566 exactly in
   !> theory. 2 %: the mesh's own collapse pressure (196 T6: +1.8 % for the rigid footing,
   !> test_massif_plasticity_fe) and the resolution.
   subroutine test_footing(error)
      type(error_t), allocatable, intent(out) :: error
      call check_factor(error, 'footing_safety', 'footing', (2.0_wp + PI)*10.0_wp/25.0_wp, &
         0.02_wp, 'Prandtl footing: Msf = q_ult / q')
   end subroutine test_footing

   !> The same footing with Drucker-Prager soil fitted to the plane-strain Mohr-Coulomb limit
   !> (MATCH = 3): for phi = 0 its plane-strain limit state is Tresca's, so the factor is the
   !> same (2 %, as above).
   subroutine test_footing_dp(error)
      type(error_t), allocatable, intent(out) :: error
      call check_factor(error, 'footing_safety_dp', 'footing_dp', &
         (2.0_wp + PI)*10.0_wp/25.0_wp, 0.02_wp, 'Prandtl footing, Drucker-Prager: Msf = q_ult / q')
   end subroutine test_footing_dp

   !> phi = 0, beta = 60, H = 10, gamma = 20, c = 50, firm base at the toe: Taylor (1948)
   !> stability number 0.191 (toe circle), F = c / (0.191 gamma H) = 1.309. 5 %: the chart
   !> is a circular-surface limit equilibrium (an upper bound of the mechanism) read to three
   !> digits; the finite elements' is a continuum mechanism on a Q8R mesh.
   subroutine test_taylor(error)
      type(error_t), allocatable, intent(out) :: error
      call check_factor(error, 'taylor_slope', 'taylor', 50.0_wp/(0.191_wp*20.0_wp*10.0_wp), &
         0.05_wp, 'undrained slope against Taylor''s chart')
   end subroutine test_taylor

   !> The block's results file: /safety with kind, factor and resolution as found, the note
   !> that the displacements are not physical, a curve from (1, 0) rising in Msf to the
   !> factor, the mechanism (the pad slides along x: its top node moves, the base does not),
   !> and the XDMF sidecar showing it.
   subroutine test_results_file(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_reader_t) :: r
      character(len=:), allocatable :: kind, note, line
      real(wp), allocatable :: msf(:), disp(:), mech(:, :)
      real(wp) :: f
      integer :: u, ios, hits
      character(len=512) :: buf
      call run_factor('block', f, error)
      if (allocated(error)) return
      call r%open(OUT//'block.h5', error)
      if (allocated(error)) return
      call r%attribute('/safety', 'kind', kind, error)
      if (.not. allocated(error)) call r%attribute('/safety', 'note', note, error)
      if (.not. allocated(error)) call r%dataset('/safety/msf', msf, error)
      if (.not. allocated(error)) call r%dataset('/safety/displacement', disp, error)
      if (.not. allocated(error)) call r%dataset('/safety/mechanism', mech, error)
      if (allocated(error)) return
      call check(error, kind == 'factor' .and. index(note, 'not physical') > 0, &
         '/safety kind '//kind//', note '//note)
      if (allocated(error)) return
      call check(error, msf(1) == 1.0_wp .and. disp(1) == 0.0_wp .and. &
         all(msf(2:) > msf(:size(msf) - 1)) .and. msf(size(msf)) == f, 'the curve rises '// &
         'from (1, 0) to the factor '//g6(f))
      if (allocated(error)) return
      ! nodes 1-3 are the fixed base (rows 1-3), the pad's top node 11 moves along +x
      call check(error, all(mech(:, 1:3) == 0.0_wp) .and. maxval(mech(1, :)) > 0.0_wp, &
         'the mechanism: the pad slides, the base is fixed')
      if (allocated(error)) return
      hits = 0
      open (newunit=u, file=OUT//'block.xmf', status='old', action='read')
      do
         read (u, '(a)', iostat=ios) buf
         if (ios /= 0) exit
         line = trim(buf)
         if (index(line, '/safety/mechanism3') > 0) hits = hits + 1
      end do
      close (u)
      call check(error, hits >= 1, 'the XDMF sidecar shows the mechanism')
   end subroutine test_results_file

   !> MAX_INCREMENTS=3: the run stops (exit 3, status stopped) with a lower bound below R / T.
   subroutine test_lower_bound(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call make_directories(OUT)
      code = run_deck(DATA//'block_budget.inp', OUT//'block_budget.h5', .true., model, problem)
      call check(error, code == 3 .and. problem%safety%kind == SAFETY_LOWER_BOUND, &
         'a budget too small: lower bound, exit 3 (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check(error, problem%safety%factor > 1.0_wp .and. &
         problem%safety%factor < 70.0_wp/30.0_wp, 'the lower bound '// &
         g6(problem%safety%factor)//' lies between 1 and R / T')
   end subroutine test_lower_bound

   !> Pushed by 90 > R = 70: the push step fails, the safety step never starts: exit 3,
   !> "unstable before reduction", no factor.
   subroutine test_unstable(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call make_directories(OUT)
      code = run_deck(DATA//'block_unstable.inp', OUT//'block_unstable.h5', .true., model, &
         problem)
      call check(error, code == 3 .and. problem%safety%kind == SAFETY_UNSTABLE .and. &
         problem%safety%factor == 0.0_wp, 'unstable before reduction, no factor, exit 3 '// &
         '(exit '//itoa(code)//', kind '//itoa(problem%safety%kind)//')')
   end subroutine test_unstable

   !> A safety step first, *REDUCE of an elastic material: refused with file:line, exit 2,
   !> no results file.
   subroutine test_bad_decks(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: names(2) = [character(len=18) :: 'bad_safety_first', &
         'bad_reduce_elastic']
      character(len=*), parameter :: expect(2) = [character(len=40) :: 'is the first step', &
         "material 'soil' has no strength"]
      character(len=*), parameter :: marker(2) = [character(len=96) :: '*STEP, NAME=safety, '// &
         'CONTROL=SAFETY, MSF_STEP=0.2, RESOLUTION=0.002, NODE=11, DOF=X', 'friction, soil']
      integer :: k
      call make_directories(OUT)
      do k = 1, size(names)
         call check_refused(error, DATA//trim(names(k))//'.inp', trim(marker(k)), &
            trim(expect(k)), OUT//'bad.h5', trim(names(k)))
         if (allocated(error)) return
      end do
   end subroutine test_bad_decks

end module test_safety
