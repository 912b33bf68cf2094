!> The phases of a staged run in its results file. The driver calls `write_phase` at the
!> start of each step (the step is the phase): the file then lists the phase under
!> /phases/<index> with its name, what it changed and the element and joint sets active
!> in it (layout: pecplas_io_results_phase_log), the increments written from then on hold
!> no fields of the sets not active, and the XDMF sidecar shows only the active sets of
!> each increment (ParaView plays the excavation).
module pecplas_io_results_phases
   use pecplas_base_error, only: error_t
   use pecplas_io_results_file, only: results_file_t
   use pecplas_io_results_phase_log, only: phase_record_t
   implicit none (type, external)
   private

   public :: write_phase

contains

   !> Records the start of step `index` (1-based) named `name`: `changes`, one line per change
   !> of the model at its start (size 0 for none), and the masks of the element sets and
   !> joint sets active during it, in the model's order of the sets. Errors: file not open,
   !> masks of the wrong size, index < 1. A detached file (MPI ranks above 0) does nothing.
   subroutine write_phase(results, index, name, changes, active_esets, active_jsets, error)
      type(results_file_t), intent(inout) :: results
      integer, intent(in) :: index
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: changes(:)
      logical, intent(in) :: active_esets(:), active_jsets(:)
      type(error_t), allocatable, intent(out) :: error
      type(phase_record_t) :: rec
      integer :: i
      rec%index = index
      rec%name = name
      rec%nchange = size(changes)
      rec%changes = ''
      do i = 1, size(changes)
         if (i > 1) rec%changes = rec%changes//new_line('a')
         rec%changes = rec%changes//trim(changes(i))
      end do
      rec%active_esets = active_esets
      rec%active_jsets = active_jsets
      call results%add_phase(rec, error)
   end subroutine write_phase

end module pecplas_io_results_phases
