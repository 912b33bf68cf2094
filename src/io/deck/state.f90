!> What the deck reader has collected before references are resolved: nodes, element
!> and node sets with user ids, and every reference (a set, material or pattern name) with
!> the index of the line that made it, so that an error after the whole deck is read still
!> names that line. Lines are indices into `deck_state_t%lines`.
module pecplas_io_deck_state
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_io_text_fields, only: keyword_line_t, itoa
   use pecplas_io_text_line_store, only: deck_lines_t
   use pecplas_model_mesh, only: mesh_t
   use pecplas_massif_materials_factory, only: material_registry_t
   use pecplas_model_node_lookup, only: node_lookup_t
   use pecplas_io_deck_raw_joints, only: raw_joint_set_t
   use pecplas_io_deck_raw_water, only: raw_water_t
   use pecplas_io_deck_raw_anchors, only: raw_anchor_t
   use pecplas_io_deck_raw_plates, only: raw_plate_set_t
   use pecplas_joints_laws_factory, only: law_registry_t
   implicit none (type, external)
   private

   public :: deck_state_t, deck_block_t, raw_eset_t, raw_nset_t, raw_edge_set_t
   public :: raw_section_t, raw_item_t, raw_pattern_t, raw_step_t, raw_change_t
   public :: line_error, where_text, grow_int, grow_int2, grow_real2, push_item

   !> A keyword line (index `at`) and its data lines first..last (none if last < first).
   type :: deck_block_t
      type(keyword_line_t) :: kw
      integer :: at = 0, first = 1, last = 0
   end type deck_block_t

   !> Elements of one set, node ids as written; where(k) = line of element k.
   type :: raw_eset_t
      character(len=:), allocatable :: name, etype
      integer :: at = 0, n = 0
      integer, allocatable :: ids(:), conn(:, :), where(:)
   end type raw_eset_t

   !> Node ids of one set as ranges ids(k), ids(k) + step(k), ..., upto(k) (upto = ids and
   !> step = 1 for a single id), where(k) = line of range k. GENERATE ranges are expanded
   !> only when the mesh is built, after their size is checked against its node count.
   type :: raw_nset_t
      character(len=:), allocatable :: name
      integer :: at = 0, n = 0
      integer, allocatable :: ids(:), upto(:), step(:), where(:)
   end type raw_nset_t

   !> Edges as node ids (3, n); nen = 2 or 3 nodes per edge, the same for the whole set
   !> (third id 0 for 2-node edges).
   type :: raw_edge_set_t
      character(len=:), allocatable :: name
      integer :: at = 0, n = 0, nen = 0
      integer, allocatable :: nodes(:, :), where(:)
   end type raw_edge_set_t

   !> *SECTION: element set and material names as written.
   type :: raw_section_t
      !> ELEMENT= as written ('' when absent).
      character(len=:), allocatable :: set, material, element
      integer :: at = 0
   end type raw_section_t

   !> One data line of *BOUNDARY, *LOAD or *STEP: a target (node id, set or pattern name),
   !> dofs (first, last) and up to two values.
   type :: raw_item_t
      character(len=:), allocatable :: target
      integer :: dof(2) = 0
      real(wp) :: value(2) = 0.0_wp
      !> PRESSURE varying with depth: value(1) + gradient (y_ref - y).
      real(wp) :: gradient = 0.0_wp, y_ref = 0.0_wp
      integer :: at = 0
      !> *BOUNDARY, NAME=group: the named support the line belongs to ('' for none).
      character(len=:), allocatable :: group
   end type raw_item_t

   !> One *LOAD block: its data lines as items.
   type :: raw_pattern_t
      character(len=:), allocatable :: name, kind
      integer :: at = 0, n = 0
      !> PRESSURE, MIN=p_min: the pressure is max(p_min, p).
      logical :: floored = .false.
      real(wp) :: p_min = 0.0_wp
      type(raw_item_t), allocatable :: items(:)
   end type raw_pattern_t

   !> One phase change of a step (*DEACTIVATE, *ACTIVATE, *CHANGE_MATERIAL, *CHANGE_LAW):
   !> kind (pecplas_model_phases), the set and new material/law names as written, how an
   !> activated set starts, and its data line.
   type :: raw_change_t
      integer :: kind = 0, start = 0, at = 0
      character(len=:), allocatable :: set, new
   end type raw_change_t

   !> One *STEP block: items hold (pattern name, target factor).
   type :: raw_step_t
      character(len=:), allocatable :: name
      integer :: increments = 1, at = 0, n = 0
      !> CONTROL=ARC_LENGTH and its options (NODE= as written: a node id or a node set of
      !> one node, resolved later; '' none).
      logical :: arc_length = .false.
      integer :: max_increments = 0, iterations_wanted = 6, dof = 0
      character(len=:), allocatable :: node
      real(wp) :: displacement = 0.0_wp, min_length = 1.0e-4_wp, max_length = 10.0_wp
      type(raw_item_t), allocatable :: items(:)
      !> RESET_DISPLACEMENTS=YES, and the phase changes of the step in deck order.
      logical :: reset_displacements = .false.
      type(raw_change_t), allocatable :: changes(:)
      !> CONTROL=SAFETY and its options, the *REDUCE names (target) with their lines (at).
      logical :: safety = .false.
      real(wp) :: msf_step = 0.1_wp, resolution = 0.002_wp
      type(raw_item_t), allocatable :: reduce(:)
      integer :: nreduce = 0, reduce_at = 0
   end type raw_step_t

   !> Everything collected while reading, before references are resolved.
   type :: deck_state_t
      type(deck_lines_t) :: lines
      !> Nodes of *NODES: user ids, coordinates (2, n), line of each.
      integer :: nnode = 0
      integer, allocatable :: node_ids(:), node_at(:)
      real(wp), allocatable :: x(:, :)
      type(raw_eset_t), allocatable :: esets(:)
      type(raw_nset_t), allocatable :: nsets(:)
      type(raw_edge_set_t), allocatable :: edge_sets(:)
      type(raw_section_t), allocatable :: sections(:)
      integer :: nboundary = 0
      type(raw_item_t), allocatable :: boundary(:)
      type(raw_pattern_t), allocatable :: patterns(:)
      type(raw_step_t), allocatable :: steps(:)
      !> The step that phase-change keywords attach to: the last *STEP, until its
      !> *END STEP (0: none open).
      integer :: open_step = 0
      !> Line of each *MATERIAL, parallel to model%materials.
      integer, allocatable :: material_at(:)
      !> Meshes read by *MESH and the line of each.
      type(mesh_t), allocatable :: imported(:)
      integer, allocatable :: imported_at(:)
      !> Line of every node of the built mesh (the *MESH line for imported nodes).
      integer, allocatable :: mesh_node_at(:)
      !> Line that defined each element set of the built mesh (*ELEMENTS or *MESH).
      integer, allocatable :: mesh_eset_at(:)
      !> Line that defined each edge set of the built mesh (*EDGES or *MESH).
      integer, allocatable :: mesh_edge_set_at(:)
      !> User node id -> internal number, set when the mesh is built.
      type(node_lookup_t) :: node_lookup
      !> Material types known to *MATERIAL.
      type(material_registry_t) :: registry
      !> Interface law types known to *INTERFACE_LAW, the line of each law of model%laws
      !> and of each Katona contact of model%contacts, and the *JOINTS blocks.
      type(law_registry_t) :: laws
      integer, allocatable :: law_at(:), contact_at(:)
      type(raw_joint_set_t), allocatable :: joint_sets(:)
      !> Groundwater keywords (*WATER, *DRY, *CHANGE_WATER) before resolution.
      type(raw_water_t) :: water
      !> The *ANCHOR blocks.
      type(raw_anchor_t), allocatable :: anchors(:)
      !> The *PLATE blocks (pecplas_io_deck_reader_plates).
      type(raw_plate_set_t), allocatable :: plate_sets(:)
   end type deck_state_t

contains

   !> Deck error at line index `at` of the state, under the keyword in force there.
   subroutine line_error(state, at, message, error)
      type(deck_state_t), intent(in) :: state
      integer, intent(in) :: at
      character(len=*), intent(in) :: message
      type(error_t), allocatable, intent(out) :: error
      call deck_error(error, state%lines%file(at), state%lines%line(at), &
         state%lines%keyword(at), message)
   end subroutine line_error

   !> 'file:line' of line index `at`, for messages that point back to a definition.
   function where_text(state, at) result(s)
      type(deck_state_t), intent(in) :: state
      integer, intent(in) :: at
      character(len=:), allocatable :: s
      s = state%lines%file(at)//':'//itoa(state%lines%line(at))
   end function where_text

   !> Makes room for at least n entries (capacity doubles).
   pure subroutine grow_int(a, n)
      integer, allocatable, intent(inout) :: a(:)
      integer, intent(in) :: n
      integer, allocatable :: tmp(:)
      if (.not. allocated(a)) allocate (a(0))
      if (size(a) >= n) return
      allocate (tmp(max(n, 2*size(a), 16)))
      tmp = 0
      tmp(1:size(a)) = a
      call move_alloc(tmp, a)
   end subroutine grow_int

   !> Makes room for at least n columns.
   pure subroutine grow_int2(a, rows, n)
      integer, allocatable, intent(inout) :: a(:, :)
      integer, intent(in) :: rows, n
      integer, allocatable :: tmp(:, :)
      if (.not. allocated(a)) allocate (a(rows, 0))
      if (size(a, 2) >= n) return
      allocate (tmp(rows, max(n, 2*size(a, 2), 16)))
      tmp = 0
      tmp(:, 1:size(a, 2)) = a
      call move_alloc(tmp, a)
   end subroutine grow_int2

   !> Makes room for at least n columns.
   pure subroutine grow_real2(a, rows, n)
      real(wp), allocatable, intent(inout) :: a(:, :)
      integer, intent(in) :: rows, n
      real(wp), allocatable :: tmp(:, :)
      if (.not. allocated(a)) allocate (a(rows, 0))
      if (size(a, 2) >= n) return
      allocate (tmp(rows, max(n, 2*size(a, 2), 16)))
      tmp = 0.0_wp
      tmp(:, 1:size(a, 2)) = a
      call move_alloc(tmp, a)
   end subroutine grow_real2

   !> Appends `item` to items(1:n).
   subroutine push_item(items, n, item)
      type(raw_item_t), allocatable, intent(inout) :: items(:)
      integer, intent(inout) :: n
      type(raw_item_t), intent(in) :: item
      type(raw_item_t), allocatable :: tmp(:)
      if (.not. allocated(items)) allocate (items(4))
      if (n == size(items)) then
         allocate (tmp(2*n))
         tmp(1:n) = items(1:n)
         call move_alloc(tmp, items)
      end if
      n = n + 1
      items(n) = item
   end subroutine push_item

end module pecplas_io_deck_state
