!> What the solver hands to the results file for one converged increment: plain data,
!> filled by the driver and written by `results_file_t%write_increment`.
module pecplas_io_results_increment
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: increment_result_t, set_fields_t, gauss_coordinates_t, joint_fields_t, &
      joint_points_t, limit_point_t, anchor_fields_t, plate_fields_t

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

   !> Forces of one anchor set: N of one anchor (nbar, tension positive) and N / L_s;
   !> `active`: the set acts in the increment's phase (only those are written).
   type :: anchor_fields_t
      character(len=:), allocatable :: name
      logical :: active = .true.
      real(wp), allocatable :: force(:), force_per_width(:)
   end type anchor_fields_t
   !> Fields of one plate set: N, Q, M at both ends of each element end_forces(3, 2, nel);
   !> at the plate's nodes (node_index: internal numbers, in the order of the plate) the
   !> mean of the element ends there node_forces(3, nnode_plate), the displacement (2, .)
   !> and the rotation (.); the points' generalized resultants (5, np, nel) and section
   !> history (3, np, nel) (pecplas_structures_section).
   type :: plate_fields_t
      !> The set's name; whether it is part of the model now (a phase may leave it out).
      character(len=:), allocatable :: name
      logical :: active = .true.
      integer, allocatable :: node_index(:)
      real(wp), allocatable :: end_forces(:, :, :), node_forces(:, :), displacement(:, :), &
         rotation(:), resultants(:, :, :), plastic(:, :, :)
      !> The moment reaction at each plate node whose rotation is held (0 elsewhere).
      real(wp), allocatable :: moment_reaction(:)
   end type plate_fields_t

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
      !> One entry per anchor set, in model%anchors order (absent: no anchors).
      type(anchor_fields_t), allocatable :: anchor_fields(:)
      !> One entry per plate set, in model%plates order (absent: no plates).
      type(plate_fields_t), allocatable :: plate_fields(:)
      !> Global error estimate and energy norm of the solution (when estimated).
      logical :: estimated = .false.
      real(wp) :: error_estimate = 0.0_wp, energy_norm = 0.0_wp
   end type increment_result_t

   !> The largest load of a path that has a maximum: step, global increment and step
   !> fraction where it was reached, the pattern factors there, and how the maximum showed
   !> ('passed': the load fell after it; 'mechanism': the tangent of the next states is
   !> singular (a rigid-plastic interface in full slip); 'flat': a plateau, the load rose by at
   !> most 0.1 % while the displacement conjugate to it doubled (pecplas_solve_arc_path) — then
   !> the increment is where the plateau began and the fraction and factors are the largest
   !> load traced on it).
   type :: limit_point_t
      character(len=:), allocatable :: kind
      integer :: step = 0, global_increment = 0
      real(wp) :: fraction = 0.0_wp, stiffness_parameter = 0.0_wp
      real(wp), allocatable :: pattern_factors(:)
   end type limit_point_t

end module pecplas_io_results_increment
