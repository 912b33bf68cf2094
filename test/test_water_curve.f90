!> Water on curved sides (doc/theory.md, Groundwater): the pressure p = gamma_w (h - y)+
!> acts normal to the true (parabolic) geometry of a curved 3-node plate element or quadratic
!> soil side and is integrated along it, cut where the level crosses the curve. Plates and
!> sides whose nodes lie on a parabola of a parameter u, at u's ends and middle, are that
!> parabola exactly (the isoparametric map), so the consistent loads must sum to the
!> closed-form resultant and moment of the pressure on the curve, polynomial integrals in u.
!> Registered in the water suite (test_water).
module test_water_curve
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_io_results_increment, only: plate_fields_t
   use pecplas_fe_plate_output, only: plate_results
   use pecplas_base_files, only: make_directories
   use pecplas_base_strings, only: itoa
   use pecplas_fe_water_faces, only: plate_water_load, add_water_faces
   use pecplas_testing, only: check, check_close
   implicit none (type, external)
   private

   public :: test_curved_wall, test_curved_wall_run, test_curved_trough, test_curved_shell, &
      test_curved_face

   character(len=*), parameter :: OUT = 'build/test_out/water/'
   real(wp), parameter :: GW = 10.0_wp, PI = acos(-1.0_wp)
   !> Round-off bound of the sums (as test_water_level): the integrals are exact (each wet
   !> part's Gauss rule is exact for its polynomial integrand), and the crossing a* of the
   !> level is found to a relative eps, which moves the load only at second order (p = 0
   !> there); about 5 elements x 2 parts x 4 points x 3 nodes = 120 terms of some 20
   !> operations each: 2.4e3 eps ~ 5e-13 of the resultant's scale. Tolerance 1e-12.
   real(wp), parameter :: TOL = 1.0e-12_wp
   !> The curved wall x = u (10 - u) / 20, y = u (coefficients from the constant up).
   real(wp), parameter :: WALL_X(3) = [0.0_wp, 0.5_wp, -0.05_wp], &
      WALL_Y(3) = [0.0_wp, 1.0_wp, 0.0_wp]

contains

   !> A wall x = u (10 - u) / 20, y = u, 0 <= u <= 10 (bulging by 1.25 at mid-height),
   !> five 3-node elements walked upwards, water on its left (the side x < wall) to the
   !> levels 6.3 (inside element 4, at a = 0.15), 7 (at its mid node), 6 (at its first node)
   !> and 12 (above the wall: no cut). Closed forms: F_x = gamma_w int (h - y)+ dy (the
   !> vertical projection's, whatever the curve), F_y = -gamma_w int (h - y)+ x'(y) dy, the
   !> moment about the origin gamma_w int (h - y)+ (-x x' - y) dy. Normal to each element's
   !> chord (before this rule) h = 6.3 gave F_x = 199.077, F_y = -55.701, M = -446.750
   !> instead of 198.45, -57.5505, -447.286 (h = 12, no cut: 701.01, -80.34 instead of 700,
   !> -83.33).
   subroutine test_curved_wall(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: LEVELS(4) = [6.3_wp, 7.0_wp, 6.0_wp, 12.0_wp]
      call curve_case(error, 'wall', WALL_X, WALL_Y, 0.0_wp, 10.0_wp, 5, LEVELS, .false.)
   end subroutine test_curved_wall

   !> The curved wall of test_curved_wall clamped at its base, the water to 6.3 on its left,
   !> released by a nil step: the cantilever is statically determinate, so its base section
   !> forces (the element's nodal forces less its own water load, in its frame at the base:
   !> t = (1/2, 1)/sqrt(5/4), n = (-t_y, t_x)) are those of the water's resultant F and
   !> moment M about the base: N = t.F, Q = n.F, M. The load is exact; the solve leaves a
   !> residual of n eps |K||u| with |K||u| ~ F L^2 EA/EI (a curved element's membrane
   !> stiffness EA/L against its bending displacement F L^3/EI, L = 2 m): 33 eps 400 ~ 3e-12
   !> relative of |F| (measured: 4e-12 of N = t.F, a difference of terms 5 times larger,
   !> 3e-13 of Q, 6e-13 of M); tolerance 1e-10 as test_wall_level_inside.
   subroutine test_curved_wall_run(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(plate_fields_t) :: f
      real(wp), parameter :: LEVEL(1) = [6.3_wp]
      character(len=:), allocatable :: deck
      real(wp) :: fc(2), mc, t(2), n(2)
      integer :: code
      deck = OUT//'curved_wall_run.inp'
      call write_curve(deck, 'wall_run', WALL_X, WALL_Y, 0.0_wp, 10.0_wp, 5, LEVEL, .false.)
      code = run_deck(deck, OUT//'curved_wall_run.h5', .true., model, problem)
      call check(error, code == 0, 'curved wall runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      call plate_results(model, problem%state%u, problem%state%plates, &
         problem%state%factors, 1, f, error, level=1)
      if (allocated(error)) return
      call closed_form(WALL_X, WALL_Y, LEVEL(1), 0.0_wp, LEVEL(1), .false., fc, mc)
      t = [0.5_wp, 1.0_wp]/sqrt(1.25_wp)
      n = [-t(2), t(1)]
      call check_close(error, f%node_forces(1, 1), dot_product(t, fc), 1.0e-10_wp, &
         'curved wall: base N = t . F')
      if (allocated(error)) return
      call check_close(error, f%node_forces(2, 1), dot_product(n, fc), 1.0e-10_wp, &
         'curved wall: base Q = n . F')
      if (allocated(error)) return
      call check_close(error, f%node_forces(3, 1), mc, 1.0e-10_wp, &
         'curved wall: base M = the moment of the water about the base')
   end subroutine test_curved_wall_run

   !> A trough y = x^2 / 4 from x = -3 to 5 (four 3-node elements walked in +x), water on
   !> its left (above it) to the level 2.5, which crosses it at x = sqrt(10) inside element 4
   !> while its left end (y = 2.25) is under water; then the level 6.5, above every node.
   !> F_y = -gamma_w (the area of the water between the level and the trough over the
   !> plate), F_x = gamma_w int (h - y)+ y' dx, M = gamma_w int (h - y)+ (-x - y y') dx.
   !> Normal to the chords, the level 2.5 gave F_y = -104.365 instead of -105.205.
   subroutine test_curved_trough(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: LEVELS(2) = [2.5_wp, 6.5_wp]
      real(wp), parameter :: XC(3) = [0.0_wp, 1.0_wp, 0.0_wp], YC(3) = [0.0_wp, 0.0_wp, 0.25_wp]
      call curve_case(error, 'trough', XC, YC, -3.0_wp, 5.0_wp, 4, LEVELS, .false.)
   end subroutine test_curved_trough

   !> Axisymmetry: a barrel shell r = 1 + y (2 - y) / 2, 0 <= y <= 2 (two 3-node elements
   !> walked upwards), water inside (on its left) to the levels 1.3 (at a = 0.3 of element
   !> 2) and 3 (above it). The ring force 2 pi gamma_w int r (h - y)+ (1, -r') dy: at 1.3,
   !> (68.623, -36.493); normal to the chords (71.618, -32.007).
   subroutine test_curved_shell(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: LEVELS(2) = [1.3_wp, 3.0_wp]
      real(wp), parameter :: XC(3) = [1.0_wp, 1.0_wp, -0.5_wp], YC(3) = [0.0_wp, 1.0_wp, 0.0_wp]
      call curve_case(error, 'shell', XC, YC, 0.0_wp, 2.0_wp, 2, LEVELS, .true.)
   end subroutine test_curved_shell

   !> One Q8 element whose bottom side runs from (0, 1) through (1, 0) to (2, 0): the
   !> parabola y = 1 - 1.5 x + x^2 / 2, lowest at x = 1.5, y = -0.125, below every node of
   !> the element. Under the level -0.05 only that dip is wet (1.5 -+ sqrt(0.15)): the face
   !> takes p (-y', 1) into the body, F = gamma_w int (h - y)+ (-y', 1) dx = (0, 0.38730)
   !> (a side whose nodes all lie at or above the level was skipped before: F = 0). Under
   !> the level 0.5 the bottom (from x = 1.5 - sqrt(1.25)) and the right side x = 2 (up to
   !> y = 0.5, F_x = -gamma_w 0.5^2 / 2) are wet: the curved side was exact already. A
   !> 3-node plate along the bottom side with the water on its free face takes the soil
   !> side's nodal forces (under -0.05, to 1e-12 of the largest; normal to the chord, before,
   !> it took the resultant (0.176, 0.352) against the side's (0, 0.387)).
   subroutine test_curved_face(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      real(wp), parameter :: YC(3) = [1.0_wp, -1.5_wp, 0.5_wp], XC(2) = [0.0_wp, 1.0_wp]
      real(wp), parameter :: LEVELS(2) = [-0.05_wp, 0.5_wp]
      real(wp), allocatable :: force(:, :)
      real(wp) :: f(2), m, x0, scale, fe(9)
      logical :: none(0), loaded
      character(len=:), allocatable :: deck
      integer :: u, k, i, c, node
      call make_directories(OUT)
      deck = OUT//'curved_face.inp'
      open (newunit=u, file=deck, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'a curved soil face dipping below its nodes', '*NODES', &
         '1, 0, 1', '2, 2, 0', '3, 2, 3', '4, 0, 3', '5, 1, 0', '6, 2, 1.5', '7, 1, 3', &
         '8, 0, 2', '*ELEMENTS, TYPE=Q8, SET=soil', '1, 1, 2, 3, 4, 5, 6, 7, 8', &
         '*MATERIAL, NAME=sand, TYPE=ELASTIC', 'E = 1e4, NU = 0.3', &
         '*SECTION, SET=soil, MATERIAL=sand', '*PLATE, SET=skin, EA=1e7, EI=1e5', '1, 2, 5', &
         '*BOUNDARY', '1, XY', '2, Y', &
         '*WATER, NAME=low, GAMMA_W=10, LEVEL=-0.05', '*WATER, NAME=high, GAMMA_W=10, LEVEL=0.5', &
         '*STEP, NAME=nil', '*END STEP'
      close (u)
      call read_deck(deck, model, error)
      if (allocated(error)) return
      do k = 1, 2
         allocate (force(2, model%mesh%nnode()), source=0.0_wp)
         call add_water_faces(model, [.true.], none, k, force, error)
         if (allocated(error)) return
         ! the bottom side, body on its left: -(the pressure of water on its left)
         x0 = 1.5_wp - sqrt(2.25_wp - 2.0_wp*(1.0_wp - LEVELS(k)))
         call closed_form(XC, YC, LEVELS(k), x0, min(2.0_wp, 3.0_wp - x0), .false., f, m)
         f = -f
         m = -m
         ! the right side x = 2 up to the level: -gamma_w h^2 / 2 along x, at y = h / 3
         if (LEVELS(k) > 0.0_wp) then
            f(1) = f(1) - GW*LEVELS(k)**2/2.0_wp
            m = m + GW*LEVELS(k)**3/6.0_wp
         end if
         scale = GW*0.125_wp**2
         call check_close(error, sum(force(1, :)), f(1), TOL, 'curved face, level '// &
            itoa(k)//': F_x', atol=TOL*scale)
         if (allocated(error)) return
         call check_close(error, sum(force(2, :)), f(2), TOL, 'curved face, level '// &
            itoa(k)//': F_y', atol=TOL*scale)
         if (allocated(error)) return
         call check_close(error, sum(model%mesh%x(1, :)*force(2, :) - &
            model%mesh%x(2, :)*force(1, :)), m, TOL, 'curved face, level '//itoa(k)// &
            ': moment about the origin', atol=TOL*scale)
         if (allocated(error)) return
         if (k == 1) then
            ! a plate on that side, the water on its free (right) face: the same load at its
            ! nodes 1, 2, 5 (the same pressure on the same parabola; both rules exact)
            call plate_water_load(model, 1, 1, k, -1, fe, loaded)
            do i = 1, 3
               node = model%plates(1)%conn(i, 1)
               do c = 1, 2
                  call check_close(error, fe(3*(i - 1) + c), force(c, node), 0.0_wp, &
                     'curved face: the plate on it takes the same load, node '// &
                     itoa(model%mesh%node_id(node)), atol=TOL*maxval(abs(force)))
                  if (allocated(error)) return
               end do
            end do
         end if
         deallocate (force)
      end do
   end subroutine test_curved_face

   !> The plate (x, y) = (X(u), Y(u)), u0 <= u <= u1 (polynomials of degree <= 2, coefficients
   !> xc, yc from the constant up) in ne 3-node elements, water on its left under each of
   !> `levels`: the consistent loads' resultant (and moment about the origin, plane strain)
   !> against the closed form.
   subroutine curve_case(error, name, xc, yc, u0, u1, ne, levels, axisym)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: xc(:), yc(:), u0, u1, levels(:)
      integer, intent(in) :: ne
      logical, intent(in) :: axisym
      type(model_t) :: model
      real(wp) :: fe(9), f(2), m, fc(2), mc, scale, x(2)
      character(len=:), allocatable :: deck
      logical :: loaded
      integer :: e, k, node, lv
      deck = OUT//'curved_'//name//'.inp'
      call write_curve(deck, name, xc, yc, u0, u1, ne, levels, axisym)
      call read_deck(deck, model, error)
      if (allocated(error)) return
      do lv = 1, size(levels)
         f = 0.0_wp
         m = 0.0_wp
         do e = 1, ne
            call plate_water_load(model, 1, e, lv, 1, fe, loaded)
            do k = 1, 3
               node = model%plates(1)%conn(k, e)
               x = model%mesh%x(:, node)
               f = f + fe(3*k - 2:3*k - 1)
               m = m + x(1)*fe(3*k - 1) - x(2)*fe(3*k - 2) + fe(3*k)
            end do
         end do
         call closed_form(xc, yc, levels(lv), u0, wet_end(yc, levels(lv), u0, u1), axisym, &
            fc, mc)
         scale = GW*maxval(abs(levels))**2
         if (axisym) scale = scale*2.0_wp*PI*maxval(abs(xc))
         call check_close(error, f(1), fc(1), TOL, name//', level '//itoa(lv)//': F_x', &
            atol=TOL*scale)
         if (allocated(error)) return
         call check_close(error, f(2), fc(2), TOL, name//', level '//itoa(lv)//': F_y', &
            atol=TOL*scale)
         if (allocated(error)) return
         if (axisym) cycle
         call check_close(error, m, mc, TOL, name//', level '//itoa(lv)// &
            ': moment about the origin', atol=TOL*scale*maxval(abs(levels)))
         if (allocated(error)) return
      end do
   end subroutine curve_case

   !> Writes the deck `path` of the plate (X(u), Y(u)), u0 <= u <= u1 in ne 3-node elements
   !> (nodes at the ends and middles of equal steps of u), clamped at its first node, with
   !> one *WATER level per entry of `levels`, the water on the plate's left, a nil step.
   subroutine write_curve(path, name, xc, yc, u0, u1, ne, levels, axisym)
      character(len=*), intent(in) :: path, name
      real(wp), intent(in) :: xc(:), yc(:), u0, u1, levels(:)
      integer, intent(in) :: ne
      logical, intent(in) :: axisym
      character(len=80) :: line
      real(wp) :: ui
      integer :: u, i, e, lv
      call make_directories(OUT)
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'water on a curved plate: '//name
      if (axisym) write (u, '(a)') '*ANALYSIS, TYPE=AXISYMMETRIC'
      write (u, '(a)') '*NODES'
      do i = 0, 2*ne
         ui = u0 + (u1 - u0)*real(i, wp)/real(2*ne, wp)
         write (line, '(i0,2(a,es24.16e3))') i + 1, ', ', poly_at(xc, ui), ', ', poly_at(yc, ui)
         write (u, '(a)') trim(line)
      end do
      write (u, '(a)') '*PLATE, SET=curve, EA=1e7, EI=1e5'
      do e = 1, ne
         write (u, '(i0,a,i0,a,i0)') 2*e - 1, ', ', 2*e + 1, ', ', 2*e
      end do
      write (u, '(a)') '*BOUNDARY', '1, ALL'
      do lv = 1, size(levels)
         write (line, '(a,i0,a,es24.16e3)') '*WATER, NAME=w', lv, ', GAMMA_W=10, LEVEL=', &
            levels(lv)
         write (u, '(a)') trim(line)
      end do
      write (u, '(a)') '*PLATE_WATER', 'curve, LEFT', '*STEP, NAME=nil', '*END STEP'
      close (u)
   end subroutine write_curve

   !> The end of the wet part of u0 <= u <= u1 under the level h, for the curves here (wet
   !> from u0 on, Y rising at the crossing): u1, or the root of Y(u) = h in (u0, u1).
   pure real(wp) function wet_end(yc, h, u0, u1) result(ue)
      real(wp), intent(in) :: yc(:), h, u0, u1
      real(wp) :: disc
      ue = u1
      if (poly_at(yc, u1) <= h) return
      if (yc(3) == 0.0_wp) then
         ue = (h - yc(1))/yc(2)
      else
         disc = yc(2)**2 - 4.0_wp*yc(3)*(yc(1) - h)
         ue = (-yc(2) + sqrt(disc))/(2.0_wp*yc(3))
      end if
   end function wet_end

   !> The resultant f and moment m about the origin of the pressure gamma_w (h - Y(u)) of
   !> water on the left of the curve (X(u), Y(u)), a <= u <= b: per du, p (Y', -X') (times
   !> 2 pi X in axisymmetry, where m is not computed), and x f_y - y f_x.
   pure subroutine closed_form(xc, yc, h, a, b, axisym, f, m)
      real(wp), intent(in) :: xc(:), yc(:), h, a, b
      logical, intent(in) :: axisym
      real(wp), intent(out) :: f(2), m
      real(wp), allocatable :: p(:), fx(:), fy(:)
      p = -yc
      p(1) = p(1) + h
      fx = poly_mul(p, poly_der(yc))
      fy = -poly_mul(p, poly_der(xc))
      if (axisym) then
         fx = 2.0_wp*PI*poly_mul(xc, fx)
         fy = 2.0_wp*PI*poly_mul(xc, fy)
      end if
      f = GW*[poly_int(fx, a, b), poly_int(fy, a, b)]
      m = 0.0_wp
      if (.not. axisym) m = GW*(poly_int(poly_mul(xc, fy), a, b) - &
         poly_int(poly_mul(yc, fx), a, b))
   end subroutine closed_form

   !> sum c(i) u^(i - 1).
   pure real(wp) function poly_at(c, u) result(v)
      real(wp), intent(in) :: c(:), u
      integer :: i
      v = 0.0_wp
      do i = size(c), 1, -1
         v = v*u + c(i)
      end do
   end function poly_at

   pure function poly_mul(a, b) result(c)
      real(wp), intent(in) :: a(:), b(:)
      real(wp) :: c(size(a) + size(b) - 1)
      integer :: i, j
      c = 0.0_wp
      do i = 1, size(a)
         do j = 1, size(b)
            c(i + j - 1) = c(i + j - 1) + a(i)*b(j)
         end do
      end do
   end function poly_mul

   pure function poly_der(a) result(d)
      real(wp), intent(in) :: a(:)
      real(wp) :: d(max(1, size(a) - 1))
      integer :: i
      d = 0.0_wp
      do i = 2, size(a)
         d(i - 1) = real(i - 1, wp)*a(i)
      end do
   end function poly_der

   !> int_a^b sum c(i) u^(i - 1) du.
   pure real(wp) function poly_int(c, a, b) result(v)
      real(wp), intent(in) :: c(:), a, b
      integer :: i
      v = 0.0_wp
      do i = 1, size(c)
         v = v + c(i)*(b**i - a**i)/real(i, wp)
      end do
   end function poly_int

end module test_water_curve
