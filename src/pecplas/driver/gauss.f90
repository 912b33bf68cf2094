!> Physical coordinates of the integration points, per element set, for the results file.
module pecplas_driver_gauss
   use pecplas_kinds, only: wp
   use pecplas_model, only: model_t
   use pecplas_driver_problem, only: problem_t
   use pecplas_massif_element_matrices, only: massif_gauss_coordinates
   use pecplas_io_results_increment, only: gauss_coordinates_t
   implicit none (type, external)
   private

   public :: gauss_coordinates

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
            nn = problem%rules(s)%nnode
            allocate (xe(2, nn))
            allocate (gxy(s)%xy(2, st%ngauss, size(set%conn, 2)))
            do e = 1, size(set%conn, 2)
               xe = model%mesh%x(:, set%conn(:, e))
               call massif_gauss_coordinates(problem%rules(s), xe, gxy(s)%xy(:, :, e))
            end do
            deallocate (xe)
         end associate
      end do
   end function gauss_coordinates

end module pecplas_driver_gauss
