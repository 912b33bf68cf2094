!> OpenBLAS's kernels: the decision (OpenBLAS's core, its build, the CPU's features, the
!> environment) -> kernels to set or none, for CPUs OpenBLAS knows and does not know, with and
!> without AVX-512 and AVX2, and the user's choices; the source text of the summary.
module test_linalg_blas_core
   use pecplas_base_error, only: error_t
   use pecplas_linalg_blas_core, only: blas_core_choice, blas_core_source, blas_core_in_use
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_linalg_blas_core

   !> What the CPU supports (blas_core_choice's level).
   integer, parameter :: AVX512 = 2, AVX2 = 1, SSE = 0

contains

   subroutine collect_linalg_blas_core(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('unknown_cpu', test_unknown_cpu), &
               new_unittest('known_cpu', test_known_cpu), &
               new_unittest('user_and_build', test_user_and_build), &
               new_unittest('source_text', test_source_text)]
   end subroutine collect_linalg_blas_core

   !> OpenBLAS fell back to a generic or old core: the best kernels the CPU supports.
   subroutine test_unknown_cpu(error)
      type(error_t), allocatable, intent(out) :: error
      call check(error, blas_core_choice('Prescott', .true., AVX512, '', '', '') == 'SkylakeX', &
         'Prescott on an AVX-512 CPU: SkylakeX')
      if (allocated(error)) return
      call check(error, blas_core_choice('Prescott', .true., AVX2, '', '', '') == 'Haswell', &
         'Prescott on an AVX2+FMA CPU without AVX-512: Haswell')
      if (allocated(error)) return
      call check(error, blas_core_choice('Prescott', .true., SSE, '', '', '') == '', &
         'Prescott on a CPU without AVX2: kept')
      if (allocated(error)) return
      call check(error, blas_core_choice('Unknown', .true., AVX512, '', '', '') == 'SkylakeX', &
         'Unknown on an AVX-512 CPU: SkylakeX')
      if (allocated(error)) return
      call check(error, blas_core_choice('Sandybridge', .true., AVX2, '', '', '') == 'Haswell', &
         'Sandybridge (AVX only) on an AVX2+FMA CPU: Haswell')
      if (allocated(error)) return
      call check(error, blas_core_choice('Nehalem', .true., AVX512, '', 'auto', '') == &
         'SkylakeX', 'PECPLAS_BLAS_CORE other than keep: the program chooses')
   end subroutine test_unknown_cpu

   !> OpenBLAS recognised the CPU: its choice stays, whatever the CPU supports.
   subroutine test_known_cpu(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=16), parameter :: KNOWN(6) = [character(len=16) :: 'SkylakeX', &
         'Cooperlake', 'Haswell', 'Zen', 'Sapphire Rapids', 'Excavator']
      integer :: i
      do i = 1, size(KNOWN)
         call check(error, blas_core_choice(trim(KNOWN(i)), .true., AVX512, '', '', '') == '', &
            trim(KNOWN(i))//' on an AVX-512 CPU: kept')
         if (allocated(error)) return
      end do
   end subroutine test_known_cpu

   !> The user's choice, a BLAS that is not OpenBLAS or cannot switch, and the marker of a
   !> program that already ran itself again: no kernels set.
   subroutine test_user_and_build(error)
      type(error_t), allocatable, intent(out) :: error
      call check(error, blas_core_choice('Prescott', .true., AVX512, 'Haswell', '', '') == '', &
         'OPENBLAS_CORETYPE set by the user: kept')
      if (allocated(error)) return
      call check(error, blas_core_choice('Prescott', .true., AVX512, '', 'keep', '') == '', &
         'PECPLAS_BLAS_CORE=keep: kept')
      if (allocated(error)) return
      call check(error, blas_core_choice('Prescott', .true., AVX512, '', 'KEEP', '') == '', &
         'PECPLAS_BLAS_CORE=KEEP: kept')
      if (allocated(error)) return
      call check(error, blas_core_choice('Prescott', .true., AVX512, '', '', 'Prescott') == '', &
         'PECPLAS_BLAS_CORE_FROM set (second start): never again')
      if (allocated(error)) return
      call check(error, blas_core_choice('', .true., AVX512, '', '', '') == '', &
         'not OpenBLAS: nothing')
      if (allocated(error)) return
      call check(error, blas_core_choice('PRESCOTT', .false., AVX512, '', '', '') == '', &
         'OpenBLAS built for one core (no DYNAMIC_ARCH): OPENBLAS_CORETYPE would do nothing')
   end subroutine test_user_and_build

   subroutine test_source_text(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: core, source
      call check(error, blas_core_source('', '') == 'detected', 'no variable: detected')
      if (allocated(error)) return
      call check(error, blas_core_source('Haswell', '') == 'OPENBLAS_CORETYPE=Haswell', &
         'set by the user')
      if (allocated(error)) return
      call check(error, blas_core_source('SkylakeX', 'Prescott') == &
         'OPENBLAS_CORETYPE=SkylakeX set by pecplas over Prescott', 'set by the program')
      if (allocated(error)) return
      ! this process: a core with a source when the BLAS is OpenBLAS, neither otherwise
      call blas_core_in_use(core, source)
      call check(error, (len(core) > 0) .eqv. (len(source) > 0), 'core "'//core// &
         '" with source "'//source//'"')
   end subroutine test_source_text

end module test_linalg_blas_core
