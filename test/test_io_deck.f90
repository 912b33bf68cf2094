!> Good decks parse into the model written in them: counts, coordinates, connectivity as
!> internal numbers, materials, expanded load patterns, supports, steps and options. The
!> expected values are read off the deck files in test/data/decks (a number read from text
!> must come back to the last bit, see `near`; a normalised direction to rounding).
module test_io_deck
   use pecplas_base_kinds, only: wp
   use pecplas_model_loads, only: LOAD_GRAVITY, LOAD_PRESSURE, LOAD_FORCE, LOAD_DISPLACEMENT, &
      LOAD_BODY_FORCE
   use pecplas_base_error, only: error_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC, METHOD_NEWTON
   use pecplas_massif_materials_elastic, only: elastic_t
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close, near
   implicit none (type, external)
   private
   public :: collect_io_deck, DECKS

   !> Test decks, relative to the project root (where fpm test runs).
   character(len=*), parameter :: DECKS = 'test/data/decks/'

contains

   subroutine collect_io_deck(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('block_q4_mesh', test_block_mesh), &
               new_unittest('block_q4_material', test_block_material), &
               new_unittest('block_q4_loads', test_block_loads), &
               new_unittest('block_q4_steps_options', test_block_steps), &
               new_unittest('t6_includes', test_t6), &
               new_unittest('axisym_patterns', test_axisym_patterns), &
               new_unittest('axisym_options', test_axisym_options), &
               new_unittest('gmsh_mesh_and_deck', test_mesh), &
               new_unittest('strip_footing_example', test_strip_footing)]
   end subroutine collect_io_deck

   subroutine load(name, model, error)
      character(len=*), intent(in) :: name
      type(model_t), intent(out) :: model
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      call read_deck(DECKS//name, model, e)
      call check(error, .not. allocated(e), 'good deck '//name//' must read')
      if (allocated(error)) error%message = error%message//': '//e%text()
   end subroutine load

   !> User ids of internal node numbers.
   pure function ids(model, nodes) result(u)
      type(model_t), intent(in) :: model
      integer, intent(in) :: nodes(:)
      integer :: u(size(nodes))
      u = model%mesh%node_id(nodes)
   end function ids

   subroutine test_block_mesh(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      call load('good_block_q4.inp', model, error)
      if (allocated(error)) return
      ! nodes are numbered in reading order: id 9 first, id 8 last
      call check(error, model%mesh%nnode() == 9 .and. model%mesh%nelem() == 4, &
         '9 nodes and 4 elements')
      if (allocated(error)) return
      call check(error, all(model%mesh%node_id == [9, 1, 2, 3, 4, 5, 6, 7, 8]), 'node order')
      if (allocated(error)) return
      call check(error, all(near(model%mesh%x(:, 1), [2.0_wp, 2.0_wp])) .and. &
         all(near(model%mesh%x(:, 9), [1.0_wp, 2.0_wp])) .and. &
         all(near(model%mesh%x(:, 5), [0.0_wp, 1.0_wp])), &
         'coordinates of ids 9, 8, 4 (1.0D0, 1.0e0)')
      if (allocated(error)) return
      ! the two *ELEMENTS blocks (Soil, SOIL) make one set, spelled as first written
      call check(error, size(model%mesh%esets) == 1, 'one element set')
      if (allocated(error)) return
      associate (es => model%mesh%esets(1))
         call check(error, es%name == 'Soil' .and. es%etype == 'Q4' .and. &
            all(es%ids == [1, 2, 3, 4]), 'set Soil, Q4, ids 1..4')
         if (allocated(error)) return
         call check(error, all(es%conn(:, 4) == [6, 7, 1, 9]) .and. &
            all(ids(model, es%conn(:, 1)) == [1, 2, 5, 4]), 'connectivity as internal numbers')
         if (allocated(error)) return
      end associate
      call check(error, size(model%mesh%nsets) == 2, 'two node sets')
      if (allocated(error)) return
      call check(error, all(ids(model, model%mesh%nsets(1)%nodes) == [1, 2, 3]) .and. &
         all(ids(model, model%mesh%nsets(2)%nodes) == [1, 4, 7]), 'base (GENERATE) and left')
      if (allocated(error)) return
      ! edges are turned so that the body is on their left: 7 -> 8 becomes 8 -> 7
      associate (top => model%mesh%edge_sets(1))
         call check(error, size(top%nodes, 1) == 2 .and. size(top%nodes, 2) == 2 .and. &
            all(ids(model, top%nodes(:, 1)) == [9, 8]) .and. &
            all(ids(model, top%nodes(:, 2)) == [8, 7]), 'edge set top: 2 two-node edges, '// &
            'body on the left')
      end associate
   end subroutine test_block_mesh

   subroutine test_block_material(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      call load('good_block_q4.inp', model, error)
      if (allocated(error)) return
      call check(error, size(model%materials) == 1, 'one material')
      if (allocated(error)) return
      select type (m => model%materials(1)%m)
      type is (elastic_t)
         call check(error, m%name == 'Sand' .and. near(m%young, 2.0e4_wp) .and. &
            near(m%poisson, 0.3_wp) .and. near(m%unit_weight, 18.0_wp), &
            'E, NU, GAMMA over two lines')
      class default
         call check(error, .false., 'TYPE=elastic must give an elastic_t')
      end select
      if (allocated(error)) return
      call check(error, model%mesh%esets(1)%material == 'Sand' .and. &
         model%mesh%esets(1)%material_index == 1, 'section SOIL -> SAND resolved')
   end subroutine test_block_material

   subroutine test_block_loads(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      integer :: i
      integer, parameter :: fixed(2, 8) = reshape([1, 1, 1, 2, 2, 1, 2, 2, 3, 1, 3, 2, 4, 1, &
         7, 1], [2, 8])
      call load('good_block_q4.inp', model, error)
      if (allocated(error)) return
      ! base XY (3 nodes x 2) + left x (1, 4, 7; node 1 already fixed) = 8 distinct dofs
      call check(error, size(model%supports%node) == 8 .and. size(model%supports%dof) == 8, &
         '8 fixed dofs')
      if (allocated(error)) return
      do i = 1, 8
         call check(error, any(model%mesh%node_id(model%supports%node) == fixed(1, i) .and. &
            model%supports%dof == fixed(2, i)), 'fixed dof missing')
         if (allocated(error)) return
      end do
      call check(error, size(model%patterns) == 3, 'three patterns')
      if (allocated(error)) return
      associate (p => model%patterns(1))
         call check(error, p%name == 'weight' .and. p%kind == LOAD_GRAVITY .and. &
            all(p%eset == [1]) .and. all(near(p%vector(:, 1), [0.0_wp, -1.0_wp])), &
            'GRAVITY ALL defaults to direction (0, -1)')
         if (allocated(error)) return
      end associate
      associate (p => model%patterns(2))
         call check(error, p%kind == LOAD_PRESSURE .and. size(p%edge, 2) == 2 .and. &
            all(near(p%pressure, 10.0_wp)) .and. all(ids(model, p%edge(1:2, 2)) == [8, 7]) .and. &
            all(p%edge(3, :) == 0), 'PRESSURE on the 2 oriented edges of top, third node 0')
         if (allocated(error)) return
      end associate
      associate (p => model%patterns(3))
         call check(error, p%kind == LOAD_FORCE .and. all(ids(model, p%node) == [9]) .and. &
            all(p%dof == [2]) .and. all(near(p%value, [-5.0_wp])), 'FORCE 9, Y, -5')
      end associate
   end subroutine test_block_loads

   subroutine test_block_steps(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      call load('good_block_q4.inp', model, error)
      if (allocated(error)) return
      call check(error, size(model%steps) == 2, 'two steps')
      if (allocated(error)) return
      call check(error, model%steps(1)%name == 'geostatic' .and. &
         model%steps(1)%increments == 1 .and. all(model%steps(1)%pattern == [1]) .and. &
         all(near(model%steps(1)%target, [1.0_wp])) .and. model%steps(1)%line == 47 .and. &
         index(model%steps(1)%file, 'good_block_q4.inp') > 0, 'step geostatic at line 47')
      if (allocated(error)) return
      call check(error, model%steps(2)%increments == 5 .and. &
         all(model%steps(2)%pattern == [2, 3]) .and. &
         all(near(model%steps(2)%target, [1.0_wp, 2.0_wp])), 'step Loading')
      if (allocated(error)) return
      call check(error, model%title == 'Block 2x2 Q4, gravity then pressure' .and. &
         model%units == 'kN, m, kPa', 'title and units without the comment')
      if (allocated(error)) return
      call check(error, model%analysis%kind == PLANE_STRAIN .and. &
         near(model%analysis%thickness, 1.0_wp), 'plane strain, thickness 1')
      if (allocated(error)) return
      ! options not given in the deck keep the defaults of options.f90
      call check(error, model%solver%linear == 'AUTO' .and. &
         model%solver%method == METHOD_NEWTON .and. near(model%solver%tolerance, 1.0e-4_wp) &
         .and. model%solver%max_iterations == 50 .and. model%solver%max_cuts == 5, &
         'solver defaults')
      if (allocated(error)) return
      call check(error, .not. allocated(model%output%file) .and. model%output%every == 1, &
         'output file left to the command line')
      if (allocated(error)) return
      call check(error, index(model%deck_text, '** ---- file: test/data/decks/good_block_q4.inp') &
         == 1 .and. index(model%deck_text, 'point, 2.0') > 0, 'deck text kept for provenance')
   end subroutine test_block_steps

   subroutine test_t6(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      call load('good_t6_main.inp', model, error)
      if (allocated(error)) return
      call check(error, model%mesh%nnode() == 9 .and. model%mesh%nelem() == 2, &
         'nodes from a data-only include, 2 elements')
      if (allocated(error)) return
      associate (es => model%mesh%esets(1))
         call check(error, es%etype == 'T6' .and. all(ids(model, es%conn(:, 2)) == &
            [1, 3, 4, 7, 8, 9]) .and. es%material == 'steel', 'T6 connectivity and section')
         if (allocated(error)) return
      end associate
      call check(error, all(ids(model, model%mesh%edge_sets(1)%nodes(:, 1)) == [3, 4, 8]), &
         'three-node edge: end, end, mid')
      if (allocated(error)) return
      select type (m => model%materials(1)%m)
      type is (elastic_t)
         call check(error, near(m%young, 2.1e8_wp) .and. near(m%poisson, 0.3_wp) .and. &
            near(m%unit_weight, 0.0_wp), 'material from an include, GAMMA defaults to 0')
      class default
         call check(error, .false., 'elastic expected')
      end select
      if (allocated(error)) return
      ! 1: dofs 1..2; 4: x; 9: X  -> 4 fixed dofs
      call check(error, size(model%supports%node) == 4, 'supports from a dof range and words')
      if (allocated(error)) return
      call check(error, near(model%patterns(1)%pressure(1), -2.5_wp) .and. &
         model%steps(1)%increments == 3, 'pressure pattern and step')
      if (allocated(error)) return
      call check(error, index(model%deck_text, '** ---- file: test/data/decks/inc/t6_mesh.inp') &
         > 0 .and. index(model%deck_text, '** ---- file: test/data/decks/inc/t6_nodes.inp') > 0 &
         .and. index(model%deck_text, '** ---- file: test/data/decks/inc/t6_material.inp') > 0, &
         'every included file in the deck text, paths normalised')
   end subroutine test_t6

   subroutine test_axisym_patterns(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      integer :: i
      integer, parameter :: fixed(2, 6) = reshape([1, 1, 8, 1, 4, 1, 1, 2, 5, 2, 2, 2], [2, 6])
      call load('good_axisym.inp', model, error)
      if (allocated(error)) return
      call check(error, model%analysis%kind == AXISYMMETRIC .and. &
         model%mesh%esets(1)%etype == 'Q8' .and. all(model%mesh%esets(1)%ids == [10]), &
         'axisymmetric Q8, element id 10')
      if (allocated(error)) return
      call check(error, size(model%supports%node) == 6, '6 fixed dofs')
      if (allocated(error)) return
      do i = 1, 6
         call check(error, any(model%mesh%node_id(model%supports%node) == fixed(1, i) .and. &
            model%supports%dof == fixed(2, i)), 'fixed dof missing')
         if (allocated(error)) return
      end do
      associate (p => model%patterns(1))
         call check(error, all(ids(model, p%node) == [3, 7]) .and. all(p%dof == 2) .and. &
            all(near(p%value, -100.0_wp)), 'FORCE on a node set: one entry per node')
         if (allocated(error)) return
      end associate
      associate (p => model%patterns(2))
         call check(error, p%kind == LOAD_DISPLACEMENT .and. all(ids(model, p%node) == [6]) .and. &
            all(p%dof == 1) .and. all(near(p%value, 1.0e-3_wp)), 'DISPLACEMENT 6, 1, 1e-3')
         if (allocated(error)) return
      end associate
      associate (p => model%patterns(3))
         call check(error, p%kind == LOAD_BODY_FORCE .and. all(p%eset == [1]) .and. &
            all(near(p%vector(:, 1), [3.0_wp, 0.0_wp])), 'BODY_FORCE ALL, 3, 0')
         if (allocated(error)) return
      end associate
      ! direction (3, -4) normalised to (0.6, -0.8)
      call check_close(error, model%patterns(4)%vector(1, 1), 0.6_wp, 1.0e-15_wp, 'dx')
      if (allocated(error)) return
      call check_close(error, model%patterns(4)%vector(2, 1), -0.8_wp, 1.0e-15_wp, 'dy')
   end subroutine test_axisym_patterns

   subroutine test_axisym_options(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      call load('good_axisym.inp', model, error)
      if (allocated(error)) return
      call check(error, model%solver%linear == 'UMFPACK' .and. model%solver%method == METHOD_NEWTON &
         .and. near(model%solver%tolerance, 1.0e-6_wp) .and. model%solver%max_iterations == 20 &
         .and. model%solver%max_cuts == 3, '*SOLVER parameters, case-insensitive values')
      if (allocated(error)) return
      call check(error, model%output%file == 'output/axisym_test.h5' .and. &
         model%output%every == 2 .and. .not. model%output%stresses .and. &
         model%output%strains .and. .not. model%output%reactions, '*OUTPUT parameters')
      if (allocated(error)) return
      call check(error, size(model%steps) == 2, 'two steps')
      if (allocated(error)) return
      call check(error, model%steps(1)%name == 'Step-1' .and. &
         all(model%steps(1)%pattern == [1, 3]) .and. &
         all(near(model%steps(1)%target, [1.0_wp, 0.5_wp])), 'unnamed step gets Step-1')
      if (allocated(error)) return
      call check(error, model%steps(2)%increments == 4 .and. &
         all(model%steps(2)%pattern == [1, 2, 4]) .and. &
         all(near(model%steps(2)%target, [0.0_wp, 1.0_wp, 1.0_wp])), 'step unload')
   end subroutine test_axisym_options

   subroutine test_mesh(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      integer :: k
      call load('good_mesh.inp', model, error)
      if (allocated(error)) return
      ! deck nodes first (101..104), then the 13 nodes of q8.msh
      call check(error, model%mesh%nnode() == 17 .and. all(model%mesh%node_id(1:5) == &
         [101, 102, 103, 104, 1]), 'deck nodes, then mesh nodes')
      if (allocated(error)) return
      call check(error, size(model%mesh%esets) == 2 .and. model%mesh%esets(1)%name == 'wall' &
         .and. model%mesh%esets(2)%name == 'cap', 'mesh set wall, then deck set cap')
      if (allocated(error)) return
      call check(error, model%mesh%esets(1)%etype == 'Q8' .and. &
         size(model%mesh%esets(1)%conn, 2) == 2 .and. all(model%mesh%esets(1)%ids == [5, 6]), &
         'two Q8 from Gmsh with their tags as ids')
      if (allocated(error)) return
      ! the clockwise deck element is kept as written (check_elements renumbers it later)
      call check(error, all(ids(model, model%mesh%esets(2)%conn(:, 1)) == [101, 104, 103, 102]), &
         'clockwise Q4 kept')
      if (allocated(error)) return
      call check(error, all(model%mesh%esets(:)%material_index == 1), 'sections on both sets')
      if (allocated(error)) return
      ! base: the 5 nodes of the bottom curve (2 three-node lines) + node 101, xy; 102, y: 13
      call check(error, size(model%supports%node) == 13, 'supports on a Gmsh node set')
      if (allocated(error)) return
      k = model%mesh%find_edge_set('top')
      call check(error, k > 0 .and. size(model%patterns(1)%edge, 2) == 2 .and. &
         all(model%patterns(1)%edge(3, :) > 0), 'pressure on the 3-node Gmsh edges of top')
      if (allocated(error)) return
      call check(error, all(ids(model, model%patterns(2)%node) == [3]) .and. &
         all(near(model%mesh%x(:, model%patterns(2)%node(1)), [2.0_wp, 1.0_wp])), &
         'node id 3 of the .msh file is found by the deck')
   end subroutine test_mesh

   !> input/examples/strip_footing.inp (make_default_deck.py): 4 x 2 Q8 on [0, 4] x [-2, 0].
   subroutine test_strip_footing(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(error_t), allocatable :: e
      call read_deck('input/examples/strip_footing.inp', model, e)
      call check(error, .not. allocated(e), 'input/examples/strip_footing.inp must read')
      if (allocated(error)) then
         error%message = error%message//': '//e%text()
         return
      end if
      ! (2*4 + 1)*(2*2 + 1) grid points less the 8 element centres
      call check(error, model%mesh%nnode() == 37 .and. model%mesh%nelem() == 8 .and. &
         model%mesh%esets(1)%etype == 'Q8', '37 nodes, 8 Q8')
      if (allocated(error)) return
      call check(error, model%patterns(1)%kind == LOAD_GRAVITY .and. &
         model%patterns(2)%kind == LOAD_PRESSURE .and. size(model%steps) == 2, &
         'gravity step, then pressure step')
      if (allocated(error)) return
      ! the footing edge runs from (1, 0) to (0, 0), mid-node at (0.5, 0)
      associate (edge => model%patterns(2)%edge(:, 1), x => model%mesh%x)
         call check(error, all(near(x(:, edge(1)), [1.0_wp, 0.0_wp])) .and. &
            all(near(x(:, edge(2)), [0.0_wp, 0.0_wp])) .and. &
            all(near(x(:, edge(3)), [0.5_wp, 0.0_wp])), 'footing edge')
      end associate
   end subroutine test_strip_footing

end module test_io_deck
