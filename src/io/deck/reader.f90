!> The keyword input deck of PECPLAS (doc/deck.md): `read_deck(path, model, error)`.
!> The deck is read in two passes: every keyword block is handed to a small handler that
!> checks its syntax and collects what it defines; then all references (node ids, set,
!> material and pattern names) are resolved, so definitions may come in any order and an
!> error still names the line of the reference.
module pecplas_io_deck_reader
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_io_text_fields, only: add_name, parse_keyword_line
   use pecplas_io_text_lines, only: read_deck_store
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, line_error
   use pecplas_io_deck_reader_mesh, only: read_nodes, read_elements, read_nset, read_edges
   use pecplas_io_deck_mesh_import, only: read_mesh
   use pecplas_io_deck_reader_materials, only: read_material, read_section, resolve_sections
   use pecplas_io_deck_reader_loads, only: read_boundary, read_load
   use pecplas_io_deck_reader_options, only: read_text, read_units, read_analysis, read_solver, &
      read_adapt, resolve_adapt_goal, &
      read_output, read_step
   use pecplas_io_deck_resolve_mesh, only: build_mesh
   use pecplas_io_deck_reader_initial, only: read_initial_stress, resolve_initial_stress
   use pecplas_io_deck_resolve_loads, only: resolve_supports, resolve_patterns, resolve_steps
   use pecplas_massif_materials_factory, only: material_registry_t, default_material_registry
   use pecplas_io_deck_reader_joints, only: read_interface_law, read_joints
   use pecplas_io_deck_resolve_joints, only: resolve_joints
   use pecplas_joints_laws_factory, only: law_registry_t, default_law_registry
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: METHOD_NEWTON
   use pecplas_io_deck_record_places, only: record_places
   use pecplas_io_deck_usage, only: check_usage
   use pecplas_io_deck_reader_phases, only: read_change, resolve_phases
   use pecplas_io_deck_reader_safety, only: read_reduce, resolve_safety
   use pecplas_io_deck_reader_water, only: read_water, read_dry, read_change_water, &
      resolve_water, read_plate_water
   use pecplas_io_deck_reader_anchors, only: read_anchor, resolve_anchors
   use pecplas_io_deck_reader_plates, only: read_plate, resolve_plates, extend_rotations
   implicit none (type, external)
   private

   public :: read_deck, read_deck_with, KNOWN_KEYWORDS

   !> Every keyword of the deck language.
   character(len=*), parameter :: KNOWN_KEYWORDS(33) = [character(len=16) :: '*TITLE', &
      '*UNITS', '*ANALYSIS', '*INCLUDE', '*NODES', '*ELEMENTS', '*MESH', '*NSET', '*EDGES', &
      '*MATERIAL', '*SECTION', '*BOUNDARY', '*LOAD', '*STEP', '*END STEP', '*SOLVER', '*OUTPUT', &
      '*INITIAL_STRESS', '*INTERFACE_LAW', '*JOINTS', '*ADAPT', '*DEACTIVATE', '*ACTIVATE', &
      '*CHANGE_MATERIAL', '*CHANGE_LAW', '*PLATE', '*ANCHOR', '*PRESTRESS', '*WATER', '*DRY', &
      '*CHANGE_WATER', '*PLATE_WATER', '*REDUCE']

contains

   !> Reads the deck `path` (with its includes) into `model`, with the built-in materials.
   subroutine read_deck(path, model, error)
      character(len=*), intent(in) :: path
      type(model_t), intent(out) :: model
      type(error_t), allocatable, intent(out) :: error
      call read_deck_with(path, default_material_registry(), model, error)
   end subroutine read_deck

   !> Same as read_deck, with the material types of `registry` (user materials) and the
   !> interface law types of `laws` (user laws; default: the built-in ones).
   subroutine read_deck_with(path, registry, model, error, laws)
      character(len=*), intent(in) :: path
      type(material_registry_t), intent(in) :: registry
      type(model_t), intent(out) :: model
      type(error_t), allocatable, intent(out) :: error
      type(law_registry_t), intent(in), optional :: laws
      type(deck_state_t) :: state
      type(deck_block_t) :: block
      integer :: i, j, n

      state%registry = registry
      if (present(laws)) then
         state%laws = laws
      else
         state%laws = default_law_registry()
      end if
      model%deck_file = path
      model%solver%linear = 'AUTO'
      model%solver%method = METHOD_NEWTON
      call read_deck_store(path, state%lines, model%deck_text, error)
      if (allocated(error)) return
      n = state%lines%n
      i = 1
      do while (i <= n)
         if (len(state%lines%keyword(i)) == 0) then
            call line_error(state, i, "data line before the first keyword: '"// &
               state%lines%text(i)//"' (a keyword line starts with *)", error)
            return
         end if
         call parse_keyword_line(state%lines%get(i), block%kw, error)
         if (allocated(error)) return
         j = i + 1
         do while (j <= n)
            if (state%lines%is_keyword(j)) exit
            j = j + 1
         end do
         block%at = i
         block%first = i + 1
         block%last = j - 1
         call dispatch(state, model, block, error)
         if (allocated(error)) return
         i = j
      end do

      call build_mesh(state, model, error)
      if (allocated(error)) return
      ! plates before supports: a rotation support needs the nodes that carry a rotation
      call resolve_plates(state, model, error)
      if (allocated(error)) return
      if (.not. allocated(state%steps)) then
         call deck_error(error, path, 0, '*STEP', 'no *STEP: the deck must define at least '// &
            'one step ("*STEP, NAME=..., INCREMENTS=n" with "pattern, target_factor" lines)')
         return
      end if
      call resolve_sections(state, model, error)
      if (allocated(error)) return
      call resolve_supports(state, model, error)
      if (allocated(error)) return
      call resolve_patterns(state, model, error)
      if (allocated(error)) return
      call resolve_steps(state, model, error)
      if (allocated(error)) return
      call resolve_initial_stress(state, model, error)
      if (allocated(error)) return
      ! before the joints split the mesh: the bars keep the original nodes
      call resolve_anchors(state, model, error)
      if (allocated(error)) return
      ! last: splitting nodes for generated joints extends supports and patterns
      call resolve_joints(state, model, error)
      if (allocated(error)) return
      call extend_rotations(model)
      ! phase changes name joint sets too
      call resolve_phases(state, model, error)
      if (allocated(error)) return
      call resolve_water(state, model, error)
      if (allocated(error)) return
      call resolve_safety(state, model, error)
      if (allocated(error)) return
      call resolve_adapt_goal(state, model, error)
      if (allocated(error)) return
      call record_places(state, model)
      call check_usage(state, model)
      ! the deck text for provenance, from the line buffer when that is it (no copy)
      call state%lines%take_text(model%deck_text)
   end subroutine read_deck_with

   !> Hands one keyword block to its handler.
   subroutine dispatch(state, model, block, error)
      type(deck_state_t), intent(inout) :: state
      type(model_t), intent(inout) :: model
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: list
      integer :: i
      select case (block%kw%name)
      case ('*TITLE')
         call read_text(state, block, model%title, error)
      case ('*UNITS')
         call read_units(state, model, block, error)
      case ('*ANALYSIS')
         call no_data(state, block, error)
         if (.not. allocated(error)) call read_analysis(state, model, block, error)
      case ('*NODES')
         call read_nodes(state, block, error)
      case ('*ELEMENTS')
         call read_elements(state, block, error)
      case ('*MESH')
         call no_data(state, block, error)
         if (.not. allocated(error)) call read_mesh(state, block, error)
      case ('*NSET')
         call read_nset(state, block, error)
      case ('*EDGES')
         call read_edges(state, block, error)
      case ('*MATERIAL')
         call read_material(state, model, block, error)
      case ('*SECTION')
         call no_data(state, block, error)
         if (.not. allocated(error)) call read_section(state, block, error)
      case ('*BOUNDARY')
         call read_boundary(state, block, error)
      case ('*LOAD')
         call read_load(state, block, error)
      case ('*STEP')
         call read_step(state, block, error)
      case ('*DEACTIVATE', '*ACTIVATE', '*CHANGE_MATERIAL', '*CHANGE_LAW', '*PRESTRESS')
         call read_change(state, block, error)
      case ('*REDUCE')
         call read_reduce(state, block, error)
      case ('*END STEP')
         state%open_step = 0
         call no_data(state, block, error)
         if (.not. allocated(error)) call block%kw%check_keys(state%lines%get(block%at), &
            [character(len=1) ::], error)
      case ('*SOLVER')
         call no_data(state, block, error)
         if (.not. allocated(error)) call read_solver(state, model, block, error)
      case ('*OUTPUT')
         call no_data(state, block, error)
         if (.not. allocated(error)) call read_output(state, model, block, error)
      case ('*ADAPT')
         call no_data(state, block, error)
         if (.not. allocated(error)) call read_adapt(state, model, block, error)
      case ('*INITIAL_STRESS')
         call read_initial_stress(state, model, block, error)
      case ('*INTERFACE_LAW')
         call read_interface_law(state, model, block, error)
      case ('*JOINTS')
         call read_joints(state, block, error)
      case ('*WATER')
         call read_water(state, model, block, error)
      case ('*DRY')
         call read_dry(state, block, error)
      case ('*CHANGE_WATER')
         call read_change_water(state, block, error)
      case ('*PLATE_WATER')
         call read_plate_water(state, block, error)
      case ('*ANCHOR')
         call read_anchor(state, block, error)
      case ('*PLATE')
         call read_plate(state, block, error)
      case default
         list = ''
         do i = 1, size(KNOWN_KEYWORDS)
            call add_name(list, trim(KNOWN_KEYWORDS(i)))
         end do
         if (index(block%kw%name, '=') > 0) list = list// &
            ' (parameters follow the keyword after commas: *KEYWORD, KEY=value)'
         call line_error(state, block%at, "unknown keyword '"//block%kw%name// &
            "'; known keywords:"//list, error)
      end select
   end subroutine dispatch

   !> Error for a data line after a keyword that takes none.
   subroutine no_data(state, block, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      if (block%last < block%first) return
      call line_error(state, block%first, block%kw%name//" takes no data lines, found '"// &
         state%lines%text(block%first)//"'", error)
   end subroutine no_data

end module pecplas_io_deck_reader
