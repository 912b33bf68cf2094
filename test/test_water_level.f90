!> Water loads where the phreatic level crosses an element (doc/theory.md, Groundwater): the
!> pressure p = gamma_w (h - y)+ has a kink at the level (and at each vertex of a polyline
!> level), so the element is cut there and each wet part integrated exactly. A plate wall
!> with the level inside an element (2-node and 3-node) carries the hydrostatic base shear
!> and moment; a plate and a soil face under a polyline level with a vertex and the level
!> crossing inside their elements get consistent loads whose resultant and moment are those
!> of the pressure.
module test_water_level
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_base_files, only: make_directories
   use pecplas_base_strings, only: itoa
   use pecplas_problem_type, only: problem_t
   use pecplas_io_results_increment, only: plate_fields_t
   use pecplas_fe_plate_output, only: plate_results
   use pecplas_fe_water_faces, only: plate_water_load, add_water_faces
   use pecplas_testing, only: check, check_close
   implicit none (type, external)
   private

   public :: test_wall_level_inside, test_plate_polyline, test_face_polyline, test_plate_cone

   character(len=*), parameter :: OUT = 'build/test_out/water/'
   !> Unit weight of water and the level of the walls.
   real(wp), parameter :: GW = 10.0_wp, LEVEL = 6.3_wp

contains

   !> A plate wall x = 0, 0 <= y <= 10, clamped at its base, water on its left to the level
   !> y = 6.3, released by a nil step: ten 2-node elements (the level at 0.3 of element 7)
   !> and five 3-node ones (at 0.15 of element 4). The base shear is the water's resultant
   !> gamma_w h^2/2 = 198.45 and the moment gamma_w h^3/6 = 416.745 (per unit length). The
   !> cantilever is statically determinate, so the base forces are the sum of the
   !> consistent loads (exact) less the solve's residual: with n = 33 dofs and the largest
   !> stiffness term times displacement |K||u| ~ 1e5 (12 EI / 1 m^3 x 0.1 m, 2-node) to 4e5
   !> (GA_s / 1 m x 0.1 m, 3-node) against a resultant of 2e2, n eps |K||u| / 2e2 ~ 1.5e-11
   !> (measured: 7e-14 and 5e-12); tolerance 1e-10. Interpolating the nodal pressures
   !> over the crossed element (before the cut) gave 199.5 and 423.5 (2-node), 199 and 420
   !> (3-node).
   subroutine test_wall_level_inside(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(plate_fields_t) :: f
      integer :: code, u, i, nen
      character(len=:), allocatable :: deck
      call make_directories(OUT)
      do nen = 2, 3
         deck = OUT//'wall_level'//itoa(nen)//'.inp'
         open (newunit=u, file=deck, status='replace', action='write')
         write (u, '(a)') '*TITLE', 'water on a wall, the level inside an element', &
            '*UNITS', 'kN, m, kPa', '*NODES'
         do i = 0, 10
            write (u, '(i0,a,i0)') i + 1, ', 0, ', i
         end do
         if (nen == 2) then
            write (u, '(a)') '*NSET, NAME=wall, GENERATE', '1, 11, 1', &
               '*PLATE, SET=wall, NODES=wall, EA=1e7, EI=1e5'
         else
            write (u, '(a)') '*PLATE, SET=wall, EA=1e7, EI=1e5'
            do i = 0, 4
               write (u, '(i0,a,i0,a,i0)') 2*i + 1, ', ', 2*i + 3, ', ', 2*i + 2
            end do
         end if
         write (u, '(a)') '*BOUNDARY', '1, ALL', '*WATER, NAME=pit, GAMMA_W=10, LEVEL=6.3', &
            '*PLATE_WATER', 'wall, LEFT', '*STEP, NAME=water, INCREMENTS=1', '*END STEP'
         close (u)
         code = run_deck(deck, OUT//'wall_level'//itoa(nen)//'.h5', .true., model, problem)
         call check(error, code == 0, 'wall of '//itoa(nen)//'-node elements runs (exit '// &
            itoa(code)//')')
         if (allocated(error)) return
         call plate_results(model, problem%state%u, problem%state%plates, &
            problem%state%factors, 1, f, error, level=1)
         if (allocated(error)) return
         call check_close(error, abs(f%node_forces(2, 1)), GW*LEVEL**2/2.0_wp, 1.0e-10_wp, &
            itoa(nen)//'-node wall: base shear = gamma_w h^2 / 2, h = 6.3')
         if (allocated(error)) return
         call check_close(error, abs(f%node_forces(3, 1)), GW*LEVEL**3/6.0_wp, 1.0e-10_wp, &
            itoa(nen)//'-node wall: base moment = gamma_w h^3 / 6, h = 6.3')
         if (allocated(error)) return
      end do
   end subroutine test_wall_level_inside

   !> A horizontal plate y = 0, 0 <= x <= 4 (two 2-node elements, then two 3-node ones),
   !> water on its left (above it) under the polyline level (0, 2), (1, 1.5), (4, -1.5): a
   !> vertex at x = 1 inside the first element, the level crossing the plate at x = 2.5
   !> inside the second. The consistent loads sum to the pressure's resultant
   !> -gamma_w int h+ dx = -28.75 (downwards) and their moment about the origin to
   !> -gamma_w int x h+ dx = -1210/48 = -25.208 (the rigid motions are in both elements'
   !> interpolations). Only round-off: about 100 terms of some 10 operations each,
   !> 1e3 eps ~ 2e-13; tolerance 1e-12 relative. Interpolating the nodal pressures gave
   !> -30 and -33.33 (2-node), -30 and -26.67 (3-node).
   subroutine test_plate_polyline(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      real(wp), parameter :: RES = -GW*(1.75_wp + 1.125_wp), &
         MOM = -GW*((1.0_wp - 1.0_wp/6.0_wp) + (1.25_wp*(2.5_wp**2 - 1.0_wp) - &
         (2.5_wp**3 - 1.0_wp)/3.0_wp))
      real(wp) :: fe(9), fy, m
      character(len=:), allocatable :: deck
      logical :: loaded
      integer :: u, nen, e, k, node
      call make_directories(OUT)
      do nen = 2, 3
         deck = OUT//'plate_polyline'//itoa(nen)//'.inp'
         open (newunit=u, file=deck, status='replace', action='write')
         write (u, '(a)') '*TITLE', 'a plate under a polyline level', '*NODES', &
            '1, 0, 0', '2, 1, 0', '3, 2, 0', '4, 3, 0', '5, 4, 0', &
            '*PLATE, SET=raft, EA=1e7, EI=1e5'
         if (nen == 2) then
            write (u, '(a)') '1, 3', '3, 5'
         else
            write (u, '(a)') '1, 3, 2', '3, 5, 4'
         end if
         write (u, '(a)') '*BOUNDARY', '1, ALL', '*WATER, NAME=w, GAMMA_W=10', '0, 2', &
            '1, 1.5', '4, -1.5', '*PLATE_WATER', 'raft, LEFT', '*STEP, NAME=nil', '*END STEP'
         close (u)
         call read_deck(deck, model, error)
         if (allocated(error)) return
         fy = 0.0_wp
         m = 0.0_wp
         do e = 1, 2
            call plate_water_load(model, 1, e, 1, 1, fe(1:3*nen), loaded)
            call check(error, loaded, 'element '//itoa(e)//' is loaded')
            if (allocated(error)) return
            do k = 1, nen
               node = model%plates(1)%conn(k, e)
               fy = fy + fe(3*k - 1)
               m = m + model%mesh%x(1, node)*fe(3*k - 1) - model%mesh%x(2, node)*fe(3*k - 2) + &
                  fe(3*k)
            end do
         end do
         call check_close(error, fy, RES, 1.0e-12_wp, itoa(nen)// &
            '-node plate: resultant = -gamma_w int h+ dx')
         if (allocated(error)) return
         call check_close(error, m, MOM, 1.0e-12_wp, itoa(nen)// &
            '-node plate: moment = -gamma_w int x h+ dx')
         if (allocated(error)) return
      end do
   end subroutine test_plate_polyline

   !> One Q4 (then Q8) element 0 <= x <= 4, 0 <= y <= 3 under the polyline level (0, 2),
   !> (2, 1), (4, -1): its bottom face takes p = gamma_w h(x)+ upwards, h with a vertex at
   !> x = 2 and falling to 0 at x = 3, so F_y = gamma_w int h+ dx = 35 and its moment about
   !> the origin gamma_w int x h+ dx = 115/3 = 38.333 (on a Q4 the nodal forces at x = 0
   !> and 4 follow from these two); the left face x = 0 takes gamma_w (2 - y)+,
   !> F_x = gamma_w 2^2/2 = 20 (x constant: h is one along it). Round-off only (as
   !> test_plate_polyline): 1e-12.
   !> Taking h at each side's middle (before the cut) gave F_y = 40 and its moment 80.
   subroutine test_face_polyline(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      real(wp), parameter :: FY = GW*3.5_wp, MY = GW*23.0_wp/6.0_wp
      real(wp), allocatable :: force(:, :)
      logical :: none(0)
      character(len=:), allocatable :: deck
      integer :: u, v
      call make_directories(OUT)
      do v = 1, 2
         deck = OUT//'face_polyline'//itoa(v)//'.inp'
         open (newunit=u, file=deck, status='replace', action='write')
         write (u, '(a)') '*TITLE', 'a soil face under a polyline level', '*NODES', &
            '1, 0, 0', '2, 4, 0', '3, 4, 3', '4, 0, 3'
         if (v == 2) write (u, '(a)') '5, 2, 0', '6, 4, 1.5', '7, 2, 3', '8, 0, 1.5'
         if (v == 1) then
            write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=soil', '1, 1, 2, 3, 4'
         else
            write (u, '(a)') '*ELEMENTS, TYPE=Q8, SET=soil', '1, 1, 2, 3, 4, 5, 6, 7, 8'
         end if
         write (u, '(a)') '*MATERIAL, NAME=sand, TYPE=ELASTIC', 'E = 1e4, NU = 0.3', &
            '*SECTION, SET=soil, MATERIAL=sand', '*BOUNDARY', '1, XY', '2, Y', &
            '*WATER, NAME=w, GAMMA_W=10', '0, 2', '2, 1', '4, -1', '*STEP, NAME=nil', &
            '*END STEP'
         close (u)
         call read_deck(deck, model, error)
         if (allocated(error)) return
         allocate (force(2, model%mesh%nnode()), source=0.0_wp)
         call add_water_faces(model, [.true.], none, 1, force, error)
         if (allocated(error)) return
         call check_close(error, sum(force(2, :)), FY, 1.0e-12_wp, 'Q'//itoa(4*v)// &
            ': bottom face F_y = gamma_w int h+ dx')
         if (allocated(error)) return
         call check_close(error, sum(model%mesh%x(1, :)*force(2, :)), MY, 1.0e-12_wp, &
            'Q'//itoa(4*v)//': its moment = gamma_w int x h+ dx')
         if (allocated(error)) return
         call check_close(error, sum(force(1, :)), GW*2.0_wp, 1.0e-12_wp, 'Q'//itoa(4*v)// &
            ': left face F_x = gamma_w 2^2 / 2')
         if (allocated(error)) return
         deallocate (force)
      end do
   end subroutine test_face_polyline

   !> Axisymmetry: a conical plate from (r, y) = (1, 0) to (3, 2) (two 2-node, then two
   !> 3-node elements), water on its left to the level y = 1.3 (at 0.3 of the upper element).
   !> Along it r = 1 + 2a, y = 2a, dl = 2 sqrt(2) da, so the consistent loads sum to the
   !> ring force 2 pi gamma_w 2 sqrt(2) int_0^0.65 (1.3 - 2a)(1 + 2a) da = 2 pi gamma_w
   !> 2 sqrt(2) 0.6055833.. along the normal (1, -1)/sqrt(2). Round-off only: 1e-12.
   !> Interpolating the nodal pressures gave the r component 92.15 instead of 76.10 (2-node).
   subroutine test_plate_cone(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      real(wp), parameter :: PI = acos(-1.0_wp), &
         RING = 2.0_wp*PI*GW*2.0_wp*sqrt(2.0_wp)*(1.3_wp*0.65_wp + 0.3_wp*0.65_wp**2 - &
         4.0_wp/3.0_wp*0.65_wp**3)
      real(wp) :: fe(9), f(2)
      character(len=:), allocatable :: deck
      logical :: loaded
      integer :: u, nen, e, k
      call make_directories(OUT)
      do nen = 2, 3
         deck = OUT//'plate_cone'//itoa(nen)//'.inp'
         open (newunit=u, file=deck, status='replace', action='write')
         write (u, '(a)') '*TITLE', 'a conical plate with the level inside an element', &
            '*ANALYSIS, TYPE=AXISYMMETRIC', '*NODES', '1, 1, 0', '2, 1.5, 0.5', '3, 2, 1', &
            '4, 2.5, 1.5', '5, 3, 2', '*PLATE, SET=cone, EA=1e7, EI=1e5'
         if (nen == 2) then
            write (u, '(a)') '1, 3', '3, 5'
         else
            write (u, '(a)') '1, 3, 2', '3, 5, 4'
         end if
         write (u, '(a)') '*BOUNDARY', '1, ALL', '*WATER, NAME=w, GAMMA_W=10, LEVEL=1.3', &
            '*PLATE_WATER', 'cone, LEFT', '*STEP, NAME=nil', '*END STEP'
         close (u)
         call read_deck(deck, model, error)
         if (allocated(error)) return
         f = 0.0_wp
         do e = 1, 2
            call plate_water_load(model, 1, e, 1, 1, fe(1:3*nen), loaded)
            do k = 1, nen
               f = f + fe(3*k - 2:3*k - 1)
            end do
         end do
         call check_close(error, f(1), RING/sqrt(2.0_wp), 1.0e-12_wp, itoa(nen)// &
            '-node cone: ring force, r component')
         if (allocated(error)) return
         call check_close(error, f(2), -RING/sqrt(2.0_wp), 1.0e-12_wp, itoa(nen)// &
            '-node cone: ring force, y component')
         if (allocated(error)) return
      end do
   end subroutine test_plate_cone

end module test_water_level
