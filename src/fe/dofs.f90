!> Equation numbering: two DOFs per node (x/r, y/z), and a rotation at the nodes of plates
!> (row 1 of the rotation columns of the nodal arrays, pecplas_model_columns); supports and
!> imposed displacements are constrained and eliminated from the system of equations.
!> Numbered node by node, a node's rotation after its translations; a model without plates
!> has the numbering it always had.
module pecplas_fe_dofs
   use pecplas_base_error, only: error_t, input_error
   use pecplas_model_loads, only: LOAD_DISPLACEMENT
   use pecplas_model_type, only: model_t
   use pecplas_model_columns, only: nodal_columns, rotation_column
   implicit none (type, external)
   private

   public :: dofs_t, new_dofs

   type :: dofs_t
      !> Number of free equations.
      integer :: neq = 0
      !> eq(d, column) > 0: equation number of a free DOF; 0: constrained. Columns of the
      !> nodal arrays: nodes 1..nnode, then the rotations (row 1; row 2 is never free).
      integer, allocatable :: eq(:, :)
      !> column and row of each equation in the nodal arrays.
      integer, allocatable :: eq_node(:), eq_dir(:)
   contains
      procedure :: describe => dofs_describe
   end type dofs_t

contains

   !> Numbers the free DOFs node by node (keeps the bandwidth of the mesh numbering; the
   !> sparse solvers reorder anyway). Supports and DISPLACEMENT patterns are constrained.
   !> `supports_on(g)` (a phased run): whether the named support g (model%supports%names)
   !> is active, i.e. constrains its dofs; without it every support does.
   subroutine new_dofs(model, dofs, error, supports_on)
      type(model_t), intent(in) :: model
      type(dofs_t), intent(out) :: dofs
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: supports_on(:)
      logical, allocatable :: fixed(:, :)
      integer :: i, k, n, d, c

      n = model%mesh%nnode()
      ! Nodes of no element carry no stiffness: they are not unknowns (and not a mechanism).
      allocate (fixed(2, nodal_columns(model)), source=.true.)
      do i = 1, size(model%mesh%esets)
         associate (conn => model%mesh%esets(i)%conn)
            do k = 1, size(conn, 2)
               do d = 1, size(conn, 1)
                  fixed(:, conn(d, k)) = .false.
               end do
            end do
         end associate
      end do
      ! joint nodes are unknowns too (a joint face may carry no massif element)
      if (allocated(model%joint_sets)) then
         do i = 1, size(model%joint_sets)
            do k = 1, size(model%joint_sets(i)%conn, 2)
               fixed(:, model%joint_sets(i)%conn(:, k)) = .false.
            end do
         end do
      end if
      ! anchor nodes too (a node that only a bar holds)
      if (allocated(model%anchors)) then
         do i = 1, size(model%anchors)
            do k = 1, size(model%anchors(i)%conn, 2)
               do d = 1, 2
                  if (model%anchors(i)%conn(d, k) > 0) fixed(:, model%anchors(i)%conn(d, k)) = &
                     .false.
               end do
            end do
         end do
      end if
      ! plate nodes and their rotations too (a plate may stand on nodes of no element)
      if (allocated(model%plates)) then
         do i = 1, size(model%plates)
            do k = 1, size(model%plates(i)%conn, 2)
               do d = 1, size(model%plates(i)%conn, 1)
                  c = model%plates(i)%conn(d, k)
                  fixed(:, c) = .false.
                  fixed(1, rotation_column(model, c)) = .false.
               end do
            end do
         end do
      end if
      if (allocated(model%supports%node)) then
         do k = 1, size(model%supports%node)
            if (.not. support_entry_on(model, k, supports_on)) cycle
            call fix(model%supports%node(k), model%supports%dof(k))
         end do
      end if
      if (allocated(model%patterns)) then
         do i = 1, size(model%patterns)
            if (model%patterns(i)%kind /= LOAD_DISPLACEMENT) cycle
            do k = 1, size(model%patterns(i)%node)
               call fix(model%patterns(i)%node(k), model%patterns(i)%dof(k))
            end do
         end do
      end if
      allocate (dofs%eq(2, size(fixed, 2)), source=0)
      dofs%neq = count(.not. fixed)
      if (dofs%neq == 0) then
         call input_error(error, 'every degree of freedom is constrained: nothing to solve')
         return
      end if
      allocate (dofs%eq_node(dofs%neq), dofs%eq_dir(dofs%neq))
      k = 0
      do i = 1, n
         do d = 1, 2
            if (fixed(d, i)) cycle
            k = k + 1
            dofs%eq(d, i) = k
            dofs%eq_node(k) = i
            dofs%eq_dir(k) = d
         end do
         c = rotation_column(model, i)
         if (c == 0) cycle
         if (fixed(1, c)) cycle
         k = k + 1
         dofs%eq(1, c) = k
         dofs%eq_node(k) = c
         dofs%eq_dir(k) = 1
      end do
   contains
      !> Holds dof d (3: the rotation, where the node carries one) of `node`.
      subroutine fix(node, d)
         integer, intent(in) :: node, d
         if (d <= 2) then
            fixed(d, node) = .true.
         else if (rotation_column(model, node) > 0) then
            fixed(1, rotation_column(model, node)) = .true.
         end if
      end subroutine fix
   end subroutine new_dofs

   !> Whether support entry k constrains its dof: always for an unnamed support, else when
   !> its group is on (or no activity is given).
   pure logical function support_entry_on(model, k, supports_on) result(on)
      type(model_t), intent(in) :: model
      integer, intent(in) :: k
      logical, intent(in), optional :: supports_on(:)
      on = .true.
      if (.not. present(supports_on)) return
      if (.not. allocated(model%supports%group)) return
      if (size(model%supports%group) /= size(model%supports%node)) return
      if (model%supports%group(k) == 0) return
      on = supports_on(model%supports%group(k))
   end function support_entry_on

   !> "node 12 (x = 0.5, y = 1) direction y" for equation `k`.
   function dofs_describe(this, model, k) result(text)
      class(dofs_t), intent(in) :: this
      type(model_t), intent(in) :: model
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      character(len=120) :: buf
      character(len=1), parameter :: names(2) = ['x', 'y']
      character(len=1), parameter :: axi_names(2) = ['r', 'z']
      integer :: node
      if (k < 1 .or. k > this%neq) then
         text = 'an unknown equation'
         return
      end if
      node = this%eq_node(k)
      if (node > model%mesh%nnode()) then
         node = findloc(model%node_rotation, node - model%mesh%nnode(), 1)
         write (buf, '(a,i0,a,g0.6,a,g0.6,a)') 'node ', model%mesh%node_id(node), ' (', &
            model%mesh%x(1, node), ', ', model%mesh%x(2, node), ') rotation'
      else if (model%analysis%kind == 2) then
         write (buf, '(a,i0,a,g0.6,a,g0.6,a,a)') 'node ', model%mesh%node_id(node), ' (r = ', &
            model%mesh%x(1, node), ', z = ', model%mesh%x(2, node), ') direction ', &
            axi_names(this%eq_dir(k))
      else
         write (buf, '(a,i0,a,g0.6,a,g0.6,a,a)') 'node ', model%mesh%node_id(node), ' (x = ', &
            model%mesh%x(1, node), ', y = ', model%mesh%x(2, node), ') direction ', &
            names(this%eq_dir(k))
      end if
      text = trim(buf)
   end function dofs_describe

end module pecplas_fe_dofs
