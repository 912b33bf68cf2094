!> The serial OpenMP regions of a one-thread CHOLMOD factorisation (linalg/omp_serial.c): while
!> the flag is set, a parallel region runs on the calling thread alone; outside it, libgomp's
!> own team.
module test_linalg_omp_serial
   use pecplas_base_error, only: error_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use omp_lib, only: omp_get_dynamic, omp_set_dynamic, omp_get_num_threads, omp_get_thread_num
   use pecplas_linalg_cholmod, only: pecplas_omp_serial_begin, pecplas_omp_serial_end
   implicit none (type, external)
   private

   public :: collect_linalg_omp_serial

contains

   subroutine collect_linalg_omp_serial(testsuite)
      type(unittest_t), allocatable, intent(out) :: testsuite(:)
      testsuite = [new_unittest('serial_openmp_regions', test_omp_serial)]
   end subroutine collect_linalg_omp_serial

   !> A region asking for two threads: between begin and end it runs on this thread alone
   !> (one thread seen, its loop covers every index once: the sum is exact in integers);
   !> after end, libgomp runs it again with the two threads asked for (dynamic adjustment off,
   !> so the count does not depend on the load).
   subroutine test_omp_serial(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: seen(2), total(2), k, run
      logical :: dynamic
      character(len=120) :: msg
      dynamic = omp_get_dynamic()
      call omp_set_dynamic(.false.)
      do run = 1, 2
         if (run == 1) call pecplas_omp_serial_begin()
         seen(run) = 0
         total(run) = 0
         !$omp parallel num_threads(2) default(shared) private(k)
         if (omp_get_thread_num() == 0) seen(run) = omp_get_num_threads()
         !$omp do reduction(+:total)
         do k = 1, 1000
            total(run) = total(run) + k
         end do
         !$omp end do
         !$omp end parallel
         if (run == 1) call pecplas_omp_serial_end()
      end do
      call omp_set_dynamic(dynamic)
      write (msg, '(a,2(1x,i0),a,2(1x,i0))') 'threads serial, after:', seen, '; sums', total
      call check(error, all(seen == [1, 2]) .and. all(total == 500500), trim(msg))
   end subroutine test_omp_serial

end module test_linalg_omp_serial
