!> What the benchmark programs report of their own process (Linux /proc/self).
module bench_process
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private
   public :: cpu_times, peak_memory_mb

contains

   !> User and system CPU time of this process so far [s] (utime and stime of
   !> /proc/self/stat, in the kernel's fixed 100 ticks per second); -1 when unreadable.
   function cpu_times() result(t)
      real(wp) :: t(2)
      character(len=4096) :: line
      character(len=32) :: field(13)
      integer :: u, ios, k
      t = -1.0_wp
      open (newunit=u, file='/proc/self/stat', status='old', action='read', iostat=ios)
      if (ios /= 0) return
      read (u, '(a)', iostat=ios) line
      close (u)
      if (ios /= 0) return
      ! the fields after the command name, which ends at the last ')': state is field 3,
      ! utime 14, stime 15
      k = index(line, ')', back=.true.)
      read (line(k + 1:), *, iostat=ios) field
      if (ios /= 0) return
      read (field(12), *, iostat=ios) t(1)
      if (ios == 0) read (field(13), *, iostat=ios) t(2)
      if (ios /= 0) then
         t = -1.0_wp
      else
         t = t/100.0_wp
      end if
   end function cpu_times

   !> Peak resident memory of this process (VmHWM of /proc/self/status), MB.
   real(wp) function peak_memory_mb()
      character(len=256) :: line
      integer :: u, ios, kb
      peak_memory_mb = -1.0_wp
      open (newunit=u, file='/proc/self/status', status='old', action='read', iostat=ios)
      if (ios /= 0) return
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:6) == 'VmHWM:') then
            read (line(7:), *) kb
            peak_memory_mb = kb/1024.0_wp
         end if
      end do
      close (u)
   end function peak_memory_mb

end module bench_process
