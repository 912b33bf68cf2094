!> Resolves the *JOINTS blocks once the mesh, supports and patterns are built: the law of
!> each set, explicit joints (node ids, coincident doublets, orientation against the bodies
!> they join) and generated joints (node doublets created along EDGES for the body SIDE,
!> pecplas_model_mesh_split). Splitting nodes also updates what referred to them:
!> - a support or an imposed displacement on a split node also holds its duplicate (the
!>   doublet sits at one point, both bodies are held there);
!> - point forces stay on the original node (a load is not doubled);
!> - pressures on sides of the SIDE body move to the duplicates; node sets gain them.
!> Springs get their tributary measure and tangent from the joint edges around them.
module pecplas_io_deck_resolve_joints
   use pecplas_base_kinds, only: wp
   use pecplas_model_loads, only: LOAD_DISPLACEMENT, LOAD_PRESSURE
   use pecplas_base_error, only: error_t
   use pecplas_io_text_fields, only: same_name, add_name, itoa
   use pecplas_io_deck_state, only: deck_state_t, line_error, where_text
   use pecplas_io_deck_raw_joints, only: raw_joint_set_t
   use pecplas_io_deck_repeats, only: first_repeat
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_set_names, only: eset_names, edge_set_names
   use pecplas_model_joints, only: joint_set_t, joint_kind, JOINT_GOODMAN4, JOINT_GOODMAN6, &
      JOINT_KATONA
   use pecplas_model_mesh_split, only: split_result_t, split_along_edges, remap_side_edges
   use pecplas_model_mesh_split_faces, only: faces_result_t, split_both_faces, &
      remap_to_copies, FACE_LEFT, FACE_EXTENSION
   use pecplas_joints_elements_tributary, only: spring_tributaries
   use pecplas_io_deck_resolve_explicit, only: explicit_joints
   implicit none (type, external)
   private

   public :: resolve_joints

   real(wp), parameter :: PI = acos(-1.0_wp)

contains

   !> Fills model%joint_sets (deck order); model%laws and model%contacts are allocated even
   !> when empty.
   subroutine resolve_joints(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      type(joint_set_t), allocatable :: tmp(:)
      type(joint_set_t) :: set
      type(joint_set_t), allocatable :: parts(:)
      integer, allocatable :: origin(:), ids(:), at(:), group(:)
      integer :: r, n, i, next_id, dup(2), p
      if (.not. allocated(model%laws)) allocate (model%laws(0))
      if (.not. allocated(model%contacts)) allocate (model%contacts(0))
      if (.not. allocated(model%joint_sets)) allocate (model%joint_sets(0))
      if (.not. allocated(state%joint_sets)) return
      origin = [(i, i=1, model%mesh%nnode())]
      allocate (ids(0), at(0))
      do i = 1, size(model%mesh%esets)
         ids = [ids, model%mesh%esets(i)%ids]
      end do
      at = [(0, i=1, size(ids))]
      next_id = 0
      if (size(ids) > 0) next_id = maxval(ids)
      do r = 1, size(state%joint_sets)
         associate (raw => state%joint_sets(r))
            do i = 1, raw%n
               next_id = max(next_id, raw%ids(i))
            end do
         end associate
      end do
      do r = 1, size(state%joint_sets)
         call one_set(state, model, state%joint_sets(r), origin, next_id, set, error, group)
         if (allocated(error)) return
         ! FACES=BOTH: one set per element set of the bodies on the faces
         call split_by_body(model, set, group, parts)
         do p = 1, size(parts)
            n = size(model%joint_sets)
            allocate (tmp(n + 1))
            tmp(1:n) = model%joint_sets
            tmp(n + 1) = parts(p)
            call move_alloc(tmp, model%joint_sets)
         end do
         ids = [ids, set%ids]
         if (state%joint_sets(r)%n > 0) then
            at = [at, state%joint_sets(r)%where]
         else
            at = [at, spread(state%joint_sets(r)%at, 1, size(set%ids))]
         end if
      end do
      dup = first_repeat(ids)
      if (dup(2) > 0) then
         if (at(dup(1)) > 0) then
            call line_error(state, at(dup(2)), 'duplicate element id '//itoa(ids(dup(2)))// &
               ' (first defined at '//where_text(state, at(dup(1)))//')', error)
         else
            call line_error(state, at(dup(2)), 'duplicate element id '//itoa(ids(dup(2)))// &
               ': a massif element has it already (ids are unique over the model)', error)
         end if
      end if
   end subroutine resolve_joints

   !> The joint set of one *JOINTS block; `group`: for FACES=BOTH the element set of the
   !> body on face 2 of each element (empty otherwise).
   subroutine one_set(state, model, raw, origin, next_id, set, error, group)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(raw_joint_set_t), intent(in) :: raw
      integer, allocatable, intent(inout) :: origin(:)
      integer, intent(inout) :: next_id
      type(joint_set_t), intent(out) :: set
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable, intent(out) :: group(:)
      integer, allocatable :: edges(:, :)
      character(len=:), allocatable :: msg
      integer :: i, bad
      allocate (group(0))
      set%name = raw%name
      set%kind = joint_kind(raw%etype)
      set%law = raw%law
      set%integration = raw%integration
      set%thickness = raw%thickness
      do i = 1, size(model%laws)
         if (same_name(model%laws(i)%law%name, raw%law)) set%law_index = i
      end do
      do i = 1, size(model%contacts)
         if (same_name(model%contacts(i)%name, raw%law)) then
            set%method = JOINT_KATONA
            set%contact_index = i
         end if
      end do
      if (set%law_index == 0 .and. set%contact_index == 0) then
         call line_error(state, raw%at, "undefined interface law '"//raw%law// &
            "'; known laws:"//law_names(model), error)
         return
      end if
      ! a thin layer hands its law strains (jump / THICKNESS): the law must accept them
      if (set%is_thin_layer() .and. .not. set%is_katona()) then
         msg = model%laws(set%law_index)%law%strain_refusal()
         if (len(msg) > 0) then
            call line_error(state, raw%at, "joint set '"//set%name//"': a THIN_LAYER joint "// &
               "passes strains (jump / THICKNESS) to its law, but law '"//raw%law//"': "// &
               msg//"; use GOODMAN4, GOODMAN6 or SPRING joints", error)
            return
         end if
      end if
      if (raw%both_faces) then
         call generated_both(state, model, raw, origin, next_id, set, group, error)
         return
      else if (len(raw%edges) > 0) then
         call generated(state, model, raw, origin, next_id, set, edges, error)
      else
         ! Katona doublets may start apart (node-to-node contact with an initial gap)
         call explicit_joints(state, model, raw, set, edges, error, &
            allow_gap=set%is_katona())
      end if
      if (allocated(error)) return
      if (.not. set%is_spring()) return
      allocate (set%tributary(size(set%conn, 2)), set%tangent(2, size(set%conn, 2)))
      call spring_tributaries(model%mesh%x, model%analysis%kind, model%analysis%thickness, &
         set%conn(1, :), edges, set%tributary, set%tangent, bad, error)
      if (allocated(error)) then
         ! the message is copied first: line_error's intent(out) error is freed on entry
         msg = "joint set '"//set%name//"', spring "//itoa(set%ids(bad))//' at node '// &
            itoa(model%mesh%node_id(set%conn(1, bad)))//': '//error%message
         call line_error(state, spring_line(raw, bad), msg, error)
         return
      end if
      if (raw%has_angle) set%tangent = spread([cos(raw%angle*PI/180.0_wp), &
         sin(raw%angle*PI/180.0_wp)], 2, size(set%conn, 2))
   end subroutine one_set

   !> ' a b' names of the interface laws (for messages).
   function law_names(model) result(list)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: list
      integer :: i
      list = ''
      do i = 1, size(model%laws)
         call add_name(list, model%laws(i)%law%name)
      end do
      do i = 1, size(model%contacts)
         call add_name(list, model%contacts(i)%name)
      end do
      if (len(list) == 0) list = ' (none: define one with *INTERFACE_LAW, NAME=..., TYPE=...)'
   end function law_names

   pure integer function spring_line(raw, k) result(at)
      type(raw_joint_set_t), intent(in) :: raw
      integer, intent(in) :: k
      at = raw%at
      if (raw%n >= k .and. k > 0) at = raw%where(k)
   end function spring_line

   !> The edge set `ke` named by EDGES= of a generated set; an error if there is none.
   subroutine find_edges(state, model, raw, ke, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      type(raw_joint_set_t), intent(in) :: raw
      integer, intent(out) :: ke
      type(error_t), allocatable, intent(out) :: error
      ke = model%mesh%find_edge_set(raw%edges)
      if (ke == 0) call line_error(state, raw%at, "undefined edge set '"//raw%edges// &
         "' in EDGES=; known edge sets:"//edge_set_names(model%mesh, ' (none)'), error)
   end subroutine find_edges

   !> `nen`, the nodes per edge of edge set `ke`; an error if they do not fit the set's type
   !> (GOODMAN4: 2, GOODMAN6: 3).
   subroutine check_edge_nodes(state, model, raw, set, ke, nen, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      type(raw_joint_set_t), intent(in) :: raw
      type(joint_set_t), intent(in) :: set
      integer, intent(in) :: ke
      integer, intent(out) :: nen
      type(error_t), allocatable, intent(out) :: error
      nen = size(model%mesh%edge_sets(ke)%nodes, 1)
      if ((set%kind == JOINT_GOODMAN4 .and. nen /= 2) .or. (set%kind == JOINT_GOODMAN6 .and. &
          nen /= 3)) call line_error(state, raw%at, set%type_name()//" joints need "// &
            trim(merge('2-node (linear)   ', '3-node (quadratic)', nen == 3))//" edges; edge set '" &
            //raw%edges//"' has "//itoa(nen)//'-node edges: use '// &
            trim(merge('GOODMAN6', 'GOODMAN4', nen == 3))//' (or THIN_LAYER, SPRING)', error)
   end subroutine check_edge_nodes

   !> EDGES=, SIDE=: splits the mesh and builds the set; edges(nen, m) = face-1 joint edges.
   subroutine generated(state, model, raw, origin, next_id, set, edges, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(raw_joint_set_t), intent(in) :: raw
      integer, allocatable, intent(inout) :: origin(:)
      integer, intent(inout) :: next_id
      type(joint_set_t), intent(inout) :: set
      integer, allocatable, intent(out) :: edges(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(split_result_t) :: res
      type(error_t), allocatable :: e
      integer, allocatable :: dupof(:)
      integer :: ke, ks, nen, nn0, i
      call find_edges(state, model, raw, ke, error)
      if (allocated(error)) return
      ks = model%mesh%find_eset(raw%side)
      if (ks == 0 .and. size(model%mesh%find_esets(raw%side)) > 1) then
         call line_error(state, raw%at, "SIDE="//raw%side//" is a Gmsh group of several "// &
            'element types; SIDE= takes one element set: mesh the body on that side with '// &
            'one element type, or name its part (known element sets:'// &
            eset_names(model%mesh, ' (none)')//')', error)
         return
      end if
      if (ks == 0) then
         call line_error(state, raw%at, "undefined element set '"//raw%side// &
            "' in SIDE=; known element sets:"//eset_names(model%mesh, ' (none)'), error)
         return
      end if
      call check_edge_nodes(state, model, raw, set, ke, nen, error)
      if (allocated(error)) return
      nn0 = model%mesh%nnode()
      call split_along_edges(model%mesh, ke, ks, origin, res, e)
      if (allocated(e)) then
         call line_error(state, raw%at, e%message, error)
         return
      end if
      allocate (dupof(nn0), source=0)
      do i = 1, size(res%created, 2)
         dupof(res%created(1, i)) = res%created(2, i)
      end do
      call extend_to_duplicates(model, ks, dupof)
      if (set%is_spring()) then
         set%conn = res%doublets
      else
         set%conn = res%conn
      end if
      edges = res%conn([1, 2], :)
      if (nen == 3) edges = res%conn([1, 2, 5], :)
      set%ids = [(next_id + i, i=1, size(set%conn, 2))]
      next_id = next_id + size(set%conn, 2)
   end subroutine generated

   !> FACES=BOTH: the line EDGES split on both faces (pecplas_model_mesh_split_faces); the
   !> supports and imposed displacements of a split node hold its copies too, the pressure
   !> edges and edge sets on one body move to its copies. Springs: one doublet per node and
   !> face, their tributaries and tangents from the joint edges of that face.
   subroutine generated_both(state, model, raw, origin, next_id, set, group, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(raw_joint_set_t), intent(in) :: raw
      integer, allocatable, intent(inout) :: origin(:)
      integer, intent(inout) :: next_id
      type(joint_set_t), intent(inout) :: set
      integer, allocatable, intent(inout) :: group(:)
      type(error_t), allocatable, intent(out) :: error
      type(faces_result_t) :: res
      type(error_t), allocatable :: e
      integer, allocatable :: dupof(:), doublets(:, :), edges(:, :), sel(:)
      real(wp), allocatable :: trib(:), tang(:, :)
      logical, allocatable :: turn(:)
      character(len=:), allocatable :: msg
      integer :: ke, nen, i, k, face, bad
      call find_edges(state, model, raw, ke, error)
      if (allocated(error)) return
      call check_edge_nodes(state, model, raw, set, ke, nen, error)
      if (allocated(error)) return
      call split_both_faces(model%mesh, ke, raw%extend, origin, res, e)
      if (allocated(e)) then
         call line_error(state, raw%at, e%message, error)
         return
      end if
      ! supports and imposed displacements: every copy (a copy per body)
      do k = 1, 2
         allocate (dupof(size(res%copies, 2)))
         dupof = res%copies(k, :)
         call extend_to_duplicates(model, 0, dupof)
         deallocate (dupof)
      end do
      ! edges on one body (pressures, other edge sets) to its copies
      if (allocated(model%patterns)) then
         do i = 1, size(model%patterns)
            if (model%patterns(i)%kind == LOAD_PRESSURE) &
               call remap_to_copies(model%mesh, res, model%patterns(i)%edge)
         end do
      end if
      do i = 1, size(model%mesh%edge_sets)
         if (i /= ke) call remap_to_copies(model%mesh, res, model%mesh%edge_sets(i)%nodes)
      end do
      if (.not. set%is_spring()) then
         set%conn = res%conn
         group = res%body_set
         if (set%is_katona()) then
            turn = katona_turned(res)
            do i = 1, size(turn)
               if (turn(i) .and. nen == 3) set%conn(:, i) = set%conn([3, 4, 1, 2, 6, 5], i)
               if (turn(i) .and. nen == 2) set%conn(:, i) = set%conn([3, 4, 1, 2], i)
            end do
         end if
      else
         ! one doublet per node of each face: (face-1 node, face-2 node)
         allocate (doublets(2, 0), trib(0), tang(2, 0))
         do face = FACE_LEFT, FACE_EXTENSION
            sel = pack([(i, i=1, size(res%face))], res%face == face)
            if (size(sel) == 0) cycle
            edges = res%conn([1, 2], sel)
            if (nen == 3) edges = res%conn([1, 2, 5], sel)
            k = size(doublets, 2)
            do i = 1, size(sel)
               call add_doublet(doublets, group, k, res%conn(1, sel(i)), res%conn(4, sel(i)), &
                  res%body_set(sel(i)))
               call add_doublet(doublets, group, k, res%conn(2, sel(i)), res%conn(3, sel(i)), &
                  res%body_set(sel(i)))
               if (nen == 3) call add_doublet(doublets, group, k, res%conn(5, sel(i)), &
                  res%conn(6, sel(i)), res%body_set(sel(i)))
            end do
            k = size(doublets, 2) - size(trib)
            trib = [trib, [(0.0_wp, i=1, k)]]
            tang = reshape([tang, [(0.0_wp, i=1, 2*k)]], [2, size(trib)])
            call spring_tributaries(model%mesh%x, model%analysis%kind, &
               model%analysis%thickness, doublets(1, size(trib) - k + 1:), edges, &
               trib(size(trib) - k + 1:), tang(:, size(trib) - k + 1:), bad, error)
            if (allocated(error)) then
               msg = "joint set '"//set%name//"': "//error%message
               call line_error(state, raw%at, msg, error)
               return
            end if
         end do
         set%conn = doublets
         set%tributary = trib
         set%tangent = tang
         if (raw%has_angle) set%tangent = spread([cos(raw%angle*PI/180.0_wp), &
            sin(raw%angle*PI/180.0_wp)], 2, size(set%conn, 2))
         if (set%is_katona()) then
            ! the doublets of the turned joints swapped, their tangents reversed: the same
            ! relative displacement, each node face 1 of one doublet at most (katona_turned)
            turn = katona_turned(res)
            do i = 1, size(set%conn, 2)
               if (.not. any(turn .and. (holds(1, 4) .or. holds(2, 3) .or. &
                   (nen == 3 .and. holds(min(5, 2*nen), 2*nen))))) cycle
               set%conn(:, i) = set%conn([2, 1], i)
               set%tangent(:, i) = -set%tangent(:, i)
            end do
         end if
      end if
      set%ids = [(next_id + i, i=1, size(set%conn, 2))]
      next_id = next_id + size(set%conn, 2)
   contains
      !> The joints whose nodes a, b (positions in res%conn) are spring doublet i.
      pure function holds(a, b) result(yes)
         integer, intent(in) :: a, b
         logical, allocatable :: yes(:)
         yes = res%conn(a, :) == set%conn(1, i) .and. res%conn(b, :) == set%conn(2, i)
      end function holds
   end subroutine generated_both

   !> Katona doublets on both faces: a doublet needs one partner per face-1 node, and the
   !> line's (the plate's) nodes are face 1 of the joints of both faces. The joints of the
   !> left face are turned over (face 1 the left body's copies, face 2 the line's nodes, (B.8)
   !> order: nodes 3, 4, 1, 2 [, 6, 5]; tangent and normal reverse, so that the relative
   !> displacement and the stresses are the same), and so are those of an extension beyond
   !> the start of a chain (oriented away from the line, its right body is the line's left
   !> one): every left copy is face 1 of one doublet (partner the line node), every line node
   !> face 1 of its right-face doublet (partner the right copy), and every right copy face 1
   !> only of an extension doublet (partner the left copy). A node the split left whole (a
   !> line's end inside a body) is its own partner (a doublet that carries no force).
   pure function katona_turned(res) result(turn)
      type(faces_result_t), intent(in) :: res
      logical, allocatable :: turn(:)
      logical :: flip
      integer :: j, m
      turn = res%face == FACE_LEFT
      flip = .false.
      m = 0
      do j = 1, size(res%face)
         if (res%face(j) /= FACE_EXTENSION) cycle
         m = m + 1
         ! a new extension starts at a line end: the start of a chain's first edge, or its end
         if (m == 1) then
            flip = any(res%conn(1, :) == res%extension(1, m) .and. res%face == FACE_LEFT)
         else if (res%extension(1, m) /= res%extension(2, m - 1)) then
            flip = any(res%conn(1, :) == res%extension(1, m) .and. res%face == FACE_LEFT)
         end if
         turn(j) = flip
      end do
   end function katona_turned


   !> Appends the doublet (a, b) of body set g unless the doublets from column k0 + 1 on
   !> hold it.
   pure subroutine add_doublet(doublets, group, k0, a, b, g)
      integer, allocatable, intent(inout) :: doublets(:, :), group(:)
      integer, intent(in) :: k0, a, b, g
      integer :: i
      do i = k0 + 1, size(doublets, 2)
         if (doublets(1, i) == a .and. doublets(2, i) == b) return
      end do
      doublets = reshape([doublets, a, b], [2, size(doublets, 2) + 1])
      group = [group, g]
   end subroutine add_doublet

   !> The joint set `set` as one set per element set in `group` (that of the body on face 2
   !> of each element, FACES=BOTH), named <set>_<element set>, so that a phase that removes
   !> a body removes the joints against it; `set` itself when there is one group or none.
   subroutine split_by_body(model, set, group, parts)
      type(model_t), intent(in) :: model
      type(joint_set_t), intent(in) :: set
      integer, intent(in) :: group(:)
      type(joint_set_t), allocatable, intent(out) :: parts(:)
      integer, allocatable :: kinds(:), sel(:)
      integer :: i, p
      allocate (kinds(0))
      do i = 1, size(group)
         if (.not. any(kinds == group(i))) kinds = [kinds, group(i)]
      end do
      if (size(kinds) <= 1) then
         parts = [set]
         return
      end if
      allocate (parts(size(kinds)))
      do p = 1, size(kinds)
         sel = pack([(i, i=1, size(group))], group == kinds(p))
         parts(p) = set
         parts(p)%name = set%name//'_'//model%mesh%esets(kinds(p))%name
         parts(p)%conn = set%conn(:, sel)
         parts(p)%ids = set%ids(sel)
         if (allocated(set%tributary)) then
            parts(p)%tributary = set%tributary(sel)
            parts(p)%tangent = set%tangent(:, sel)
         end if
      end do
   end subroutine split_by_body

   !> Supports and imposed displacements on split nodes also hold the duplicates; pressure
   !> edges on SIDE-only sides move to them (point forces stay where they were given). Nodes
   !> beyond dupof (copies made by an earlier call: FACES=BOTH calls once per face) have none.
   subroutine extend_to_duplicates(model, ks, dupof)
      type(model_t), intent(inout) :: model
      integer, intent(in) :: ks, dupof(:)
      integer :: k, p, n
      associate (sup => model%supports)
         if (allocated(sup%node)) then
            n = size(sup%node)
            do k = 1, n
               if (sup%node(k) > size(dupof)) cycle
               if (dupof(sup%node(k)) == 0) cycle
               sup%node = [sup%node, dupof(sup%node(k))]
               sup%dof = [sup%dof, sup%dof(k)]
               if (allocated(sup%group)) sup%group = [sup%group, sup%group(k)]
            end do
         end if
      end associate
      if (.not. allocated(model%patterns)) return
      do p = 1, size(model%patterns)
         associate (pat => model%patterns(p))
            select case (pat%kind)
            case (LOAD_DISPLACEMENT)
               n = size(pat%node)
               do k = 1, n
                  if (pat%node(k) > size(dupof)) cycle
                  if (dupof(pat%node(k)) == 0) cycle
                  pat%node = [pat%node, dupof(pat%node(k))]
                  pat%dof = [pat%dof, pat%dof(k)]
                  pat%value = [pat%value, pat%value(k)]
               end do
            case (LOAD_PRESSURE)
               call remap_side_edges(model%mesh, ks, dupof, pat%edge)
            end select
         end associate
      end do
   end subroutine extend_to_duplicates
end module pecplas_io_deck_resolve_joints
