!> The phases of a run as the results file records them: one record per step start
!> (pecplas_io_results_phases: write_phase), written as the group /phases/<index>:
!>   attributes  index (the step, 1-based), name, changes (one line per change of the model
!>               made at the phase's start; an empty list for a phase that changes nothing),
!>               first_global_increment and first_history_row (1-based) of the phase's first
!>               increment in this file (-1 when the run ended before it), element_sets and
!>               joint_sets (the names of the sets, in the order of the masks)
!>   datasets    active_element_sets (nset) and active_joint_sets (njset, only with joint
!>               sets): 1 where the set is active during the phase, else 0.
!> A change line "initial procedure: <how>" also sets the root attribute initial_procedure.
!> A record is written with the phase's first increment (into both copies of the file, as the
!> increment), so that its first increment is known; a phase the run ended in before any
!> increment is written by `finish` with first_global_increment = -1.
module pecplas_io_results_phase_log
   use hdf5, only: hid_t
   use pecplas_base_error, only: error_t
   use pecplas_base_strings, only: itoa
   use pecplas_io_results_h5, only: h5_group, h5_close_group, h5_attr, h5_write, h5_exists
   implicit none (type, external)
   private

   public :: phase_record_t, write_phase_group, phase_group

   !> One phase: what write_phase was given, and where its increments start.
   type :: phase_record_t
      integer :: index = 0
      character(len=:), allocatable :: name
      !> The changes, one line each, joined by new_line('a') (a scalar: copies of records
      !> with deferred-length character array components are not reliable in gfortran).
      character(len=:), allocatable :: changes
      integer :: nchange = 0
      logical, allocatable :: active_esets(:), active_jsets(:)
      integer :: first_global_increment = -1, first_history_row = -1
      !> Not yet in the file (written with the next increment, or by `finish`).
      logical :: pending = .true.
   end type phase_record_t

contains

   !> Path of the group of phase `index`: /phases/<index>.
   pure function phase_group(index) result(path)
      integer, intent(in) :: index
      character(len=:), allocatable :: path
      path = '/phases/'//itoa(index)
   end function phase_group

   !> Writes `rec` as /phases/<index> of `file`; eset_names / jset_names are the set names
   !> in the order of the masks. A group of the same index already there (a step started
   !> again, e.g. after a restart inside it) is left as it is.
   subroutine write_phase_group(file, rec, eset_names, jset_names, error)
      integer(hid_t), intent(in) :: file
      type(phase_record_t), intent(in) :: rec
      character(len=*), intent(in) :: eset_names(:), jset_names(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: top, g
      if (h5_exists(file, phase_group(rec%index))) return
      top = -1
      if (.not. h5_exists(file, '/phases')) then
         call h5_group(file, 'phases', top, error)
         call h5_close_group(top)
         if (allocated(error)) return
      end if
      call h5_group(file, phase_group(rec%index), g, error)
      if (allocated(error)) return
      call h5_attr(g, 'index', rec%index, error)
      if (.not. allocated(error)) call h5_attr(g, 'name', rec%name, error)
      if (.not. allocated(error)) call h5_attr(g, 'changes', change_lines(rec), error)
      if (.not. allocated(error)) call h5_attr(g, 'first_global_increment', &
         rec%first_global_increment, error)
      if (.not. allocated(error)) call h5_attr(g, 'first_history_row', rec%first_history_row, &
         error)
      if (.not. allocated(error)) call h5_attr(g, 'element_sets', eset_names, error)
      if (.not. allocated(error)) call h5_attr(g, 'joint_sets', jset_names, error)
      if (.not. allocated(error) .and. size(rec%active_esets) > 0) call h5_write(g, &
         'active_element_sets', merge(1, 0, rec%active_esets), error)
      if (.not. allocated(error) .and. size(rec%active_jsets) > 0) call h5_write(g, &
         'active_joint_sets', merge(1, 0, rec%active_jsets), error)
      call h5_close_group(g)
      if (.not. allocated(error)) call write_procedure(file, rec, error)
   end subroutine write_phase_group

   !> A change line "initial procedure: <how>" (the driver's first line of the first phase)
   !> also goes into the root attribute `initial_procedure` (<how>: K0 procedure, gravity
   !> loading, none).
   subroutine write_procedure(file, rec, error)
      integer(hid_t), intent(in) :: file
      type(phase_record_t), intent(in) :: rec
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: KEY = 'initial procedure:'
      character(len=:), allocatable :: lines(:)
      integer :: i
      lines = change_lines(rec)
      do i = 1, size(lines)
         if (index(lines(i), KEY) /= 1) cycle
         call h5_attr(file, 'initial_procedure', trim(adjustl(lines(i)(len(KEY) + 1:))), error)
         return
      end do
   end subroutine write_procedure

   !> The changes of `rec` as a list of lines.
   function change_lines(rec) result(lines)
      type(phase_record_t), intent(in) :: rec
      character(len=:), allocatable :: lines(:)
      integer :: i, j, k
      allocate (character(len=max(1, len(rec%changes))) :: lines(rec%nchange))
      j = 1
      do i = 1, rec%nchange
         k = index(rec%changes(j:), new_line('a'))
         if (k == 0) then
            lines(i) = rec%changes(j:)
            j = len(rec%changes) + 1
         else
            lines(i) = rec%changes(j:j + k - 2)
            j = j + k
         end if
      end do
   end function change_lines

end module pecplas_io_results_phase_log
