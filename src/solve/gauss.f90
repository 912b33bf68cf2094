!> Physical coordinates of the integration points, per element set and per joint set, for
!> the results file.
module pecplas_solve_gauss
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_problem_type, only: problem_t
   use pecplas_massif_element_matrices, only: massif_gauss_coordinates
   use pecplas_io_results_increment, only: gauss_coordinates_t, joint_points_t
   use pecplas_base_error, only: error_t
   use pecplas_joints_points, only: joint_point_geometry
   implicit none (type, external)
   private

   public :: gauss_coordinates, joint_points

contains

   function gauss_coordinates(model, problem) result(gxy)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      type(gauss_coordinates_t), allocatable :: gxy(:)
      real(wp), allocatable :: xe(:, :)
      integer :: s, e, nn

      allocate (gxy(size(model%mesh%esets)))
      do s = 1, size(model%mesh%esets)
         associate (set => model%mesh%esets(s), st => problem%state%sets(s))
            nn = problem%system%rules(s)%nnode
            allocate (xe(2, nn))
            allocate (gxy(s)%xy(2, st%ngauss, size(set%conn, 2)))
            do e = 1, size(set%conn, 2)
               xe = model%mesh%x(:, set%conn(:, e))
               call massif_gauss_coordinates(problem%system%rules(s), xe, gxy(s)%xy(:, :, e))
            end do
            deallocate (xe)
         end associate
      end do
   end function gauss_coordinates

   !> Coordinates and tangents of the points of every joint set.
   subroutine joint_points(model, points, error)
      type(model_t), intent(in) :: model
      type(joint_points_t), allocatable, intent(out) :: points(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: s
      allocate (points(0))
      if (.not. allocated(model%joint_sets)) return
      deallocate (points)
      allocate (points(size(model%joint_sets)))
      do s = 1, size(model%joint_sets)
         call joint_point_geometry(model, s, points(s)%xy, points(s)%tangent, error)
         if (allocated(error)) return
      end do
   end subroutine joint_points

end module pecplas_solve_gauss
