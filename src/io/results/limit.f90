!> /limit of the results file: where the load of the run had its maximum. Attributes kind,
!> step, global_increment, fraction, stiffness_parameter; dataset pattern_factors (one per
!> load pattern, described with the patterns' names).
module pecplas_io_results_limit
   use hdf5, only: hid_t
   use pecplas_base_error, only: error_t
   use pecplas_io_results_increment, only: limit_point_t
   use pecplas_io_results_h5, only: h5_group, h5_close_group, h5_attr, h5_write, h5_describe
   implicit none (type, external)
   private

   public :: write_limit_group

contains

   !> Writes `limit` as the group /limit of `file`; patterns: the names of the load patterns.
   subroutine write_limit_group(file, limit, patterns, error)
      integer(hid_t), intent(in) :: file
      type(limit_point_t), intent(in) :: limit
      character(len=*), intent(in) :: patterns(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: g
      call h5_group(file, 'limit', g, error)
      if (allocated(error)) return
      call h5_attr(g, 'kind', limit%kind, error)
      if (.not. allocated(error)) call h5_attr(g, 'step', limit%step, error)
      if (.not. allocated(error)) call h5_attr(g, 'global_increment', limit%global_increment, &
         error)
      if (.not. allocated(error)) call h5_attr(g, 'fraction', limit%fraction, error)
      if (.not. allocated(error)) call h5_attr(g, 'stiffness_parameter', &
         limit%stiffness_parameter, error)
      if (.not. allocated(error)) call h5_write(g, 'pattern_factors', limit%pattern_factors, &
         error)
      if (.not. allocated(error)) call h5_describe(g, 'pattern_factors', '1', error, &
         patterns)
      call h5_close_group(g)
   end subroutine write_limit_group

end module pecplas_io_results_limit
