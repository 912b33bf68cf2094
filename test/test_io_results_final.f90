!> The final increment of a run (results_file_t%write_increment with `final`): written into
!> the copy not published only. The published `.tmp` keeps the increment before (whole,
!> readable) until `finish` renames the copy with the final increment onto the target; a
!> run stopped without finish publishes that copy; no increment may follow a final one.
module test_io_results_final
   use pecplas_base_run_status, only: RUN_COMPLETED
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use pecplas_model_type, only: model_t
   use pecplas_io_results_increment, only: increment_result_t
   use pecplas_io_results_file, only: results_file_t, temporary_path
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_base_files, only: remove_file
   use test_io_results_data, only: sample_model, sample_gauss, sample_increment, &
      same_bits, OUT_DIR, make_out_dir, copy_file
   implicit none (type, external)
   private
   public :: collect_io_results_final

contains

   subroutine collect_io_results_final(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('final_into_one_copy', test_final_finish), &
               new_unittest('final_then_free_publishes', test_final_free)]
   end subroutine collect_io_results_final

   !> Creates OUT_DIR/name and writes increments 1..n-1, then n as the final one.
   subroutine write_final(rf, name, n, error)
      type(results_file_t), intent(inout) :: rf
      character(len=*), intent(in) :: name
      integer, intent(in) :: n
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      integer :: k
      call make_out_dir(error)
      if (allocated(error)) return
      model = sample_model()
      call rf%create(OUT_DIR//'/'//name, model, '0.1.0-test', sample_gauss(), error)
      do k = 1, n
         if (allocated(error)) return
         call rf%write_increment(sample_increment(k), error, final=k == n)
      end do
   end subroutine write_final

   !> Three increments, the third final: the published .tmp (its bytes copied as a kill
   !> would leave them) holds increments 1-2 and reads as a whole running file; a fourth
   !> increment is refused with a message naming the final one; finish renames the copy
   !> with all three increments onto the target and leaves no temporary file.
   subroutine test_final_finish(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: rf
      character(len=:), allocatable :: target, tmp, stem
      type(error_t), allocatable :: refused
      logical :: exists
      target = OUT_DIR//'/io_results_final_once.h5'
      tmp = temporary_path(target)
      stem = tmp(1:len(tmp) - 4)
      call write_final(rf, 'io_results_final_once.h5', 3, error)
      if (allocated(error)) return
      call copy_file(tmp, OUT_DIR//'/crash/io_results_final_once.h5', error)
      if (allocated(error)) return
      call check_rows(OUT_DIR//'/crash/io_results_final_once.h5', 'running', 2, error)
      if (allocated(error)) return
      call rf%write_increment(sample_increment(4), refused)
      call check(error, allocated(refused), 'an increment after the final one is refused')
      if (allocated(error)) return
      call check(error, index(refused%text(), 'after the final one') > 0, &
         'the refusal names the final increment: '//refused%text())
      if (allocated(error)) return
      call rf%finish(RUN_COMPLETED, 'normal end', error)
      if (allocated(error)) return
      call check_rows(target, 'completed', 3, error)
      if (allocated(error)) return
      inquire (file=tmp, exist=exists)
      call check(error, .not. exists, 'finish leaves '//tmp)
      if (allocated(error)) return
      inquire (file=stem//'.a', exist=exists)
      if (.not. exists) inquire (file=stem//'.b', exist=exists)
      call check(error, .not. exists, 'finish leaves a copy '//stem//'.a/.b')
      call remove_file(OUT_DIR//'/crash/io_results_final_once.h5')
   end subroutine test_final_finish

   !> A run stopped after its final increment without finish (free): the copy with the
   !> final increment is published, so the .tmp holds both increments, and the running
   !> sidecar lists both.
   subroutine test_final_free(error)
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: rf
      character(len=:), allocatable :: tmp, xmf
      tmp = temporary_path(OUT_DIR//'/io_results_final_free.h5')
      xmf = temporary_path(OUT_DIR//'/io_results_final_free.xmf')
      call write_final(rf, 'io_results_final_free.h5', 2, error)
      if (allocated(error)) return
      call rf%free()
      call check_rows(tmp, 'running', 2, error)
      if (allocated(error)) return
      call check(error, count_in(xmf, ':/increments/') > 0 .and. &
         count_in(xmf, ':/increments/000002/') > 0, &
         'the running sidecar lists the final increment after free')
      call remove_file(tmp)
      call remove_file(xmf)
   end subroutine test_final_free

   !> `path` has status `status` and exactly `nrow` history rows, the displacement of each
   !> bit for bit the one written (increments 1..nrow).
   subroutine check_rows(path, status, nrow, error)
      character(len=*), intent(in) :: path, status
      integer, intent(in) :: nrow
      type(error_t), allocatable, intent(out) :: error
      type(results_reader_t) :: rd
      type(increment_result_t) :: inc
      character(len=:), allocatable :: s
      real(wp), allocatable :: u(:, :)
      integer :: n, k
      call rd%open(path, error); if (allocated(error)) return
      call rd%attribute('/', 'status', s, error); if (allocated(error)) return
      call check(error, s == status, path//': status '//s); if (allocated(error)) return
      call rd%history_length(n, error); if (allocated(error)) return
      call check(error, n == nrow, path//': history rows'); if (allocated(error)) return
      do k = 1, nrow
         call rd%displacement(k, u, error); if (allocated(error)) return
         inc = sample_increment(k)
         call check(error, same_bits(u, inc%displacement), path//': displacement written')
         if (allocated(error)) return
      end do
      call check(error, .not. rd%exists('/increments/'//repeat('0', 5)//achar(48 + nrow + 1)), &
         path//': no increment beyond the last row')
   end subroutine check_rows

   !> Lines of text file `path` containing `what` (0 when the file cannot be read).
   integer function count_in(path, what) result(n)
      character(len=*), intent(in) :: path, what
      character(len=1024) :: line
      integer :: u, ios
      n = 0
      open (newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) return
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (index(line, what) > 0) n = n + 1
      end do
      close (u)
   end function count_in

end module test_io_results_final
