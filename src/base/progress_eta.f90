!> Progress of a long run with an estimate of the time left, printed every few seconds
!> rather than every increment when increments are fast. The caller passes the clock
!> (wall seconds), so the logic is testable without waiting:
!>   call eta%start(wall_time(), total_increments)
!>   ... after each increment:  if (eta%due(wall_time())) print *, eta%line(done, wall_time())
!> A run of steps whose end is not a count of increments (cuts, arc-length) estimates per
!> step from a measure of the way done (the step fraction, a displacement towards its target):
!>   call eta%begin_step(istep, clock_at_step_start, measure_at_step_start)
!>   left = eta%step_left(measure_now, measure_target, now)     ! -1: no estimate
module pecplas_base_progress_eta
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: progress_eta_t, duration

   type :: progress_eta_t
      !> Clock at start and at the last line printed; seconds between lines.
      real(wp) :: t0 = 0.0_wp, last = 0.0_wp, interval = 5.0_wp
      !> Increments planned (all steps, before cuts).
      integer :: total = 0
      !> The step under way (0 none), the clock and the measure of the way done at its start.
      integer :: step = 0
      real(wp) :: t_step = 0.0_wp, m_start = 0.0_wp
      !> Clock at the last accepted increment (the start of the next step, if it ends one).
      real(wp) :: t_last = 0.0_wp
   contains
      procedure :: begin_step => eta_begin_step
      procedure :: step_left => eta_step_left
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
      this%t_last = now
      this%step = 0
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

   !> Starts step `step` at clock `now` with the measure of the way done `m_start`.
   pure subroutine eta_begin_step(this, step, now, m_start)
      class(progress_eta_t), intent(inout) :: this
      integer, intent(in) :: step
      real(wp), intent(in) :: now, m_start
      this%step = step
      this%t_step = now
      this%m_start = m_start
   end subroutine eta_begin_step

   !> Seconds left in the step when its measure is `m` of `target` at `now`, at the mean rate
   !> since the step began: -1 (not known) when the measure has not moved towards the target
   !> (or the target is where the step began); 0 at or past the target.
   pure real(wp) function eta_step_left(this, m, target, now) result(left)
      class(progress_eta_t), intent(in) :: this
      real(wp), intent(in) :: m, target, now
      real(wp) :: done
      left = -1.0_wp
      if (target == this%m_start) return
      done = (m - this%m_start)/(target - this%m_start)
      if (.not. (done > 0.0_wp)) return
      left = max(now - this%t_step, 0.0_wp)*max(1.0_wp - done, 0.0_wp)/done
   end function eta_step_left

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
