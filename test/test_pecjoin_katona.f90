!> Katona contact (Lagrange multipliers on node doublets) through the whole program:
!> joint patch tests with an exact uniform pressure and zero interpenetration (springs,
!> Goodman 4/6 doublets, plane strain and axisymmetric, regular and floating bodies), the
!> Hertz line contact against the closed form (doc/validation.md), the S1 opening-closing cycle,
!> separation at the tensile strength, and the state iteration's answer when it cannot settle.
module test_pecjoin_katona
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error, ERR_RUN
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_joints_laws_type, only: MODE_OPEN, MODE_SLIP
   use pecplas_joints_katona_type, only: katona_t
   use pecplas_joints_katona_states, only: solve_states, MAX_FLIPS
   use doc_report, only: report
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_pecjoin_katona

   character(len=*), parameter :: DIR = 'build/test_out/katona', DATA = 'test/data/katona/'
   !> make_katona_decks.py: DELTA, heights, materials; pressure of the floating decks.
   real(wp), parameter :: DELTA = 1.0e-3_wp, H1 = 1.0_wp, H2 = 0.5_wp, E1 = 1.0e4_wp, &
      NU1 = 0.3_wp, E2 = 5.0e4_wp, NU2 = 0.2_wp, P = 100.0_wp

contains

   subroutine collect_pecjoin_katona(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('patch_spring_plane', test_patch_spring_plane), &
               new_unittest('patch_goodman4_plane', test_patch_goodman4_plane), &
               new_unittest('patch_goodman6_plane', test_patch_goodman6_plane), &
               new_unittest('patch_spring_axi', test_patch_spring_axi), &
               new_unittest('patch_goodman6_axi', test_patch_goodman6_axi), &
               new_unittest('floating_spring_plane', test_float_spring), &
               new_unittest('floating_goodman6_axi', test_float_goodman6), &
               new_unittest('hertz_line_contact', test_hertz), &
               new_unittest('s1_open_close', test_s1_open_close), &
               new_unittest('tensile_strength', test_tension), &
               new_unittest('unsettled_states_fail', test_unsettled_states)]
   end subroutine collect_pecjoin_katona

   subroutine run(name, model, problem, code)
      character(len=*), intent(in) :: name
      type(model_t), intent(out) :: model
      type(problem_t), intent(out) :: problem
      integer, intent(out) :: code
      call make_directories(DIR)
      code = run_deck(DATA//name//'.inp', DIR//'/'//name//'.h5', .true., model, problem)
   end subroutine run

   !> Uniaxial stress in both blocks (frictionless contact slips freely):
   !> p = DELTA / (H1 c1/E1 + H2 c2/E2), c = 1 - nu^2 in plane strain, 1 in axisymmetry.
   pure real(wp) function patch_pressure(axi) result(p)
      logical, intent(in) :: axi
      if (axi) then
         p = DELTA/(H1/E1 + H2/E2)
      else
         p = DELTA/(H1*(1.0_wp - NU1**2)/E1 + H2*(1.0_wp - NU2**2)/E2)
      end if
   end function patch_pressure

   !> Every doublet of measure > 0 and every joint point carries sigma_n = p, tau = 0 (1e-9,
   !> roundoff of a direct solve), no doublet interpenetrates (1e-12 of the relative
   !> displacement scale), and the augmentation is used exactly when expected.
   subroutine check_patch(name, p, floating, error)
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: p
      logical, intent(in) :: floating
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code, k
      real(wp) :: sn_err, t_err
      call run(name, model, problem, code)
      call check(error, code == 0, name//' completes')
      if (allocated(error)) return
      associate (kt => problem%katona, st => problem%state%joints%sets(1))
         call check(error, kt%active .and. kt%nd > 0, name//': Katona doublets built')
         if (allocated(error)) return
         sn_err = 0.0_wp
         t_err = 0.0_wp
         do k = 1, kt%nd
            if (kt%area(k) <= 0.0_wp) cycle
            sn_err = max(sn_err, abs(kt%f(1, k)/kt%area(k) - p))
            t_err = max(t_err, abs(kt%f(2, k)/kt%area(k)))
         end do
         call check_close(error, sn_err, 0.0_wp, 0.0_wp, name//': doublet sigma_n = p', &
            atol=1.0e-9_wp*p)
         if (allocated(error)) return
         call check_close(error, t_err, 0.0_wp, 0.0_wp, name//': doublet tau = 0', &
            atol=1.0e-9_wp*p)
         if (allocated(error)) return
         call check_close(error, maxval(abs(st%sigma(1, :, :) - p)), 0.0_wp, 0.0_wp, &
            name//': sigma_n = p at every joint point of the results', atol=1.0e-9_wp*p)
         if (allocated(error)) return
         call check(error, all(st%mode /= MODE_OPEN) .and. all(kt%mode /= MODE_OPEN), &
            name//': every doublet in contact')
         if (allocated(error)) return
         call check_close(error, maxval(abs(kt%z(1, :) - kt%gap0)), 0.0_wp, 0.0_wp, &
            name//': zero interpenetration', atol=1.0e-12_wp*DELTA)
         if (allocated(error)) return
         call check(error, (kt%alpha > 0.0_wp) .eqv. floating, name// &
            ': augmented form used exactly when R alone is singular')
      end associate
   end subroutine check_patch

   subroutine test_patch_spring_plane(error)
      type(error_t), allocatable, intent(out) :: error
      call check_patch('disp_spring_plane', patch_pressure(.false.), .false., error)
   end subroutine test_patch_spring_plane

   subroutine test_patch_goodman4_plane(error)
      type(error_t), allocatable, intent(out) :: error
      call check_patch('disp_goodman4_plane', patch_pressure(.false.), .false., error)
   end subroutine test_patch_goodman4_plane

   subroutine test_patch_goodman6_plane(error)
      type(error_t), allocatable, intent(out) :: error
      call check_patch('disp_goodman6_plane', patch_pressure(.false.), .false., error)
   end subroutine test_patch_goodman6_plane

   subroutine test_patch_spring_axi(error)
      type(error_t), allocatable, intent(out) :: error
      call check_patch('disp_spring_axi', patch_pressure(.true.), .false., error)
   end subroutine test_patch_spring_axi

   subroutine test_patch_goodman6_axi(error)
      type(error_t), allocatable, intent(out) :: error
      call check_patch('disp_goodman6_axi', patch_pressure(.true.), .false., error)
   end subroutine test_patch_goodman6_axi

   !> Upper block held only by its contacts: sigma_n = P exactly (statics), R singular.
   subroutine test_float_spring(error)
      type(error_t), allocatable, intent(out) :: error
      call check_patch('float_spring_plane', P, .true., error)
   end subroutine test_float_spring

   subroutine test_float_goodman6(error)
      type(error_t), allocatable, intent(out) :: error
      call check_patch('float_goodman6_axi', P, .true., error)
   end subroutine test_float_goodman6

   !> Hertz (doc/validation.md) on test/data/katona/hertz.inp (tools/pecplas_py/decks/make_hertz_deck.py, h = 0.1 mm):
   !> a = sqrt(4 F R / (pi E*)), p0 = 2 F / (pi a) within 2 % (a: midway between the last
   !> closed and the first open doublet, +-h/2 = 0.8 %); p(x) within 5 % of p0 of
   !> p0 sqrt(1 - x^2/a^2) at the doublets in contact; resultant = F/2 (half model) to 1e-8
   !> (equilibrium of the floating cylinder); no interpenetration (1e-10 of a).
   subroutine test_hertz(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: r = 50.0_wp, e_cyl = 70.0e3_wp, e_blk = 210.0e3_wp, &
         nu = 0.3_wp, f = 35.0e3_wp, pi = acos(-1.0_wp)
      real(wp) :: estar, a, p0, a_fe, x, xclosed, xopen, p_err, resultant
      integer :: code, k
      call run('hertz', model, problem, code)
      call check(error, code == 0, 'hertz completes')
      if (allocated(error)) return
      estar = 1.0_wp/((1.0_wp - nu**2)/e_cyl + (1.0_wp - nu**2)/e_blk)
      a = sqrt(4.0_wp*f*r/(pi*estar))
      p0 = 2.0_wp*f/(pi*a)
      associate (kt => problem%katona)
         xclosed = 0.0_wp
         xopen = huge(1.0_wp)
         p_err = 0.0_wp
         resultant = 0.0_wp
         do k = 1, kt%nd
            x = model%mesh%x(1, kt%node(1, k))
            resultant = resultant + kt%f(1, k)
            if (kt%mode(k) == MODE_OPEN) then
               xopen = min(xopen, x)
            else
               xclosed = max(xclosed, x)
               p_err = max(p_err, abs(kt%f(1, k)/kt%area(k) - &
                  p0*sqrt(max(0.0_wp, 1.0_wp - (x/a)**2))))
            end if
         end do
         a_fe = 0.5_wp*(xclosed + xopen)
         k = minloc(abs(model%mesh%x(1, kt%node(1, :))), dim=1)
         call report('hertz/h01', [a_fe, a, kt%f(1, k)/kt%area(k), p0, p_err/p0, &
            resultant/(0.5_wp*f) - 1.0_wp, kt%max_penetration])
         call check_close(error, a_fe, a, 0.02_wp, 'contact half-width a = 6.21 mm')
         if (allocated(error)) return
         k = minloc(abs(model%mesh%x(1, kt%node(1, :))), dim=1)
         call check_close(error, kt%f(1, k)/kt%area(k), p0, 0.02_wp, 'peak pressure 3585 MPa')
         if (allocated(error)) return
         call check_close(error, p_err, 0.0_wp, 0.0_wp, 'p(x) = p0 sqrt(1 - x^2/a^2)', &
            atol=0.05_wp*p0)
         if (allocated(error)) return
         call check_close(error, resultant, 0.5_wp*f, 1.0e-8_wp, 'contact resultant = F')
         if (allocated(error)) return
         call check(error, kt%max_penetration <= 1.0e-10_wp*a, 'no interpenetration')
         if (allocated(error)) return
         call check(error, kt%alpha > 0.0_wp, 'the cylinder floats: augmented path')
      end associate
   end subroutine test_hertz

   !> S1 compression-opening-closing with Katona contact (the MOHR_COULOMB deck with only
   !> TYPE=KATONA changed): completes; every doublet opened during the lift (bond broken)
   !> and is closed and compressed again at the end; no interpenetration at any converged
   !> increment (1e-12 of the 1 mm stroke); at most 5 state iterations per increment.
   subroutine test_s1_open_close(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call run('s1_open_close', model, problem, code)
      call check(error, code == 0, 's1_open_close (Katona) completes')
      if (allocated(error)) return
      associate (kt => problem%katona)
         call check(error, all(kt%broken), 'every doublet separated during the lift')
         if (allocated(error)) return
         call check(error, all(kt%mode /= MODE_OPEN) .and. all(kt%f(1, :) > 0.0_wp), &
            'closed and compressed after re-contact')
         if (allocated(error)) return
         call check(error, kt%max_penetration <= 1.0e-15_wp, 'zero interpenetration')
         if (allocated(error)) return
         call report('katona/s1_open_close', [real(kt%max_state_iterations, wp), &
            kt%max_penetration])
         call check(error, kt%max_state_iterations <= 5, '<= 5 state iterations per increment')
      end associate
   end subroutine test_s1_open_close


   !> Tensile strength: the frictionless patch (disp_spring_plane) pulled apart by DELTA, so
   !> that the bond would carry sigma_n = -p. TENSION = 20 > p: bonded, sigma_n = -p at every
   !> doublet (1e-9). TENSION = 5 < p: every doublet separates (N = T = 0, gap opening > 0).
   subroutine test_tension(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp) :: p
      integer :: code, k
      p = patch_pressure(.false.)
      call pulled('20', model, problem, code, error)
      if (allocated(error)) return
      call check(error, code == 0, 'pulled, TENSION = 20 completes')
      if (allocated(error)) return
      associate (kt => problem%katona)
         call check(error, all(kt%mode /= MODE_OPEN), 'TENSION = 20 > p: the bond holds')
         if (allocated(error)) return
         do k = 1, kt%nd
            call check_close(error, kt%f(1, k)/kt%area(k), -p, 1.0e-9_wp, 'sigma_n = -p')
            if (allocated(error)) return
         end do
      end associate
      call pulled('5', model, problem, code, error)
      if (allocated(error)) return
      call check(error, code == 0, 'pulled, TENSION = 5 completes')
      if (allocated(error)) return
      associate (kt => problem%katona)
         call check(error, all(kt%mode == MODE_OPEN) .and. all(kt%f == 0.0_wp), &
            'TENSION = 5 < p: every doublet separates, no force')
         if (allocated(error)) return
         call check(error, all(kt%z(1, :) < 0.0_wp) .and. all(kt%broken), &
            'the doublets open (eps_n < 0) and the bond is broken')
      end associate
   end subroutine test_tension

   !> One doublet, slipping (s = +1) at the start of the increment, with a flexibility
   !> G = [1 -0.9; -0.9 1] that couples N and T, mu = 2, w = (1, 3) (pressed and pushed along
   !> +t). Slip gives N (G11 + mu G12) = w_n, N = -1.25 < 0: open; open leaves z = w, pressed
   !> in and moved 3 from its anchor: slip again, and so on. After MAX_FLIPS changes the doublet
   !> is held in a state its own checks reject: solve_states must report a run error (the
   !> increment is cut), not accept the held state, nor (as the iteration once did) come back
   !> in stick anchored where the open iterate had moved it.
   subroutine test_unsettled_states(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: err
      type(katona_t) :: kt
      real(wp) :: h(2)
      integer :: flips(1), nit
      kt%nd = 1
      call kt%allocate_states()
      kt%mu = [2.0_wp]
      kt%cohesion = [0.0_wp]
      kt%tension = [0.0_wp]
      kt%gap0 = [0.0_wp]
      kt%g = reshape([1.0_wp, -0.9_wp, -0.9_wp, 1.0_wp], [2, 2])
      kt%mode = MODE_SLIP
      kt%sgn = 1
      call kt%begin_increment()
      flips = 0
      call solve_states(kt, [1.0_wp, 3.0_wp], [0.0_wp, 0.0_wp], h, flips, nit, err)
      call check(error, allocated(err), 'an unsettled state iteration reports an error')
      if (allocated(error)) return
      call check(error, err%kind == ERR_RUN .and. flips(1) == MAX_FLIPS, &
         'a run error after MAX_FLIPS changes of the doublet: '//err%message)
   end subroutine test_unsettled_states

   !> Runs disp_spring_plane.inp pulled up by DELTA with TENSION = `tension`.
   subroutine pulled(tension, model, problem, code, error)
      character(len=*), intent(in) :: tension
      type(model_t), intent(out) :: model
      type(problem_t), intent(out) :: problem
      integer, intent(out) :: code
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      integer :: u, n
      call make_directories(DIR)
      open (newunit=u, file=DATA//'disp_spring_plane.inp', access='stream', &
         form='unformatted', status='old', action='read')
      inquire (unit=u, size=n)
      allocate (character(len=n) :: text)
      read (u) text
      close (u)
      call replace(text, 'MU = 0', 'MU = 0, TENSION = '//tension, error)
      if (allocated(error)) return
      call replace(text, 'top, Y, -0.001', 'top, Y, 0.001', error)
      if (allocated(error)) return
      open (newunit=u, file=DIR//'/pulled_'//tension//'.inp', access='stream', &
         form='unformatted', status='replace', action='write')
      write (u) text
      close (u)
      code = run_deck(DIR//'/pulled_'//tension//'.inp', DIR//'/pulled_'//tension//'.h5', &
         .true., model, problem)
   end subroutine pulled

   subroutine replace(text, old, new, error)
      character(len=:), allocatable, intent(inout) :: text
      character(len=*), intent(in) :: old, new
      type(error_t), allocatable, intent(out) :: error
      integer :: at
      at = index(text, old)
      if (at == 0) then
         call fatal_error(error, 'deck text not found: '//old)
         return
      end if
      text = text(:at - 1)//new//text(at + len(old):)
   end subroutine replace

end module test_pecjoin_katona
