!> Termination requests (SIGTERM from Slurm before its kill, SIGINT from Ctrl-C, SIGHUP from
!> a closed terminal) turned into a flag that the increment loop reads between increments,
!> so that the run ends with its results file marked 'interrupted' instead of dying.
!> A second signal of the same kind ends the process at once (default action restored).
module pecplas_base_signals
   use, intrinsic :: iso_c_binding, only: c_int, c_char
   implicit none (type, external)
   private

   public :: install_signal_handlers, interrupt_requested, interrupt_signal, clear_interrupt
   public :: crash_guard_begin, crash_guard_end

   interface
      integer(c_int) function c_guard_begin(message, n) bind(C, name='pecplas_guard_begin')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: message(*)
         integer(c_int), value :: n
      end function c_guard_begin
      subroutine c_guard_end() bind(C, name='pecplas_guard_end')
      end subroutine c_guard_end
      integer(c_int) function c_install() bind(C, name='pecplas_install_signal_handlers')
         import :: c_int
      end function c_install
      integer(c_int) function c_signal_number() bind(C, name='pecplas_signal_number')
         import :: c_int
      end function c_signal_number
      subroutine c_clear() bind(C, name='pecplas_signal_clear')
      end subroutine c_clear
   end interface

contains

   !> Installs the handlers of SIGTERM, SIGINT and SIGHUP; false if the system refused.
   logical function install_signal_handlers() result(ok)
      ok = c_install() == 0
   end function install_signal_handlers

   !> True once a termination signal has been caught.
   logical function interrupt_requested()
      interrupt_requested = c_signal_number() /= 0
   end function interrupt_requested

   !> Name of the signal caught ('' if none).
   function interrupt_signal() result(name)
      character(len=:), allocatable :: name
      select case (c_signal_number())
      case (0)
         name = ''
      case (1)
         name = 'SIGHUP'
      case (2)
         name = 'SIGINT'
      case (15)
         name = 'SIGTERM'
      case default
         name = 'a signal'
      end select
   end function interrupt_signal

   !> Forgets a caught signal (tests that raise one on purpose).
   subroutine clear_interrupt()
      call c_clear()
   end subroutine clear_interrupt

   !> Until crash_guard_end, a crash (segmentation fault, bus error, floating-point or
   !> illegal-instruction trap) writes `message` to standard error and ends the process with
   !> exit code 2 (an input error). For library calls reading a file that may be damaged
   !> (HDF5 crashes on some damaged files); the previous signal actions are put back by
   !> crash_guard_end. False when the guard could not be set up.
   logical function crash_guard_begin(message) result(ok)
      character(len=*), intent(in) :: message
      ok = c_guard_begin(message, int(len(message), c_int)) == 0
   end function crash_guard_begin

   subroutine crash_guard_end()
      call c_guard_end()
   end subroutine crash_guard_end

end module pecplas_base_signals
