!> Groundwater (doc/theory.md, Groundwater): the hydrostatic state of a layered column,
!> undrained oedometric loading against the closed form, undrained plane-strain
!> Mohr-Coulomb compression, undrained-then-drained phases against a drained run, joints
!> under pore pressure, bad decks.
module test_water
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_massif_element_matrices, only: massif_gauss_coordinates
   use pecplas_base_strings, only: itoa
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_water

   character(len=*), parameter :: OUT = 'build/test_out/water/'
   character(len=*), parameter :: NL = new_line('a')

contains

   subroutine collect_water(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('hydrostatic_column', test_hydrostatic)]
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
   !> the pore pressures (a formula of the point) are checked the same way.
   subroutine test_hydrostatic(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: GW = 10.0_wp, K0 = 0.5_wp, HS = 10.0_wp, HC = 4.0_wp
      real(wp), parameter :: GSU = 17.0_wp, GSS = 20.0_wp, GCS = 21.0_wp
      real(wp) :: level, xg(2, 4), p, sv, q, worst_p, worst_s, scale
      integer :: code, s, el, g, v
      character(len=:), allocatable :: body
      character(len=32) :: buf
      call make_directories(OUT)
      do v = 1, 2
         level = merge(7.0_wp, 7.25_wp, v == 1)
         q = GSU*(HS - level) + (GSS - GW)*(level - HC)
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
         code = run_deck(OUT//'hydro'//itoa(v)//'.inp', OUT//'hydro'//itoa(v)//'.h5', .true., &
            model, problem)
         call check(error, code == 0, 'hydrostatic column runs (exit '//itoa(code)//')')
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
                        sv = GSU*(HS - max(xg(2, g), level)) + (GSS - GW)*max(level - xg(2, g), &
                           0.0_wp)
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
         if (v == 1) call check_close(error, worst_s, 0.0_wp, 0.0_wp, &
            "sigma'_v, sigma'_h closed form", atol=1.0e-12_wp*scale)
         if (allocated(error)) return
      end do
   end subroutine test_hydrostatic

end module test_water
