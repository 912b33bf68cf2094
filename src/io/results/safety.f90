!> /safety of the results file (doc/results.md, Safety factor): what a safety step (strength
!> reduction) found. Attributes kind ('factor', 'lower bound', 'unstable before reduction'),
!> factor, resolution, increments, wall_time, displacement_of, note, reduced and kept (the
!> materials and laws whose strength was divided by Msf, and the others); datasets msf and
!> displacement (the curve, one value per converged increment, Msf = 1 first), mechanism
!> (2, nnode) and mechanism3 (3, nnode, z = 0, for ParaView): the incremental displacements
!> of the last increments.
module pecplas_io_results_safety
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use hdf5, only: hid_t
   use pecplas_io_results_h5, only: h5_group, h5_close_group, h5_write, h5_attr
   implicit none (type, external)
   private

   public :: safety_record_t, write_safety_group, SAFETY_NOTE

   !> What the results file says of the displacements of a safety step.
   character(len=*), parameter :: SAFETY_NOTE = 'the displacements of the safety step are '// &
      'not physical: they follow strengths divided by Msf; only the factor and the shape '// &
      'of the mechanism mean something'

   type :: safety_record_t
      character(len=:), allocatable :: kind, displacement_of
      real(wp) :: factor = 0.0_wp, resolution = 0.0_wp, wall = 0.0_wp
      integer :: increments = 0
      real(wp), allocatable :: msf(:), displacement(:), mechanism(:, :)
      !> Names of the materials and laws whose strength was reduced, and of those kept.
      character(len=:), allocatable :: reduced, kept
   end type safety_record_t

contains

   subroutine write_safety_group(loc, rec, error)
      integer(hid_t), intent(in) :: loc
      type(safety_record_t), intent(in) :: rec
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: g
      real(wp), allocatable :: m3(:, :)
      call h5_group(loc, 'safety', g, error)
      if (allocated(error)) return
      call h5_attr(g, 'kind', rec%kind, error)
      if (.not. allocated(error)) call h5_attr(g, 'factor', rec%factor, error)
      if (.not. allocated(error)) call h5_attr(g, 'resolution', rec%resolution, error)
      if (.not. allocated(error)) call h5_attr(g, 'increments', rec%increments, error)
      if (.not. allocated(error)) call h5_attr(g, 'wall_time', rec%wall, error)
      if (.not. allocated(error)) call h5_attr(g, 'displacement_of', rec%displacement_of, error)
      if (.not. allocated(error)) call h5_attr(g, 'note', SAFETY_NOTE, error)
      if (allocated(rec%reduced) .and. .not. allocated(error)) &
         call h5_attr(g, 'reduced', rec%reduced, error)
      if (allocated(rec%kept) .and. .not. allocated(error)) call h5_attr(g, 'kept', rec%kept, error)
      if (.not. allocated(error)) call h5_write(g, 'msf', rec%msf, error)
      if (.not. allocated(error)) call h5_write(g, 'displacement', rec%displacement, error)
      if (allocated(rec%mechanism) .and. .not. allocated(error)) then
         call h5_write(g, 'mechanism', rec%mechanism, error)
         allocate (m3(3, size(rec%mechanism, 2)), source=0.0_wp)
         m3(1:2, :) = rec%mechanism
         if (.not. allocated(error)) call h5_write(g, 'mechanism3', m3, error)
      end if
      call h5_close_group(g)
   end subroutine write_safety_group

end module pecplas_io_results_safety
