!> Results file round trips: what the writer puts in is what the HDF5 API reads back,
!> bit for bit for doubles (written and read as IEEE doubles, no conversion); a run that
!> stops without `finish` never claims completion. The files are left in output/test/
!> for test/python/test_results_file.py (h5py + XDMF checker).
module test_io_results
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use pecplas_base_run_status, only: RUN_COMPLETED, RUN_FAILED, RUN_LIMIT_LOAD, RUN_NOT_RUN
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use pecplas_model_type, only: model_t
   use pecplas_io_results_increment, only: increment_result_t, gauss_coordinates_t
   use pecplas_io_results_file, only: results_file_t, temporary_path
   use pecplas_base_files, only: rename_file, remove_file, path_base, same_file
   use pecplas_io_results_reader, only: results_reader_t
   use test_io_results_data, only: sample_model, sample_gauss, sample_increment, &
      same_bits, OUT_DIR, make_out_dir, copy_file
   implicit none (type, external)
   private
   public :: collect_io_results

contains

   subroutine collect_io_results(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('round_trip', test_round_trip), &
               new_unittest('crash_keeps_increments', test_crash), &
               new_unittest('two_copies_one_published', test_two_copies), &
               new_unittest('limit_load_not_complete', test_limit_load), &
               new_unittest('refuses_bad_input', test_refuses), &
               new_unittest('finaliser_keeps_running', test_finaliser), &
               new_unittest('no_load_pattern', test_no_pattern)]
   end subroutine collect_io_results

   !> Creates `name` in OUT_DIR and writes global increments first..last with fields.
   subroutine write_sample(rf, name, first, last, error)
      type(results_file_t), intent(inout) :: rf
      character(len=*), intent(in) :: name
      integer, intent(in) :: first, last
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      integer :: k
      call make_out_dir(error)
      if (allocated(error)) return
      model = sample_model()
      call rf%create(OUT_DIR//'/'//name, model, '0.1.0-test', sample_gauss(), error)
      do k = first, last
         if (allocated(error)) return
         call rf%write_increment(sample_increment(k), error)
      end do
   end subroutine write_sample

   subroutine test_round_trip(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: rf
      type(results_reader_t) :: rd
      type(model_t) :: model
      type(gauss_coordinates_t), allocatable :: gxy(:)
      character(len=:), allocatable :: s
      integer, allocatable :: iv(:), im(:, :)
      real(wp), allocatable :: r1(:), r2(:, :), r3(:, :, :), expected(:)
      type(increment_result_t) :: incs(3)
      integer :: k, n
      do k = 1, 3
         incs(k) = sample_increment(k)
      end do
      call write_sample(rf, 'io_results_completed.h5', 1, 3, error)
      if (allocated(error)) return
      call rf%finish(RUN_COMPLETED, 'normal end', error)
      if (allocated(error)) return
      call check(error, .not. rf%is_open(), 'finish closes the file')
      if (allocated(error)) return
      model = sample_model()
      allocate (gxy, source=sample_gauss())
      call rd%open(OUT_DIR//'/io_results_completed.h5', error)
      if (allocated(error)) return

      ! provenance and status (strings compared exactly, deck text with newlines and UTF-8)
      call rd%attribute('/', 'program', s, error); if (allocated(error)) return
      call check(error, s == 'PECPLAS', 'program attribute: '//s); if (allocated(error)) return
      call rd%attribute('/', 'version', s, error); if (allocated(error)) return
      call check(error, s == '0.1.0-test', 'version: '//s); if (allocated(error)) return
      call rd%attribute('/', 'deck_text', s, error); if (allocated(error)) return
      call check(error, s == model%deck_text, 'deck text round trip'); if (allocated(error)) return
      call rd%attribute('/', 'analysis', s, error); if (allocated(error)) return
      call check(error, s == 'plane strain', 'analysis: '//s); if (allocated(error)) return
      call rd%attribute('/', 'status', s, error); if (allocated(error)) return
      call check(error, s == 'completed', 'status: '//s); if (allocated(error)) return
      call rd%attribute('/', 'status_message', s, error); if (allocated(error)) return
      call check(error, s == 'normal end', 'status_message: '//s); if (allocated(error)) return
      call rd%attribute('/', 'complete', n, error); if (allocated(error)) return
      call check(error, n == 1, 'complete = 1 after finish(completed)')
      if (allocated(error)) return
      call rd%attribute('/', 'completed', s, error); if (allocated(error)) return
      call check(error, len(s) == 25 .and. s(5:5) == '-' .and. s(11:11) == 'T', &
         'completed timestamp in ISO 8601: '//s)
      if (allocated(error)) return

      ! mesh
      call rd%dataset('/mesh/coordinates', r2, error); if (allocated(error)) return
      call check(error, same_bits(r2, model%mesh%x), 'coordinates bitwise')
      if (allocated(error)) return
      call rd%dataset('/mesh/node_ids', iv, error); if (allocated(error)) return
      call check(error, all(iv == model%mesh%node_id), 'node ids'); if (allocated(error)) return
      call rd%dataset('/mesh/sets/SOIL/connectivity', im, error); if (allocated(error)) return
      call check(error, all(im == model%mesh%esets(1)%conn - 1), 'connectivity is 0-based')
      if (allocated(error)) return
      call rd%dataset('/mesh/sets/LINING/gauss_coordinates', r3, error)
      if (allocated(error)) return
      call check(error, same_bits(r3, gxy(2)%xy), 'Gauss coordinates bitwise')
      if (allocated(error)) return
      call rd%attribute('/mesh/sets/LINING', 'etype', s, error); if (allocated(error)) return
      call check(error, s == 'T3', 'etype attribute: '//s); if (allocated(error)) return
      call rd%dataset('/mesh/node_sets/BASE/nodes', iv, error); if (allocated(error)) return
      call check(error, all(iv == [0, 1, 2]), 'node set 0-based'); if (allocated(error)) return
      call rd%dataset('/mesh/edge_sets/TOP/nodes', im, error); if (allocated(error)) return
      call check(error, all(im == reshape([5, 4, 4, 3], [2, 2])), 'edge set 0-based')
      if (allocated(error)) return

      ! history: 3 rows, reals bitwise
      call rd%history_length(n, error); if (allocated(error)) return
      call check(error, n == 3, 'history has 3 rows'); if (allocated(error)) return
      call rd%dataset('/history/step', iv, error); if (allocated(error)) return
      call check(error, all(iv == [1, 1, 2]), 'history step'); if (allocated(error)) return
      call rd%dataset('/history/time', r1, error); if (allocated(error)) return
      expected = incs%time
      call check(error, same_bits(r1, expected), 'history time')
      if (allocated(error)) return
      call rd%dataset('/history/residual', r1, error); if (allocated(error)) return
      expected = incs%residual
      call check(error, same_bits(r1, expected), 'residual')
      if (allocated(error)) return
      call rd%dataset('/history/pattern_factors', r2, error); if (allocated(error)) return
      call check(error, size(r2, 1) == 2 .and. size(r2, 2) == 3, 'pattern_factors (2, 3)')
      if (allocated(error)) return
      do k = 1, 3
         call check(error, same_bits(r2(:, k), incs(k)%pattern_factors), &
            'pattern factors row')
         if (allocated(error)) return
      end do

      ! fields of each increment
      do k = 1, 3
         call check_fields(rd, k, error)
         if (allocated(error)) return
      end do
      call rd%close()
      call check_xdmf(OUT_DIR//'/io_results_completed.xmf', 'io_results_completed.h5', 3, error)
   end subroutine test_round_trip

   !> Fields of global increment k equal sample_increment(k).
   subroutine check_fields(rd, k, error)
      type(results_reader_t), intent(in) :: rd
      integer, intent(in) :: k
      type(error_t), allocatable, intent(out) :: error
      type(increment_result_t) :: inc
      real(wp), allocatable :: r2(:, :), r3(:, :, :), mean(:, :)
      character(len=:), allocatable :: g
      character(len=32) :: buf
      real(wp) :: t
      integer :: i, e, c
      character(len=*), parameter :: SETS(2) = [character(len=6) :: 'SOIL', 'LINING']
      inc = sample_increment(k)
      write (buf, '(a,i6.6)') '/increments/', k
      g = trim(buf)
      call rd%displacement(k, r2, error); if (allocated(error)) return
      call check(error, same_bits(r2, inc%displacement), 'displacement bitwise, increment '//g)
      if (allocated(error)) return
      call rd%dataset(g//'/displacement3', r2, error); if (allocated(error)) return
      call check(error, same_bits(r2(1:2, :), inc%displacement) .and. &
         same_bits(r2(3, :), spread(0.0_wp, 1, size(r2, 2))), 'displacement3 = (u, +0)')
      if (allocated(error)) return
      call rd%dataset(g//'/reaction', r2, error); if (allocated(error)) return
      call check(error, same_bits(r2, inc%reaction), 'reaction bitwise'); if (allocated(error)) return
      call rd%attribute(g, 'time', t, error); if (allocated(error)) return
      call check(error, same_bits([t], [inc%time]), 'time attribute'); if (allocated(error)) return
      do i = 1, 2
         call rd%dataset(g//'/sets/'//trim(SETS(i))//'/stress', r3, error)
         if (allocated(error)) return
         call check(error, same_bits(r3, inc%set_fields(i)%stress), 'stress bitwise')
         if (allocated(error)) return
         call rd%dataset(g//'/sets/'//trim(SETS(i))//'/strain', r3, error)
         if (allocated(error)) return
         call check(error, same_bits(r3, inc%set_fields(i)%strain), 'strain bitwise')
         if (allocated(error)) return
         call rd%dataset(g//'/sets/'//trim(SETS(i))//'/stress_mean', mean, error)
         if (allocated(error)) return
         do e = 1, size(mean, 2)
            do c = 1, 4
               ! mean of <= 4 Gauss values: a few roundings at most
               call check_close(error, mean(c, e), sum(inc%set_fields(i)%stress(c, :, e))/ &
                  size(inc%set_fields(i)%stress, 2), 4*epsilon(1.0_wp), 'stress_mean')
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine check_fields

   !> The .xmf exists, names the .h5 by its base name and has one <Time> per increment.
   subroutine check_xdmf(path, h5, nincrement, error)
      character(len=*), intent(in) :: path, h5
      integer, intent(in) :: nincrement
      type(error_t), allocatable, intent(out) :: error
      character(len=512) :: line
      integer :: u, ios, ntime
      logical :: found_last
      character(len=16) :: last
      write (last, '(i6.6)') nincrement
      open (newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) then
         call fatal_error(error, 'no XDMF file '//path)
         return
      end if
      ntime = 0
      found_last = .false.
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (index(line, '<Time ') > 0) ntime = ntime + 1
         if (index(line, h5//':/increments/'//trim(last)//'/displacement3<') > 0) &
            found_last = .true.
      end do
      close (u)
      call check(error, ntime == nincrement .and. found_last, &
         'XDMF has one time per increment and references the last displacement3')
   end subroutine check_xdmf

   !> A writer that stops after 2 increments without finish: the bytes on disk (copied
   !> while the file is still open, as a crash would leave them) and the file closed by
   !> free both read as status 'running', complete = 0, with both increments; they stay
   !> under the temporary name (with a sidecar listing both) and the target is not created.
   !> The temporary file is then renamed for test/python/test_results_file.py.
   subroutine test_crash(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: rf
      character(len=:), allocatable :: target, tmp
      logical :: exists
      target = OUT_DIR//'/io_results_running.h5'
      tmp = temporary_path(target)
      call remove_file(target)
      call write_sample(rf, 'io_results_running.h5', 1, 2, error)
      if (allocated(error)) return
      call check(error, rf%working_path() == tmp, 'working path '//rf%working_path())
      if (allocated(error)) return
      call copy_file(tmp, OUT_DIR//'/crash/io_results_running.h5', error)
      if (allocated(error)) return
      call check_running(OUT_DIR//'/crash/io_results_running.h5', 2, error)
      if (allocated(error)) return
      call rf%free()
      call check_running(tmp, 2, error)
      if (allocated(error)) return
      inquire (file=target, exist=exists)
      call check(error, .not. exists, 'a run that did not finish leaves the target alone')
      if (allocated(error)) return
      call check_xdmf(temporary_path(OUT_DIR//'/io_results_running.xmf'), path_base(tmp), 2, &
         error)
      if (allocated(error)) return
      call remove_file(temporary_path(OUT_DIR//'/io_results_running.xmf'))
      call check(error, rename_file(tmp, target), 'rename '//tmp)
   end subroutine test_crash

   !> Between increments both copies of a running file hold every increment (their bytes,
   !> copied as a kill would leave them, read back with all rows), the published name .tmp
   !> is the same file as one of them, and `finish` leaves no temporary name behind.
   subroutine test_two_copies(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: rf
      character(len=:), allocatable :: tmp, stem
      character(len=*), parameter :: SUFFIX(3) = ['.a  ', '.b  ', '.new']
      logical :: exists
      integer :: i
      tmp = temporary_path(OUT_DIR//'/io_results_copies.h5')
      stem = tmp(1:len(tmp) - 4)
      call write_sample(rf, 'io_results_copies.h5', 1, 3, error)
      if (allocated(error)) return
      call check(error, same_file(tmp, stem//'.a') .neqv. same_file(tmp, stem//'.b'), &
         tmp//' must be another name of exactly one copy')
      do i = 1, 2
         if (allocated(error)) return
         call copy_file(stem//trim(SUFFIX(i)), OUT_DIR//'/crash/io_results_copy'// &
            SUFFIX(i)(2:2)//'.h5', error)
         if (allocated(error)) return
         call check_running(OUT_DIR//'/crash/io_results_copy'//SUFFIX(i)(2:2)//'.h5', 3, error)
      end do
      if (allocated(error)) return
      call rf%finish(RUN_COMPLETED, 'normal end', error)
      if (allocated(error)) return
      do i = 1, 3
         inquire (file=stem//trim(SUFFIX(i)), exist=exists)
         call check(error, .not. exists, 'finish leaves '//stem//trim(SUFFIX(i)))
         if (allocated(error)) return
      end do
      inquire (file=tmp, exist=exists)
      call check(error, .not. exists, 'finish leaves '//tmp)
      call remove_file(OUT_DIR//'/crash/io_results_copya.h5')
      call remove_file(OUT_DIR//'/crash/io_results_copyb.h5')
   end subroutine test_two_copies

   subroutine check_running(path, nrow, error)
      character(len=*), intent(in) :: path
      integer, intent(in) :: nrow
      type(error_t), allocatable, intent(out) :: error
      type(results_reader_t) :: rd
      character(len=:), allocatable :: s
      real(wp), allocatable :: u(:, :)
      type(increment_result_t) :: inc
      integer :: n, k
      call rd%open(path, error); if (allocated(error)) return
      call rd%attribute('/', 'status', s, error); if (allocated(error)) return
      call check(error, s == 'running', path//': status '//s); if (allocated(error)) return
      call rd%attribute('/', 'complete', n, error); if (allocated(error)) return
      call check(error, n == 0, path//': complete must stay 0'); if (allocated(error)) return
      call rd%history_length(n, error); if (allocated(error)) return
      call check(error, n == nrow, path//': history rows'); if (allocated(error)) return
      do k = 1, nrow
         call rd%displacement(k, u, error); if (allocated(error)) return
         inc = sample_increment(k)
         call check(error, same_bits(u, inc%displacement), &
            path//': displacement of a flushed increment')
         if (allocated(error)) return
      end do
   end subroutine check_running

   !> finish('limit load') keeps complete = 0; a history-only row has no field group.
   subroutine test_limit_load(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: rf
      type(results_reader_t) :: rd
      type(increment_result_t) :: inc
      character(len=:), allocatable :: s
      integer, allocatable :: fields(:)
      integer :: n
      call write_sample(rf, 'io_results_limit.h5', 1, 1, error)
      if (allocated(error)) return
      inc = sample_increment(2)
      inc%write_fields = .false.
      call rf%write_increment(inc, error); if (allocated(error)) return
      call rf%finish(RUN_LIMIT_LOAD, 'no convergence after 5 cuts', error)
      if (allocated(error)) return
      call rd%open(OUT_DIR//'/io_results_limit.h5', error); if (allocated(error)) return
      call rd%attribute('/', 'status', s, error); if (allocated(error)) return
      call check(error, s == 'limit load', 'status: '//s); if (allocated(error)) return
      call rd%attribute('/', 'complete', n, error); if (allocated(error)) return
      call check(error, n == 0, 'limit load is not complete'); if (allocated(error)) return
      call check(error, .not. rd%has_attribute('/', 'completed'), 'no completed timestamp')
      if (allocated(error)) return
      call rd%dataset('/history/fields', fields, error); if (allocated(error)) return
      call check(error, size(fields) == 2 .and. all(fields == [1, 0]), 'fields flags [1, 0]')
      if (allocated(error)) return
      call check(error, rd%exists('/increments/000001/displacement') .and. &
         .not. rd%exists('/increments/000002'), 'no field group for a history-only row')
   end subroutine test_limit_load

   !> NaN in a field and an unknown status are errors that leave the file unchanged.
   subroutine test_refuses(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(results_file_t) :: rf
      type(results_reader_t) :: rd
      type(increment_result_t) :: inc
      character(len=:), allocatable :: s
      integer :: n
      call write_sample(rf, 'io_results_failed.h5', 1, 1, error)
      if (allocated(error)) return
      inc = sample_increment(2)
      inc%set_fields(2)%stress(3, 1, 1) = ieee_value(1.0_wp, ieee_quiet_nan)
      call rf%write_increment(inc, e)
      call check(error, allocated(e), 'NaN stress must be refused'); if (allocated(error)) return
      call check(error, index(e%text(), 'stress of set LINING') > 0, 'message names the field: ' &
         //e%text())
      if (allocated(error)) return
      inc = sample_increment(2)
      deallocate (inc%reaction)
      call rf%write_increment(inc, e)
      call check(error, allocated(e), 'missing reaction must be refused')
      if (allocated(error)) return
      call rf%finish(RUN_NOT_RUN, '', e)
      call check(error, allocated(e) .and. rf%is_open(), 'unknown status refused, file open')
      if (allocated(error)) return
      call rf%finish(RUN_FAILED, 'NaN in the stress of set LINING', error)
      if (allocated(error)) return
      call rd%open(OUT_DIR//'/io_results_failed.h5', error); if (allocated(error)) return
      call rd%history_length(n, error); if (allocated(error)) return
      call check(error, n == 1 .and. .not. rd%exists('/increments/000002'), &
         'refused increments leave no trace')
      if (allocated(error)) return
      call rd%attribute('/', 'status', s, error); if (allocated(error)) return
      call check(error, s == 'failed', 'status: '//s)
   end subroutine test_refuses

   !> Deallocating an open writer (finaliser) closes it without marking it complete.
   subroutine test_finaliser(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t), allocatable :: rf
      character(len=:), allocatable :: tmp
      tmp = temporary_path(OUT_DIR//'/io_results_final.h5')
      allocate (rf)
      call write_sample(rf, 'io_results_final.h5', 1, 1, error)
      if (allocated(error)) return
      deallocate (rf)
      call check_running(tmp, 1, error)
      if (allocated(error)) return
      ! HDF5 refuses to truncate a file that is still open: this proves the close
      allocate (rf)
      call write_sample(rf, 'io_results_final.h5', 1, 1, error)
      if (allocated(error)) return
      call rf%free()
      call remove_file(temporary_path(OUT_DIR//'/io_results_final.xmf'))
      call check(error, rename_file(tmp, OUT_DIR//'/io_results_final.h5'), 'rename '//tmp)
   end subroutine test_finaliser

   !> A model without load patterns (an empty pattern_factors column set) and a writer
   !> object reused for a second file.
   subroutine test_no_pattern(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: rf
      type(results_reader_t) :: rd
      type(model_t) :: model
      type(increment_result_t) :: inc
      real(wp), allocatable :: factors(:, :)
      integer :: n
      logical :: exists
      call write_sample(rf, 'io_results_scratch.h5', 1, 1, error)
      if (allocated(error)) return
      call rf%discard()
      model = sample_model()
      deallocate (model%patterns)
      call rf%create(OUT_DIR//'/io_results_nopattern.h5', model, '0.1.0-test', sample_gauss(), &
         error)
      if (allocated(error)) return
      inc = sample_increment(1)
      deallocate (inc%pattern_factors)
      call rf%write_increment(inc, error); if (allocated(error)) return
      inc = sample_increment(2)
      deallocate (inc%pattern_factors)
      call rf%write_increment(inc, error); if (allocated(error)) return
      call rf%finish(RUN_COMPLETED, '', error); if (allocated(error)) return
      call rd%open(OUT_DIR//'/io_results_nopattern.h5', error); if (allocated(error)) return
      call rd%dataset('/history/pattern_factors', factors, error); if (allocated(error)) return
      call check(error, size(factors, 1) == 0 .and. size(factors, 2) == 2, &
         'pattern_factors of shape (0, 2)')
      if (allocated(error)) return
      call rd%attribute('/', 'complete', n, error); if (allocated(error)) return
      call check(error, n == 1, 'completed without patterns')
      if (allocated(error)) return
      inquire (file=temporary_path(OUT_DIR//'/io_results_nopattern.h5'), exist=exists)
      call check(error, .not. exists, 'finish renamed the temporary file onto the target')
      if (allocated(error)) return
      inquire (file=temporary_path(OUT_DIR//'/io_results_nopattern.xmf'), exist=exists)
      call check(error, .not. exists, 'finish removed the temporary sidecar')
   end subroutine test_no_pattern

end module test_io_results
