!> What the solver hands to the results file for one converged increment: plain data,
!> filled by the driver and written by `results_file_t%write_increment`.
module pecplas_io_results_increment
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: increment_result_t, set_fields_t, gauss_coordinates_t, joint_fields_t, &
      joint_points_t, limit_point_t

   !> Gauss-point fields of one element set, components (xx, yy, zz, xy) as in the
   !> massif materials (xy strain is engineering shear).
   type :: set_fields_t
      !> stress(4, ngauss, nel), strain(4, ngauss, nel).
      real(wp), allocatable :: stress(:, :, :), strain(:, :, :)
      !> Material history state(nstate, ngauss, nel) (e.g. plastic strains); unallocated or
      !> empty when the material has none.
      real(wp), allocatable :: state(:, :, :)
      !> Error indicator of each element (nel), with *OUTPUT, ERROR_ESTIMATE=YES.
      real(wp), allocatable :: error_indicator(:)
      !> A model with groundwater: steady and excess pore pressures (ngauss, nel),
      !> compression positive; `stress` is then the effective stress.
      real(wp), allocatable :: pore_steady(:, :), pore_excess(:, :)
   end type set_fields_t

   !> Coordinates of the Gauss points of one element set, xy(2, ngauss, nel); given once to
   !> `create` so that post-processing can place Gauss-point values without the elements.
   type :: gauss_coordinates_t
      real(wp), allocatable :: xy(:, :, :)
   end type gauss_coordinates_t

   !> Point fields of one joint set (PECJOIN), law conventions: eps(2, np, nel) =
   !> (eps_n closure positive, eps_t) relative displacements (strains for a thin layer),
   !> sigma(2, np, nel) = (sigma_n compression positive, tau), mode(np, nel) = 1 stick,
   !> 2 slip, 3 open, slip(np, nel) irreversible tangential displacement, state(nstate, np,
   !> nel) the law's history variables.
   type :: joint_fields_t
      real(wp), allocatable :: eps(:, :, :), sigma(:, :, :), slip(:, :), state(:, :, :)
      integer, allocatable :: mode(:, :)
      !> Error indicator of each joint element (nel), with *OUTPUT, ERROR_ESTIMATE=YES.
      real(wp), allocatable :: error_indicator(:)
   end type joint_fields_t

   !> Coordinates and unit tangents (2, np, nel) of the points of one joint set.
   type :: joint_points_t
      real(wp), allocatable :: xy(:, :, :), tangent(:, :, :)
   end type joint_points_t

   type :: increment_result_t
      !> Step number (1-based), increment within the step, global increment number.
      integer :: step = 0, increment = 0, global_increment = 0
      !> Cumulative pseudo-time: the end of step k is k.
      real(wp) :: time = 0.0_wp
      !> Factor of each load pattern (model%patterns order) at the end of the increment.
      real(wp), allocatable :: pattern_factors(:)
      !> Method that converged (1 modified Newton, 2 quasi-Newton, 3 full Newton), line
      !> search residual evaluations, control (0 load, 1 arc-length).
      integer :: method = 0, line_searches = 0, control = 0
      !> Newton iterations and final relative residual ||FR|| / ||F||.
      integer :: iterations = 0
      real(wp) :: residual = 0.0_wp
      !> CPU seconds since the start of the run.
      real(wp) :: cpu_time = 0.0_wp
      !> False: only the history row is written (output every n increments).
      logical :: write_fields = .true.
      !> displacement(2, nnode), reaction(2, nnode) (reaction needed only when the model
      !> asks for reactions).
      real(wp), allocatable :: displacement(:, :), reaction(:, :)
      !> One entry per element set, in model%mesh%esets order.
      type(set_fields_t), allocatable :: set_fields(:)
      !> One entry per joint set, in model%joint_sets order (absent: no joints).
      type(joint_fields_t), allocatable :: joint_fields(:)
      !> Global error estimate and energy norm of the solution (when estimated).
      logical :: estimated = .false.
      real(wp) :: error_estimate = 0.0_wp, energy_norm = 0.0_wp
   end type increment_result_t

   !> The largest load of a path that has a maximum: step, global increment and step
   !> fraction where it was reached, the pattern factors there, and how the maximum showed
   !> ('passed': the load fell after it; 'mechanism': the tangent of the next states is
   !> singular (a rigid-plastic interface in full slip); 'flat': the current stiffness parameter ~ 0 — then
   !> the increment is where the plateau began and the fraction and factors are the largest
   !> load traced on it).
   type :: limit_point_t
      character(len=:), allocatable :: kind
      integer :: step = 0, global_increment = 0
      real(wp) :: fraction = 0.0_wp, stiffness_parameter = 0.0_wp
      real(wp), allocatable :: pattern_factors(:)
   end type limit_point_t

end module pecplas_io_results_increment
