!> Progress of a long run with an estimate of the time left, printed every few seconds
!> rather than every increment when increments are fast. The caller passes the clock
!> (wall seconds), so the logic is testable without waiting:
!>   call eta%start(wall_time(), total_increments)
!>   ... after each increment:  if (eta%due(wall_time())) print *, eta%line(done, wall_time())
module pecplas_base_progress_eta
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: progress_eta_t

   type :: progress_eta_t
      !> Clock at start and at the last line printed; seconds between lines.
      real(wp) :: t0 = 0.0_wp, last = 0.0_wp, interval = 5.0_wp
      !> Increments planned (all steps, before cuts).
      integer :: total = 0
   contains
      procedure :: start => eta_start
      procedure :: due => eta_due
      procedure :: remaining => eta_remaining
      procedure :: line => eta_line
   end type progress_eta_t

contains

   !> Starts the clock at `now` for `total` increments; `interval` seconds between lines.
   pure subroutine eta_start(this, now, total, interval)
      class(progress_eta_t), intent(inout) :: this
      real(wp), intent(in) :: now
      integer, intent(in) :: total
      real(wp), intent(in), optional :: interval
      this%t0 = now
      this%last = now
      this%total = max(total, 0)
      if (present(interval)) this%interval = max(interval, 0.0_wp)
   end subroutine eta_start

   !> True (and the line clock reset) when `interval` seconds have passed since the last line.
   logical function eta_due(this, now) result(due)
      class(progress_eta_t), intent(inout) :: this
      real(wp), intent(in) :: now
      due = now - this%last >= this%interval
      if (due) this%last = now
   end function eta_due

   !> Seconds left after `done` of `total` increments at `now`, at the mean rate so far
   !> (-1 when there is nothing to go on yet).
   pure real(wp) function eta_remaining(this, done, now) result(left)
      class(progress_eta_t), intent(in) :: this
      integer, intent(in) :: done
      real(wp), intent(in) :: now
      left = -1.0_wp
      if (done <= 0 .or. this%total <= 0) return
      left = (now - this%t0)*real(max(this%total - done, 0), wp)/real(done, wp)
   end function eta_remaining

   !> "increment 120/1000 (12 %), 34 s elapsed, about 4.1 min left".
   function eta_line(this, done, now) result(s)
      class(progress_eta_t), intent(in) :: this
      integer, intent(in) :: done
      real(wp), intent(in) :: now
      character(len=:), allocatable :: s
      character(len=64) :: a, b
      real(wp) :: left
      write (a, '(i0,a,i0,a,i0,a)') done, '/', this%total, ' (', &
         nint(100.0_wp*real(done, wp)/real(max(this%total, 1), wp)), ' %)'
      s = 'increment '//trim(a)//', '//duration(now - this%t0)//' elapsed'
      left = this%remaining(done, now)
      if (left >= 0.0_wp) then
         s = s//', about '//duration(left)//' left'
      else
         write (b, '(a)') ', time left not known yet'
         s = s//trim(b)
      end if
   end function eta_line

   !> "34 s", "4.1 min", "2.3 h".
   pure function duration(t) result(s)
      real(wp), intent(in) :: t
      character(len=:), allocatable :: s
      character(len=32) :: buf
      if (t < 120.0_wp) then
         write (buf, '(i0,a)') nint(t), ' s'
      else if (t < 7200.0_wp) then
         write (buf, '(f0.1,a)') t/60.0_wp, ' min'
      else
         write (buf, '(f0.1,a)') t/3600.0_wp, ' h'
      end if
      s = trim(buf)
   end function duration

end module pecplas_base_progress_eta
