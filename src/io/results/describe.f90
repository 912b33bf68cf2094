!> Self-describing results: the `units` and `components` attributes of the datasets of a
!> results file (doc/results.md, "Units and components"). Units come from the deck's *UNITS
!> (pecplas_base_units): length, force, stress, "1" for dimensionless values, "s" for CPU
!> time and UNITS_NOT_STATED for a dimensional value of a deck without *UNITS.
module pecplas_io_results_describe
   use hdf5, only: hid_t
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: AXISYMMETRIC
   use pecplas_base_units, only: UNITS_NOT_STATED
   use pecplas_io_results_h5, only: h5_describe, h5_object_attr, safe_name
   implicit none (type, external)
   private

   public :: results_units_t, set_units_t, plan_units, describe_mesh, describe_history
   public :: XY, XYZ, STRESS_COMPONENTS, JOINT_EPS, JOINT_SIGMA, MIXED_UNITS

   character(len=*), parameter :: XY(2) = [character(len=1) :: 'x', 'y']
   character(len=*), parameter :: XYZ(3) = [character(len=1) :: 'x', 'y', 'z']
   !> Continuum stress and strain vectors (zz: out of plane, or hoop in axisymmetry).
   character(len=*), parameter :: STRESS_COMPONENTS(4) = [character(len=2) :: 'xx', 'yy', &
      'zz', 'xy']
   character(len=*), parameter :: JOINT_EPS(2) = [character(len=5) :: 'eps_n', 'eps_t']
   character(len=*), parameter :: JOINT_SIGMA(2) = [character(len=7) :: 'sigma_n', 'tau']
   !> Units of a law history whose variables differ in kind (named by `state_names`).
   character(len=*), parameter :: MIXED_UNITS = 'mixed, see state_names'

   !> Per element or joint set: the unit of the relative displacements (joints) and the
   !> names of the history variables.
   type :: set_units_t
      character(len=:), allocatable :: eps
      character(len=16), allocatable :: state(:)
   end type set_units_t

   !> What the writer needs to describe every dataset.
   type :: results_units_t
      character(len=:), allocatable :: length, force, stress
      type(set_units_t), allocatable :: sets(:), joints(:)
      !> Load pattern names: the components of pattern_factors.
      character(len=64), allocatable :: patterns(:)
   end type results_units_t

contains

   !> Units of `model`'s results; element and joint sets in the model's order.
   subroutine plan_units(model, units)
      type(model_t), intent(in) :: model
      type(results_units_t), intent(out) :: units
      integer :: s, m, n
      n = 0
      if (allocated(model%patterns)) n = size(model%patterns)
      allocate (units%patterns(n))
      do s = 1, n
         units%patterns(s) = model%patterns(s)%name
      end do
      units%length = model%unit_system%of('length')
      units%force = model%unit_system%of('force')
      units%stress = model%unit_system%of('stress')
      allocate (units%sets(size(model%mesh%esets)))
      do s = 1, size(units%sets)
         m = model%mesh%esets(s)%material_index
         allocate (units%sets(s)%state(0))
         if (allocated(model%materials) .and. m > 0) then
            if (m <= size(model%materials)) &
               call model%materials(m)%m%state_names(units%sets(s)%state)
         end if
      end do
      allocate (units%joints(0))
      if (.not. allocated(model%joint_sets)) return
      deallocate (units%joints)
      allocate (units%joints(size(model%joint_sets)))
      do s = 1, size(units%joints)
         associate (set => model%joint_sets(s), j => units%joints(s))
            ! a thin layer works with strains: displacements / thickness (doc/results.md)
            j%eps = units%length
            if (set%is_thin_layer()) j%eps = '1'
            if (set%is_katona()) then
               allocate (j%state(0))
            else
               call model%laws(set%law_index)%law%state_names(j%state)
            end if
         end associate
      end do
   end subroutine plan_units

   !> /mesh: coordinates, Gauss coordinates, soil state names, joint point coordinates,
   !> tangents and tributary lengths (areas in axisymmetry).
   subroutine describe_mesh(file, model, units, error)
      integer(hid_t), intent(in) :: file
      type(model_t), intent(in) :: model
      type(results_units_t), intent(in) :: units
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: g, area
      integer :: s
      call h5_describe(file, '/mesh/coordinates', units%length, error, XY)
      do s = 1, size(units%sets)
         if (allocated(error)) return
         g = '/mesh/sets/'//safe_name(model%mesh%esets(s)%name)
         call h5_describe(file, g//'/gauss_coordinates', units%length, error, XY)
         if (.not. allocated(error) .and. size(units%sets(s)%state) > 0) &
            call h5_object_attr(file, g, 'state_names', units%sets(s)%state, error)
      end do
      area = units%length
      if (model%analysis%kind == AXISYMMETRIC .and. area /= UNITS_NOT_STATED) area = area//'2'
      do s = 1, size(units%joints)
         if (allocated(error)) return
         g = '/mesh/joint_sets/'//safe_name(model%joint_sets(s)%name)
         call h5_describe(file, g//'/point_coordinates', units%length, error, XY)
         if (.not. allocated(error)) &
            call h5_describe(file, g//'/point_tangents', '1', error, XY)
         if (.not. allocated(error) .and. allocated(model%joint_sets(s)%tributary)) &
            call h5_describe(file, g//'/tributary', area, error)
      end do
   end subroutine describe_mesh

   !> /history: time and pattern factors are load factors ("1"), residual relative,
   !> cpu_time in seconds; pattern_factors has one component per load pattern.
   subroutine describe_history(file, units, error)
      integer(hid_t), intent(in) :: file
      type(results_units_t), intent(in) :: units
      type(error_t), allocatable, intent(out) :: error
      call h5_describe(file, '/history/time', '1', error)
      if (.not. allocated(error)) call h5_describe(file, '/history/residual', '1', error)
      if (.not. allocated(error)) call h5_describe(file, '/history/cpu_time', 's', error)
      if (allocated(error)) return
      call h5_describe(file, '/history/pattern_factors', '1', error, units%patterns)
   end subroutine describe_history

end module pecplas_io_results_describe
