!> *MESH, FILE=path.msh: reads a Gmsh mesh when the keyword is met and appends it to the
!> model mesh when the mesh is built (after the deck nodes, before the deck element sets),
!> so that deck keywords can use its node ids and set names.
module pecplas_io_deck_mesh_import
   use pecplas_base_error, only: error_t, ERR_INPUT
   use pecplas_io_text_fields, only: deck_line_t, itoa
   use pecplas_io_text_lines, only: join_path, dir_name
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, line_error
   use pecplas_io_mesh_gmsh, only: read_gmsh
   use pecplas_model_mesh, only: mesh_t
   use pecplas_model_mesh_tools, only: append_mesh
   implicit none (type, external)
   private

   public :: read_mesh, append_imported

contains

   !> *MESH, FILE=path -- path relative to the file holding the line; no data lines.
   subroutine read_mesh(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      character(len=:), allocatable :: file
      type(mesh_t), allocatable :: tmp(:)
      type(mesh_t) :: mesh
      logical :: exists
      integer :: n
      kwline = state%lines%get(block%at)
      call block%kw%check_keys(kwline, [character(len=4) :: 'FILE'], error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'FILE', file, error)
      if (allocated(error)) return
      file = join_path(dir_name(kwline%file), file)
      inquire (file=file, exist=exists)
      if (.not. exists) then
         call line_error(state, block%at, "cannot read mesh file '"//file//"'", error)
         return
      end if
      ! errors inside the .msh file name that file and line; say which *MESH read it
      call read_gmsh(file, mesh, error)
      if (allocated(error)) then
         if (.not. allocated(error%message)) error%message = ''
         ! a file that cannot be opened (a directory...) has no line of its own
         if (error%line <= 0) then
            error%file = state%lines%file(block%at)
            error%line = state%lines%line(block%at)
            error%keyword = '*MESH'
            error%kind = ERR_INPUT
            return
         end if
         error%message = error%message//' (mesh read by *MESH at '// &
            state%lines%file(block%at)//':'//itoa(state%lines%line(block%at))//')'
         return
      end if
      if (.not. allocated(state%imported)) allocate (state%imported(0), state%imported_at(0))
      n = size(state%imported)
      allocate (tmp(n + 1))
      tmp(1:n) = state%imported
      tmp(n + 1) = mesh
      call move_alloc(tmp, state%imported)
      state%imported_at = [state%imported_at, block%at]
   end subroutine read_mesh

   !> Appends the meshes read by *MESH to `mesh`; state%mesh_node_at, mesh_eset_at and
   !> mesh_edge_set_at get the *MESH line of each node, element set and edge set added.
   subroutine append_imported(state, mesh, error)
      type(deck_state_t), intent(inout) :: state
      type(mesh_t), intent(inout) :: mesh
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: message
      integer :: i, nnode, neset, nedge
      if (.not. allocated(state%imported)) return
      do i = 1, size(state%imported)
         nnode = mesh%nnode()
         neset = size(mesh%esets)
         nedge = size(mesh%edge_sets)
         call append_mesh(mesh, state%imported(i), error)
         if (allocated(error)) then
            message = error%message
            call line_error(state, state%imported_at(i), message, error)
            return
         end if
         state%mesh_node_at = [state%mesh_node_at, &
            spread(state%imported_at(i), 1, mesh%nnode() - nnode)]
         state%mesh_eset_at = [state%mesh_eset_at, &
            spread(state%imported_at(i), 1, size(mesh%esets) - neset)]
         state%mesh_edge_set_at = [state%mesh_edge_set_at, &
            spread(state%imported_at(i), 1, size(mesh%edge_sets) - nedge)]
      end do
   end subroutine append_imported

end module pecplas_io_deck_mesh_import
