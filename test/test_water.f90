!> Groundwater (doc/theory.md, Groundwater): the hydrostatic state of a layered column,
!> undrained oedometric loading (by a load and by an imposed displacement) against the closed
!> form, undrained plane-strain Mohr-Coulomb compression, smooth strip footings on UNDRAINED_A
!> and UNDRAINED_B clay against Prandtl, undrained-then-drained phases against a drained run,
!> joints under pore pressure, bad decks.
module test_water
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_massif_element_matrices, only: massif_gauss_coordinates
   use pecplas_base_strings, only: itoa, g6
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_io_results_increment, only: plate_fields_t
   use pecplas_fe_plate_output, only: plate_results
   use test_water_free, only: test_free_stages, test_free_equals_split, test_free_quay, &
      test_free_raft, test_free_bad_mode
   use test_water_joint_level, only: test_joint_level_bound
   use test_joint_k0_lobatto, only: test_k0_lobatto_at_rest
   use test_water_stiffness, only: test_undrained_penalty, test_undrained_estimator
   use test_water_held, only: test_held_plate_water
   use test_held_warning, only: test_held_warning_without_nil, test_no_held_warning_with_nil
   use test_water_level, only: test_wall_level_inside, test_plate_polyline, test_face_polyline, &
      test_plate_cone
   use test_water_curve, only: test_curved_wall, test_curved_wall_run, test_curved_trough, &
      test_curved_shell, test_curved_face
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_bad_decks, only: check_refused
   use fixtures_water, only: write_wall
   use fixtures_runs, only: run_completes
   implicit none (type, external)
   private
   public :: collect_water

   character(len=*), parameter :: OUT = 'build/test_out/water/'
   character(len=*), parameter :: NL = new_line('a')

contains

   subroutine collect_water(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('hydrostatic_column', test_hydrostatic), &
               new_unittest('undrained_oedometer', test_oedometer), &
               new_unittest('undrained_mc_compression', test_compression), &
               new_unittest('undrained_then_drained', test_short_long), &
               new_unittest('footing_undrained_b', test_footing_b), &
               new_unittest('footing_undrained_a', test_footing_a), &
               new_unittest('undrained_imposed', test_imposed), &
               new_unittest('undrained_spring_penalty', test_undrained_penalty), &
               new_unittest('undrained_estimator', test_undrained_estimator), &
               new_unittest('undrained_b_cu_depth', test_cu_depth), &
               new_unittest('joint_effective_stress', test_joint), &
               new_unittest('restart_keeps_excess', test_restart), &
               new_unittest('flooded_pit', test_flooded_pit), &
               new_unittest('water_on_a_wall', test_wall), &
               new_unittest('water_on_a_wall_phased', test_wall_phased), &
               new_unittest('water_on_a_wall_gravity_loading', test_wall_gravity), &
               new_unittest('water_on_a_wall_held_by_k0', test_held_plate_water), &
               new_unittest('held_water_warns_without_nil_step', test_held_warning_without_nil), &
               new_unittest('no_held_warning_after_nil_step', test_no_held_warning_with_nil), &
               new_unittest('water_level_inside_a_wall_element', test_wall_level_inside), &
               new_unittest('water_polyline_level_on_a_plate', test_plate_polyline), &
               new_unittest('water_polyline_level_on_a_face', test_face_polyline), &
               new_unittest('water_level_inside_a_conical_plate', test_plate_cone), &
               new_unittest('water_on_a_curved_wall', test_curved_wall), &
               new_unittest('water_on_a_curved_wall_run', test_curved_wall_run), &
               new_unittest('water_in_a_curved_trough', test_curved_trough), &
               new_unittest('water_in_a_curved_shell', test_curved_shell), &
               new_unittest('water_on_a_curved_soil_face', test_curved_face), &
               new_unittest('water_level_inside_a_joint_element', test_joint_level_bound), &
               new_unittest('k0_state_with_lobatto_joints_at_rest', test_k0_lobatto_at_rest), &
               new_unittest('water_on_free_plate_faces', test_free_stages), &
               new_unittest('water_free_faces_equal_split_sets', test_free_equals_split), &
               new_unittest('water_free_faces_quay_wall', test_free_quay), &
               new_unittest('water_free_faces_submerged_raft', test_free_raft), &
               new_unittest('water_free_faces_bad_mode', test_free_bad_mode), &
               new_unittest('bad_decks', test_bad_decks), &
               new_unittest('gravity_column', test_gravity_column)]
   end subroutine collect_water

   !> A column of nel Q4 elements (width 1, height h, base y = 0, sides on rollers): the
   !> elements below y = ysplit form set 'low', the others 'high'. `body`: the deck after
   !> the mesh, sets and supports (materials, sections, water, stresses, steps).
   subroutine write_column(path, nel, h, ysplit, body)
      character(len=*), intent(in) :: path, body
      integer, intent(in) :: nel
      real(wp), intent(in) :: h, ysplit
      integer :: u, i
      real(wp) :: dy
      dy = h/nel
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'water column', '*NODES'
      do i = 0, nel
         write (u, '(i0,a,es23.16)') 2*i + 1, ', 0.0, ', i*dy
         write (u, '(i0,a,es23.16)') 2*i + 2, ', 1.0, ', i*dy
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=low'
      do i = 1, nel
         if ((i - 0.5_wp)*dy > ysplit) exit
         write (u, '(i0,4(", ",i0))') i, 2*i - 1, 2*i, 2*i + 2, 2*i + 1
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=high'
      do i = 1, nel
         if ((i - 0.5_wp)*dy < ysplit) cycle
         write (u, '(i0,4(", ",i0))') i, 2*i - 1, 2*i, 2*i + 2, 2*i + 1
      end do
      write (u, '(a)') '*NSET, NAME=base', '1, 2', '*NSET, NAME=sides, GENERATE'
      write (u, '(a,i0)') '1, ', 2*nel + 2
      write (u, '(a)') '*NSET, NAME=top'
      write (u, '(i0,a,i0)') 2*nel + 1, ', ', 2*nel + 2
      write (u, '(a)') '*BOUNDARY', 'base, XY', 'sides, X'
      write (u, '(a)') body
      close (u)
   end subroutine write_column

   !> A layered column (sand over clay at y = 4, surface y = 10) with the phreatic level at
   !> y = 7 inside the sand, K0 procedure then a nil step: at every Gauss point the pore
   !> pressure is gamma_w (7 - y)+ and sigma'_v the closed form from the effective weights
   !> (gamma_unsat above the level, gamma_sat - gamma_w below), sigma'_h = K0 sigma'_v.
   !> The level lies on an element edge, so the K0 state is in discrete equilibrium (each
   !> integrand a polynomial that 2 x 2 Gauss integrates exactly): the nil step moves it by
   !> round-off only, 1e-12 of the stress scale (a bound on the solve's round-off for
   !> 20 elements, condition number ~ nel^2). With the level at y = 7.25 inside an element
   !> the pore pressures (a formula of the point) are checked the same way. With the level
   !> at y = 12, 2 m of water above the ground, the water's pressure on the surface
   !> (pecplas_fe_water_faces, a linear pressure integrated exactly) keeps the effective
   !> stresses those of the buoyant weight from the surface down: the same check.
   subroutine test_hydrostatic(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: GW = 10.0_wp, K0 = 0.5_wp, HS = 10.0_wp, HC = 4.0_wp
      real(wp), parameter :: GSU = 17.0_wp, GSS = 20.0_wp, GCS = 21.0_wp
      real(wp) :: level, xg(2, 4), p, sv, q, worst_p, worst_s, scale
      integer :: s, el, g, v
      character(len=:), allocatable :: body
      character(len=32) :: buf
      call make_directories(OUT)
      do v = 1, 3
         level = merge(7.0_wp, 7.25_wp, v == 1)
         if (v == 3) level = 12.0_wp
         q = GSU*max(HS - level, 0.0_wp) + (GSS - GW)*(min(level, HS) - HC)
         write (buf, '(es23.16)') level
         body = '*MATERIAL, NAME=sand'//NL//'E = 3e4, NU = 0.25, GAMMA_UNSAT = 17, '// &
            'GAMMA_SAT = 20'//NL//'*MATERIAL, NAME=clay'//NL// &
            'E = 1e4, NU = 0.3, GAMMA = 18, GAMMA_SAT = 21'//NL// &
            '*SECTION, SET=high, MATERIAL=sand'//NL//'*SECTION, SET=low, MATERIAL=clay'//NL// &
            '*WATER, NAME=gwt, GAMMA_W=10, LEVEL='//trim(adjustl(buf))//NL// &
            '*INITIAL_STRESS, TYPE=GEOSTATIC'//NL//'high, 10.0, 0.5'
         write (buf, '(es23.16)') q
         body = body//NL//'low, 4.0, 0.5, '//trim(adjustl(buf))//NL// &
            '*STEP, NAME=nil, INCREMENTS=1'//NL//'*END STEP'
         call write_column(OUT//'hydro'//itoa(v)//'.inp', 20, HS, HC, body)
         call run_completes(error, OUT//'hydro'//itoa(v)//'.inp', OUT//'hydro'//itoa(v)//'.h5', &
            model, problem, 'hydrostatic column')
         if (allocated(error)) return
         scale = GSS*HS
         worst_p = 0.0_wp
         worst_s = 0.0_wp
         do s = 1, 2
            associate (set => model%mesh%esets(s), st => problem%state%sets(s))
               do el = 1, size(set%conn, 2)
                  call massif_gauss_coordinates(problem%system%rules(s), &
                     model%mesh%x(:, set%conn(:, el)), xg)
                  do g = 1, 4
                     p = GW*max(level - xg(2, g), 0.0_wp)
                     worst_p = max(worst_p, abs(st%pore%steady(g, el) + st%pore%excess(g, el) &
                        - p))
                     if (set%name == 'high') then
                        sv = GSU*max(HS - max(xg(2, g), level), 0.0_wp) + (GSS - GW)* &
                           max(min(level, HS) - xg(2, g), 0.0_wp)
                     else
                        sv = q + (GCS - GW)*(HC - xg(2, g))
                     end if
                     worst_s = max(worst_s, abs(st%stress(2, g, el) + sv), &
                        abs(st%stress(1, g, el) + K0*sv), abs(st%stress(4, g, el)))
                  end do
               end do
            end associate
         end do
         call check_close(error, worst_p, 0.0_wp, 0.0_wp, 'pore pressure = gamma_w (h - y)', &
            atol=1.0e-12_wp*scale)
         if (allocated(error)) return
         if (v /= 2) call check_close(error, worst_s, 0.0_wp, 0.0_wp, &
            "sigma'_v, sigma'_h closed form", atol=1.0e-12_wp*scale)
         if (allocated(error)) return
      end do
   end subroutine test_hydrostatic

   !> An oedometric column (10 Q4 elements, weightless, no phreatic level) of UNDRAINED_A
   !> elastic soil under a surcharge q = 100: the strain is uniform, eps_v = -q / (M' + K_w/n)
   !> (M' = K' + 4 G / 3), so the excess pore pressure is q B_oed with
   !> B_oed = K_w/n / (M' + K_w/n) and sigma'_v = -q M' / (M' + K_w/n) at every point. Once
   !> with the default K_w/n (the nu_u = 0.495 rule: K_w/n = 45 K' for nu' = 0.3) and once
   !> with KW_N = 2e5 given. The elements represent the uniform strain exactly: 1e-8 of q
   !> is far above the round-off.
   subroutine test_oedometer(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: E = 1.0e4_wp, NU = 0.3_wp, Q = 100.0_wp
      real(wp) :: bulk, shear, m, kwn, b
      integer :: v
      character(len=:), allocatable :: body
      call make_directories(OUT)
      bulk = E/(3.0_wp*(1.0_wp - 2.0_wp*NU))
      shear = E/(2.0_wp*(1.0_wp + NU))
      m = bulk + 4.0_wp*shear/3.0_wp
      do v = 1, 2
         if (v == 1) then
            kwn = 3.0_wp*(0.495_wp - NU)/((1.0_wp - 2.0_wp*0.495_wp)*(1.0_wp + NU))*bulk
            body = '*MATERIAL, NAME=clay, DRAINAGE=UNDRAINED_A'//NL//'E = 1e4, NU = 0.3'
         else
            kwn = 2.0e5_wp
            body = '*MATERIAL, NAME=clay, DRAINAGE=UNDRAINED_A'//NL// &
               'E = 1e4, NU = 0.3, KW_N = 2e5'
         end if
         b = kwn/(m + kwn)
         body = body//NL//'*SECTION, SET=low, MATERIAL=clay'//NL// &
            '*SECTION, SET=high, MATERIAL=clay'//NL//'*LOAD, NAME=q, TYPE=FORCE'//NL// &
            'top, Y, -50'//NL//'*STEP, NAME=load, INCREMENTS=1'//NL//'q, 1.0'
         call write_column(OUT//'oedo'//itoa(v)//'.inp', 10, 10.0_wp, 5.0_wp, body)
         call run_completes(error, OUT//'oedo'//itoa(v)//'.inp', OUT//'oedo'//itoa(v)//'.h5', &
            model, problem, 'undrained oedometer')
         if (allocated(error)) return
         call check_uniform(error, problem, Q*b, Q*m/(m + kwn), 1.0e-8_wp*Q, &
            'excess pore pressure = q B_oed', "sigma'_v = -q (1 - B_oed)")
         if (allocated(error)) return
      end do
   end subroutine test_oedometer

   !> The uniform state of the oedometric column (both sets, every point): excess pore
   !> pressure `p` and sigma'_v = -`sv`, each to `atol` (the tests say why); `what_p`,
   !> `what_s` name the two checks.
   subroutine check_uniform(error, problem, p, sv, atol, what_p, what_s)
      type(error_t), allocatable, intent(out) :: error
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: p, sv, atol
      character(len=*), intent(in) :: what_p, what_s
      real(wp) :: worst_p, worst_s
      integer :: s
      worst_p = 0.0_wp
      worst_s = 0.0_wp
      do s = 1, 2
         associate (st => problem%state%sets(s))
            worst_p = max(worst_p, maxval(abs(st%pore%excess - p)))
            worst_s = max(worst_s, maxval(abs(st%stress(2, :, :) + sv)))
         end associate
      end do
      call check_close(error, worst_p, 0.0_wp, 0.0_wp, what_p, atol=atol)
      if (allocated(error)) return
      call check_close(error, worst_s, 0.0_wp, 0.0_wp, what_s, atol=atol)
   end subroutine check_uniform

   !> The oedometric column of test_oedometer (elastic UNDRAINED_A, default K_w/n) with its
   !> top pushed down d = 0.01 (imposed displacement) in 2 increments: the strain is uniform,
   !> eps_v = -d / H, so the excess pore pressure is K_w/n d / H and sigma'_v = -M' d / H at
   !> every point (1e-8 of M' d / H: the elements represent the uniform strain exactly). The
   !> problem is linear and the first iteration of each increment carries the imposed
   !> displacement's linear response K_fc d_up, with the pore water's stiffness K_w/n m m^T
   !> in K as in the assembly: each increment converges at its first iteration. (Without
   !> the water in K_fc the first iteration leaves K_w/n / (M' + K_w/n) of the response as
   !> residual and the increment needs a second.)
   subroutine test_imposed(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: E = 1.0e4_wp, NU = 0.3_wp, D = 0.01_wp, H = 10.0_wp
      real(wp) :: bulk, shear, m, kwn
      call make_directories(OUT)
      bulk = E/(3.0_wp*(1.0_wp - 2.0_wp*NU))
      shear = E/(2.0_wp*(1.0_wp + NU))
      m = bulk + 4.0_wp*shear/3.0_wp
      kwn = 3.0_wp*(0.495_wp - NU)/((1.0_wp - 2.0_wp*0.495_wp)*(1.0_wp + NU))*bulk
      call write_column(OUT//'oedo_imposed.inp', 10, H, 5.0_wp, &
         '*MATERIAL, NAME=clay, DRAINAGE=UNDRAINED_A'//NL//'E = 1e4, NU = 0.3'//NL// &
         '*SECTION, SET=low, MATERIAL=clay'//NL//'*SECTION, SET=high, MATERIAL=clay'//NL// &
         '*LOAD, NAME=push, TYPE=DISPLACEMENT'//NL//'top, Y, -1.0'//NL// &
         '*STEP, NAME=push, INCREMENTS=2'//NL//'push, 0.01')
      call run_completes(error, OUT//'oedo_imposed.inp', OUT//'oedo_imposed.h5', model, problem, &
         'undrained column pushed down')
      if (allocated(error)) return
      call check_uniform(error, problem, kwn*D/H, m*D/H, 1.0e-8_wp*m*D/H, &
         'excess pore pressure = K_w/n d / H', "sigma'_v = -M' d / H")
      if (allocated(error)) return
      call check(error, problem%stats%increments == 2 .and. problem%stats%iterations == 2, &
         'one iteration per increment (increments '//itoa(problem%stats%increments)// &
         ', iterations '//itoa(problem%stats%iterations)//')')
   end subroutine test_imposed

   !> Undrained plane-strain compression of one Q4 element of Mohr-Coulomb soil (c' = 10,
   !> phi' = 30, psi = 0) from an isotropic effective stress s'_0 = 100, the top pushed down
   !> 2 % in 40 increments against a constant lateral total stress: with no dilatancy the
   !> mean effective stress stays s'_0 (up to the pore water's compressibility: with
   !> KW_N = 1000 K' the drift is below K'/K_w/n of the deviator, 0.1 %), so the strength is
   !> t = (sigma'_1 - sigma'_3) / 2 = c' cos phi' + s'_0 sin phi', checked within 0.5 %.
   !> With psi = 10 the strength keeps rising (dilatancy lowers the pore pressure): the
   !> last increment's t is above the psi = 0 strength and still growing.
   subroutine test_compression(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: C = 10.0_wp, PHI = 30.0_wp, S0 = 100.0_wp
      real(wp) :: deg, t, expect, sig(4)
      deg = acos(-1.0_wp)/180.0_wp
      expect = C*cos(PHI*deg) + S0*sin(PHI*deg)
      call make_directories(OUT)
      call write_block(OUT//'triax0.inp', 0.0_wp)
      call run_completes(error, OUT//'triax0.inp', OUT//'triax0.h5', model, problem, &
         'undrained compression')
      if (allocated(error)) return
      sig = problem%state%sets(1)%stress(:, 1, 1)
      t = 0.5_wp*sqrt((sig(1) - sig(2))**2 + 4.0_wp*sig(4)**2)
      call check_close(error, t, expect, 5.0e-3_wp, "undrained strength c' cos phi' + "// &
         "s'_0 sin phi'")
      if (allocated(error)) return
      call write_block(OUT//'triax10.inp', 10.0_wp)
      call run_completes(error, OUT//'triax10.inp', OUT//'triax10.h5', model, problem, &
         'undrained compression, psi = 10,')
      if (allocated(error)) return
      sig = problem%state%sets(1)%stress(:, 1, 1)
      t = 0.5_wp*sqrt((sig(1) - sig(2))**2 + 4.0_wp*sig(4)**2)
      call check(error, t > 1.05_wp*expect, 'psi = 10: the strength rises above the psi = 0 '// &
         'one (dilatancy lowers the pore pressure)')
   contains
      subroutine write_block(path, psi)
         character(len=*), intent(in) :: path
         real(wp), intent(in) :: psi
         integer :: u
         open (newunit=u, file=path, status='replace', action='write')
         write (u, '(a)') '*TITLE', 'undrained plane-strain compression', '*NODES', &
            '1, 0, 0', '2, 1, 0', '3, 1, 1', '4, 0, 1', '*ELEMENTS, TYPE=Q4, SET=soil', &
            '1, 1, 2, 3, 4', '*MATERIAL, NAME=clay, TYPE=MOHR_COULOMB, DRAINAGE=UNDRAINED_A'
         write (u, '(a,f4.1,a)') 'E = 1e4, NU = 0.3, C = 10, PHI = 30, PSI = ', psi, &
            ', KW_N = 8.333333e6'
         write (u, '(a)') '*SECTION, SET=soil, MATERIAL=clay', '*NSET, NAME=top', '3, 4', &
            '*BOUNDARY', '1, XY', '2, Y', '4, X', '*INITIAL_STRESS, TYPE=HOMOGENEOUS', &
            'ALL, -100, -100, -100, 0', '*LOAD, NAME=push, TYPE=DISPLACEMENT', &
            'top, Y, -0.02', '*STEP, NAME=push, INCREMENTS=40', 'push, 1.0'
         close (u)
      end subroutine write_block
   end subroutine test_compression

   !> Elastic soil loaded undrained (q = 100 on the oedometric column), then a phase that
   !> makes it drained and sets the excess pore pressures to zero: the end state equals a
   !> drained run of the same loading (elastic: the state depends on the end strain only),
   !> displacements to 1e-10 of the drained settlement, effective stresses to 1e-10 of q.
   subroutine test_short_long(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: two, one
      real(wp) :: du, ds, umax
      integer :: code, s
      character(len=*), parameter :: MATS = '*MATERIAL, NAME=short, DRAINAGE=UNDRAINED_A'// &
         NL//'E = 1e4, NU = 0.3, GAMMA = 0'//NL//'*MATERIAL, NAME=long'//NL// &
         'E = 1e4, NU = 0.3, GAMMA = 0'//NL
      call make_directories(OUT)
      call write_column(OUT//'short_long.inp', 10, 10.0_wp, 5.0_wp, MATS// &
         '*SECTION, SET=low, MATERIAL=short'//NL//'*SECTION, SET=high, MATERIAL=short'//NL// &
         '*LOAD, NAME=q, TYPE=FORCE'//NL//'top, Y, -50'//NL// &
         '*STEP, NAME=undrained, INCREMENTS=2'//NL//'q, 1.0'//NL// &
         '*STEP, NAME=drained, INCREMENTS=2'//NL//'*CHANGE_MATERIAL'//NL//'low, long'//NL// &
         'high, long'//NL//'*CHANGE_WATER, RESET_EXCESS=YES'//NL//'*END STEP')
      call run_completes(error, OUT//'short_long.inp', OUT//'short_long.h5', model, two, &
         'undrained then drained')
      if (allocated(error)) return
      call write_column(OUT//'drained.inp', 10, 10.0_wp, 5.0_wp, MATS// &
         '*SECTION, SET=low, MATERIAL=long'//NL//'*SECTION, SET=high, MATERIAL=long'//NL// &
         '*LOAD, NAME=q, TYPE=FORCE'//NL//'top, Y, -50'//NL// &
         '*STEP, NAME=drained, INCREMENTS=2'//NL//'q, 1.0')
      code = run_deck(OUT//'drained.inp', OUT//'drained.h5', .true., model, one)
      call check(error, code == 0, 'drained run (exit '//itoa(code)//')')
      if (allocated(error)) return
      umax = maxval(abs(one%state%u))
      du = maxval(abs(two%state%u - one%state%u))
      ds = 0.0_wp
      do s = 1, 2
         ds = max(ds, maxval(abs(two%state%sets(s)%stress - one%state%sets(s)%stress)))
         ds = max(ds, maxval(abs(two%state%sets(s)%pore%excess)))
      end do
      call check_close(error, du, 0.0_wp, 0.0_wp, 'displacements = drained run', &
         atol=1.0e-10_wp*umax)
      if (allocated(error)) return
      call check_close(error, ds, 0.0_wp, 0.0_wp, 'effective stresses = drained run', &
         atol=1.0e-10_wp*100.0_wp)
   end subroutine test_short_long

   !> Smooth rigid strip footing on weightless UNDRAINED_B clay (c_u = 10, effective E, nu,
   !> K_w/n of nu_u = 0.495), 200 Q8R elements (test/data/water/footing_undrained_b.inp):
   !> the footing pressure reaches Prandtl's (2 + pi) c_u within 2 % (measured 51.859,
   !> +0.86 %; T6 on the same mesh density +0.75 %, full Q8 +1.6 %, the stiffening of
   !> full integration) and has levelled off (last 10 increments within 0.2 %).
   subroutine test_footing_b(error)
      type(error_t), allocatable, intent(out) :: error
      call check_footing(error, 'footing_undrained_b', 0.02_wp)
   end subroutine test_footing_b

   !> The same footing on weightless UNDRAINED_A clay (c' = 2, phi' = 20, psi = 0) from the
   !> isotropic effective stress s'_0 that makes c' cos phi' + s'_0 sin phi' = 10 = c_u
   !> everywhere, with the pore water's own K_w/n (4.4e6 kPa = 528 K'; the finite K_w/n
   !> raises c_u where the mean total stress rises, by K'_ps / (K'_ps + K_w/n) sin phi' of
   !> it, doc/theory.md 14; test/data/water/footing_undrained_a.inp): the plateau lies
   !> within 3 % of (2 + pi) c_u (measured 51.998, +1.13 %: +0.86 % the mesh's own, as the
   !> UNDRAINED_B footing, +0.27 % the effective stress path on it) and has levelled off.
   subroutine test_footing_a(error)
      type(error_t), allocatable, intent(out) :: error
      call check_footing(error, 'footing_undrained_a', 0.03_wp)
   end subroutine test_footing_a

   !> Runs test/data/water/<name>.inp (the half footing of width 1, c_u = 10): the footing
   !> pressure of the last increment is (2 + pi) c_u within rtol, and within 0.2 % of the
   !> one 10 increments before (levelled off).
   subroutine check_footing(error, name, rtol)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: rtol
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: rd
      real(wp), allocatable :: reac(:, :)
      real(wp) :: q(2), qu
      character(len=40) :: path
      integer :: n, k, i
      call make_directories(OUT)
      call run_completes(error, 'test/data/water/'//name//'.inp', OUT//name//'.h5', model, &
         problem, name)
      if (allocated(error)) return
      k = model%mesh%find_nset('footing')
      call rd%open(OUT//name//'.h5', error)
      if (allocated(error)) return
      call rd%history_length(n, error)
      if (allocated(error)) return
      do i = 1, 2
         write (path, '(a,i6.6,a)') '/increments/', merge(n, n - 10, i == 1), '/reaction'
         call rd%dataset(trim(path), reac, error)
         if (allocated(error)) return
         q(i) = -sum(reac(2, model%mesh%nsets(k)%nodes)) ! half-width 1: q b = q
      end do
      call rd%close()
      qu = (2.0_wp + acos(-1.0_wp))*10.0_wp
      call check_close(error, q(1), qu, rtol, name//': footing pressure vs (2 + pi) c_u')
      if (allocated(error)) return
      call check(error, abs(q(1) - q(2)) <= 2.0e-3_wp*q(1), name//': the footing pressure '// &
         'has levelled off')
   end subroutine check_footing

   !> A pad (2 x 0.25 at y = 1 to 1.25, low so that the push's moment keeps every joint
   !> point closed; weightless elastic) pressed by 100 onto a fixed block through
   !> Mohr-Coulomb Goodman joints (phi = 30, c = 5) at y = 1, all under a phreatic level at
   !> y = 5 (gamma_w = 10); a nil step after the pressure releases the out-of-balance of the
   !> pore pressures (the buoyancy of the weightless pad). The joint takes the pore pressure
   !> u = 40 of its position; the water on the pad's top (37.5) adds to the pressure, so the
   !> pad's vertical equilibrium makes the mean total normal stress sigma_n = 137.5 and the
   !> law's mean effective normal stress sigma_n - u = 97.5 (1e-8 of 100; the submerged pad's
   !> buoyancy, 2.5, taken off the 100), and the sliding resistance over the width 2 is
   !> 2 ((sigma_n - u) tan phi + c) = 122.58. Pushed sideways by 0.99 of it the run converges,
   !> the mean shear stress T / 2 (1e-8); by 1.01 of it the pad slides away (the run stops,
   !> exit 3), where a joint blind to the pore pressure (resistance 2 (137.5 tan phi + c) =
   !> 168.8) would hold.
   subroutine test_joint(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp) :: resist, tanphi, worst_n, worst_t
      integer :: code
      tanphi = tan(30.0_wp*acos(-1.0_wp)/180.0_wp)
      resist = 2.0_wp*((137.5_wp - 40.0_wp)*tanphi + 5.0_wp)
      call make_directories(OUT)
      call write_pad(OUT//'pad_hold.inp', 0.99_wp*resist)
      code = run_deck(OUT//'pad_hold.inp', OUT//'pad_hold.h5', .true., model, problem)
      call check(error, code == 0, 'pad below the effective resistance holds (exit '// &
         itoa(code)//')')
      if (allocated(error)) return
      associate (js => problem%state%joints%sets(1))
         ! equal weights: 2 Gauss points on each of 2 elements of length 1
         worst_n = abs(sum(js%sigma(1, :, :))/4.0_wp - 97.5_wp)
         worst_t = abs(abs(sum(js%sigma(2, :, :)))/4.0_wp - 0.99_wp*resist/2.0_wp)
         call check(error, all(abs(js%pore - 40.0_wp) <= 1.0e-12_wp*40.0_wp), &
            'joint pore pressure = gamma_w (5 - 1)')
      end associate
      if (allocated(error)) return
      call check_close(error, worst_n, 0.0_wp, 0.0_wp, 'effective normal stress sigma_n - u', &
         atol=1.0e-8_wp*100.0_wp)
      if (allocated(error)) return
      call check_close(error, worst_t, 0.0_wp, 0.0_wp, 'shear stress T / width', &
         atol=1.0e-8_wp*100.0_wp)
      if (allocated(error)) return
      call write_pad(OUT//'pad_slide.inp', 1.01_wp*resist)
      code = run_deck(OUT//'pad_slide.inp', OUT//'pad_slide.h5', .true., model, problem)
      call check(error, code == 3, 'pad above the effective resistance slides (exit 3, got '// &
         itoa(code)//')')
   contains
      subroutine write_pad(path, push)
         character(len=*), intent(in) :: path
         real(wp), intent(in) :: push
         integer :: u
         character(len=32) :: buf
         write (buf, '(es23.16)') push/3.0_wp
         open (newunit=u, file=path, status='replace', action='write')
         write (u, '(a)') '*TITLE', 'pad under water', '*NODES', '1, 0, 0', '2, 1, 0', &
            '3, 2, 0', '4, 0, 1', '5, 1, 1', '6, 2, 1', '10, 0, 1.25', '11, 1, 1.25', &
            '12, 2, 1.25', &
            '*ELEMENTS, TYPE=Q4, SET=ground', '1, 1, 2, 5, 4', '2, 2, 3, 6, 5', &
            '*ELEMENTS, TYPE=Q4, SET=pad', '3, 4, 5, 11, 10', '4, 5, 6, 12, 11', &
            '*MATERIAL, NAME=soil', 'E = 1e4, NU = 0.3', '*SECTION, SET=ground, MATERIAL=soil', &
            '*SECTION, SET=pad, MATERIAL=soil', &
            '*INTERFACE_LAW, NAME=friction, TYPE=MOHR_COULOMB', &
            'KN = 1e5, KT = 1e5, PHI = 30, C = 5', '*EDGES, NAME=interface', '4, 5', '5, 6', &
            '*JOINTS, TYPE=GOODMAN4, SET=contact, LAW=friction, EDGES=interface, SIDE=pad', &
            '*WATER, NAME=gwt, GAMMA_W=10, LEVEL=5', &
            '*NSET, NAME=base', '1, 2, 3', '*NSET, NAME=pad_top', '10, 11, 12', '*BOUNDARY', &
            'base, XY', '*EDGES, NAME=top', '10, 11', '11, 12', '*LOAD, NAME=p, TYPE=PRESSURE', &
            'top, 100', '*LOAD, NAME=push, TYPE=FORCE', 'pad_top, X, '//trim(adjustl(buf)), &
            '*SOLVER, METHOD=NEWTON, TOLERANCE=1e-10, MAX_ITERATIONS=50, MAX_CUTS=4', &
            '*STEP, NAME=press, INCREMENTS=1', 'p, 1', &
            '*STEP, NAME=water, INCREMENTS=1', '*END STEP', '*STEP, NAME=push, INCREMENTS=4', 'push, 1'
         close (u)
      end subroutine write_pad
   end subroutine test_joint

   !> Bad groundwater decks stop while reading, with file:line and the reason, exit 2 and no
   !> results file: a phreatic polyline that does not span the model, GAMMA_SAT below
   !> GAMMA_UNSAT, an undrained interface law, an unknown level in *CHANGE_WATER, CU
   !> without UNDRAINED_B, UNDRAINED_B on an elastic material.
   subroutine test_bad_decks(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: MAT = '*MATERIAL, NAME=clay'//NL//'E = 1e4, NU = 0.3'//NL
      character(len=*), parameter :: SECS = '*SECTION, SET=low, MATERIAL=clay'//NL// &
         '*SECTION, SET=high, MATERIAL=clay'//NL
      character(len=*), parameter :: STEP = '*STEP, NAME=nil, INCREMENTS=1'//NL//'*END STEP'
      character(len=160) :: bodies(6), marker(6), expect(6)
      character(len=:), allocatable :: deck, body
      integer :: k, i
      bodies(1) = '*WATER, NAME=w, GAMMA_W=10|0.2, 5|0.8, 6|'
      marker(1) = '*WATER, NAME=w, GAMMA_W=10'
      expect(1) = 'does not cross the model'
      bodies(2) = '*MATERIAL, NAME=clay|E = 1e4, NU = 0.3, GAMMA = 18, GAMMA_SAT = 16|'
      marker(2) = 'E = 1e4, NU = 0.3, GAMMA = 18, GAMMA_SAT = 16'
      expect(2) = 'GAMMA_SAT = 16 is below'
      bodies(3) = '*INTERFACE_LAW, NAME=j, TYPE=MOHR_COULOMB, DRAINAGE=UNDRAINED_A|'// &
         'KN = 1e5, KT = 1e5, PHI = 30, C = 0|'
      marker(3) = '*INTERFACE_LAW, NAME=j, TYPE=MOHR_COULOMB, DRAINAGE=UNDRAINED_A'
      expect(3) = 'joints are drained'
      bodies(4) = '*WATER, NAME=w, GAMMA_W=10, LEVEL=5|*STEP, NAME=two, INCREMENTS=1|'// &
         '*CHANGE_WATER, LEVEL=low|*END STEP|'
      marker(4) = '*CHANGE_WATER, LEVEL=low'
      expect(4) = "undefined phreatic level 'low'"
      bodies(5) = '*MATERIAL, NAME=clay, TYPE=MOHR_COULOMB|E = 1e4, NU = 0.3, C = 5, '// &
         'PHI = 20, PSI = 0, CU = 10|'
      marker(5) = 'E = 1e4, NU = 0.3, C = 5, PHI = 20, PSI = 0, CU = 10'
      expect(5) = 'is for DRAINAGE=UNDRAINED_B'
      bodies(6) = '*MATERIAL, NAME=clay, DRAINAGE=UNDRAINED_B|E = 1e4, NU = 0.3, CU = 10|'
      marker(6) = 'E = 1e4, NU = 0.3, CU = 10'
      expect(6) = 'needs a plastic model'
      call make_directories(OUT)
      do k = 1, size(bodies)
         body = trim(bodies(k))
         do i = 1, len(body)
            if (body(i:i) == '|') body(i:i) = NL
         end do
         if (k /= 2 .and. k /= 5 .and. k /= 6) body = MAT//body
         deck = OUT//'bad'//itoa(k)//'.inp'
         call write_column(deck, 4, 4.0_wp, 2.0_wp, body//SECS//STEP)
         call check_refused(error, deck, trim(marker(k)), trim(expect(k)), OUT//'bad.h5', &
            'bad deck '//itoa(k))
         if (allocated(error)) return
      end do
   end subroutine test_bad_decks

   !> The undrained oedometer loaded in 4 increments, stopped after 2 and restarted from its
   !> results file, ends with the excess pore pressures and displacements of the
   !> uninterrupted run (1e-12 of q and of the settlement: the same operations).
   subroutine test_restart(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: whole, resumed
      character(len=*), parameter :: deck = OUT//'oedo_restart.inp'
      real(wp) :: dp, du
      integer :: code, s
      call make_directories(OUT)
      call write_column(deck, 10, 10.0_wp, 5.0_wp, '*MATERIAL, NAME=clay, '// &
         'DRAINAGE=UNDRAINED_A'//NL//'E = 1e4, NU = 0.3'//NL// &
         '*SECTION, SET=low, MATERIAL=clay'//NL//'*SECTION, SET=high, MATERIAL=clay'//NL// &
         '*LOAD, NAME=q, TYPE=FORCE'//NL//'top, Y, -50'//NL// &
         '*STEP, NAME=load, INCREMENTS=4'//NL//'q, 1.0')
      call run_completes(error, deck, OUT//'oedo_whole.h5', model, whole, 'undrained oedometer')
      if (allocated(error)) return
      code = run_deck(deck, OUT//'oedo_part.h5', .true., model, resumed, stop_after=2)
      call check(error, code == 4, 'stopped after increment 2 (exit '//itoa(code)//')')
      if (allocated(error)) return
      code = run_deck(deck, OUT//'oedo_resumed.h5', .true., model, resumed, &
         restart=OUT//'oedo_part.h5')
      call check(error, code == 0, 'restarted (exit '//itoa(code)//')')
      if (allocated(error)) return
      du = maxval(abs(resumed%state%u - whole%state%u))
      dp = 0.0_wp
      do s = 1, 2
         dp = max(dp, maxval(abs(resumed%state%sets(s)%pore%excess - &
            whole%state%sets(s)%pore%excess)))
      end do
      call check_close(error, dp, 0.0_wp, 0.0_wp, 'restarted = uninterrupted: excess pore '// &
         'pressures', atol=1.0e-12_wp*100.0_wp)
      if (allocated(error)) return
      call check_close(error, du, 0.0_wp, 0.0_wp, 'restarted = uninterrupted: displacements', &
         atol=1.0e-12_wp*maxval(abs(whole%state%u)))
   end subroutine test_restart

   !> A saturated K0 column (gamma_sat = 20, level at the surface y = 10, K0 = 0.5, elastic
   !> E = 3e4, nu = 0.25) dug to y = 7 with the pit kept flooded to y = 10: the water on the
   !> pit floor (gamma_w 3 = 30) replaces the 60 of the soil removed, so the effective
   !> stresses below fall uniformly by 30 (oedometric unloading, which Q4 elements represent
   !> exactly): sigma'_v = 10 (7 - y), sigma'_h = 5 (10 - y) - nu/(1 - nu) 30, and the floor
   !> heaves 30 y / M. To 1e-10 of the stress scale (round-off of the solves).
   subroutine test_flooded_pit(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: E = 3.0e4_wp, NU = 0.25_wp
      real(wp) :: xg(2, 4), worst_s, worst_u, m, sv, sh
      integer :: el, g, n
      call make_directories(OUT)
      call write_column(OUT//'pit.inp', 20, 10.0_wp, 7.0_wp, '*MATERIAL, NAME=soil'//NL// &
         'E = 3e4, NU = 0.25, GAMMA = 20, GAMMA_SAT = 20'//NL// &
         '*SECTION, SET=low, MATERIAL=soil'//NL//'*SECTION, SET=high, MATERIAL=soil'//NL// &
         '*WATER, NAME=gwt, GAMMA_W=10, LEVEL=10'//NL//'*INITIAL_STRESS, TYPE=GEOSTATIC'// &
         NL//'ALL, 10.0, 0.5'//NL//'*STEP, NAME=nil, INCREMENTS=1'//NL//'*END STEP'//NL// &
         '*STEP, NAME=dig, INCREMENTS=1'//NL//'*DEACTIVATE'//NL//'high'//NL//'*END STEP')
      call run_completes(error, OUT//'pit.inp', OUT//'pit.h5', model, problem, 'flooded pit')
      if (allocated(error)) return
      m = E*(1.0_wp - NU)/((1.0_wp + NU)*(1.0_wp - 2.0_wp*NU))
      worst_s = 0.0_wp
      associate (set => model%mesh%esets(1), st => problem%state%sets(1))
         do el = 1, size(set%conn, 2)
            call massif_gauss_coordinates(problem%system%rules(1), &
               model%mesh%x(:, set%conn(:, el)), xg)
            do g = 1, 4
               sv = 10.0_wp*(7.0_wp - xg(2, g))
               sh = 5.0_wp*(10.0_wp - xg(2, g)) - NU/(1.0_wp - NU)*30.0_wp
               worst_s = max(worst_s, abs(st%stress(2, g, el) + sv), &
                  abs(st%stress(1, g, el) + sh))
            end do
         end do
      end associate
      worst_u = 0.0_wp
      do n = 1, 30
         worst_u = max(worst_u, abs(problem%state%u(2, n) - 30.0_wp*model%mesh%x(2, n)/m))
      end do
      call check_close(error, worst_s, 0.0_wp, 0.0_wp, "sigma' below the flooded pit", &
         atol=1.0e-10_wp*200.0_wp)
      if (allocated(error)) return
      call check_close(error, worst_u, 0.0_wp, 0.0_wp, 'heave 30 y / M', &
         atol=1.0e-10_wp*30.0_wp*7.0_wp/m)
   end subroutine test_flooded_pit

   !> UNDRAINED_B with c_u rising with depth, c_u(y) = 10 + 4 (1 - y) below y = 1: one Q4
   !> element (0 <= y <= 1) from an isotropic effective stress of 100 compressed 2 % in plane
   !> strain (far beyond the yield strain c_u / G ~ 0.3 %): every Gauss point ends on its own
   !> Tresca surface, t = (sigma'_1 - sigma'_3) / 2 = c_u(y_g), to 1e-8 of c_u (the return
   !> map lands on the surface to round-off).
   subroutine test_cu_depth(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp) :: xg(2, 4), sig(4), t, worst
      integer :: u, g
      call make_directories(OUT)
      open (newunit=u, file=OUT//'cu_depth.inp', status='replace', action='write')
      write (u, '(a)') '*TITLE', 'c_u rising with depth', '*NODES', '1, 0, 0', '2, 1, 0', &
         '3, 1, 1', '4, 0, 1', '*ELEMENTS, TYPE=Q4, SET=soil', '1, 1, 2, 3, 4', &
         '*MATERIAL, NAME=clay, TYPE=MOHR_COULOMB, DRAINAGE=UNDRAINED_B', &
         'E = 1e4, NU = 0.3, CU = 10, CU_INC = 4, CU_YREF = 1', &
         '*SECTION, SET=soil, MATERIAL=clay', '*NSET, NAME=top', '3, 4', '*BOUNDARY', &
         '1, XY', '2, Y', '4, X', '*INITIAL_STRESS, TYPE=HOMOGENEOUS', &
         'ALL, -100, -100, -100, 0', '*LOAD, NAME=push, TYPE=DISPLACEMENT', &
         'top, Y, -0.02', '*STEP, NAME=push, INCREMENTS=20', 'push, 1.0'
      close (u)
      call run_completes(error, OUT//'cu_depth.inp', OUT//'cu_depth.h5', model, problem, &
         'UNDRAINED_B with CU_INC')
      if (allocated(error)) return
      call massif_gauss_coordinates(problem%system%rules(1), &
         model%mesh%x(:, model%mesh%esets(1)%conn(:, 1)), xg)
      worst = 0.0_wp
      do g = 1, 4
         sig = problem%state%sets(1)%stress(:, g, 1)
         t = 0.5_wp*sqrt((sig(1) - sig(2))**2 + 4.0_wp*sig(4)**2)
         worst = max(worst, abs(t - (10.0_wp + 4.0_wp*(1.0_wp - xg(2, g)))))
      end do
      call check_close(error, worst, 0.0_wp, 0.0_wp, 't = c_u(y) at every Gauss point', &
         atol=1.0e-8_wp*10.0_wp)
   end subroutine test_cu_depth

   !> A plate wall (x = 0, 0 <= y <= 10, ten 2-node elements, clamped at its base) with water
   !> on its left to the level y = 6 (*PLATE_WATER), released by a nil step: the shear at
   !> the base is the water's resultant gamma_w h^2 / 2 = 180 and the moment gamma_w h^3 / 6
   !> = 360 per unit length (1e-8: the consistent loads of the linear pressure are exact, the
   !> level on a node, and the cantilever is statically determinate).
   subroutine test_wall(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(plate_fields_t) :: f
      call make_directories(OUT)
      call write_wall(OUT//'wall.inp', 'water on a wall', 10, '6', [character(len=32) :: &
         '*PLATE_WATER', 'wall, LEFT', '*STEP, NAME=water, INCREMENTS=1', '*END STEP'])
      call run_completes(error, OUT//'wall.inp', OUT//'wall.h5', model, problem, 'wall in water')
      if (allocated(error)) return
      call plate_results(model, problem%state%u, problem%state%plates, problem%state%factors, &
         1, f, error, level=1)
      if (allocated(error)) return
      call check_wall_base(error, f%node_forces, 1.0_wp, '')
      if (allocated(error)) return
      call check(error, problem%state%u(1, 11) > 0.0_wp, 'the water on the left pushes the '// &
         'wall to the right (+x)')
   end subroutine test_wall

   !> Gravity loading (a GRAVITY pattern, no *INITIAL_STRESS) of the layered wet column of
   !> hydrostatic_column (sand over clay at y = 4, surface y = 10, 20 Q4), four increments:
   !> the pore pressures' forces and the water on the faces come in with the weight
   !> (doc/theory.md, Groundwater), so at increment i of n every Gauss point has sigma'_v =
   !> (i/n) times the closed form of the effective weights, the reported steady pore
   !> pressure is (i/n) gamma_w (h - y)+ (exact: the same formula), and the vertical base
   !> reaction plus the water's push on the base, (i/n) gamma_w h, is (i/n) times the
   !> column's total weight (gamma_sat below the
   !> level, the water standing on the ground included). A Q4 column has u_y linear in each
   !> element, so its sigma'_v is constant per element: the closed form at the element's
   !> middle (the average of the linear sigma'_v over the element, exact since the nodal
   !> displacements of a 1D bar of linear elements under consistent loads are exact, the
   !> level and the layer boundary on element edges); in a drained Mohr-Coulomb soil that
   !> yields (sand: phi = 20, c = 1, Ka = 0.49 > K0 = 1/3) the vertical equilibrium gives the
   !> same sigma'_v (both Gauss rows of an element follow the same strain path). Tolerance
   !> 1e-10 of gamma_sat H: the solve's round-off for 20 elements (condition ~ nel^2) and
   !> the Newton tolerance 1e-12 of the plastic runs.
   subroutine test_gravity_column(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: rd
      real(wp), parameter :: GW = 10.0_wp, HS = 10.0_wp, HC = 4.0_wp
      real(wp), parameter :: GSU = 17.0_wp, GSS = 20.0_wp, GCS = 21.0_wp
      integer, parameter :: NINC = 4
      real(wp), allocatable :: sig(:, :, :), reac(:, :), pst(:, :)
      real(wp) :: level, xg(2, 4), p, sv, q, worst_p, worst_s, scale, ym, weight, base, lam, ratio
      integer :: s, el, g, v, i
      character(len=:), allocatable :: body, name
      character(len=64) :: path
      character(len=32) :: buf
      call make_directories(OUT)
      do v = 1, 3
         level = merge(12.0_wp, 7.0_wp, v == 2)
         q = GSU*max(HS - level, 0.0_wp) + (GSS - GW)*(min(level, HS) - HC)
         weight = GSU*max(HS - level, 0.0_wp) + GSS*(min(level, HS) - HC) + GCS*HC + &
            GW*max(level - HS, 0.0_wp)
         write (buf, '(es23.16)') level
         if (v == 3) then
            body = '*MATERIAL, NAME=sand, TYPE=MOHR_COULOMB'//NL//'E = 3e4, NU = 0.25, '// &
               'C = 1, PHI = 20, PSI = 0, GAMMA_UNSAT = 17, GAMMA_SAT = 20'//NL// &
               '*MATERIAL, NAME=clay, TYPE=MOHR_COULOMB'//NL// &
               'E = 1e4, NU = 0.3, C = 2, PHI = 15, PSI = 0, GAMMA = 18, GAMMA_SAT = 21'
         else
            body = '*MATERIAL, NAME=sand'//NL//'E = 3e4, NU = 0.25, GAMMA_UNSAT = 17, '// &
               'GAMMA_SAT = 20'//NL//'*MATERIAL, NAME=clay'//NL// &
               'E = 1e4, NU = 0.3, GAMMA = 18, GAMMA_SAT = 21'
         end if
         body = body//NL//'*SECTION, SET=high, MATERIAL=sand'//NL// &
            '*SECTION, SET=low, MATERIAL=clay'//NL// &
            '*WATER, NAME=gwt, GAMMA_W=10, LEVEL='//trim(adjustl(buf))//NL// &
            '*LOAD, NAME=weight, TYPE=GRAVITY'//NL//'ALL'//NL// &
            '*SOLVER, TOLERANCE=1e-12'//NL// &
            '*STEP, NAME=gravity, INCREMENTS='//itoa(NINC)//NL//'weight, 1'//NL//'*END STEP'
         name = OUT//'gravity'//itoa(v)
         call write_column(name//'.inp', 20, HS, HC, body)
         call run_completes(error, name//'.inp', name//'.h5', model, problem, 'gravity column')
         if (allocated(error)) return
         scale = GSS*HS
         call rd%open(name//'.h5', error)
         if (allocated(error)) return
         do i = 1, NINC
            lam = real(i, wp)/NINC
            ratio = 0.0_wp
            worst_p = 0.0_wp
            worst_s = 0.0_wp
            do s = 1, 2
               associate (set => model%mesh%esets(s))
                  write (path, '(a,i6.6,a)') '/increments/', i, '/sets/'//trim(set%name)// &
                     '/stress'
                  call rd%dataset(trim(path), sig, error)
                  if (allocated(error)) return
                  write (path, '(a,i6.6,a)') '/increments/', i, '/sets/'//trim(set%name)// &
                     '/pore_steady'
                  call rd%dataset(trim(path), pst, error)
                  if (allocated(error)) return
                  do el = 1, size(set%conn, 2)
                     call massif_gauss_coordinates(problem%system%rules(s), &
                        model%mesh%x(:, set%conn(:, el)), xg)
                     ym = 0.5_wp*(minval(xg(2, :)) + maxval(xg(2, :)))
                     if (set%name == 'high') then
                        sv = GSU*max(HS - max(ym, level), 0.0_wp) + (GSS - GW)* &
                           max(min(level, HS) - ym, 0.0_wp)
                     else
                        sv = q + (GCS - GW)*(HC - ym)
                     end if
                     do g = 1, 4
                        p = GW*max(level - xg(2, g), 0.0_wp)
                        worst_p = max(worst_p, abs(pst(g, el) - lam*p))
                        worst_s = max(worst_s, abs(sig(2, g, el) + lam*sv), abs(sig(4, g, el)))
                        if (set%name == 'high' .and. sig(2, g, el) < 0.0_wp) &
                           ratio = max(ratio, sig(1, g, el)/sig(2, g, el))
                     end do
                  end do
               end associate
            end do
            write (path, '(a,i6.6,a)') '/increments/', i, '/reaction'
            call rd%dataset(trim(path), reac, error)
            if (allocated(error)) return
            ! the water's push on the supported base (lambda gamma_w h at y = 0, width 1)
            base = sum(reac(2, 1:2)) + lam*GW*level
            call check_close(error, worst_p, 0.0_wp, 0.0_wp, 'p = gamma_w (h - y)+', &
               atol=1.0e-10_wp*scale)
            if (allocated(error)) return
            call check_close(error, worst_s, 0.0_wp, 0.0_wp, "sigma'_v = lambda closed form", &
               atol=1.0e-10_wp*scale)
            if (allocated(error)) return
            call check_close(error, base, lam*weight, 0.0_wp, &
               'base reaction + water on the base = lambda total weight', atol=1.0e-10_wp*scale)
            if (allocated(error)) return
            ! the Mohr-Coulomb sand yields: sigma'_h / sigma'_v rises towards K_a = 0.49 (c = 1
            ! lowers it, the more the lower the stress), above the elastic nu / (1 - nu) = 1/3
            if (v == 3) call check(error, ratio > 0.4_wp, 'the Mohr-Coulomb sand yields')
            if (allocated(error)) return
         end do
         call rd%close()
      end do
   end subroutine test_gravity_column

   !> The wall of test_wall with the water appearing in phase 2 (*PLATE_WATER inside the
   !> step, applied over its two increments): after phase 1 the wall carries nothing (base
   !> shear 0: no load at all), at the end of phase 2 the base shear is gamma_w h^2/2 = 180
   !> and the moment gamma_w h^3/6 = 360 (linear, 1e-8 as in test_wall); a run stopped after
   !> phase 1 (and one stopped inside phase 2) and restarted ends as the uninterrupted run
   !> (1e-12 of the displacements: the same operations on the same numbers but for the
   !> restart file's round trip).
   subroutine test_wall_phased(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: whole, part
      type(plate_fields_t) :: f
      type(results_reader_t) :: file
      real(wp), allocatable :: nf(:, :)
      character(len=*), parameter :: deck = OUT//'wall_phased.inp'
      integer :: code, stop
      call make_directories(OUT)
      call write_wall(deck, 'water on a wall from phase 2', 10, '6', [character(len=32) :: &
         '*STEP, NAME=dry, INCREMENTS=1', '*END STEP', '*STEP, NAME=flood, INCREMENTS=2', &
         '*PLATE_WATER', 'wall, LEFT', '*END STEP'])
      code = run_deck(deck, OUT//'wall_phase1.h5', .true., model, part, stop_after=1)
      call check(error, code == 4, 'stopped after phase 1 (exit '//itoa(code)//')')
      if (allocated(error)) return
      call plate_results(model, part%state%u, part%state%plates, part%state%factors, 1, f, &
         error, level=1, step=1)
      if (allocated(error)) return
      call check_close(error, abs(f%node_forces(2, 1)) + abs(f%node_forces(3, 1)), 0.0_wp, &
         0.0_wp, 'no water on the wall in phase 1', atol=1.0e-8_wp*180.0_wp)
      if (allocated(error)) return
      call run_completes(error, deck, OUT//'wall_phased.h5', model, whole, 'phased wall in water')
      if (allocated(error)) return
      call plate_results(model, whole%state%u, whole%state%plates, whole%state%factors, 1, f, &
         error, level=1, step=2)
      if (allocated(error)) return
      call check_wall_base(error, f%node_forces, 1.0_wp, ' at the end of phase 2')
      if (allocated(error)) return
      ! the results file: the water comes in along the phase's two increments (the carried
      ! out-of-balance), so the forces the first one writes are half the final ones (linear)
      call file%open(OUT//'wall_phased.h5', error)
      if (allocated(error)) return
      call file%dataset('/increments/000002/plates/wall/node_forces', nf, error)
      if (allocated(error)) return
      call check_wall_base(error, nf, 0.5_wp, ' written half-way through phase 2')
      if (allocated(error)) return
      call file%close()
      do stop = 1, 2
         code = run_deck(deck, OUT//'wall_part'//itoa(stop)//'.h5', .true., model, part, &
            stop_after=stop)
         call check(error, code == 4, 'stopped (exit '//itoa(code)//')')
         if (allocated(error)) return
         code = run_deck(deck, OUT//'wall_resumed'//itoa(stop)//'.h5', .true., model, part, &
            restart=OUT//'wall_part'//itoa(stop)//'.h5')
         call check(error, code == 0, 'restarted (exit '//itoa(code)//')')
         if (allocated(error)) return
         call check_close(error, maxval(abs(part%state%u - whole%state%u)), 0.0_wp, 0.0_wp, &
            'restarted after increment '//itoa(stop)//' = uninterrupted', &
            atol=1.0e-12_wp*maxval(abs(whole%state%u)))
         if (allocated(error)) return
      end do
   end subroutine test_wall_phased

   !> Gravity loading brings the water on a plate in with the weight (the GRAVITY pattern's
   !> factor): the wall of water_on_a_wall_phased with its water from the start and a GRAVITY
   !> pattern in two increments: the section forces written after the first are half the
   !> hydrostatic ones (linear: 1e-8), the whole after the second.
   subroutine test_wall_gravity(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: whole
      type(results_reader_t) :: file
      real(wp), allocatable :: nf(:, :)
      character(len=*), parameter :: deck = OUT//'wall_gravity.inp'
      integer :: i
      call make_directories(OUT)
      call write_wall(deck, 'water on a wall under gravity loading', 10, '6', &
         [character(len=34) :: '*PLATE_WATER', 'wall, LEFT', '*LOAD, NAME=weight, TYPE=GRAVITY', &
         'wall', '*STEP, NAME=gravity, INCREMENTS=2', 'weight, 1', '*END STEP'])
      call run_completes(error, deck, OUT//'wall_gravity.h5', model, whole, &
         'wall under gravity loading')
      if (allocated(error)) return
      call file%open(OUT//'wall_gravity.h5', error)
      if (allocated(error)) return
      do i = 1, 2
         call file%dataset('/increments/00000'//itoa(i)//'/plates/wall/node_forces', nf, error)
         if (allocated(error)) return
         call check_wall_base(error, nf, 0.5_wp*i, ' after increment '//itoa(i)//' of 2')
         if (allocated(error)) return
      end do
      call file%close()
   end subroutine test_wall_gravity

   !> The wall of the water tests (water 6 m deep on one face, gamma_w = 10): its base shear
   !> and moment (rows 2 and 3 of the plate's node forces at its base node) are `share` of the
   !> hydrostatic resultant gamma_w h^2 / 2 = 180 and its moment gamma_w h^3 / 6 = 360
   !> (tolerance 1e-8: the wall is statically determinate, the forces its own equilibrium).
   subroutine check_wall_base(error, forces, share, when)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in) :: forces(:, :), share
      character(len=*), intent(in) :: when
      call check_close(error, abs(forces(2, 1)), share*180.0_wp, 1.0e-8_wp, &
         'base shear'//when//' = '//g6(share)//' gamma_w h^2 / 2')
      if (allocated(error)) return
      call check_close(error, abs(forces(3, 1)), share*360.0_wp, 1.0e-8_wp, &
         'base moment'//when//' = '//g6(share)//' gamma_w h^3 / 6')
   end subroutine check_wall_base
end module test_water
