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
   use pecplas_linalg_threads, only: PARALLEL_MIN_ELEMENTS
   implicit none (type, external)
   private

   public :: gauss_coordinates, joint_points

contains

   !> The elements' points in parallel (each element's own, so the same values on any
   !> number of threads).
   function gauss_coordinates(model, problem) result(gxy)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      type(gauss_coordinates_t), allocatable :: gxy(:)
      real(wp), allocatable :: xe(:, :)
      integer :: s, e, nn, nel

      allocate (gxy(size(model%mesh%esets)))
      do s = 1, size(model%mesh%esets)
         associate (set => model%mesh%esets(s), st => problem%state%sets(s), &
                    rule => problem%system%rules(s))
            nn = rule%nnode
            nel = size(set%conn, 2)
            allocate (gxy(s)%xy(2, st%ngauss, nel))
            !$omp parallel default(shared) private(e, xe) if (nel >= PARALLEL_MIN_ELEMENTS)
            allocate (xe(2, nn))
            !$omp do schedule(static)
            do e = 1, nel
               xe = model%mesh%x(:, set%conn(:, e))
               call massif_gauss_coordinates(rule, xe, gxy(s)%xy(:, :, e))
            end do
            !$omp end do
            deallocate (xe)
            !$omp end parallel
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
