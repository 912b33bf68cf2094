!> Tributary measures of the springs of a locally refined model (pecplas_model_refine_local):
!> recomputed as at reading (pecplas_joints_elements_tributary) from the boundary sides of the refined mesh
!> that join face-1 nodes of the set; the tangents are kept.
module pecplas_model_refine_local_springs
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_mesh_sides, only: side_table_t, build_side_table, find_sides
   use pecplas_joints_elements_tributary, only: spring_tributaries
   implicit none (type, external)
   private

   public :: spring_measures

contains

   subroutine spring_measures(fine, s, reason)
      type(model_t), intent(inout) :: fine
      integer, intent(in) :: s
      character(len=:), allocatable, intent(out) :: reason
      type(side_table_t) :: table
      type(error_t), allocatable :: error
      logical, allocatable :: face1(:)
      integer, allocatable :: edges(:, :)
      real(wp), allocatable :: tangent(:, :)
      integer :: k, n, bad
      call build_side_table(fine%mesh, table)
      allocate (face1(fine%mesh%nnode()), source=.false.)
      face1(fine%joint_sets(s)%conn(1, :)) = .true.
      allocate (edges(3, size(table%nodes, 2)))
      n = 0
      do k = 1, size(table%nodes, 2)
         if (.not. all(face1(table%nodes(1:2, k)))) cycle
         if (size(find_sides(table, table%nodes(:, k))) /= 1) cycle
         n = n + 1
         edges(:, n) = table%nodes(:, k)
      end do
      associate (js => fine%joint_sets(s))
         allocate (tangent(2, size(js%conn, 2)))
         call spring_tributaries(fine%mesh%x, fine%analysis%kind, fine%analysis%thickness, &
            js%conn(1, :), edges(:, 1:n), js%tributary, tangent, bad, error)
      end associate
      if (allocated(error)) reason = 'springs of set '//fine%joint_sets(s)%name//': '// &
         error%message
   end subroutine spring_measures

end module pecplas_model_refine_local_springs
