!> The cap on the OpenMP regions of CHOLMOD's factorisation (linalg/omp_serial.c): while a cap
!> of one is set, a parallel region runs on the calling thread alone; a cap of n gives a
!> region at most n threads; outside it, libgomp's own team.
module test_linalg_omp_serial
   use pecplas_base_error, only: error_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use omp_lib, only: omp_get_dynamic, omp_set_dynamic, omp_get_num_threads, omp_get_thread_num
   use, intrinsic :: iso_c_binding, only: c_int
   use pecplas_linalg_cholmod, only: pecplas_omp_serial_begin, pecplas_omp_serial_end, &
      pecplas_omp_cap_begin, pecplas_omp_cap_end
   implicit none (type, external)
   private

   public :: collect_linalg_omp_serial

contains

   subroutine collect_linalg_omp_serial(testsuite)
      type(unittest_t), allocatable, intent(out) :: testsuite(:)
      testsuite = [new_unittest('serial_openmp_regions', test_omp_serial), &
                   new_unittest('capped_openmp_regions', test_omp_cap)]
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

   !> A region asking for three threads under a cap of two gets two (dynamic adjustment off,
   !> so the count does not depend on the load); one whose `if` clause is false runs on this
   !> thread alone under the cap; after the cap, three again. Every loop covers every index
   !> once: the sums are exact in integers.
   subroutine test_omp_cap(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: seen(3), total(3), k, run
      logical :: dynamic, yes
      character(len=120) :: msg
      dynamic = omp_get_dynamic()
      call omp_set_dynamic(.false.)
      yes = .true.
      do run = 1, 3
         if (run <= 2) call pecplas_omp_cap_begin(2_c_int)
         seen(run) = 0
         total(run) = 0
         !$omp parallel num_threads(3) default(shared) private(k) if (run /= 2 .and. yes)
         if (omp_get_thread_num() == 0) seen(run) = omp_get_num_threads()
         !$omp do reduction(+:total)
         do k = 1, 1000
            total(run) = total(run) + k
         end do
         !$omp end do
         !$omp end parallel
         if (run <= 2) call pecplas_omp_cap_end()
      end do
      call omp_set_dynamic(dynamic)
      write (msg, '(a,3(1x,i0),a,3(1x,i0))') 'threads capped, if false, after:', seen, &
         '; sums', total
      call check(error, all(seen == [2, 1, 3]) .and. all(total == 500500), trim(msg))
   end subroutine test_omp_cap

end module test_linalg_omp_serial
