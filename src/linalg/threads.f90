!> Thread control of a run: one setting governs the OpenMP team of the element loops, the
!> team CHOLMOD opens in its supernodal factorisation (capped in cholmod_shim.c) and the
!> BLAS threads under it (OpenBLAS, BLIS or MKL, set through threads_shim.c). The setting
!> is the deck's *SOLVER, THREADS=n when given, else OMP_NUM_THREADS, else 1: a run
!> neither oversubscribes a shared machine nor depends on library defaults. Results do not
!> depend on it (element loops write their own rows; nodal sums are serial, in a fixed order).
module pecplas_linalg_threads
   use, intrinsic :: iso_c_binding, only: c_int, c_ptr, c_char, c_f_pointer, c_associated
   implicit none (type, external)
   private

   public :: thread_setting_t, resolve_threads, apply_threads, openmp_threads
   public :: PARALLEL_MIN_ELEMENTS

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
   end type thread_setting_t

   interface
      integer(c_int) function pecplas_threads_set(n) bind(C)
         import :: c_int
         integer(c_int), value :: n
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

   !> The setting for a deck value `deck_threads` (0: not given in the deck).
   function resolve_threads(deck_threads) result(setting)
      integer, intent(in) :: deck_threads
      type(thread_setting_t) :: setting
      character(len=32) :: text
      integer :: n, length, status, ios
      setting%n = 1
      setting%source = 'default'
      setting%blas = ''
      if (deck_threads > 0) then
         setting%n = deck_threads
         setting%source = 'deck'
         return
      end if
      call get_environment_variable('OMP_NUM_THREADS', text, length, status)
      if (status /= 0 .or. length == 0) return
      ! OMP_NUM_THREADS may list one count per nesting level ("2,1"): the first applies
      if (index(text, ',') > 0) text = text(:index(text, ',') - 1)
      read (text, *, iostat=ios) n
      if (ios /= 0 .or. n < 1) return
      setting%n = n
      setting%source = 'OMP_NUM_THREADS'
   end function resolve_threads

   !> Applies `setting` to OpenMP and the BLAS; records the BLAS found and whether OpenMP is on.
   subroutine apply_threads(setting)
      type(thread_setting_t), intent(inout) :: setting
      integer(c_int) :: k
      k = pecplas_threads_set(int(setting%n, c_int))
      setting%blas = c_text(pecplas_threads_blas_name(k))
      setting%openmp = pecplas_threads_openmp() /= 0
   end subroutine apply_threads

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
