!> Everything a run does between reading the deck and the first increment (checks, problem
!> set-up, default penalties, initial stresses, first factorisation, joint points), shared by
!> the batch command (pecplas_cmd_pecplas: run_deck) and the advice mode (pecplas_advise_advise).
module pecplas_solve_prepare
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_provenance, only: place_t
   use pecplas_model_geometry, only: check_geometry
   use pecplas_model_mesh_tools, only: orient_edge_sets, check_elements
   use pecplas_problem_type, only: problem_t, setup_problem, initialise_stresses
   use pecplas_solve_stiffness, only: factorise_stiffness
   use pecplas_solve_gauss, only: joint_points
   use pecplas_io_results_increment, only: joint_points_t
   use pecplas_fe_joint_penalty, only: set_default_penalties
   implicit none (type, external)
   private

   public :: prepare_run

contains

   !> Checks and sets up the problem of a read `model`; `nflipped` clockwise elements were
   !> renumbered; `jpoints` are the joint integration points for the results file.
   subroutine prepare_run(model, problem, nflipped, jpoints, error)
      type(model_t), intent(inout) :: model
      type(problem_t), intent(out) :: problem
      integer, intent(out) :: nflipped
      type(joint_points_t), allocatable, intent(out) :: jpoints(:)
      type(error_t), allocatable, intent(out) :: error
      type(place_t) :: p
      character(len=:), allocatable :: keyword
      integer :: bad(2)
      call check_elements(model%mesh, nflipped, error, bad)
      if (allocated(error)) then
         if (bad(2) > 0) then
            call model%provenance%element(bad(1), bad(2), p, keyword)
            call model%provenance%locate(error, p, keyword, as_input=.true.)
         end if
         return
      end if
      call check_geometry(model, error)
      if (.not. allocated(error)) call orient_edge_sets(model%mesh, error)
      if (.not. allocated(error)) call setup_problem(model, problem, error)
      if (.not. allocated(error)) call set_default_penalties(model, problem%system%rules, &
         problem%state%joints, error)
      if (.not. allocated(error)) call initialise_stresses(model, problem, error)
      if (.not. allocated(error)) call factorise_stiffness(model, problem, .false., error)
      if (.not. allocated(error)) call joint_points(model, jpoints, error)
   end subroutine prepare_run

end module pecplas_solve_prepare
