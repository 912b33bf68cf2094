!> Columns of the nodal arrays (2, ncolumns): one per node (x/r, y/z), then one per rotation
!> of a plate node (row 1 the rotation, row 2 unused and never an equation). A model without
!> plates has exactly one column per node.
module pecplas_model_columns
   use pecplas_model_type, only: model_t
   implicit none (type, external)
   private

   public :: nodal_columns, rotation_count, rotation_column

contains

   !> Number of rotations (nodes that carry a plate).
   pure integer function rotation_count(model) result(n)
      type(model_t), intent(in) :: model
      n = 0
      if (allocated(model%node_rotation)) then
         if (size(model%node_rotation) > 0) n = maxval(model%node_rotation)
      end if
   end function rotation_count

   !> Columns of the nodal arrays: nodes, then rotations.
   pure integer function nodal_columns(model) result(n)
      type(model_t), intent(in) :: model
      n = model%mesh%nnode() + rotation_count(model)
   end function nodal_columns

   !> Column of the rotation of `node` (row 1), 0 when it has none.
   pure integer function rotation_column(model, node) result(c)
      type(model_t), intent(in) :: model
      integer, intent(in) :: node
      c = 0
      if (.not. allocated(model%node_rotation)) return
      if (node > size(model%node_rotation)) return
      if (model%node_rotation(node) > 0) c = model%mesh%nnode() + model%node_rotation(node)
   end function rotation_column

end module pecplas_model_columns
