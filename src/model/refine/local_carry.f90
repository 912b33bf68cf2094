!> What refers to nodes, carried over to a locally refined mesh (pecplas_model_refine_local):
!> joints, node sets, edge sets, supports and loads, from the nodes made on split sides.
module pecplas_model_refine_local_carry
   use pecplas_base_kinds, only: wp
   use pecplas_model_loads, only: LOAD_FORCE, LOAD_DISPLACEMENT, LOAD_PRESSURE
   use pecplas_model_type, only: model_t
   use pecplas_model_refine_local_edges, only: local_edges_t, edge_of
   implicit none (type, external)
   private

   public :: node_store_t, add_node, split_joints, carry_sets, carry_loads

   !> Coordinates of the refined mesh as they are made (n used columns of x).
   type :: node_store_t
      real(wp), allocatable :: x(:, :)
      integer :: n = 0
   end type node_store_t

contains

   subroutine add_node(store, x, node)
      type(node_store_t), intent(inout) :: store
      real(wp), intent(in) :: x(2)
      integer, intent(out) :: node
      real(wp), allocatable :: grown(:, :)
      if (store%n == size(store%x, 2)) then
         allocate (grown(2, max(16, 2*store%n)))
         grown(:, 1:store%n) = store%x(:, 1:store%n)
         call move_alloc(grown, store%x)
      end if
      store%n = store%n + 1
      store%x(:, store%n) = x
      node = store%n
   end subroutine add_node

   !> Node at fraction t (1/4, 1/2, 3/4) of split side e from its end `from`; 0 if not made.
   pure integer function on_side(le, e, from, t) result(node)
      type(local_edges_t), intent(in) :: le
      integer, intent(in) :: e, from
      real(wp), intent(in) :: t
      integer :: slot
      slot = nint(4.0_wp*t)
      if (le%ends(1, e) /= from) slot = 4 - slot
      node = le%node(slot, e)
   end function on_side

   !> Joints whose faces were split: two joints each (4- and 6-node, node order of (B.8));
   !> springs: a doublet on every new node of a split face-1 side.
   subroutine split_joints(model, le, next_eid, fine, reason)
      type(model_t), intent(in) :: model
      type(local_edges_t), intent(in) :: le
      integer, intent(inout) :: next_eid
      type(model_t), intent(inout) :: fine
      character(len=:), allocatable, intent(out) :: reason
      integer, allocatable :: c(:, :), id(:)
      integer :: s, j, e1, e2, n, npe, q(6)
      do s = 1, size(model%joint_sets)
         associate (js => model%joint_sets(s), cj => model%joint_sets(s)%conn)
            npe = size(cj, 1)
            if (npe == 2) then
               call split_springs(model, s, le, next_eid, fine)
               cycle
            end if
            allocate (c(npe, 2*size(cj, 2)), id(2*size(cj, 2)))
            n = 0
            do j = 1, size(cj, 2)
               e1 = edge_of(le, cj(1, j), cj(2, j))
               e2 = edge_of(le, cj(3, j), cj(4, j))
               if (e1 == 0 .or. e2 == 0) then
                  reason = 'a face of joint set '//js%name//' is no element edge'
                  return
               end if
               if (.not. le%marked(e1)) then
                  n = n + 1
                  c(:, n) = cj(:, j)
                  id(n) = js%ids(j)
                  cycle
               end if
               if (npe == 4) then
                  q(1) = on_side(le, e1, cj(1, j), 0.5_wp)
                  q(2) = on_side(le, e2, cj(4, j), 0.5_wp)
                  c(:, n + 1) = [cj(1, j), q(1), q(2), cj(4, j)]
                  c(:, n + 2) = [q(1), cj(2, j), cj(3, j), q(2)]
               else
                  q(1) = on_side(le, e1, cj(1, j), 0.25_wp)
                  q(2) = on_side(le, e1, cj(1, j), 0.75_wp)
                  q(3) = on_side(le, e2, cj(4, j), 0.25_wp)
                  q(4) = on_side(le, e2, cj(4, j), 0.75_wp)
                  c(:, n + 1) = [cj(1, j), cj(5, j), cj(6, j), cj(4, j), q(1), q(3)]
                  c(:, n + 2) = [cj(5, j), cj(2, j), cj(3, j), cj(6, j), q(2), q(4)]
               end if
               if (any(c(:, n + 1:n + 2) == 0)) then
                  reason = 'a face of joint set '//js%name//' was not split with its element'
                  return
               end if
               id(n + 1) = js%ids(j)
               next_eid = next_eid + 1
               id(n + 2) = next_eid
               n = n + 2
            end do
            fine%joint_sets(s)%conn = c(:, 1:n)
            fine%joint_sets(s)%ids = id(1:n)
            deallocate (c, id)
         end associate
      end do
   end subroutine split_joints

   !> New doublets on the split sides between face-1 nodes of springs, facing the nodes made
   !> on the side between their partners; tangent: mean of the two ends' (tributary: later).
   subroutine split_springs(model, s, le, next_eid, fine)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      type(local_edges_t), intent(in) :: le
      integer, intent(inout) :: next_eid
      type(model_t), intent(inout) :: fine
      integer :: i, j, e1, e2, k, a, b
      real(wp) :: t(2)
      associate (c => model%joint_sets(s)%conn, fs => fine%joint_sets(s))
         do i = 1, size(c, 2)
            do j = i + 1, size(c, 2)
               e1 = edge_of(le, c(1, i), c(1, j))
               e2 = edge_of(le, c(2, i), c(2, j))
               if (e1 == 0 .or. e2 == 0) cycle
               if (.not. le%marked(e1)) cycle
               t = model%joint_sets(s)%tangent(:, i) + model%joint_sets(s)%tangent(:, j)
               t = t/norm2(t)
               do k = 1, 3
                  if (k == 2 .and. le%mid(e1) /= 0) cycle
                  a = on_side(le, e1, c(1, i), 0.25_wp*k)
                  b = on_side(le, e2, c(2, i), 0.25_wp*k)
                  if (a == 0 .or. b == 0) cycle
                  fs%conn = reshape([reshape(fs%conn, [size(fs%conn)]), a, b], &
                     [2, size(fs%conn, 2) + 1])
                  next_eid = next_eid + 1
                  fs%ids = [fs%ids, next_eid]
                  fs%tributary = [fs%tributary, 0.0_wp]
                  fs%tangent = reshape([reshape(fs%tangent, [size(fs%tangent)]), t], &
                     [2, size(fs%tangent, 2) + 1])
               end do
            end do
         end do
      end associate
   end subroutine split_springs

   !> Node sets gain the new nodes of the boundary sides whose two ends they hold; edge sets
   !> are split.
   subroutine carry_sets(model, le, fine)
      type(model_t), intent(in) :: model
      type(local_edges_t), intent(in) :: le
      type(model_t), intent(inout) :: fine
      logical, allocatable :: inset(:)
      integer :: s
      if (allocated(model%mesh%nsets)) then
         allocate (inset(model%mesh%nnode()))
         do s = 1, size(model%mesh%nsets)
            inset = .false.
            inset(model%mesh%nsets(s)%nodes) = .true.
            fine%mesh%nsets(s)%nodes = [fine%mesh%nsets(s)%nodes, new_on_boundary(le, inset)]
         end do
      end if
      if (.not. allocated(model%mesh%edge_sets)) return
      do s = 1, size(model%mesh%edge_sets)
         call split_edge_list(le, model%mesh%edge_sets(s)%nodes, fine%mesh%edge_sets(s)%nodes)
      end do
   end subroutine carry_sets

   !> New nodes of split boundary sides with both ends flagged.
   function new_on_boundary(le, flag) result(nodes)
      type(local_edges_t), intent(in) :: le
      logical, intent(in) :: flag(:)
      integer, allocatable :: nodes(:)
      integer :: e, k
      allocate (nodes(0))
      do e = 1, size(le%marked)
         if (.not. (le%marked(e) .and. le%nel(e) == 1)) cycle
         if (.not. all(flag(le%ends(:, e)))) cycle
         do k = 1, 3
            if (k == 2 .and. le%mid(e) /= 0) cycle
            if (le%node(k, e) > 0) nodes = [nodes, le%node(k, e)]
         end do
      end do
   end function new_on_boundary

   !> Each listed side (end, end, mid or 0) that was split becomes two, in order.
   subroutine split_edge_list(le, e, f)
      type(local_edges_t), intent(in) :: le
      integer, intent(in) :: e(:, :)
      integer, allocatable, intent(inout) :: f(:, :)
      integer :: k, n, ed
      deallocate (f)
      allocate (f(size(e, 1), 2*size(e, 2)), source=0)
      n = 0
      do k = 1, size(e, 2)
         ed = edge_of(le, e(1, k), e(2, k))
         if (ed == 0) then
            n = n + 1
            f(:, n) = e(:, k)
            cycle
         end if
         if (.not. le%marked(ed)) then
            n = n + 1
            f(:, n) = e(:, k)
         else if (size(e, 1) < 3 .or. le%mid(ed) == 0) then
            f(1:2, n + 1) = [e(1, k), on_side(le, ed, e(1, k), 0.5_wp)]
            f(1:2, n + 2) = [on_side(le, ed, e(1, k), 0.5_wp), e(2, k)]
            n = n + 2
         else
            f(:, n + 1) = [e(1, k), e(3, k), on_side(le, ed, e(1, k), 0.25_wp)]
            f(:, n + 2) = [e(3, k), e(2, k), on_side(le, ed, e(1, k), 0.75_wp)]
            n = n + 2
         end if
      end do
      f = f(:, 1:n)
   end subroutine split_edge_list

   !> Supports, imposed displacements (interpolated along the side), pressures; point forces
   !> on both ends of a split side are refused.
   subroutine carry_loads(model, le, fine, reason)
      type(model_t), intent(in) :: model
      type(local_edges_t), intent(in) :: le
      type(model_t), intent(inout) :: fine
      character(len=:), allocatable, intent(out) :: reason
      integer :: p, k
      if (allocated(model%supports%node)) then
         call carry_nodal(le, model%supports%node, model%supports%dof, &
            [(0.0_wp, k=1, size(model%supports%node))], fine%supports%node, &
            fine%supports%dof, reason)
         if (allocated(reason)) return
      end if
      do p = 1, size(model%patterns)
         associate (pat => model%patterns(p), fp => fine%patterns(p))
            select case (pat%kind)
            case (LOAD_FORCE)
               if (both_ends_split(le, pat%node, pat%dof)) then
                  reason = 'nodal loads on a refined set ('//pat%name//')'
                  return
               end if
            case (LOAD_DISPLACEMENT)
               call carry_nodal(le, pat%node, pat%dof, pat%value, fp%node, fp%dof, reason, &
                  fp%value)
               if (allocated(reason)) return
            case (LOAD_PRESSURE)
               call split_pressure(le, pat%edge, pat%pressure, fp%edge, fp%pressure)
               ! a pressure linear in y is the same function on the halves of a side
               if (allocated(pat%pressure_gradient)) then
                  call split_pressure(le, pat%edge, pat%pressure_gradient, fp%edge, &
                     fp%pressure_gradient)
                  call split_pressure(le, pat%edge, pat%pressure_y_ref, fp%edge, &
                     fp%pressure_y_ref)
               end if
            end select
         end associate
      end do
   end subroutine carry_loads

   subroutine split_pressure(le, e, pr, f, fpr)
      type(local_edges_t), intent(in) :: le
      integer, intent(in) :: e(:, :)
      real(wp), intent(in) :: pr(:)
      integer, allocatable, intent(inout) :: f(:, :)
      real(wp), allocatable, intent(inout) :: fpr(:)
      integer :: k, ed
      call split_edge_list(le, e, f)
      if (allocated(fpr)) deallocate (fpr)
      allocate (fpr(0))
      do k = 1, size(e, 2)
         ed = edge_of(le, e(1, k), e(2, k))
         fpr = [fpr, pr(k)]
         if (ed == 0) cycle
         if (le%marked(ed)) fpr = [fpr, pr(k)]
      end do
   end subroutine split_pressure

   logical function both_ends_split(le, node, dof) result(both)
      type(local_edges_t), intent(in) :: le
      integer, intent(in) :: node(:), dof(:)
      integer :: e, d
      both = .false.
      do e = 1, size(le%marked)
         if (.not. le%marked(e)) cycle
         do d = 1, 2
            if (any(node == le%ends(1, e) .and. dof == d) .and. &
                any(node == le%ends(2, e) .and. dof == d)) both = .true.
         end do
      end do
   end function both_ends_split

   !> Appends (new node, dof, value) on split boundary sides holding dof at both ends; the
   !> value is interpolated along the side (linear, or quadratic through the mid node).
   subroutine carry_nodal(le, node, dof, value, fnode, fdof, reason, fvalue)
      type(local_edges_t), intent(in) :: le
      integer, intent(in) :: node(:), dof(:)
      real(wp), intent(in) :: value(:)
      integer, allocatable, intent(inout) :: fnode(:), fdof(:)
      character(len=:), allocatable, intent(out) :: reason
      real(wp), allocatable, intent(inout), optional :: fvalue(:)
      real(wp), parameter :: W(3, 3) = reshape([0.375_wp, 0.75_wp, -0.125_wp, 0.0_wp, 0.0_wp, &
         0.0_wp, -0.125_wp, 0.75_wp, 0.375_wp], [3, 3])
      integer :: e, d, k, ia, ib, im
      real(wp) :: v(3)
      do e = 1, size(le%marked)
         if (.not. le%marked(e)) cycle
         do d = 1, 2
            ia = findloc(node == le%ends(1, e) .and. dof == d, .true., 1)
            ib = findloc(node == le%ends(2, e) .and. dof == d, .true., 1)
            if (ia == 0 .or. ib == 0) cycle
            if (le%nel(e) > 1) then
               reason = 'supports or imposed displacements on both ends of an interior edge'
               return
            end if
            im = 0
            if (le%mid(e) > 0) im = findloc(node == le%mid(e) .and. dof == d, .true., 1)
            v = [value(ia), 0.5_wp*(value(ia) + value(ib)), value(ib)]
            if (im > 0) v(2) = value(im)
            do k = 1, 3
               if ((k == 2 .and. le%mid(e) /= 0) .or. le%node(k, e) == 0) cycle
               fnode = [fnode, le%node(k, e)]
               fdof = [fdof, d]
               if (present(fvalue)) then
                  if (le%mid(e) == 0) then
                     fvalue = [fvalue, v(2)]
                  else
                     fvalue = [fvalue, dot_product(W(:, k), v)]
                  end if
               end if
            end do
         end do
      end do
   end subroutine carry_nodal

end module pecplas_model_refine_local_carry
