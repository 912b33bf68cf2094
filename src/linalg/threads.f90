!> Thread control of a run. The setting n is the deck's *SOLVER, THREADS=n when given, else
!> OMP_NUM_THREADS, else 1: a run neither oversubscribes a shared machine nor depends on
!> library defaults. From n the program decides what each part gets (doc/deck.md, THREADS):
!> the OpenMP team of the element loops, the threads of the parallel regions CHOLMOD opens
!> in its supernodal factorisation (omp_serial.c), and the BLAS threads under it (OpenBLAS,
!> BLIS or MKL, set through threads_shim.c). Results of the element loops do not depend on it (each element writes its own rows;
!> nodal sums are serial, in a fixed order); the threaded BLAS rounds differently.
module pecplas_linalg_threads
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_char, c_f_pointer, &
      c_associated
   use pecplas_base_strings, only: itoa
   use pecplas_linalg_blas_core, only: blas_core_in_use
   implicit none (type, external)
   private

   public :: thread_setting_t, resolve_threads, apply_threads, openmp_threads
   public :: PARALLEL_MIN_ELEMENTS, parts_text

   !> Element loops shorter than this run serially: a parallel region costs a few
   !> microseconds on an idle machine (a scheduler time slice on a loaded one), more than
   !> the work of a few dozen elements.
   integer, parameter :: PARALLEL_MIN_ELEMENTS = 64

   !> The thread setting of a run, as printed in the summary and stored in the results.
   type :: thread_setting_t
      !> Number of threads (>= 1).
      integer :: n = 1
      !> Where it came from: 'deck', 'OMP_NUM_THREADS' or 'default'.
      character(len=:), allocatable :: source
      !> BLAS whose threads were set ('OpenBLAS', 'BLIS', 'MKL'), '' when none was found.
      character(len=:), allocatable :: blas
      !> False when the program was built without OpenMP (element loops then serial).
      logical :: openmp = .false.
      !> Threads of the program's element loops (the OpenMP team).
      integer :: loops = 1
      !> Threads of the parallel regions of CHOLMOD's factorisation (1: run as plain code).
      integer :: regions = 1
      !> Most threads one BLAS call under CHOLMOD gets.
      integer :: blas_threads = 1
      !> Flops per BLAS thread of a call under CHOLMOD (0: every call gets blas_threads).
      real :: blas_work = 0.0
      !> Where the parts came from: 'rule' (decide_parts) or 'PECPLAS_THREAD_PARTS'.
      character(len=:), allocatable :: parts_source
      !> How the BLAS threads: 'pthreads', 'OpenMP', 'none' or '' (not known).
      character(len=:), allocatable :: blas_threading
      !> Core whose kernels OpenBLAS runs ('SkylakeX', 'Haswell', 'Prescott', ...; '' when the
      !> BLAS is not OpenBLAS) and where that came from (blas_core_source).
      character(len=:), allocatable :: blas_core, blas_core_source
   end type thread_setting_t

   interface
      integer(c_int) function pecplas_threads_configure(loops, regions, blas, work) bind(C)
         import :: c_int, c_double
         integer(c_int), value :: loops, regions, blas
         real(c_double), value :: work
      end function
      type(c_ptr) function pecplas_threads_blas_threading() bind(C)
         import :: c_ptr
      end function
      type(c_ptr) function pecplas_threads_blas_name(k) bind(C)
         import :: c_ptr, c_int
         integer(c_int), value :: k
      end function
      integer(c_int) function pecplas_threads_openmp() bind(C)
         import :: c_int
      end function
      integer(c_int) function pecplas_threads_max() bind(C)
         import :: c_int
      end function
   end interface

contains

   !> The setting for a deck value `deck_threads` (0: not given in the deck), with the parts
   !> decided from it (see decide_parts).
   function resolve_threads(deck_threads) result(setting)
      integer, intent(in) :: deck_threads
      type(thread_setting_t) :: setting
      character(len=32) :: text
      integer :: n, length, status, ios
      setting%n = 1
      setting%source = 'default'
      setting%blas = ''
      setting%blas_threading = ''
      if (deck_threads > 0) then
         setting%n = deck_threads
         setting%source = 'deck'
      else
         call get_environment_variable('OMP_NUM_THREADS', text, length, status)
         if (status == 0 .and. length > 0) then
            ! OMP_NUM_THREADS may list one count per nesting level ("2,1"): the first applies
            if (index(text, ',') > 0) text = text(:index(text, ',') - 1)
            read (text, *, iostat=ios) n
            if (ios == 0 .and. n >= 1) then
               setting%n = n
               setting%source = 'OMP_NUM_THREADS'
            end if
         end if
      end if
      call decide_parts(setting)
   end function resolve_threads

   !> The threads of each part for the setting n, as measured on a 16-core node
   !> (doc/bench/threads.md): the element loops get n; CHOLMOD's parallel regions (clearing
   !> and assembling supernodes, memory-bound) run as plain code on the calling thread: a
   !> team for them made the factorisation 1.5 to 2 times slower at 16 threads than plain
   !> code, since its threads take the cores the BLAS threads need; every BLAS call under
   !> CHOLMOD gets n threads (giving small calls fewer paid nothing with OpenBLAS's pthreads
   !> build and cost 2.4 times with its OpenMP build). PECPLAS_THREAD_PARTS="R,B,W" sets the
   !> regions' threads R, the BLAS's B and W > 0 flops per BLAS thread of a call (a call of w
   !> flops then gets min(B, max(1, floor(w/W))) threads; 0: every call gets B) instead, for
   !> benchmarks; a malformed value is ignored.
   subroutine decide_parts(setting)
      type(thread_setting_t), intent(inout) :: setting
      character(len=64) :: text
      integer :: length, status, ios, r, b
      real :: w
      setting%loops = setting%n
      setting%regions = 1
      setting%blas_threads = setting%n
      setting%blas_work = 0.0
      setting%parts_source = 'rule'
      call get_environment_variable('PECPLAS_THREAD_PARTS', text, length, status)
      if (status /= 0 .or. length == 0) return
      read (text, *, iostat=ios) r, b, w
      ! a failed read leaves r, b, w undefined: tested apart, not in one expression with them
      if (ios /= 0) return
      if (r < 1 .or. b < 1 .or. w < 0.0) return
      setting%regions = r
      setting%blas_threads = b
      setting%blas_work = w
      setting%parts_source = 'PECPLAS_THREAD_PARTS'
   end subroutine decide_parts

   !> Applies `setting` to OpenMP, CHOLMOD's regions and the BLAS; records the BLAS found,
   !> how it threads, OpenBLAS's kernels and whether OpenMP is on.
   subroutine apply_threads(setting)
      type(thread_setting_t), intent(inout) :: setting
      integer(c_int) :: k
      if (.not. allocated(setting%parts_source)) call decide_parts(setting)
      k = pecplas_threads_configure(int(setting%loops, c_int), int(setting%regions, c_int), &
         int(setting%blas_threads, c_int), real(setting%blas_work, c_double))
      setting%blas = c_text(pecplas_threads_blas_name(k))
      setting%blas_threading = c_text(pecplas_threads_blas_threading())
      call blas_core_in_use(setting%blas_core, setting%blas_core_source)
      setting%openmp = pecplas_threads_openmp() /= 0
   end subroutine apply_threads

   !> The parts of `setting` in words, as the run summary prints them.
   function parts_text(setting) result(text)
      type(thread_setting_t), intent(in) :: setting
      character(len=:), allocatable :: text
      character(len=16) :: work
      character(len=:), allocatable :: blas, detail
      blas = setting%blas
      if (len(blas) == 0) blas = 'without thread control'
      detail = ''
      if (allocated(setting%blas_threading)) detail = setting%blas_threading
      if (allocated(setting%blas_core)) then
         if (len(setting%blas_core) > 0) then
            if (len(detail) > 0) detail = detail//'; '
            detail = detail//setting%blas_core//' kernels: '//setting%blas_core_source
         end if
      end if
      if (len(detail) > 0) blas = blas//' ('//detail//')'
      text = 'element loops '//itoa(setting%loops)//', CHOLMOD regions '// &
         itoa(setting%regions)//', BLAS '//blas//' '//itoa(setting%blas_threads)
      if (setting%blas_work > 0.0) then
         write (work, '(es9.2)') setting%blas_work
         text = text//' at most, one per '//trim(adjustl(work))//' flops of a call'
      end if
      if (allocated(setting%parts_source)) then
         if (setting%parts_source /= 'rule') text = text//' ('//setting%parts_source//')'
      end if
   end function parts_text

   !> Threads an OpenMP parallel region would use now (1 without OpenMP).
   integer function openmp_threads()
      openmp_threads = int(pecplas_threads_max())
   end function openmp_threads

   !> Copy of a NUL-terminated C string.
   function c_text(p) result(text)
      type(c_ptr), intent(in) :: p
      character(len=:), allocatable :: text
      character(kind=c_char), pointer :: chars(:)
      integer :: n
      text = ''
      if (.not. c_associated(p)) return
      call c_f_pointer(p, chars, [64])
      n = 0
      do while (n < 64)
         if (chars(n + 1) == achar(0)) exit
         n = n + 1
      end do
      if (n > 0) text = transfer(chars(1:n), repeat(' ', n))
   end function c_text

end module pecplas_linalg_threads
