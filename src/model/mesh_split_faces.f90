!> Joints on both faces of a line (a plate, a wall; doc/deck.md, *JOINTS FACES=BOTH): the
!> elements on each side of the line get their own copies of its nodes, so that the left and
!> the right body no longer share nodes through it; the original nodes stay on the line (the
!> plate's). Which elements take which copy is decided around each node of the line: the
!> elements touching it form groups joined through sides that are not line edges, and each
!> group gets a copy (a node where one group remains, the line's end inside a body, is not
!> split: both bodies and the plate keep it).
!>
!> The line's edges are ordered into chains and oriented along them; a joint is made on
!> each face of every line edge (face 1 the original nodes, face 2 the copies of the body
!> on that face, oriented with that body on the left of 1 -> 2, (B.8) order); the edge set
!> then names the line's edges on its left body (the body on the left of the chains). With
!> `extend` > 0 the cut goes on from each end of a chain along the element sides that
!> continue it (within 30 degrees), over that length or up to the boundary: along those
!> extension edges one joint joins the right body (face 1) to the left body (face 2)
!> directly (the soil below a wall's toe), no original node being left between them.
module pecplas_model_mesh_split_faces
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error
   use pecplas_model_mesh, only: mesh_t
   use pecplas_model_mesh_sides, only: side_table_t, build_side_table, find_sides, &
      element_centroid
   use pecplas_model_mesh_tools, only: corner_count, id_list
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private

   public :: faces_result_t, split_both_faces, remap_to_copies, FACE_LEFT, FACE_RIGHT, &
      FACE_EXTENSION

   !> What a joint of the result lies on: the left face of the line (the body on the left
   !> of the chain's direction), the right face, or the extension beyond the line's end.
   integer, parameter :: FACE_LEFT = 1, FACE_RIGHT = 2, FACE_EXTENSION = 3

   type :: faces_result_t
      !> Joint connectivity (2 nen, njoint) in (B.8) order, the face of each joint and the
      !> element set of the body on its face 2.
      integer, allocatable :: conn(:, :), face(:), body_set(:)
      !> Nodes created (original, copy).
      integer, allocatable :: created(:, :)
      !> copies(:, node): the (up to 2) copies of each original node, 0 where none.
      integer, allocatable :: copies(:, :)
      !> The extension edges (nen, m) in original nodes, oriented along their chain.
      integer, allocatable :: extension(:, :)
   end type faces_result_t

   real(wp), parameter :: COS_CONTINUE = 0.866_wp

contains

   !> Splits `mesh` along edge set `ke` on both faces; `extend`: length of the cut beyond
   !> each end of the line (0: none). origin(node) is extended to the new nodes. Errors: an
   !> edge that is not between two elements, a line that branches, a node already split.
   subroutine split_both_faces(mesh, ke, extend, origin, res, error)
      type(mesh_t), intent(inout) :: mesh
      integer, intent(in) :: ke
      real(wp), intent(in) :: extend
      integer, allocatable, intent(inout) :: origin(:)
      type(faces_result_t), intent(out) :: res
      type(error_t), allocatable, intent(out) :: error
      type(side_table_t) :: table
      integer, allocatable :: line(:, :), cut(:, :), owner(:, :, :), inc_ptr(:), inc(:, :)
      integer :: nn, nen, ne, f, i, nline, ncut
      nn = mesh%nnode()
      if (.not. allocated(origin)) allocate (origin(0))
      if (size(origin) < nn) origin = [origin, [(i, i=size(origin) + 1, nn)]]
      nen = size(mesh%edge_sets(ke)%nodes, 1)
      ne = size(mesh%edge_sets(ke)%nodes, 2)
      if (ne == 0) then
         call input_error(error, "edge set '"//mesh%edge_sets(ke)%name//"' has no edges")
         return
      end if
      if (any(origin(1:nn) /= [(i, i=1, nn)] .and. on_edges(mesh%edge_sets(ke)%nodes, nn))) then
         call input_error(error, "edge set '"//mesh%edge_sets(ke)%name//"' has a node split "// &
            'by joints generated before: FACES=BOTH splits a line once, give it all its joints')
         return
      end if
      call build_side_table(mesh, table)
      call orient_chains(mesh, mesh%edge_sets(ke)%nodes, line, error)
      if (allocated(error)) then
         error%message = "edge set '"//mesh%edge_sets(ke)%name//"': "//error%message
         return
      end if
      nline = size(line, 2)
      call extension_edges(mesh, table, line, extend, res%extension)
      cut = reshape([line, res%extension], [nen, nline + size(res%extension, 2)])
      ncut = size(cut, 2)
      ! the two elements (set, element) beside each cut edge, the left one first
      allocate (owner(2, 2, ncut))
      do f = 1, ncut
         call left_right(mesh, table, cut(:, f), owner(:, :, f), error)
         if (allocated(error)) then
            error%message = 'edge '//id_list(mesh, cut(:, f))//" of edge set '"// &
               mesh%edge_sets(ke)%name//"' "//error%message
            return
         end if
      end do
      call incidence(mesh, inc_ptr, inc)
      call split_nodes(mesh, cut, inc_ptr, inc, origin, res, error)
      if (allocated(error)) return
      call make_joints(mesh, cut, nline, owner, res)
      ! the edge set: the line's edges on its left body (its original nodes are on no
      ! element side any more), in the order of the chains
      if (nen == 3) then
         mesh%edge_sets(ke)%nodes = res%conn([4, 3, 6], 1:nline)
      else
         mesh%edge_sets(ke)%nodes = res%conn([4, 3], 1:nline)
      end if
   end subroutine split_both_faces

   !> Mask over the nodes 1..nn: the nodes of `edges` (a 0 is no node).
   pure function on_edges(edges, nn) result(mask)
      integer, intent(in) :: edges(:, :), nn
      logical :: mask(nn)
      integer :: i
      mask = .false.
      do i = 1, size(edges, 2)
         mask(pack(edges(:, i), edges(:, i) > 0)) = .true.
      end do
   end function on_edges

   !> The edges (nen, m) ordered into chains, each edge oriented along its chain (ends 1 ->
   !> 2). A node of three or more edges is an error.
   subroutine orient_chains(mesh, edges, line, error)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: edges(:, :)
      integer, allocatable, intent(out) :: line(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: degree(:)
      logical, allocatable :: used(:)
      integer :: ne, k, f, v, g, n
      ne = size(edges, 2)
      allocate (degree(mesh%nnode()), source=0)
      do f = 1, ne
         degree(edges(1:2, f)) = degree(edges(1:2, f)) + 1
      end do
      if (any(degree > 2)) then
         v = findloc(degree > 2, .true., 1)
         call input_error(error, 'the line branches at node '//itoa(mesh%node_id(v))// &
            ' (three or more of its edges meet there): give each branch its own *JOINTS')
         return
      end if
      allocate (used(ne), source=.false.)
      allocate (line(size(edges, 1), 0))
      n = 0
      do while (n < ne)
         ! a chain starts at an end (a node of one edge), or anywhere on a closed loop
         g = 0
         do f = 1, ne
            if (used(f)) cycle
            if (degree(edges(1, f)) == 1 .or. degree(edges(2, f)) == 1) then
               g = f
               exit
            end if
         end do
         if (g == 0) g = findloc(used, .false., 1)
         v = edges(1, g)
         if (degree(edges(2, g)) == 1 .and. degree(edges(1, g)) /= 1) v = edges(2, g)
         do
            k = 0
            do f = 1, ne
               if (.not. used(f) .and. any(edges(1:2, f) == v)) then
                  k = f
                  exit
               end if
            end do
            if (k == 0) exit
            used(k) = .true.
            n = n + 1
            if (edges(1, k) == v) then
               line = reshape([line, edges(:, k)], [size(edges, 1), n])
               v = edges(2, k)
            else
               line = reshape([line, edges(2, k), edges(1, k), edges(3:, k)], &
                  [size(edges, 1), n])
               v = edges(1, k)
            end if
         end do
      end do
   end subroutine orient_chains

   !> Edges that continue each open end of the chains of `line` along element sides (within
   !> 30 degrees of the direction there), over `extend`, each side beside two elements.
   subroutine extension_edges(mesh, table, line, extend, ext)
      type(mesh_t), intent(in) :: mesh
      type(side_table_t), intent(in) :: table
      integer, intent(in) :: line(:, :)
      real(wp), intent(in) :: extend
      integer, allocatable, intent(out) :: ext(:, :)
      integer, allocatable :: cnt(:)
      real(wp) :: t(2), d(2), best, done
      integer :: f, e, v, s, w, pick, nen, m
      nen = size(line, 1)
      allocate (ext(nen, 0))
      if (.not. extend > 0.0_wp) return
      allocate (cnt(mesh%nnode()), source=0)
      do f = 1, size(line, 2)
         cnt(line(1:2, f)) = cnt(line(1:2, f)) + 1
      end do
      do f = 1, size(line, 2)
         do e = 1, 2
            v = line(e, f)
            if (cnt(v) /= 1) cycle
            ! the direction out of the line at its end v
            t = mesh%x(:, line(e, f)) - mesh%x(:, line(3 - e, f))
            t = t/norm2(t)
            done = 0.0_wp
            do while (done < extend*(1.0_wp - 1.0e-9_wp))
               best = COS_CONTINUE
               pick = 0
               do s = 1, size(table%elem)
                  if (table%nodes(1, s) /= v .and. table%nodes(2, s) /= v) cycle
                  if ((table%nodes(3, s) > 0) .neqv. (nen == 3)) cycle
                  w = merge(table%nodes(2, s), table%nodes(1, s), table%nodes(1, s) == v)
                  d = mesh%x(:, w) - mesh%x(:, v)
                  if (dot_product(d, t)/norm2(d) > best) then
                     best = dot_product(d, t)/norm2(d)
                     pick = s
                  end if
               end do
               if (pick == 0) exit
               if (size(find_sides(table, table%nodes(1:nen, pick))) /= 2) exit
               w = merge(table%nodes(2, pick), table%nodes(1, pick), table%nodes(1, pick) == v)
               m = size(ext, 2) + 1
               if (nen == 3) then
                  ext = reshape([ext, v, w, table%nodes(3, pick)], [nen, m])
               else
                  ext = reshape([ext, v, w], [nen, m])
               end if
               d = mesh%x(:, w) - mesh%x(:, v)
               done = done + norm2(d)
               t = d/norm2(d)
               v = w
            end do
         end do
      end do
   end subroutine extension_edges

   !> owner(:, 1) = (set, element) of the left body, owner(:, 2) of the right body beside
   !> edge en (oriented 1 -> 2): the edge must be a side of exactly two elements.
   subroutine left_right(mesh, table, en, owner, error)
      type(mesh_t), intent(in) :: mesh
      type(side_table_t), intent(in) :: table
      integer, intent(in) :: en(:)
      integer, intent(out) :: owner(2, 2)
      integer :: sides(2)
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: found(:)
      real(wp) :: c(2), t(2)
      allocate (found(0)) ! gives the descriptor bounds (silences a gfortran 12 false warning)
      found = find_sides(table, en)
      if (size(found) /= 2) then
         call input_error(error, 'is a side of '//itoa(size(found))//' element(s): '// &
            'FACES=BOTH needs a body on each side of every edge (use SIDE= for a joint '// &
            'on one face)')
         return
      end if
      t = mesh%x(:, en(2)) - mesh%x(:, en(1))
      c = element_centroid(mesh, table%set(found(1)), table%elem(found(1)))
      sides = found
      if (-t(2)*(c(1) - mesh%x(1, en(1))) + t(1)*(c(2) - mesh%x(2, en(1))) < 0.0_wp) &
         sides = found([2, 1])
      owner(:, 1) = [table%set(sides(1)), table%elem(sides(1))]
      owner(:, 2) = [table%set(sides(2)), table%elem(sides(2))]
   end subroutine left_right

   !> Node -> (set, element) incidence in CSR form: inc(:, inc_ptr(v):inc_ptr(v+1)-1).
   subroutine incidence(mesh, inc_ptr, inc)
      type(mesh_t), intent(in) :: mesh
      integer, allocatable, intent(out) :: inc_ptr(:), inc(:, :)
      integer, allocatable :: fill(:)
      integer :: s, j, i, v
      allocate (inc_ptr(mesh%nnode() + 1), source=0)
      do s = 1, size(mesh%esets)
         do j = 1, size(mesh%esets(s)%conn, 2)
            do i = 1, size(mesh%esets(s)%conn, 1)
               v = mesh%esets(s)%conn(i, j)
               inc_ptr(v + 1) = inc_ptr(v + 1) + 1
            end do
         end do
      end do
      inc_ptr(1) = 1
      do v = 1, mesh%nnode()
         inc_ptr(v + 1) = inc_ptr(v + 1) + inc_ptr(v)
      end do
      allocate (inc(2, inc_ptr(mesh%nnode() + 1) - 1), fill(mesh%nnode()))
      fill = inc_ptr(1:mesh%nnode())
      do s = 1, size(mesh%esets)
         do j = 1, size(mesh%esets(s)%conn, 2)
            do i = 1, size(mesh%esets(s)%conn, 1)
               v = mesh%esets(s)%conn(i, j)
               inc(:, fill(v)) = [s, j]
               fill(v) = fill(v) + 1
            end do
         end do
      end do
   end subroutine incidence

   !> Around each node of the cut edges: the groups of elements joined through sides that
   !> are not cut edges; with two groups or more, each takes a new copy of the node.
   subroutine split_nodes(mesh, cut, inc_ptr, inc, origin, res, error)
      type(mesh_t), intent(inout) :: mesh
      integer, intent(in) :: cut(:, :), inc_ptr(:), inc(:, :)
      integer, allocatable, intent(inout) :: origin(:)
      type(faces_result_t), intent(inout) :: res
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: on_cut(:)
      integer, allocatable :: group(:), newx(:), extra(:)
      real(wp), allocatable :: x(:, :)
      integer :: nn, v, a, b, na, ng, k, i, nnew, kk
      logical :: changed
      nn = mesh%nnode()
      allocate (on_cut(nn), source=.false.)
      do k = 1, size(cut, 2)
         on_cut(pack(cut(:, k), cut(:, k) > 0)) = .true.
      end do
      allocate (res%copies(2, nn), source=0)
      allocate (res%created(2, 0))
      nnew = 0
      allocate (newx(0))
      do v = 1, nn
         if (.not. on_cut(v)) cycle
         na = inc_ptr(v + 1) - inc_ptr(v)
         if (na == 0) cycle
         group = [(i, i=1, na)]
         ! join elements that share a side through v that is not a cut edge (to a fixpoint)
         changed = .true.
         do while (changed)
            changed = .false.
            do a = 1, na
               do b = a + 1, na
                  if (group(a) == group(b)) cycle
                  if (.not. share_open_side(mesh, cut, v, inc(:, inc_ptr(v) + a - 1), &
                      inc(:, inc_ptr(v) + b - 1))) cycle
                  where (group == max(group(a), group(b))) group = min(group(a), group(b))
                  changed = .true.
               end do
            end do
         end do
         ng = count([(group(i) == i, i=1, na)])
         if (ng == 1) cycle
         if (ng > 2) then
            call input_error(error, 'node '//itoa(mesh%node_id(v))//' has '//itoa(ng)// &
               ' groups of elements around it cut apart by the line: FACES=BOTH splits a '// &
               'node in two')
            return
         end if
         kk = 0
         do i = 1, na
            if (group(i) /= i) cycle
            kk = kk + 1
            nnew = nnew + 1
            res%copies(kk, v) = nn + nnew
            res%created = reshape([res%created, v, nn + nnew], [2, nnew])
            newx = [newx, v]
            do k = 1, na
               if (group(k) /= i) cycle
               associate (c => mesh%esets(inc(1, inc_ptr(v) + k - 1))%conn(:, &
                          inc(2, inc_ptr(v) + k - 1)))
                  where (c == v) c = nn + nnew
               end associate
            end do
         end do
      end do
      if (nnew == 0) return
      allocate (x(2, nn + nnew))
      x(:, 1:nn) = mesh%x
      x(:, nn + 1:) = mesh%x(:, newx)
      call move_alloc(x, mesh%x)
      mesh%node_id = [mesh%node_id, (maxval(mesh%node_id) + i, i=1, nnew)]
      origin = [origin, origin(newx)]
      ! node sets gain the copies
      do i = 1, size(mesh%nsets)
         extra = [integer ::]
         do k = 1, size(mesh%nsets(i)%nodes)
            v = mesh%nsets(i)%nodes(k)
            if (v > nn) cycle
            if (res%copies(1, v) > 0) extra = [extra, pack(res%copies(:, v), res%copies(:, v) > 0)]
         end do
         if (size(extra) > 0) mesh%nsets(i)%nodes = [mesh%nsets(i)%nodes, extra]
      end do
   end subroutine split_nodes

   !> Whether elements a and b (set, element) share a side through node v that is not an
   !> edge of `cut`.
   logical function share_open_side(mesh, cut, v, a, b) result(share)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: cut(:, :), v, a(2), b(2)
      integer :: sa(2), sb(2), i, j, na, nb
      integer :: pa(2, 2), pb(2, 2)
      share = .false.
      call sides_through(mesh, a, v, pa, na)
      call sides_through(mesh, b, v, pb, nb)
      do i = 1, na
         do j = 1, nb
            sa = [minval(pa(:, i)), maxval(pa(:, i))]
            sb = [minval(pb(:, j)), maxval(pb(:, j))]
            if (any(sa /= sb)) cycle
            if (is_cut(cut, sa)) cycle
            share = .true.
            return
         end do
      end do
   end function share_open_side

   !> The corner pairs (2, n) of the sides of element e = (set, element) that hold node v
   !> (as a corner: its two sides; as a mid node: its side).
   subroutine sides_through(mesh, e, v, pairs, n)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: e(2), v
      integer, intent(out) :: pairs(2, 2), n
      integer :: nc, i
      logical :: mid
      n = 0
      pairs = 0
      associate (conn => mesh%esets(e(1))%conn(:, e(2)))
         nc = corner_count(mesh%esets(e(1))%etype)
         do i = 1, nc
            mid = .false.
            if (size(conn) == 2*nc) mid = conn(nc + i) == v
            if (conn(i) == v .or. conn(mod(i, nc) + 1) == v .or. mid) then
               if (n == 2) exit
               n = n + 1
               pairs(:, n) = [conn(i), conn(mod(i, nc) + 1)]
            end if
         end do
      end associate
   end subroutine sides_through

   pure logical function is_cut(cut, pair)
      integer, intent(in) :: cut(:, :), pair(2)
      integer :: f
      is_cut = .false.
      do f = 1, size(cut, 2)
         if (min(cut(1, f), cut(2, f)) == pair(1) .and. max(cut(1, f), cut(2, f)) == pair(2)) &
            is_cut = .true.
      end do
   end function is_cut

   !> The joints: on each line edge one per face (face 1 the original nodes), on each
   !> extension edge one from the right body (face 1) to the left one (face 2).
   subroutine make_joints(mesh, cut, nline, owner, res)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: cut(:, :), nline, owner(:, :, :)
      type(faces_result_t), intent(inout) :: res
      integer, allocatable :: l(:), r(:)
      integer :: f, nen, nj, face
      nen = size(cut, 1)
      nj = 2*nline + (size(cut, 2) - nline)
      allocate (res%conn(2*nen, nj), res%face(nj), res%body_set(nj))
      nj = 0
      do face = FACE_LEFT, FACE_EXTENSION
         do f = 1, size(cut, 2)
            if ((face == FACE_EXTENSION) .neqv. (f > nline)) cycle
            l = body_nodes(mesh, res%copies, cut(:, f), owner(1, 1, f), owner(2, 1, f))
            r = body_nodes(mesh, res%copies, cut(:, f), owner(1, 2, f), owner(2, 2, f))
            nj = nj + 1
            res%face(nj) = face
            res%body_set(nj) = owner(1, merge(2, 1, face == FACE_RIGHT), f)
            select case (face)
            case (FACE_LEFT)
               res%conn(1:4, nj) = [cut(1, f), cut(2, f), l(2), l(1)]
               if (nen == 3) res%conn(5:6, nj) = [cut(3, f), l(3)]
            case (FACE_RIGHT)
               res%conn(1:4, nj) = [cut(2, f), cut(1, f), r(1), r(2)]
               if (nen == 3) res%conn(5:6, nj) = [cut(3, f), r(3)]
            case default
               res%conn(1:4, nj) = [r(1), r(2), l(2), l(1)]
               if (nen == 3) res%conn(5:6, nj) = [r(3), l(3)]
            end select
         end do
      end do
   end subroutine make_joints

   !> The nodes of element (s, j) (renumbered) at the original nodes of edge en: its copy
   !> of each (copies(:, node)), or the node itself where it was not split.
   function body_nodes(mesh, copies, en, s, j) result(nodes)
      type(mesh_t), intent(in) :: mesh
      integer, intent(in) :: copies(:, :), en(:), s, j
      integer, allocatable :: nodes(:)
      integer :: k
      nodes = en
      do k = 1, size(en)
         if (en(k) < 1) cycle
         if (any(mesh%esets(s)%conn(:, j) == copies(1, en(k))) .and. copies(1, en(k)) > 0) &
            nodes(k) = copies(1, en(k))
         if (any(mesh%esets(s)%conn(:, j) == copies(2, en(k))) .and. copies(2, en(k)) > 0) &
            nodes(k) = copies(2, en(k))
      end do
   end function body_nodes

   !> Edges (nen, n; a 0 is no node) through split nodes that are a side of one element:
   !> moved to that element's copies (the one choice of copies that is an element side); the
   !> line's own edges (sides of both bodies) and edges of no element stay as they are.
   subroutine remap_to_copies(mesh, res, edges)
      type(mesh_t), intent(in) :: mesh
      type(faces_result_t), intent(in) :: res
      integer, intent(inout) :: edges(:, :)
      type(side_table_t) :: table
      integer :: f, k, nen, combo, ncombo, nmatch, pick(3), trial(3), c, nn0
      if (size(edges, 2) == 0 .or. size(res%created, 2) == 0) return
      call build_side_table(mesh, table)
      nen = size(edges, 1)
      nn0 = size(res%copies, 2)
      do f = 1, size(edges, 2)
         if (.not. any(edges(:, f) > 0 .and. edges(:, f) <= nn0)) cycle
         if (all(res%copies(1, pack(edges(:, f), edges(:, f) > 0 .and. edges(:, f) <= nn0)) &
             == 0)) cycle
         ncombo = 3**nen
         nmatch = 0
         do combo = 0, ncombo - 1
            trial(1:nen) = edges(:, f)
            c = combo
            do k = 1, nen
               if (trial(k) > 0 .and. trial(k) <= nn0) then
                  if (mod(c, 3) > 0) then
                     if (res%copies(mod(c, 3), trial(k)) == 0) then
                        trial(k) = -1
                     else
                        trial(k) = res%copies(mod(c, 3), trial(k))
                     end if
                  end if
               else if (mod(c, 3) > 0) then
                  trial(k) = -1
               end if
               c = c/3
            end do
            if (any(trial(1:nen) < 0)) cycle
            if (size(find_sides(table, trial(1:nen))) == 0) cycle
            nmatch = nmatch + 1
            pick(1:nen) = trial(1:nen)
         end do
         if (nmatch == 1) edges(:, f) = pick(1:nen)
      end do
   end subroutine remap_to_copies

end module pecplas_model_mesh_split_faces
