!> The water of a flooded pit on the free faces of a plate (*PLATE_WATER FREE, doc/deck.md,
!> Groundwater): a wall dug free in two stages takes the hydrostatic resultant over the height
!> dug free, the same run as a wall split into one plate set per stage with LEFT/RIGHT
!> switched per step, a quay wall whose water side is free from the start, a bad mode word.
!> Registered in the water suite (test_water).
module test_water_free
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_base_strings, only: itoa
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_testing, only: check, check_close
   use fixtures_bad_decks, only: check_refused
   use fixtures_water, only: write_wall
   use fixtures_runs, only: run_completes
   implicit none (type, external)
   private
   public :: test_free_stages, test_free_equals_split, test_free_quay, test_free_raft, &
      test_free_bad_mode

   character(len=*), parameter :: OUT = 'build/test_out/water/'
   !> The pit: wall height, level of the pit water, its gamma_w, the bottoms of the two
   !> stages dug, the stiffness of the joints (ELASTIC KN = KT).
   real(wp), parameter :: H = 10.0_wp, LEVEL = 8.0_wp, GW = 10.0_wp, FLOOR1 = 6.0_wp, &
      FLOOR2 = 3.0_wp, KJ = 1.0e-8_wp

contains

   !> A pit beside a wall (x = 0, 0 <= y <= 10, ten 2-node plate elements walked upwards,
   !> clamped at its base), 5 x 11 nodes of 1 m Q4 from x = -2 to 2: the retained ground on
   !> the left (`soil_l`), on the right `exc_1` (6 <= y <= 10), `exc_2` (3 <= y <= 6) and
   !> `soil_r`; joints on both faces of the wall (`wif_<set>`, ELASTIC, KN = KT = KJ); the
   !> ground dry (*DRY: no pore pressure) and held at every node off the wall; the pit water
   !> at y = 8 from the start. Step 1 digs exc_1, step 2 exc_2, two increments each. `free`:
   !> one plate set `wall` with *PLATE_WATER FREE; else three (wall_3, wall_2, wall_1 from the
   !> base up) and *PLATE_WATER RIGHT for wall_1 in step 1, wall_2 in step 2.
   subroutine write_pit(path, free)
      character(len=*), intent(in) :: path
      logical, intent(in) :: free
      character(len=*), parameter :: SETS(4) = [character(len=6) :: 'soil_l', 'soil_r', &
         'exc_2', 'exc_1']
      integer :: u, r, c, k
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'wall in a flooded pit dug in two stages', '*UNITS', &
         'kN, m, kPa', '*NODES'
      do r = 0, 10
         do c = 0, 4
            write (u, '(i0,a,i0,a,i0)') node(r, c), ', ', c - 2, ', ', r
         end do
      end do
      do k = 1, 4
         write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET='//trim(SETS(k))
         do r = 0, 9
            do c = 0, 3
               if (set_of(r, c) /= k) cycle
               write (u, '(i0,4(a,i0))') 4*r + c + 1, ', ', node(r, c), ', ', node(r, c + 1), &
                  ', ', node(r + 1, c + 1), ', ', node(r + 1, c)
            end do
         end do
      end do
      write (u, '(a)') '*MATERIAL, NAME=ground', 'E = 1e4, NU = 0.3'
      do k = 1, 4
         write (u, '(a)') '*SECTION, SET='//trim(SETS(k))//', MATERIAL=ground'
      end do
      write (u, '(a)') '*NSET, NAME=ground'
      do r = 0, 10
         write (u, '(4(i0,:,", "))') node(r, 0), node(r, 1), node(r, 3), node(r, 4)
      end do
      write (u, '(a)') '*BOUNDARY', 'ground, XY', itoa(node(0, 2))//', ALL', &
         '*INTERFACE_LAW, NAME=weak, TYPE=ELASTIC', 'KN = 1e-8, KT = 1e-8', &
         '*EDGES, NAME=wall_line'
      do r = 0, 9
         write (u, '(i0,a,i0)') node(r, 2), ', ', node(r + 1, 2)
      end do
      if (free) then
         call plate(u, 'wall', 0, 10)
      else
         call plate(u, 'wall_3', 0, 3)
         call plate(u, 'wall_2', 3, 6)
         call plate(u, 'wall_1', 6, 10)
      end if
      write (u, '(a)') '*JOINTS, TYPE=GOODMAN4, SET=wif, LAW=weak, EDGES=wall_line, '// &
         'FACES=BOTH', '*DRY', 'soil_l, soil_r, exc_1, exc_2', &
         '*WATER, NAME=pit, GAMMA_W=10, LEVEL=8'
      if (free) write (u, '(a)') '*PLATE_WATER', 'wall, FREE'
      write (u, '(a)') '*STEP, NAME=dig_1, INCREMENTS=2', '*DEACTIVATE', 'exc_1, wif_exc_1'
      if (.not. free) write (u, '(a)') '*PLATE_WATER', 'wall_1, RIGHT'
      write (u, '(a)') '*END STEP', '*STEP, NAME=dig_2, INCREMENTS=2', '*DEACTIVATE', &
         'exc_2, wif_exc_2'
      if (.not. free) write (u, '(a)') '*PLATE_WATER', 'wall_2, RIGHT'
      write (u, '(a)') '*END STEP'
      close (u)
   contains
      integer function node(r, c)
         integer, intent(in) :: r, c
         node = 5*r + c + 1
      end function node
      integer function set_of(r, c)
         integer, intent(in) :: r, c
         if (c < 2) then
            set_of = 1
         else if (r < 3) then
            set_of = 2
         else if (r < 6) then
            set_of = 3
         else
            set_of = 4
         end if
      end function set_of
      subroutine plate(u, name, r0, r1)
         integer, intent(in) :: u, r0, r1
         character(len=*), intent(in) :: name
         integer :: i
         write (u, '(a)') '*PLATE, SET='//name//', EA=1e7, EI=1e5'
         do i = r0, r1 - 1
            write (u, '(i0,a,i0)') node(i, 2), ', ', node(i + 1, 2)
         end do
      end subroutine plate
   end subroutine write_pit

   !> The wall of write_pit in one plate set, *PLATE_WATER FREE: after stage 1 the water
   !> stands on its right face from y = 6 up, after stage 2 from y = 3 up (the left face stays
   !> covered by the retained ground's joints, the faces below the pit floor by the pit
   !> side's), so the base shear is the hydrostatic resultant gamma_w h^2 / 2 of the height
   !> h = 8 - y_floor dug free below the level (20, then 125) and the base moment that
   !> resultant times its height over the base, y_floor + h / 3 (400/3, then 1750/3). The
   !> increments half-way through each stage write the last stage's forces plus half the
   !> change (the solver applies the change of the water over the step's increments). The
   !> ground is held off the wall, so the only other forces on the plate are those of the
   !> joints, |f| <= KJ |jump|: over both faces of the wall at most 2 KJ H 2 max|u| on the
   !> shear (4 KJ H^2 max|u| on the moment, lever <= H), added to 1e-8 of the closed form
   !> (the consistent loads of the linear pressure are exact with the level and the pit
   !> floors on nodes; the cantilever is statically determinate).
   subroutine test_free_stages(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: file
      real(wp), allocatable :: nf(:, :)
      real(wp) :: shear(0:2), moment(0:2), v, m, umax
      character(len=*), parameter :: deck = OUT//'pit_free.inp'
      integer :: i, stage
      call make_directories(OUT)
      call write_pit(deck, .true.)
      call run_completes(error, deck, OUT//'pit_free.h5', model, problem, &
         'wall in a flooded pit (FREE)')
      if (allocated(error)) return
      shear(0) = 0.0_wp
      moment(0) = 0.0_wp
      shear(1) = 0.5_wp*GW*(LEVEL - FLOOR1)**2
      moment(1) = shear(1)*(FLOOR1 + (LEVEL - FLOOR1)/3.0_wp)
      shear(2) = 0.5_wp*GW*(LEVEL - FLOOR2)**2
      moment(2) = shear(2)*(FLOOR2 + (LEVEL - FLOOR2)/3.0_wp)
      umax = maxval(abs(problem%state%u))
      call file%open(OUT//'pit_free.h5', error)
      if (allocated(error)) return
      do i = 1, 4
         stage = (i + 1)/2
         v = shear(stage)
         m = moment(stage)
         if (mod(i, 2) == 1) then
            v = 0.5_wp*(shear(stage - 1) + shear(stage))
            m = 0.5_wp*(moment(stage - 1) + moment(stage))
         end if
         call file%dataset('/increments/00000'//itoa(i)//'/plates/wall/node_forces', nf, error)
         if (allocated(error)) return
         call check_close(error, abs(nf(2, 1)), v, 0.0_wp, 'base shear after increment '// &
            itoa(i)//' = gamma_w h^2 / 2 of the height dug free', &
            atol=1.0e-8_wp*v + 4.0_wp*KJ*H*umax)
         if (allocated(error)) return
         call check_close(error, abs(nf(3, 1)), m, 0.0_wp, 'base moment after increment '// &
            itoa(i)//' = its resultant times its height over the base', &
            atol=1.0e-8_wp*m + 4.0_wp*KJ*H*H*umax)
         if (allocated(error)) return
      end do
      call file%close()
      call check(error, problem%state%u(1, 53) < 0.0_wp, 'the pit water on the right pushes '// &
         'the wall to the left (-x)')
   end subroutine test_free_stages

   !> The pit of write_pit with the wall as one plate set under *PLATE_WATER FREE and as three
   !> with LEFT/RIGHT switched in the steps that dig them free: the same loads on the same
   !> system, so the same displacements and base section forces to round-off (1e-10 of the
   !> largest: the same element loads scattered per set in another grouping, one linear
   !> solve per increment), at the end and half-way through each stage (the results file).
   subroutine test_free_equals_split(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: free, split
      type(results_reader_t) :: file
      real(wp), allocatable :: a(:, :), b(:, :)
      integer :: i
      call make_directories(OUT)
      call write_pit(OUT//'pit_free2.inp', .true.)
      call write_pit(OUT//'pit_split.inp', .false.)
      call run_completes(error, OUT//'pit_free2.inp', OUT//'pit_free2.h5', model, free, 'FREE wall')
      if (allocated(error)) return
      call run_completes(error, OUT//'pit_split.inp', OUT//'pit_split.h5', model, split, &
         'split wall')
      if (allocated(error)) return
      call check(error, all(shape(free%state%u) == shape(split%state%u)), 'same unknowns')
      if (allocated(error)) return
      call check_close(error, maxval(abs(free%state%u - split%state%u)), 0.0_wp, 0.0_wp, &
         'displacements: FREE = split plate sets with LEFT/RIGHT', &
         atol=1.0e-10_wp*maxval(abs(split%state%u)))
      if (allocated(error)) return
      do i = 1, 4
         call file%open(OUT//'pit_free2.h5', error)
         if (allocated(error)) return
         call file%dataset('/increments/00000'//itoa(i)//'/plates/wall/node_forces', a, error)
         if (allocated(error)) return
         call file%close()
         call file%open(OUT//'pit_split.h5', error)
         if (allocated(error)) return
         call file%dataset('/increments/00000'//itoa(i)//'/plates/wall_3/node_forces', b, &
            error)
         if (allocated(error)) return
         call file%close()
         call check_close(error, maxval(abs(a(:, 1) - b(:, 1))), 0.0_wp, 0.0_wp, &
            'base N, Q, M after increment '//itoa(i)//': FREE = split', &
            atol=1.0e-10_wp*max(maxval(abs(b(:, 1))), 1.0_wp))
         if (allocated(error)) return
      end do
   end subroutine test_free_equals_split

   !> A quay wall (x = 0, 0 <= y <= 6, six 2-node plate elements walked upwards, clamped at
   !> its base) with dry ground on its left only, sharing its nodes (no joints), held at every
   !> node off the wall, the sea at y = 4 from the start, the wall under `mode` ('' : not
   !> named in *PLATE_WATER). Writes the deck and runs it; rx, ry: the sums of the horizontal
   !> and vertical reactions; u: the displacements.
   subroutine run_quay(name, mode, rx, ry, u, error)
      character(len=*), intent(in) :: name, mode
      real(wp), intent(out) :: rx, ry
      real(wp), allocatable, intent(out) :: u(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: file
      real(wp), allocatable :: reac(:, :)
      integer :: k, r, c
      call make_directories(OUT)
      open (newunit=k, file=OUT//name//'.inp', status='replace', action='write')
      write (k, '(a)') '*TITLE', 'quay wall', '*UNITS', 'kN, m, kPa', '*NODES'
      do r = 0, 6
         do c = 0, 2
            write (k, '(i0,a,i0,a,i0)') 3*r + c + 1, ', ', c - 2, ', ', r
         end do
      end do
      write (k, '(a)') '*ELEMENTS, TYPE=Q4, SET=ground'
      do r = 0, 5
         do c = 0, 1
            write (k, '(i0,4(a,i0))') 2*r + c + 1, ', ', 3*r + c + 1, ', ', 3*r + c + 2, &
               ', ', 3*r + c + 5, ', ', 3*r + c + 4
         end do
      end do
      write (k, '(a)') '*MATERIAL, NAME=ground', 'E = 1e4, NU = 0.3', &
         '*SECTION, SET=ground, MATERIAL=ground', '*DRY', 'ground', '*NSET, NAME=held'
      do r = 0, 6
         write (k, '(i0,a,i0)') 3*r + 1, ', ', 3*r + 2
      end do
      write (k, '(a)') '*BOUNDARY', 'held, XY', '3, ALL', '*PLATE, SET=wall, EA=1e7, EI=1e5'
      do r = 0, 5
         write (k, '(i0,a,i0)') 3*r + 3, ', ', 3*r + 6
      end do
      write (k, '(a)') '*WATER, NAME=sea, GAMMA_W=10, LEVEL=4'
      if (len(mode) > 0) write (k, '(a)') '*PLATE_WATER', 'wall, '//mode
      write (k, '(a)') '*STEP, NAME=water, INCREMENTS=1', '*END STEP'
      close (k)
      call run_completes(error, OUT//name//'.inp', OUT//name//'.h5', model, problem, &
         'quay wall '//name)
      if (allocated(error)) return
      call file%open(OUT//name//'.h5', error)
      if (allocated(error)) return
      call file%dataset('/increments/000001/reaction', reac, error)
      if (allocated(error)) return
      call file%close()
      rx = sum(reac(1, :))
      ry = sum(reac(2, :))
      u = problem%state%u
   end subroutine run_quay

   !> The quay wall of run_quay. The water stands on a contour that the wall closes: the
   !> ground's far side x = -2 (pushing +x, gamma_w h^2 / 2 = 80 for h = 4), its base, and
   !> the wall. The wall is impermeable: the ground's side along it is never a free face, in
   !> any mode, and the wall takes the water on its faces by its mode. FREE (the wall's right
   !> face is free from the start), RIGHT (the sea's side, given) and the default (not named:
   !> FREE) put the water once on the wall's line, so the horizontal reactions sum to zero
   !> (1e-10 of 80: equilibrium of the whole, to round-off); the default is the same run as
   !> FREE (displacements and reactions to 1e-10 of the largest: one deck, the same loads).
   !> NONE (no water on the wall, by the user's word) leaves the far side's 80 to the
   !> supports: -80. The water counted twice on the wall's line (the plate's and the
   !> ground's side, as RIGHT did while the ground's side along a plate was a free face)
   !> would give +80.
   subroutine test_free_quay(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=5), parameter :: MODES(4) = [character(len=5) :: 'FREE', 'RIGHT', '', &
         'NONE']
      real(wp), parameter :: F = 0.5_wp*10.0_wp*4.0_wp**2
      real(wp) :: rx(4), ry(4), expect
      real(wp), allocatable :: u(:, :), u_free(:, :)
      integer :: k
      do k = 1, 4
         call run_quay('quay_'//label(MODES(k)), trim(MODES(k)), rx(k), ry(k), u, error)
         if (allocated(error)) return
         expect = merge(-F, 0.0_wp, MODES(k) == 'NONE')
         call check_close(error, rx(k), expect, 0.0_wp, 'horizontal reactions ('// &
            label(MODES(k))//') sum to '//itoa(nint(expect))//': the water on the wall counted '// &
            trim(merge('never', 'once ', MODES(k) == 'NONE')), atol=1.0e-10_wp*F)
         if (allocated(error)) return
         if (k == 1) u_free = u
         if (k == 3) then
            call check_close(error, maxval(abs(u - u_free)), 0.0_wp, 0.0_wp, &
               'displacements: default = FREE', atol=1.0e-10_wp*maxval(abs(u_free)))
            if (allocated(error)) return
            call check_close(error, abs(rx(3) - rx(1)) + abs(ry(3) - ry(1)), 0.0_wp, &
               0.0_wp, 'reactions: default = FREE', atol=1.0e-10_wp*F)
            if (allocated(error)) return
         end if
      end do
   end subroutine test_free_quay

   !> A raft on a saturated column (width B = 1, height H = 10, ten Q4, base held, sides on
   !> rollers; GAMMA_SAT = 20, the K0 procedure, then a nil step) under the level y = 12:
   !> d = 2 m of water stand on the raft, one 2-node plate on the column's top side (walked
   !> from x = 0 to x = 1: the water on its left face). The vertical reactions balance the
   !> column's saturated weight, the water's weight on the raft and the water's pressure
   !> on the base (a free face of the soil, pushing up): R_y = gamma_sat H B + gamma_w d B
   !> - gamma_w (H + d) B = (gamma_sat - gamma_w) H B = 100, the buoyant weight; to 1e-10
   !> of it (equilibrium of the whole, to round-off) for the default (the raft not named in
   !> *PLATE_WATER: FREE, the top face free, the soil's top side covered by the raft) and for
   !> LEFT. Water counted twice (the raft's load and the soil's top side as a free face, as
   !> LEFT did before) would give 120; NONE (no water on the raft, by the user's word; the
   !> soil under the raft cannot take it) gives 80. The raft carries the water itself: its
   !> consistent load puts q L / 2 (q = gamma_w d = 20, L = 1) on each end node as the soil's
   !> side did, so the K0 state stays in equilibrium, the soil does not move, and the raft
   !> is a simply supported beam under q (the end moments of its load rotate its ends):
   !> end shear q L / 2 = 10 and end rotations q L^3 / (24 EI), to 1e-10 (one element,
   !> exact; the soil's nodes still to round-off). A transparent raft carried nothing.
   subroutine test_free_raft(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=4), parameter :: MODES(3) = [character(len=4) :: '', 'LEFT', 'NONE']
      real(wp), parameter :: GSAT = 20.0_wp, GW = 10.0_wp, HC = 10.0_wp, D = 2.0_wp
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: file
      real(wp), parameter :: Q = GW*D, EI = 1.0e5_wp
      real(wp), allocatable :: reac(:, :), nf(:, :), rot(:)
      real(wp) :: expect
      character(len=:), allocatable :: name
      integer :: k, u, i
      call make_directories(OUT)
      do k = 1, 3
         name = 'raft_'//label(MODES(k))
         open (newunit=u, file=OUT//name//'.inp', status='replace', action='write')
         write (u, '(a)') '*TITLE', 'submerged raft', '*UNITS', 'kN, m, kPa', '*NODES'
         do i = 0, 10
            write (u, '(i0,a,i0)') 2*i + 1, ', 0, ', i
            write (u, '(i0,a,i0)') 2*i + 2, ', 1, ', i
         end do
         write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=soil'
         do i = 1, 10
            write (u, '(i0,4(", ",i0))') i, 2*i - 1, 2*i, 2*i + 2, 2*i + 1
         end do
         write (u, '(a)') '*NSET, NAME=base', '1, 2', '*NSET, NAME=sides, GENERATE', '1, 22', &
            '*BOUNDARY', 'base, XY', 'sides, X', '*MATERIAL, NAME=soil', &
            'E = 3e4, NU = 0.25, GAMMA_UNSAT = 18, GAMMA_SAT = 20', &
            '*SECTION, SET=soil, MATERIAL=soil', '*PLATE, SET=raft, EA=1e7, EI=1e5', '21, 22', &
            '*WATER, NAME=lake, GAMMA_W=10, LEVEL=12'
         if (len_trim(MODES(k)) > 0) write (u, '(a)') '*PLATE_WATER', 'raft, '//trim(MODES(k))
         write (u, '(a)') '*INITIAL_STRESS, TYPE=GEOSTATIC', 'ALL, 10.0, 0.5', &
            '*STEP, NAME=nil, INCREMENTS=1', '*END STEP'
         close (u)
         call run_completes(error, OUT//name//'.inp', OUT//name//'.h5', model, problem, name)
         if (allocated(error)) return
         call file%open(OUT//name//'.h5', error)
         if (allocated(error)) return
         call file%dataset('/increments/000001/reaction', reac, error)
         if (allocated(error)) return
         call file%dataset('/increments/000001/plates/raft/node_forces', nf, error)
         if (allocated(error)) return
         call file%dataset('/increments/000001/plates/raft/rotation', rot, error)
         if (allocated(error)) return
         call file%close()
         if (MODES(k) /= 'NONE') then
            call check_close(error, maxval(abs(abs(nf(2, :)) - 0.5_wp*Q)), 0.0_wp, 0.0_wp, &
               name//': the raft carries its water, end shear q L / 2', atol=1.0e-10_wp*Q)
            if (allocated(error)) return
            call check_close(error, maxval(abs(abs(rot) - Q/(24.0_wp*EI))), 0.0_wp, 0.0_wp, &
               name//': end rotations q L^3 / (24 EI)', atol=1.0e-10_wp*Q/(24.0_wp*EI))
            if (allocated(error)) return
         end if
         expect = (GSAT - GW)*HC
         if (MODES(k) == 'NONE') expect = expect - GW*D
         call check_close(error, sum(reac(2, :)), expect, 0.0_wp, name//': vertical '// &
            'reactions = the weights of soil and water less the uplift on the base', &
            atol=1.0e-10_wp*(GSAT - GW)*HC)
         if (allocated(error)) return
      end do
   end subroutine test_free_raft

   !> The mode word of a test deck, DEFAULT for none (the plate set not named).
   pure function label(mode) result(text)
      character(len=*), intent(in) :: mode
      character(len=:), allocatable :: text
      text = trim(mode)
      if (len(text) == 0) text = 'DEFAULT'
   end function label

   !> *PLATE_WATER with a mode word that is none of LEFT, RIGHT, FREE, NONE: refused with the
   !> deck's file and line of the data line and the modes in the message, exit 2, no results.
   subroutine test_free_bad_mode(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: deck = OUT//'bad_plate_water.inp'
      call make_directories(OUT)
      call write_wall(deck, 'bad plate water mode', 4, '3', [character(len=32) :: &
         '*PLATE_WATER', 'wall, FLOODED', '*STEP, NAME=water, INCREMENTS=1', '*END STEP'])
      call check_refused(error, deck, 'wall, FLOODED', "side 'FLOODED': expected LEFT or "// &
         'RIGHT (of the plate walked from its first node to its last), FREE', &
         OUT//'bad_plate_water.h5', 'unknown *PLATE_WATER mode')
   end subroutine test_free_bad_mode

end module test_water_free
