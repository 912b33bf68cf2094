!> Physical coordinates of the integration points, per element set, for the results file.
module pecplas_driver_gauss
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t
   use pecplas_model, only: model_t
   use pecplas_driver_problem, only: problem_t
   use pecplas_massif_materials_type, only: NCOMP
   use pecplas_massif_kinematics, only: point_kinematics
   use pecplas_io_results_file, only: gauss_points_t
   implicit none (type, external)
   private

   public :: gauss_coordinates

contains

   function gauss_coordinates(model, problem) result(gxy)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      type(gauss_points_t), allocatable :: gxy(:)
      real(wp), allocatable :: xe(:, :), n(:), b(:, :)
      real(wp) :: dvol
      type(error_t), allocatable :: error
      integer :: s, e, g, nn

      allocate (gxy(size(model%mesh%esets)))
      do s = 1, size(model%mesh%esets)
         associate (set => model%mesh%esets(s), st => problem%state%sets(s))
            nn = problem%elems(s)%e%nnode()
            allocate (xe(2, nn), n(nn), b(NCOMP, 2*nn))
            allocate (gxy(s)%xy(2, st%ngauss, size(set%conn, 2)))
            do e = 1, size(set%conn, 2)
               xe = model%mesh%x(:, set%conn(:, e))
               do g = 1, st%ngauss
                  ! Geometry was checked when the stiffness was factorised: no error here.
                  call point_kinematics(problem%elems(s)%e, model%analysis, xe, st%xi(:, g), &
                     st%w(g), n, b, dvol, gxy(s)%xy(:, g, e), error)
               end do
            end do
            deallocate (xe, n, b)
         end associate
      end do
   end function gauss_coordinates

end module pecplas_driver_gauss
