!> The phases of a staged run in the results file (pecplas_io_results_phases): /phases/<k>
!> names each phase, its changes, its active sets and its first increment; an increment holds
!> no fields of a set not active in its phase, and the XDMF has no grid of it. The file is
!> left in output/test/io_results_phases.h5 for test/python/test_results_file.py, which reads
!> the changes (a list of strings) and plays the XDMF back.
module test_io_results_phases
   use pecplas_base_error, only: error_t
   use pecplas_base_run_status, only: RUN_COMPLETED, RUN_STOPPED
   use pecplas_testing, only: unittest_t, new_unittest, check
   use pecplas_model_type, only: model_t
   use pecplas_io_results_file, only: results_file_t
   use pecplas_io_results_increment, only: increment_result_t
   use pecplas_io_results_phases, only: write_phase
   use pecplas_io_results_reader, only: results_reader_t
   use test_io_results_data, only: sample_model, sample_gauss, sample_increment, OUT_DIR, &
      make_out_dir
   implicit none (type, external)
   private
   public :: collect_io_results_phases

contains

   subroutine collect_io_results_phases(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('phases_listed_and_masked', test_phases), &
               new_unittest('phase_with_no_increment', test_phase_without_increment), &
               new_unittest('phase_masks_checked', test_bad_masks)]
   end subroutine collect_io_results_phases

   !> Phase 1 (all active, increments 1-2), phase 2 removes LINING (increment 3), phase 3
   !> installs it again stress-free (increment 4, a nil step).
   subroutine test_phases(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: rf
      type(results_reader_t) :: rd
      type(model_t) :: model
      character(len=:), allocatable :: s, xmf
      integer, allocatable :: mask(:)
      integer :: n, k
      call make_out_dir(error)
      if (allocated(error)) return
      model = sample_model()
      call rf%create(OUT_DIR//'/io_results_phases.h5', model, '0.1.0-test', sample_gauss(), &
         error)
      if (allocated(error)) return
      call write_phase(rf, 1, 'geostatic', ['initial procedure: K0 procedure'], &
         [.true., .true.], [logical ::], error)
      if (allocated(error)) return
      do k = 1, 2
         call rf%write_increment(in_step(k, 1), error)
         if (allocated(error)) return
      end do
      call write_phase(rf, 2, 'excavate', ['DEACTIVATE LINING (1 element)'], [.true., .false.], &
         [logical ::], error)
      if (allocated(error)) return
      call rf%write_increment(in_step(3, 2), error)
      if (allocated(error)) return
      call write_phase(rf, 3, 'install', [character(len=30) :: 'ACTIVATE LINING, STRESS=ZERO', &
         'CHANGE_MATERIAL SOIL, clay2'], [.true., .true.], [logical ::], error)
      if (allocated(error)) return
      call rf%write_increment(in_step(4, 3), error)
      if (allocated(error)) return
      call rf%finish(RUN_COMPLETED, '', error)
      if (allocated(error)) return

      call rd%open(OUT_DIR//'/io_results_phases.h5', error)
      if (allocated(error)) return
      call rd%attribute('/', 'initial_procedure', s, error); if (allocated(error)) return
      call check(error, s == 'K0 procedure', 'root initial_procedure: '//s)
      if (allocated(error)) return
      call rd%attribute('/phases/2', 'name', s, error); if (allocated(error)) return
      call check(error, s == 'excavate', 'phase 2 name: '//s); if (allocated(error)) return
      call rd%attribute('/phases/1', 'first_global_increment', n, error)
      if (allocated(error)) return
      call check(error, n == 1, 'phase 1 starts at increment 1'); if (allocated(error)) return
      call rd%attribute('/phases/2', 'first_global_increment', n, error)
      if (allocated(error)) return
      call check(error, n == 3, 'phase 2 starts at increment 3'); if (allocated(error)) return
      call rd%attribute('/phases/3', 'first_history_row', n, error)
      if (allocated(error)) return
      call check(error, n == 4, 'phase 3 starts at history row 4'); if (allocated(error)) return
      call rd%dataset('/phases/2/active_element_sets', mask, error)
      if (allocated(error)) return
      call check(error, all(mask == [1, 0]), 'phase 2: SOIL active, LINING not')
      if (allocated(error)) return
      call check(error, .not. rd%exists('/phases/1/active_joint_sets'), &
         'no joint mask without joint sets')
      if (allocated(error)) return
      call check(error, rd%exists('/increments/000002/sets/LINING/stress') .and. &
         .not. rd%exists('/increments/000003/sets/LINING') .and. &
         rd%exists('/increments/000003/sets/SOIL/stress') .and. &
         rd%exists('/increments/000004/sets/LINING/stress'), &
         'fields of LINING in increments 2 and 4, none in 3 (removed)')
      if (allocated(error)) return
      call rd%close()

      call read_text(OUT_DIR//'/io_results_phases.xmf', xmf, error)
      if (allocated(error)) return
      ! SOIL in each of the 4 increments, LINING in 1, 2 and 4 (+ the topology references)
      call check(error, count_of(xmf, '<Grid Name="SOIL"') == 4 .and. &
         count_of(xmf, '<Grid Name="LINING"') == 3 .and. &
         count_of(xmf, '/increments/000003/sets/LINING') == 0, &
         'the XDMF shows LINING only in the increments of the phases it is active in')
   end subroutine test_phases

   !> A run that ends in a phase before any of its increments: the phase is listed, with
   !> first_global_increment = -1.
   subroutine test_phase_without_increment(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: rf
      type(results_reader_t) :: rd
      integer :: n
      call make_out_dir(error)
      if (allocated(error)) return
      call rf%create(OUT_DIR//'/io_results_phase_empty.h5', sample_model(), '0.1.0-test', &
         sample_gauss(), error)
      if (allocated(error)) return
      call rf%write_increment(sample_increment(1), error)
      if (allocated(error)) return
      call write_phase(rf, 2, 'nil', [character(len=1) ::], [.true., .true.], [logical ::], &
         error)
      if (allocated(error)) return
      call rf%finish(RUN_STOPPED, 'stopped in phase 2', error)
      if (allocated(error)) return
      call rd%open(OUT_DIR//'/io_results_phase_empty.h5', error)
      if (allocated(error)) return
      call rd%attribute('/phases/2', 'first_global_increment', n, error)
      if (allocated(error)) return
      call check(error, n == -1, 'a phase without increment has first_global_increment -1')
      if (allocated(error)) return
      call check(error, .not. rd%exists('/phases/1'), 'only the phases recorded are listed')
      call rd%close()
   end subroutine test_phase_without_increment

   !> Masks that do not match the model's sets are an error; nothing is recorded.
   subroutine test_bad_masks(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: rf
      type(error_t), allocatable :: e2
      call make_out_dir(error)
      if (allocated(error)) return
      call rf%create(OUT_DIR//'/io_results_phase_bad.h5', sample_model(), '0.1.0-test', &
         sample_gauss(), error)
      if (allocated(error)) return
      call write_phase(rf, 1, 'x', [character(len=1) ::], [.true.], [logical ::], e2)
      call check(error, allocated(e2), 'one element mask for two element sets is refused')
      if (allocated(error)) return
      call write_phase(rf, 0, 'x', [character(len=1) ::], [.true., .true.], [logical ::], e2)
      call check(error, allocated(e2), 'phase index 0 is refused')
      call rf%discard()
   end subroutine test_bad_masks

   !> sample_increment(k) as an increment of step `step` (the step is the phase).
   function in_step(k, step) result(inc)
      integer, intent(in) :: k, step
      type(increment_result_t) :: inc
      inc = sample_increment(k)
      inc%step = step
      inc%increment = k
      if (step > 1) inc%increment = 1
   end function in_step

   subroutine read_text(path, text, error)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: text
      type(error_t), allocatable, intent(out) :: error
      integer :: u, n, ios
      open (newunit=u, file=path, access='stream', form='unformatted', status='old', &
         action='read', iostat=ios)
      call check(error, ios == 0, 'cannot open '//path)
      if (allocated(error)) return
      inquire (unit=u, size=n)
      allocate (character(len=n) :: text)
      read (u, iostat=ios) text
      close (u)
      call check(error, ios == 0, 'cannot read '//path)
   end subroutine read_text

   integer function count_of(text, pattern) result(n)
      character(len=*), intent(in) :: text, pattern
      integer :: i, j
      n = 0
      i = 1
      do
         j = index(text(i:), pattern)
         if (j == 0) exit
         n = n + 1
         i = i + j + len(pattern) - 1
      end do
   end function count_of

end module test_io_results_phases
