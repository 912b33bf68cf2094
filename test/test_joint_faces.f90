!> Joints on both faces of a line (*JOINTS, FACES=BOTH; doc/deck.md): the topology of the
!> split (node counts, which elements took which copies, the joints' nodes, the extension
!> below the line's end, springs per face), and a plate wall with joints on both faces in
!> elastic soil under an excavation phase: at every plate node the plate's nodal forces
!> balance those of the joints (the jump of the interface forces across the wall), to the
!> solver tolerance; the same wall with Katona doublets on both faces (bonded: plate and
!> contact forces balance; frictional: the Coulomb limit); bad FACES= decks.
!>
!> The mesh: 4 x 4 unit Q4 cells, node (i, j) = id 5 j + i + 1 at (i, j), cell (i, j) = id
!> 4 j + i + 1; the line x = 2 from the surface y = 4 down to y = 2 (nodes 23, 18, 13).
module test_joint_faces
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_fe_assembly, only: internal_forces
   use pecplas_base_strings, only: itoa
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use pecplas_joints_katona_operator, only: add_contact_forces
   use pecplas_joints_laws_type, only: MODE_OPEN, MODE_SLIP
   implicit none (type, external)
   private
   public :: collect_joint_faces

   character(len=*), parameter :: OUT = 'build/test_out/joint_faces/'
   character(len=1), parameter :: NL = new_line('a')

contains

   subroutine collect_joint_faces(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('topology', test_topology), &
               new_unittest('topology_extended', test_extended), &
               new_unittest('springs_per_face', test_springs), &
               new_unittest('plate_wall_equilibrium', test_wall), &
               new_unittest('thin_layer_and_goodman6', test_other_types), &
               new_unittest('katona_both_faces', test_katona), &
               new_unittest('bad_decks', test_bad)]
   end subroutine collect_joint_faces

   !> The 4 x 4 block with the line edges 'wall' (23-18, 18-13); `extra` after the mesh.
   subroutine write_block(path, extra)
      character(len=*), intent(in) :: path, extra
      integer :: u, i, j, n
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'line in a block', '*NODES'
      do j = 0, 4
         do i = 0, 4
            write (u, '(i0,a,i0,a,i0)') 5*j + i + 1, ', ', i, ', ', j
         end do
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=soil'
      do j = 0, 3
         do i = 0, 3
            n = 5*j + i + 1
            write (u, '(i0,4(", ",i0))') 4*j + i + 1, n, n + 1, n + 6, n + 5
         end do
      end do
      write (u, '(a)') '*MATERIAL, NAME=m', 'E = 1e4, NU = 0.3', '*SECTION, SET=soil, MATERIAL=m', &
         '*EDGES, NAME=wall', '23, 18', '18, 13', '*NSET, NAME=base', '1, 2, 3, 4, 5', &
         '*NSET, NAME=sides', '1, 6, 11, 16, 21, 5, 10, 15, 20, 25', '*BOUNDARY', 'base, XY', &
         'sides, X', '*INTERFACE_LAW, NAME=smooth, TYPE=ELASTIC', 'KN = 1e6, KT = 1e3', extra
      close (u)
   end subroutine write_block

   !> Element id k's node at the position of user node id `id` (0 if none).
   integer function node_at(model, k, id) result(node)
      type(model_t), intent(in) :: model
      integer, intent(in) :: k, id
      integer :: i, v
      node = 0
      v = findloc(model%mesh%node_id, id, 1)
      do i = 1, 4
         associate (c => model%mesh%esets(1)%conn(i, k))
            if (all(model%mesh%x(:, c) == model%mesh%x(:, v))) node = c
         end associate
      end do
   end function node_at

   !> Without extension: the head 23 and node 18 are split in two (25 + 4 nodes), the toe
   !> 13 (inside the soil) is not; cells 10 and 14 (left of the line) share the left copies,
   !> 11 and 15 the right ones, none the original; 4 joints, face 1 on the original nodes.
   subroutine test_topology(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(error_t), allocatable :: e
      integer :: n18, n23, n13
      call make_directories(OUT)
      call write_block(OUT//'topo.inp', '*JOINTS, TYPE=GOODMAN4, SET=wj, LAW=smooth, '// &
         'EDGES=wall, FACES=BOTH'//NL//'*STEP, NAME=s'//NL//'*END STEP')
      call read_deck(OUT//'topo.inp', model, e)
      call check(error, .not. allocated(e), 'deck reads')
      if (allocated(error)) return
      call check(error, model%mesh%nnode() == 29, 'nodes: 25 + 2 copies of 23 and of 18, got '// &
         itoa(model%mesh%nnode()))
      if (allocated(error)) return
      n23 = findloc(model%mesh%node_id, 23, 1)
      n18 = findloc(model%mesh%node_id, 18, 1)
      n13 = findloc(model%mesh%node_id, 13, 1)
      call check(error, node_at(model, 10, 18) == node_at(model, 14, 18) .and. &
         node_at(model, 11, 18) == node_at(model, 15, 18) .and. &
         node_at(model, 10, 18) /= node_at(model, 11, 18) .and. node_at(model, 10, 18) > 25 &
         .and. node_at(model, 11, 18) > 25, 'cells 10, 14 share one copy of 18, 11, 15 the other')
      if (allocated(error)) return
      call check(error, node_at(model, 14, 23) > 25 .and. node_at(model, 15, 23) > 25 .and. &
         node_at(model, 14, 23) /= node_at(model, 15, 23), 'the head 23 split between 14 and 15')
      if (allocated(error)) return
      call check(error, all([node_at(model, 10, 13), node_at(model, 11, 13), &
         node_at(model, 6, 13), node_at(model, 7, 13)] == n13), 'the toe 13 is not split')
      if (allocated(error)) return
      call check(error, size(model%joint_sets(1)%conn, 2) == 4, '4 joints (2 edges x 2 faces)')
      if (allocated(error)) return
      associate (c => model%joint_sets(1)%conn)
         ! the two faces of edge 23-18 (joints 1 and 3): face 1 the originals, face 2 the
         ! copies of one body each (cells 14 and 15), that body on the left of face 1
         call check(error, all([c(1, 1), c(2, 1), c(1, 3), c(2, 3)] == [n23, n18, n18, n23]) &
            .or. all([c(1, 1), c(2, 1), c(1, 3), c(2, 3)] == [n18, n23, n23, n18]), &
            'face 1 of both joints on the original nodes 23, 18')
         if (allocated(error)) return
         call check(error, (all(c(3:4, 1) == [node_at(model, 15, 18), node_at(model, 15, 23)]) &
            .and. all(c(3:4, 3) == [node_at(model, 14, 23), node_at(model, 14, 18)])) .or. &
            (all(c(3:4, 1) == [node_at(model, 14, 18), node_at(model, 14, 23)]) .and. &
            all(c(3:4, 3) == [node_at(model, 15, 23), node_at(model, 15, 18)])), &
            'face 2: the copies of cell 15 and of cell 14, each body on its joint''s left')
         if (allocated(error)) return
         ! going down the line (23 -> 18) the body on the left is the east one (cell 15)
         if (c(1, 1) == n23) then
            call check(error, c(3, 1) == node_at(model, 15, 18), 'left of 23 -> 18 is cell 15')
            if (allocated(error)) return
         end if
      end associate
      ! the supports follow: side nodes are not on the line; nothing else to hold
      call check(error, count(model%mesh%x(1, :) == 2.0_wp .and. model%mesh%x(2, :) == 4.0_wp) &
         == 3, 'three nodes at the head (plate, left, right)')
   end subroutine test_topology

   !> EXTEND=1: the cut goes on from the toe 13 down to 8 (one cell): 13 is split too (25 +
   !> 6 nodes), 8 (inside) is not; cells 6 and 7 beside the extension take the copies of 13;
   !> a fifth joint joins the right body (face 1) to the left one (face 2) along 13-8.
   subroutine test_extended(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(error_t), allocatable :: e
      integer :: n8
      call make_directories(OUT)
      call write_block(OUT//'ext.inp', '*JOINTS, TYPE=GOODMAN4, SET=wj, LAW=smooth, '// &
         'EDGES=wall, FACES=BOTH, EXTEND=1'//NL//'*STEP, NAME=s'//NL//'*END STEP')
      call read_deck(OUT//'ext.inp', model, e)
      call check(error, .not. allocated(e), 'deck reads')
      if (allocated(error)) return
      call check(error, model%mesh%nnode() == 31, 'nodes: 25 + 3 x 2 copies, got '// &
         itoa(model%mesh%nnode()))
      if (allocated(error)) return
      n8 = findloc(model%mesh%node_id, 8, 1)
      call check(error, node_at(model, 6, 13) == node_at(model, 10, 13) .and. &
         node_at(model, 7, 13) == node_at(model, 11, 13) .and. &
         node_at(model, 6, 13) /= node_at(model, 7, 13), 'the toe split: 6, 10 left, 7, 11 right')
      if (allocated(error)) return
      call check(error, node_at(model, 6, 8) == n8 .and. node_at(model, 7, 8) == n8, &
         'the end of the extension 8 is not split')
      if (allocated(error)) return
      associate (c => model%joint_sets(1)%conn)
         call check(error, size(c, 2) == 5, '5 joints')
         if (allocated(error)) return
         ! one body's copy of 13 and 8 on face 1, the other's copy of 13 and 8 on face 2
         call check(error, (all(c(:, 5) == [node_at(model, 7, 13), n8, n8, node_at(model, 6, 13)]) &
            .or. all(c(:, 5) == [node_at(model, 6, 13), n8, n8, node_at(model, 7, 13)]) .or. &
            all(c(:, 5) == [n8, node_at(model, 7, 13), node_at(model, 6, 13), n8]) .or. &
            all(c(:, 5) == [n8, node_at(model, 6, 13), node_at(model, 7, 13), n8])), &
            'extension joint: one body to the other along 13-8')
      end associate
   end subroutine test_extended

   !> SPRING joints on both faces: one doublet per line node and face (3 + 3), each with
   !> the tributary length of its face (1/2, 1, 1/2 m).
   subroutine test_springs(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(error_t), allocatable :: e
      call make_directories(OUT)
      call write_block(OUT//'springs.inp', '*INTERFACE_LAW, NAME=sp, TYPE=SPRING'//NL// &
         'KN = 1e6, KT = 1e3'//NL//'*JOINTS, TYPE=SPRING, SET=wj, LAW=sp, '// &
         'EDGES=wall, FACES=BOTH'//NL//'*STEP, NAME=s'//NL//'*END STEP')
      call read_deck(OUT//'springs.inp', model, e)
      call check(error, .not. allocated(e), 'deck reads')
      if (allocated(error)) return
      call check(error, size(model%joint_sets(1)%conn, 2) == 6, '6 springs, got '// &
         itoa(size(model%joint_sets(1)%conn, 2)))
      if (allocated(error)) return
      call check_close(error, sum(model%joint_sets(1)%tributary), 4.0_wp, 1.0e-14_wp, &
         'tributaries sum to twice the line length')
   end subroutine test_springs

   !> A plate wall (EA = 1e7, EI = 1e4) on the line, Goodman joints on both faces and an
   !> extension of one cell, in elastic soil; a phase removes the top-left cells 13, 14 (an
   !> excavation). At every plate node the plate's nodal forces and the joints' (the jump
   !> of the interface forces across the wall) balance: |f_plate + f_joints| <= sqrt(2) TOL
   !> ref per node (the converged residual), ref at least the largest joint force there.
   subroutine test_wall(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), allocatable :: fall(:, :), fnp(:, :)
      logical, allocatable :: keep(:)
      real(wp) :: worst, ref
      integer :: code, k, v
      integer, parameter :: ids(3) = [23, 18, 13]
      call make_directories(OUT)
      call write_wall(OUT//'wall.inp')
      code = run_deck(OUT//'wall.inp', OUT//'wall.h5', .true., model, problem)
      call check(error, code == 0, 'plate wall excavation runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      allocate (fall(size(problem%state%u, 1), size(problem%state%u, 2)))
      allocate (fnp, mold=fall)
      call internal_forces(model, problem%system%rules, problem%state%u, problem%state, fall, &
         error)
      if (allocated(error)) return
      keep = problem%state%plates%sets%active
      problem%state%plates%sets%active = .false.
      call internal_forces(model, problem%system%rules, problem%state%u, problem%state, fnp, &
         error)
      problem%state%plates%sets%active = keep
      call problem%state%rollback()
      if (allocated(error)) return
      worst = 0.0_wp
      ref = 0.0_wp
      do k = 1, size(ids)
         v = findloc(model%mesh%node_id, ids(k), 1)
         ! plate part fall - fnp, joint part fnp: their sum is the residual at v
         worst = max(worst, norm2(fall(:, v)))
         ref = max(ref, norm2(fnp(:, v)))
      end do
      write (*, '(a,es10.3,a,es10.3)') '  plate nodes: largest joint force ', ref, &
         ', largest |f_plate + f_joints| ', worst
      call check(error, ref > 0.0_wp, 'the joints load the plate')
      if (allocated(error)) return
      call check_close(error, worst, 0.0_wp, 0.0_wp, 'plate + joint forces at the plate nodes', &
         atol=sqrt(2.0_wp)*1.0e-9_wp*max(ref, 1.0_wp))
   end subroutine test_wall

   !> The plate wall with Katona doublets on both faces (the left face's turned over: face 1
   !> the soil copy, face 2 the plate node; every node face 1 of one doublet at most).
   !> Bonded (C and TENSION 1e6: every doublet sticks): at every plate node the plate's nodal
   !> forces balance the contact forces D^T f, to the convergence test: |f_plate + D^T f|
   !> <= sqrt(2) TOL W per node, W = 320 the soil's weight (gamma x 16 cells), which bounds the
   !> loads and reactions that are the reference of either step. Frictional (MU = 0.05, no
   !> cohesion): some doublets slip, and every doublet in contact obeys the Coulomb limit as
   !> the state iteration checks it, |T| <= MU N + 1e-9 max |f| (FORCE_TOL), with |T| at the
   !> limit (within the same) where it slips.
   subroutine test_katona(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), allocatable :: fall(:, :), fnp(:, :), fc(:, :)
      logical, allocatable :: keep(:)
      real(wp) :: worst, ref, ftol, excess
      integer :: code, k, v, nstick, nslip, nopen, nface1, c
      integer, parameter :: ids(3) = [23, 18, 13]
      real(wp), parameter :: W = 320.0_wp, TOL = 1.0e-9_wp
      call make_directories(OUT)
      do c = 1, 3
      ! GOODMAN4 joints, the chain down then up (extension at its end, at its start); springs
      call write_wall(OUT//'katona'//itoa(c)//'.inp', katona='MU = 0.5, C = 1e6, TENSION = 1e6', &
         reversed=c >= 2, spring=c == 3)
      code = run_deck(OUT//'katona'//itoa(c)//'.inp', OUT//'katona'//itoa(c)//'.h5', .true., &
         model, problem)
      call check(error, code == 0, 'bonded Katona wall '//itoa(c)//' runs (exit '// &
         itoa(code)//')')
      if (allocated(error)) return
      associate (kt => problem%katona)
         call kt%count_modes(nstick, nslip, nopen)
         write (*, '(a,3(1x,i0))') '  bonded: doublets stick, slip, open:', nstick, nslip, nopen
         ! one partner per face-1 node
         nface1 = 0
         do k = 1, kt%nd
            if (count(kt%node(1, :) == kt%node(1, k) .and. kt%set_of == kt%set_of(k)) > 1) &
               nface1 = nface1 + 1
         end do
         call check(error, nface1 == 0, 'each node is face 1 of one doublet of a set at most')
         if (allocated(error)) return
         call check(error, nslip == 0 .and. nstick > 0, 'bonded doublets stick')
         if (allocated(error)) return
         do k = 1, size(ids)
            v = findloc(model%mesh%node_id, ids(k), 1)
            call check(error, count(kt%node(1, :) == v) + count(kt%node(2, :) == v) >= 2, &
               'plate node '//itoa(ids(k))//' is in a doublet of each face')
            if (allocated(error)) return
         end do
         allocate (fall(size(problem%state%u, 1), size(problem%state%u, 2)))
         allocate (fnp, fc, mold=fall)
         call internal_forces(model, problem%system%rules, problem%state%u, problem%state, &
            fall, error)
         if (allocated(error)) return
         keep = problem%state%plates%sets%active
         problem%state%plates%sets%active = .false.
         call internal_forces(model, problem%system%rules, problem%state%u, problem%state, &
            fnp, error)
         problem%state%plates%sets%active = keep
         call problem%state%rollback()
         if (allocated(error)) return
         fc = 0.0_wp
         call add_contact_forces(kt, kt%f, fc)
         worst = 0.0_wp
         ref = 0.0_wp
         do k = 1, size(ids)
            v = findloc(model%mesh%node_id, ids(k), 1)
            worst = max(worst, norm2(fall(:, v) - fnp(:, v) + fc(:, v)))
            ref = max(ref, norm2(fc(:, v)))
         end do
         write (*, '(a,es10.3,a,es10.3)') '  plate nodes: largest contact force ', ref, &
            ', largest |f_plate + D^T f| ', worst
         call check(error, ref > 0.0_wp, 'the contact loads the plate')
         if (allocated(error)) return
         call check_close(error, worst, 0.0_wp, 0.0_wp, 'plate + contact forces at the '// &
            'plate nodes', atol=sqrt(2.0_wp)*TOL*W)
         if (allocated(error)) return
      end associate
      deallocate (fall, fnp, fc)
      end do
      call write_wall(OUT//'katona_mu.inp', katona='MU = 0.05', reversed=.true.)
      code = run_deck(OUT//'katona_mu.inp', OUT//'katona_mu.h5', .true., model, problem)
      call check(error, code == 0, 'frictional Katona wall runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      associate (kt => problem%katona)
         call kt%count_modes(nstick, nslip, nopen)
         write (*, '(a,3(1x,i0))') '  MU = 0.05: doublets stick, slip, open:', nstick, nslip, &
            nopen
         call check(error, nslip > 0, 'some doublets slip')
         if (allocated(error)) return
         ftol = 1.0e-9_wp*maxval(abs(kt%f))
         excess = 0.0_wp
         do k = 1, kt%nd
            if (kt%mode(k) == MODE_OPEN .or. kt%off(k)) cycle
            excess = max(excess, abs(kt%f(2, k)) - kt%mu(k)*kt%f(1, k))
            if (kt%mode(k) == MODE_SLIP) excess = max(excess, &
               abs(abs(kt%f(2, k)) - kt%mu(k)*kt%f(1, k)))
         end do
         write (*, '(a,es10.3,a,es10.3)') '  largest |T| - MU N (stick), ||T| - MU N| (slip) ', &
            excess, ', max |f| ', maxval(abs(kt%f))
         call check(error, excess <= ftol, 'Coulomb limit held, reached where slipping')
      end associate
   end subroutine test_katona

   !> The wall deck: soil cells 13, 14 (left of the line, top row) in set 'dig', removed by
   !> the second phase; gravity in the first.
   subroutine write_wall(path, thin, katona, spring, reversed)
      character(len=*), intent(in) :: path
      !> thin: THIN_LAYER joints; spring: SPRING joints; reversed: the line's edges listed
      !> from its toe up (its chain starts at the toe: the extension is at its start).
      logical, intent(in), optional :: thin, spring, reversed
      !> The data line of a TYPE=KATONA law that replaces the elastic one.
      character(len=*), intent(in), optional :: katona
      integer :: u, i, j, n
      character(len=:), allocatable :: joints, law(:), wall(:)
      law = [character(len=48) :: '*INTERFACE_LAW, NAME=smooth, TYPE=ELASTIC', 'KN = 1e6, KT = 1e3']
      if (present(katona)) law = [character(len=48) :: '*INTERFACE_LAW, NAME=smooth, TYPE=KATONA', &
         katona]
      joints = '*JOINTS, TYPE=GOODMAN4, SET=wj, LAW=smooth, EDGES=wall, FACES=BOTH, EXTEND=1'
      if (present(thin)) then
         if (thin) joints = '*JOINTS, TYPE=THIN_LAYER, SET=wj, LAW=smooth, EDGES=wall, '// &
            'FACES=BOTH, EXTEND=1, THICKNESS=0.01'
      end if
      if (present(spring)) then
         if (spring) joints = '*JOINTS, TYPE=SPRING, SET=wj, LAW=smooth, EDGES=wall, '// &
            'FACES=BOTH, EXTEND=1'
      end if
      wall = [character(len=6) :: '23, 18', '18, 13']
      if (present(reversed)) then
         if (reversed) wall = [character(len=6) :: '13, 18', '18, 23']
      end if
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'plate wall with joints on both faces', '*NODES'
      do j = 0, 4
         do i = 0, 4
            write (u, '(i0,a,i0,a,i0)') 5*j + i + 1, ', ', i, ', ', j
         end do
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=soil'
      do j = 0, 3
         do i = 0, 3
            if (j == 3 .and. i <= 1) cycle
            n = 5*j + i + 1
            write (u, '(i0,4(", ",i0))') 4*j + i + 1, n, n + 1, n + 6, n + 5
         end do
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=dig'
      do i = 0, 1
         n = 15 + i + 1
         write (u, '(i0,4(", ",i0))') 12 + i + 1, n, n + 1, n + 6, n + 5
      end do
      write (u, '(a)') '*MATERIAL, NAME=m', 'E = 1e4, NU = 0.3, GAMMA = 20', &
         '*SECTION, SET=soil, MATERIAL=m', '*SECTION, SET=dig, MATERIAL=m', &
         '*EDGES, NAME=wall', wall, '*NSET, NAME=base', '1, 2, 3, 4, 5', &
         '*NSET, NAME=sides', '1, 6, 11, 16, 21, 5, 10, 15, 20, 25', '*NSET, NAME=line', &
         '23, 18, 13', '*BOUNDARY', 'base, XY', 'sides, X'
      write (u, '(a)') (trim(law(i)), i=1, size(law))
      write (u, '(a)') joints, '*PLATE, SET=plate, NODES=line, EA=1e7, EI=1e4', &
         '*LOAD, NAME=weight, TYPE=GRAVITY', 'ALL', '*SOLVER, TOLERANCE=1e-9', &
         '*STEP, NAME=gravity', 'weight, 1', '*END STEP', '*STEP, NAME=dig, INCREMENTS=2', &
         '*DEACTIVATE', 'dig', '*END STEP'
      close (u)
   end subroutine write_wall

   !> The plate wall deck with THIN_LAYER joints (THICKNESS = 0.01) runs the excavation and
   !> keeps the plate in equilibrium with them as the Goodman one; a Q8 block with a 3-node
   !> line gets GOODMAN6 joints on both faces and runs: 77 nodes, 65 + two copies of each of
   !> the six nodes split (the line's five, the toe included with EXTEND=1, and the mid node
   !> of the extension edge; its end stays whole).
   subroutine test_other_types(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code, u, i, j, k, n, e
      integer :: ids(0:8, 0:8)
      call make_directories(OUT)
      call write_wall(OUT//'thin.inp', thin=.true.)
      code = run_deck(OUT//'thin.inp', OUT//'thin.h5', .true., model, problem)
      call check(error, code == 0, 'THIN_LAYER on both faces runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check(error, model%joint_sets(1)%is_thin_layer() .and. size(model%joint_sets) == 2, &
         'two THIN_LAYER sets (soil, dig)')
      if (allocated(error)) return
      open (newunit=u, file=OUT//'q8.inp', status='replace', action='write')
      write (u, '(a)') '*TITLE', 'q8 block', '*NODES'
      k = 0
      ids = 0
      do j = 0, 8
         do i = 0, 8
            if (mod(i, 2) == 1 .and. mod(j, 2) == 1) cycle
            k = k + 1
            ids(i, j) = k
            write (u, '(i0,a,f4.1,a,f4.1)') k, ', ', 0.5*i, ', ', 0.5*j
         end do
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q8, SET=soil'
      e = 0
      do j = 0, 6, 2
         do i = 0, 6, 2
            e = e + 1
            write (u, '(i0,8(", ",i0))') e, ids(i, j), ids(i + 2, j), ids(i + 2, j + 2), &
               ids(i, j + 2), ids(i + 1, j), ids(i + 2, j + 1), ids(i + 1, j + 2), ids(i, j + 1)
         end do
      end do
      write (u, '(a)') '*MATERIAL, NAME=m', 'E = 1e4, NU = 0.3, GAMMA = 20', &
         '*SECTION, SET=soil, MATERIAL=m', '*EDGES, NAME=wall'
      write (u, '(i0,2(", ",i0))') ids(4, 8), ids(4, 6), ids(4, 7)
      write (u, '(i0,2(", ",i0))') ids(4, 6), ids(4, 4), ids(4, 5)
      write (u, '(a)') '*NSET, NAME=base'
      write (u, '(i0,8(", ",i0))') (ids(i, 0), i=0, 8)
      write (u, '(a)') '*NSET, NAME=sides'
      write (u, '(i0,15(", ",i0))') (ids(0, j), j=1, 8), (ids(8, j), j=1, 8)
      write (u, '(a)') '*BOUNDARY', 'base, XY', 'sides, X', &
         '*INTERFACE_LAW, NAME=smooth, TYPE=ELASTIC', 'KN = 1e6, KT = 1e3', &
         '*JOINTS, TYPE=GOODMAN6, SET=wj, LAW=smooth, EDGES=wall, FACES=BOTH, EXTEND=1', &
         '*PLATE, SET=plate, EDGES=wall, EA=1e7, EI=1e4', '*LOAD, NAME=weight, TYPE=GRAVITY', &
         'ALL', '*SOLVER, TOLERANCE=1e-9', '*STEP, NAME=gravity', 'weight, 1', '*END STEP'
      close (u)
      code = run_deck(OUT//'q8.inp', OUT//'q8.h5', .true., model, problem)
      call check(error, code == 0, 'GOODMAN6 on both faces runs (exit '//itoa(code)//')')
      if (allocated(error)) return
      n = model%mesh%nnode()
      call check(error, n == 77, 'Q8 nodes 65 + 12 copies, got '//itoa(n))
      if (allocated(error)) return
      call check(error, size(model%joint_sets(1)%conn, 1) == 6 .and. &
         size(model%joint_sets(1)%conn, 2) == 5, '5 GOODMAN6 joints (2 x 2 faces + extension)')
   end subroutine test_other_types

   !> FACES= other than BOTH, FACES=BOTH with SIDE=, EXTEND without FACES=BOTH, a line on
   !> the boundary: exit 2 with the line.
   subroutine test_bad(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(error_t), allocatable :: e
      character(len=*), parameter :: cases(4) = [character(len=120) :: &
         '*JOINTS, TYPE=GOODMAN4, SET=wj, LAW=smooth, EDGES=wall, FACES=ONE', &
         '*JOINTS, TYPE=GOODMAN4, SET=wj, LAW=smooth, EDGES=wall, FACES=BOTH, SIDE=soil', &
         '*JOINTS, TYPE=GOODMAN4, SET=wj, LAW=smooth, EDGES=wall, SIDE=soil, EXTEND=1', &
         '*JOINTS, TYPE=GOODMAN4, SET=wj, LAW=smooth, EDGES=top, FACES=BOTH']
      character(len=*), parameter :: expect(4) = [character(len=40) :: 'expected FACES=BOTH', &
         'no SIDE=', 'EXTEND= goes with FACES=BOTH', 'is a side of 1 element']
      character(len=:), allocatable :: text
      integer :: k, i
      call make_directories(OUT)
      do k = 1, size(cases)
         text = trim(cases(k))
         do i = 1, len(text)
            if (text(i:i) == '|') text(i:i) = NL
         end do
         call write_block(OUT//'bad'//itoa(k)//'.inp', '*EDGES, NAME=top'//NL//'21, 22'//NL// &
            text//NL//'*STEP, NAME=s'//NL//'*END STEP')
         call read_deck(OUT//'bad'//itoa(k)//'.inp', model, e)
         call check(error, allocated(e), 'bad deck '//itoa(k)//' refused')
         if (allocated(error)) return
         call check(error, index(e%text(), OUT//'bad'//itoa(k)//'.inp:') > 0 .and. &
            index(e%text(), trim(expect(k))) > 0, 'bad deck '//itoa(k)//': '//e%text())
         if (allocated(error)) return
         deallocate (e)
      end do
   end subroutine test_bad

end module test_joint_faces
