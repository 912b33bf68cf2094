!> The names of a mesh's sets, listed for error messages: ' a b c' in mesh order (each name
!> after one blank), `none` (default: nothing) when the mesh has no set of that kind.
module pecplas_io_deck_set_names
   use pecplas_io_text_parse, only: add_name
   use pecplas_model_mesh, only: mesh_t
   implicit none (type, external)
   private

   public :: eset_names, nset_names, edge_set_names

contains

   !> ' a b c': the element sets of `mesh`.
   pure function eset_names(mesh, none) result(list)
      type(mesh_t), intent(in) :: mesh
      character(len=*), intent(in), optional :: none
      character(len=:), allocatable :: list
      integer :: k
      list = ''
      do k = 1, size(mesh%esets)
         call add_name(list, mesh%esets(k)%name)
      end do
      if (len(list) == 0 .and. present(none)) list = none
   end function eset_names

   !> ' a b c': the node sets of `mesh`.
   pure function nset_names(mesh, none) result(list)
      type(mesh_t), intent(in) :: mesh
      character(len=*), intent(in), optional :: none
      character(len=:), allocatable :: list
      integer :: k
      list = ''
      do k = 1, size(mesh%nsets)
         call add_name(list, mesh%nsets(k)%name)
      end do
      if (len(list) == 0 .and. present(none)) list = none
   end function nset_names

   !> ' a b c': the edge sets of `mesh`.
   pure function edge_set_names(mesh, none) result(list)
      type(mesh_t), intent(in) :: mesh
      character(len=*), intent(in), optional :: none
      character(len=:), allocatable :: list
      integer :: k
      list = ''
      do k = 1, size(mesh%edge_sets)
         call add_name(list, mesh%edge_sets(k)%name)
      end do
      if (len(list) == 0 .and. present(none)) list = none
   end function edge_set_names

end module pecplas_io_deck_set_names
