!> What a new user writes from doc/deck.md alone: every keyword that takes one node takes a
!> node id or a node set of one node, every dof the words X, Y, R, Z (test/data/user/).
!> Node indices and dofs are integers: compared exactly.
module test_io_deck_user
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_model_type, only: model_t
   use pecplas_model_mesh, only: mesh_t, node_set_t
   use pecplas_model_adapt_request, only: goal_spec_t, parse_goal_spec, goal_node_index, &
      GOAL_NODE
   use pecplas_testing, only: unittest_t, new_unittest, check
   use pecplas_fe_loads, only: pattern_vectors
   use pecplas_massif_kinematics, only: massif_rule_t
   use pecplas_model_refine_refine, only: refine_model
   use fixtures_bad_decks, only: bad, run_bad_cases
   use pecplas_cmd_pecplas, only: force_notes
   implicit none (type, external)
   private
   public :: collect_io_deck_user

   character(len=*), parameter :: DIR = 'test/data/user/'

contains

   subroutine collect_io_deck_user(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('step_node_and_dof_forms', test_step_forms), &
               new_unittest('adapt_goal_node_set', test_adapt_goal), &
               new_unittest('node_set_used_not_warned', test_no_unused_warning), &
               new_unittest('node_forms_refused', test_bad_forms), &
               new_unittest('node_of_doublet', test_node_of), &
               new_unittest('depth_pressure_deck', test_depth_pressure), &
               new_unittest('depth_pressure_refused', test_bad_pressure), &
               new_unittest('depth_pressure_refined', test_depth_refined), &
               new_unittest('gmsh_group_one_name', test_gmsh_group), &
               new_unittest('gmsh_group_phase', test_gmsh_group_phase), &
               new_unittest('gmsh_q8r', test_gmsh_q8r), &
               new_unittest('gmsh_forms_refused', test_bad_gmsh), &
               new_unittest('weightless_geostatic_warned', test_weightless), &
               new_unittest('force_on_node_set_noted', test_force_notes)]
   end subroutine collect_io_deck_user

   subroutine load(name, model, error)
      character(len=*), intent(in) :: name
      type(model_t), intent(out) :: model
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      call read_deck(DIR//name, model, e)
      call check(error, .not. allocated(e), 'good deck '//name//' must read')
      if (allocated(error)) error%message = error%message//': '//e%text()
   end subroutine load

   !> Five arc-length steps name node 9 or 8 as an id or a set of one node, and the dof as
   !> Y, z, R, 1, x: each resolves to that node's internal index and dof 2, 2, 1, 1, 1; FORCE
   !> and DISPLACEMENT lines and *BOUNDARY take sets and words (Z, x, r) too.
   subroutine test_step_forms(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      integer :: n9, n8
      call load('good_node_forms.inp', model, error)
      if (allocated(error)) return
      n9 = findloc(model%mesh%node_id, 9, 1)
      n8 = findloc(model%mesh%node_id, 8, 1)
      call check(error, size(model%steps) == 6, 'six steps')
      if (allocated(error)) return
      call check(error, all(model%steps(1:5)%node == [n9, n9, n9, n8, n9]), &
         'NODE=head|9|HEAD|corner|head -> nodes 9 9 9 8 9')
      if (allocated(error)) return
      call check(error, all(model%steps(1:5)%dof == [2, 2, 1, 1, 1]), &
         'DOF=Y|z|R|1|x -> 2 2 1 1 1')
      if (allocated(error)) return
      ! the DISPLACEMENT on a set of one node with dof x; *BOUNDARY left, r holds x on 1 4 7
      associate (pat => model%patterns(2))
         call check(error, size(pat%node) == 1 .and. pat%node(1) == n8 .and. pat%dof(1) == 1, &
            'DISPLACEMENT corner, x: one entry on node 8, dof 1')
      end associate
      if (allocated(error)) return
      call check(error, count(model%supports%dof == 1) == 5, &
         'x held on base (nodes 1 2 3) and on left, r (1 4 7): 5 nodes, 1 counted once')
      if (allocated(error)) return
      ! the FORCE on a set of one node with dof Z: one entry, on node 9, along y
      associate (pat => model%patterns(1))
         call check(error, size(pat%node) == 1 .and. pat%node(1) == n9 .and. pat%dof(1) == 2, &
            'FORCE head, Z: one entry on node 9, dof 2')
      end associate
   end subroutine test_step_forms

   !> *ADAPT GOAL=node:corner:Z: the set's one node (id 8), dof 2; the same goal from the
   !> command line (--goal) resolves alike, and node:8:y names the same node.
   subroutine test_adapt_goal(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(goal_spec_t) :: goal
      character(len=:), allocatable :: msg
      integer :: inode, byid
      call load('good_node_forms.inp', model, error)
      if (allocated(error)) return
      call parse_goal_spec(model%adapt%goal, goal, msg)
      call check(error, .not. allocated(msg) .and. goal%kind == GOAL_NODE .and. goal%dof == 2, &
         'GOAL=node:corner:Z parses as a node goal on dof 2')
      if (allocated(error)) return
      call goal_node_index(goal, model%mesh, inode, msg)
      call check(error, inode == findloc(model%mesh%node_id, 8, 1), 'node:corner -> node 8')
      if (allocated(error)) return
      call parse_goal_spec('node:8:y', goal, msg)
      call goal_node_index(goal, model%mesh, byid, msg)
      call check(error, byid == inode, 'node:8:y names the same node')
      if (allocated(error)) return
      call parse_goal_spec('node:base:y', goal, msg)
      call goal_node_index(goal, model%mesh, inode, msg)
      call check(error, inode == 0 .and. allocated(msg), 'node:base (3 nodes) is refused')
      if (allocated(error)) return
      call check(error, index(msg, "node set 'base' has 3 nodes") > 0, 'message: '//msg)
   end subroutine test_adapt_goal

   !> The sets named only by NODE= and GOAL= are used: the one warning about node sets is
   !> the one for 'unused_on_purpose'.
   subroutine test_no_unused_warning(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      character(len=:), allocatable :: text
      integer :: i
      call load('good_node_forms.inp', model, error)
      if (allocated(error)) return
      text = ''
      do i = 1, model%warnings%count()
         text = text//model%warnings%line(i)//'; '
      end do
      call check(error, index(text, "'unused_on_purpose'") > 0, &
         'the unused set is warned: '//text)
      if (allocated(error)) return
      call check(error, index(text, "'head'") == 0 .and. index(text, "'corner'") == 0, &
         'head (NODE=) and corner (GOAL=) are not warned: '//text)
   end subroutine test_no_unused_warning

   !> A geostatic initial stress of a material without unit weight is zero everywhere (a
   !> forgotten GAMMA): warned at its data line; with a surcharge it is not zero, no warning.
   subroutine test_weightless(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      character(len=:), allocatable :: text
      integer :: i
      call load('warn_weightless.inp', model, error)
      if (allocated(error)) return
      text = ''
      do i = 1, model%warnings%count()
         text = text//model%warnings%line(i)//'; '
      end do
      call check(error, index(text, "warn_weightless.inp:5: warning: geostatic initial "// &
         "stress of set 'soil' is zero everywhere") > 0, 'warned at line 5: '//text)
      if (allocated(error)) return
      call load('good_weightless_surcharge.inp', model, error)
      if (allocated(error)) return
      text = ''
      do i = 1, model%warnings%count()
         text = text//model%warnings%line(i)//'; '
      end do
      call check(error, index(text, 'zero everywhere') == 0, 'a surcharge: no warning: '//text)
   end subroutine test_weightless

   !> A FORCE on a node set loads each node with the value: the banner's note says what that
   !> makes in all (block.inc's top row, nodes 7, 8, 9: 3 x -5 = -15 kN); a force on one node
   !> gets no note. Sums of three exact binary fractions: compared as text.
   subroutine test_force_notes(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      character(len=:), allocatable :: text
      call load('force_on_set.inp', model, error)
      if (allocated(error)) return
      text = force_notes(model)
      call check(error, index(text, "load pattern 'spread' (FORCE) acts on 3 nodes along y, "// &
         'each with its value: -15 kN in all at factor 1') > 0, 'note: '//text)
      if (allocated(error)) return
      call check(error, index(text, "'point'") == 0, 'a force on one node: no note: '//text)
   end subroutine test_force_notes

   !> A set of several nodes, a missing set, two dofs, a goal on a set of three nodes: input
   !> errors at the line of the keyword, each saying what is expected.
   subroutine test_bad_forms(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DIR, [ &
         bad('step_big_set', 5, '*STEP', "NODE=base: node set 'base' has 3 nodes", &
         'a node set of one node'), &
         bad('step_no_set', 5, '*STEP', "no node set 'nohead'", 'a node id'), &
         bad('step_dof_word', 5, '*STEP', 'expected DOF=1 or X', "found 'XY'"), &
         bad('adapt_big_set', 7, '*ADAPT', "node set 'base' has 3 nodes")], error)
   end subroutine test_bad_forms

   !> A node set that generated joints extended with the node's duplicate (two nodes at one
   !> point) names its first node; two nodes at two points name none.
   subroutine test_node_of(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      character(len=:), allocatable :: msg
      integer :: inode
      mesh%x = reshape([0.0_wp, 1.0_wp, 2.0_wp, 3.0_wp, 0.0_wp, 1.0_wp], [2, 3])
      mesh%node_id = [10, 20, 30]
      mesh%nsets = [node_set_t('doublet', [1, 3]), node_set_t('pair', [1, 2])]
      call mesh%node_of('doublet', inode, msg)
      call check(error, inode == 1 .and. .not. allocated(msg), 'doublet -> its first node')
      if (allocated(error)) return
      call mesh%node_of('PAIR', inode, msg)
      call check(error, inode == 0 .and. allocated(msg), 'two points: refused')
      if (allocated(error)) return
      call mesh%node_of(' 20 ', inode, msg)
      call check(error, inode == 2, 'id 20 -> node 2')
      if (allocated(error)) return
      call mesh%node_of('40', inode, msg)
      call check(error, inode == 0 .and. allocated(msg), 'no node 40')
   end subroutine test_node_of

   !> good_linear_pressure.inp: water p = max(0, 10 (1.5 - y)) on the side x = 2 (edges 3-6
   !> from y = 0 to 1, 6-9 from 1 to 2, inward normal -x). Edge 3-6 is a trapezoid 15 -> 5:
   !> (2 15 + 5)/6 = 35/6 to node 3, (15 + 2 5)/6 = 25/6 to node 6; edge 6-9 a triangle 5 -> 0
   !> over its lower half: int (1 - t) 10 (1/2 - t) = 25/24 to node 6, int t 10 (1/2 - t) =
   !> 5/24 to node 9 (t from 0 to 1/2); in all 10 1.5**2/2 = 11.25. 'shifted' (5 more, no
   !> floor): 50/6, 60/6, 10/6. 'split' (the uniform 5 and the gradient on two lines) equals
   !> 'shifted'. Tolerance 1e-13 of the largest force: every integral is exact (Gauss rules of
   !> the polynomial's degree on each piece), only the rounding of a few dozen operations
   !> remains.
   subroutine test_depth_pressure(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: TOL = 1.0e-13_wp
      type(model_t) :: model
      type(massif_rule_t) :: none(0)
      real(wp), allocatable :: force(:, :, :), disp(:, :, :), want(:, :)
      integer :: n3, n6, n9
      call load('good_linear_pressure.inp', model, error)
      if (allocated(error)) return
      call pattern_vectors(model, none, force, disp, error)
      if (allocated(error)) return
      n3 = findloc(model%mesh%node_id, 3, 1)
      n6 = findloc(model%mesh%node_id, 6, 1)
      n9 = findloc(model%mesh%node_id, 9, 1)
      allocate (want(2, model%mesh%nnode()), source=0.0_wp)
      want(1, [n3, n6, n9]) = -[35.0_wp/6, 25.0_wp/6 + 25.0_wp/24, 5.0_wp/24]
      call check(error, all(abs(force(:, :, 1) - want) <= TOL*maxval(abs(want))), &
         'water: -35/6, -125/24, -5/24 along x on nodes 3, 6, 9')
      if (allocated(error)) return
      call check(error, abs(sum(force(1, :, 1)) + 11.25_wp) <= TOL*11.25_wp, &
         'water: resultant 10 1.5**2/2')
      if (allocated(error)) return
      want = 0.0_wp
      want(1, [n3, n6, n9]) = -[50.0_wp, 60.0_wp, 10.0_wp]/6
      call check(error, all(abs(force(:, :, 2) - want) <= TOL*maxval(abs(want))), &
         'shifted: -50/6, -60/6, -10/6')
      if (allocated(error)) return
      call check(error, all(abs(force(:, :, 3) - force(:, :, 2)) <= TOL*maxval(abs(want))), &
         'uniform + gradient on two lines = the same on one line')
   end subroutine test_depth_pressure

   !> Refined once (every side halved), the patterns of good_linear_pressure.inp keep their
   !> resultants, -11.25 (water, cut at y = 1.5, now a node) and -20 (shifted): the halves
   !> carry the same linear function, integrated exactly (tolerance as in
   !> test_depth_pressure), and the side's new mid node gets its share.
   subroutine test_depth_refined(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: TOL = 1.0e-13_wp
      type(model_t) :: model, fine
      type(massif_rule_t) :: none(0)
      real(wp), allocatable :: force(:, :, :), disp(:, :, :)
      character(len=:), allocatable :: reason
      call load('good_linear_pressure.inp', model, error)
      if (allocated(error)) return
      call refine_model(model, fine, reason)
      call check(error, .not. allocated(reason), 'refined')
      if (allocated(error)) return
      call check(error, size(fine%patterns(1)%pressure) == 4 .and. &
         size(fine%patterns(1)%pressure_gradient) == 4, 'four half edges with their gradient')
      if (allocated(error)) return
      call pattern_vectors(fine, none, force, disp, error)
      if (allocated(error)) return
      call check(error, abs(sum(force(1, :, 1)) + 11.25_wp) <= TOL*11.25_wp .and. &
         abs(sum(force(2, :, 1))) <= TOL*11.25_wp, 'water: resultant -11.25 along x')
      if (allocated(error)) return
      call check(error, abs(sum(force(1, :, 2)) + 20.0_wp) <= TOL*20.0_wp, &
         'shifted: resultant -20 along x')
   end subroutine test_depth_refined

   !> Three fields on a pressure line, MIN= on a force pattern: input errors at the line.
   subroutine test_bad_pressure(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DIR, [ &
         bad('pressure_three', 6, '*LOAD', 'p_ref, gradient, y_ref', 'found 3 fields'), &
         bad('force_min', 3, '*LOAD', 'MIN= is an option of TYPE=PRESSURE')], error)
   end subroutine test_bad_pressure

   !> ../mixed.msh's surface group 'soil' holds Q4 and T3 elements (sets soil_Q4, soil_T3):
   !> *SECTION, *INITIAL_STRESS and a BODY_FORCE naming 'soil' reach both parts.
   subroutine test_gmsh_group(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      integer :: q, t
      integer, allocatable :: sets(:)
      call load('good_gmsh_group.inp', model, error)
      if (allocated(error)) return
      q = model%mesh%find_eset('soil_Q4')
      t = model%mesh%find_eset('soil_T3')
      call check(error, q > 0 .and. t > 0 .and. size(model%mesh%esets) == 2, &
         'two parts soil_Q4, soil_T3')
      if (allocated(error)) return
      call check(error, same_two(model%mesh%find_esets('SOIL'), q, t), 'soil names both parts')
      if (allocated(error)) return
      call check(error, model%mesh%esets(q)%material == 'clay' .and. &
         model%mesh%esets(t)%material == 'clay', '*SECTION, SET=soil gives both parts clay')
      if (allocated(error)) return
      call check(error, size(model%initial_stresses) == 2, 'one initial stress line per part')
      if (allocated(error)) return
      sets = model%initial_stresses%eset
      call check(error, same_two(sets, q, t), 'initial stress on both')
      if (allocated(error)) return
      call check(error, same_two(model%patterns(1)%eset, q, t), 'body force on both parts')
   end subroutine test_gmsh_group

   !> `list` is {a, b} in some order.
   pure logical function same_two(list, a, b)
      integer, intent(in) :: list(:), a, b
      same_two = size(list) == 2 .and. any(list == a) .and. any(list == b) .and. a /= b
   end function same_two

   !> *CHANGE_MATERIAL naming the group 'soil' changes both parts (one change per part).
   subroutine test_gmsh_group_phase(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      integer, allocatable :: sets(:)
      call load('good_gmsh_group_phase.inp', model, error)
      if (allocated(error)) return
      call check(error, size(model%steps) == 2, 'two steps')
      if (allocated(error)) return
      call check(error, size(model%steps(2)%changes) == 2, 'two changes in step 2')
      if (allocated(error)) return
      sets = model%steps(2)%changes%set
      call check(error, same_two(sets, model%mesh%find_eset('soil_Q4'), &
         model%mesh%find_eset('soil_T3')), 'the change reaches soil_Q4 and soil_T3')
   end subroutine test_gmsh_group_phase

   !> *SECTION, SET=wall, ELEMENT=Q8R on ../q8.msh's 8-node quadrilaterals: the set is Q8R.
   subroutine test_gmsh_q8r(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      integer :: k
      call load('good_gmsh_q8r.inp', model, error)
      if (allocated(error)) return
      k = model%mesh%find_eset('wall')
      call check(error, k > 0, 'set wall')
      if (allocated(error)) return
      call check(error, model%mesh%esets(k)%etype == 'Q8R', 'wall is Q8R, got '// &
         model%mesh%esets(k)%etype)
   end subroutine test_gmsh_q8r

   !> A second section on a part of a sectioned group, ELEMENT=Q8R without 8-node
   !> quadrilaterals, an unknown ELEMENT=.
   subroutine test_bad_gmsh(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DIR, [ &
         bad('gmsh_group_twice', 9, '*SECTION', "element set 'soil_T3' already has a section"), &
         bad('gmsh_q8r_on_q4', 8, '*SECTION', 'ELEMENT=Q8R is for 8-node quadrilaterals', &
         "'soil' has none"), &
         bad('section_element', 3, '*SECTION', 'bad value ELEMENT=T6R', 'Q8R')], error)
   end subroutine test_bad_gmsh

end module test_io_deck_user
