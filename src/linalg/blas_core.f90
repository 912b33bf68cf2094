!> OpenBLAS's kernels. An OpenBLAS built with DYNAMIC_ARCH chooses its kernels when it loads,
!> before the program starts, from OPENBLAS_CORETYPE or its own CPU detection; a version that
!> does not know the CPU falls back to its generic SSE kernels (Prescott), which take twice
!> the time of its AVX-512 kernels for a CHOLMOD factorisation (doc/bench/threads.md). At
!> start-up (blas_core_start, first statement of the programs that factorise) the program
!> therefore runs itself again, once, with OPENBLAS_CORETYPE set to the best kernels the CPU
!> supports when OpenBLAS reported a generic or old core (blas_core_choice);
!> PECPLAS_BLAS_CORE=keep keeps OpenBLAS's own choice (doc/build.md). The summary and the
!> results file say which kernels ran (blas_core_text).
module pecplas_linalg_blas_core
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   use pecplas_base_strings, only: same_name
   implicit none (type, external)
   private

   public :: blas_core_start, blas_core_choice, blas_core_source, blas_core_in_use

   !> Cores OpenBLAS names for CPUs it does not know (Unknown, and the fallback Prescott) or
   !> whose kernels use no AVX2/FMA: replaced when the CPU supports Haswell's or SkylakeX's.
   character(len=*), parameter :: OLD_CORES(18) = [character(len=13) :: 'Unknown', 'Katmai', &
      'Coppermine', 'Northwood', 'Prescott', 'Banias', 'Atom', 'Core2', 'Penryn', 'Dunnington', &
      'Nehalem', 'Athlon', 'Opteron', 'Opteron(SSE3)', 'Barcelona', 'Nano', 'Bobcat', &
      'Sandybridge']

   interface
      subroutine pecplas_blas_core_name(out, size) bind(C)
         import :: c_int, c_char
         character(kind=c_char), intent(out) :: out(*)
         integer(c_int), value :: size
      end subroutine
      integer(c_int) function pecplas_blas_core_dynamic() bind(C)
         import :: c_int
      end function
      integer(c_int) function pecplas_blas_core_level() bind(C)
         import :: c_int
      end function
      integer(c_int) function pecplas_blas_core_reexec(core, from) bind(C)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: core(*), from(*)
      end function
   end interface

contains

   !> The kernels to set through OPENBLAS_CORETYPE, '' for none: `core` is the core OpenBLAS
   !> reports ('' when the BLAS is not OpenBLAS), `dynamic` whether it was built with
   !> DYNAMIC_ARCH (else the variable does nothing), `level` what the CPU supports (2: AVX-512
   !> F/BW/DQ/VL with AVX2 and FMA, SkylakeX's kernels; 1: AVX2 and FMA, Haswell's; 0:
   !> neither); `coretype`, `setting` and `from` are the values of OPENBLAS_CORETYPE,
   !> PECPLAS_BLAS_CORE and PECPLAS_BLAS_CORE_FROM ('' when unset). None when the user chose
   !> (OPENBLAS_CORETYPE set, or PECPLAS_BLAS_CORE=keep), when the program already ran itself
   !> again (the marker PECPLAS_BLAS_CORE_FROM: never a second time), or when OpenBLAS's core
   !> is not one of OLD_CORES.
   pure function blas_core_choice(core, dynamic, level, coretype, setting, from) result(choice)
      character(len=*), intent(in) :: core, coretype, setting, from
      logical, intent(in) :: dynamic
      integer, intent(in) :: level
      character(len=:), allocatable :: choice
      integer :: i
      choice = ''
      if (len_trim(core) == 0 .or. .not. dynamic .or. len_trim(coretype) > 0 .or. &
         len_trim(from) > 0 .or. same_name(setting, 'keep') .or. level < 1) return
      if (.not. any([(same_name(OLD_CORES(i), core), i=1, size(OLD_CORES))])) return
      choice = merge('SkylakeX', 'Haswell ', level >= 2)
      choice = trim(choice)
   end function blas_core_choice

   !> Where OpenBLAS's kernels came from, for the summary and the results file: 'detected'
   !> (its own choice), 'OPENBLAS_CORETYPE=X' (set by the user) or 'OPENBLAS_CORETYPE=X set
   !> by pecplas over C' (this program ran itself again; OpenBLAS had detected C).
   pure function blas_core_source(coretype, from) result(text)
      character(len=*), intent(in) :: coretype, from
      character(len=:), allocatable :: text
      if (len_trim(coretype) == 0) then
         text = 'detected'
      else if (len_trim(from) > 0) then
         text = 'OPENBLAS_CORETYPE='//trim(coretype)//' set by pecplas over '//trim(from)
      else
         text = 'OPENBLAS_CORETYPE='//trim(coretype)
      end if
   end function blas_core_source

   !> The core whose kernels OpenBLAS runs and where that came from (blas_core_source); both
   !> '' when the BLAS is not OpenBLAS.
   subroutine blas_core_in_use(core, source)
      character(len=:), allocatable, intent(out) :: core, source
      core = blas_core_name()
      source = ''
      if (len(core) > 0) source = blas_core_source(env('OPENBLAS_CORETYPE'), &
         env('PECPLAS_BLAS_CORE_FROM'))
   end subroutine blas_core_in_use

   !> The core whose kernels OpenBLAS runs ('' when the BLAS is not OpenBLAS).
   function blas_core_name() result(name)
      character(len=:), allocatable :: name
      character(kind=c_char, len=64) :: buffer
      call pecplas_blas_core_name(buffer, 64_c_int)
      name = trim(buffer)
   end function blas_core_name

   !> Runs the program again with OPENBLAS_CORETYPE set when blas_core_choice says so; returns
   !> (with OpenBLAS's own kernels) when it does not, or when the re-execution fails. Call it
   !> first in the program, before MPI_Init and before anything is read or written.
   subroutine blas_core_start()
      character(len=:), allocatable :: core, choice
      integer(c_int) :: rc
      core = blas_core_name()
      if (len(core) == 0) return
      choice = blas_core_choice(core, pecplas_blas_core_dynamic() /= 0, &
         int(pecplas_blas_core_level()), env('OPENBLAS_CORETYPE'), env('PECPLAS_BLAS_CORE'), &
         env('PECPLAS_BLAS_CORE_FROM'))
      if (len(choice) == 0) return
      rc = pecplas_blas_core_reexec(choice//c_null_char, core//c_null_char)
   end subroutine blas_core_start

   !> Value of environment variable `name`, '' when unset.
   function env(name) result(value)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: value
      integer :: length, status
      call get_environment_variable(name, length=length, status=status)
      value = ''
      if (status /= 0 .or. length == 0) return
      value = repeat(' ', length)
      call get_environment_variable(name, value)
   end function env

end module pecplas_linalg_blas_core
