!> Line search along a Newton or quasi-Newton direction du (Crisfield 1991, §9.3): finds a
!> step eta where the slope of the energy along du vanishes,
!>     g(eta) = du . r(u + eta du) = 0,   r = F_ext - F_int,
!> starting from g(0) > 0 (du is a descent direction) and g(1), which the iteration has
!> computed anyway. eta = 1 is kept when |g(1)| <= TOL |g(0)| (most iterations). Otherwise
!> a bracket [0, 1] (g(1) < 0: the step overshoots) is narrowed by regula falsi with the
!> Illinois correction; with g(1) > 0 (the minimum lies beyond 1) the secant extrapolates,
!> up to ETA_MAX. At most MAX_EVALS extra residuals; eta stays in [ETA_MIN, ETA_MAX].
!>
!> Reverse communication, so that the caller keeps its own state (displacements, trial
!> stresses) and the search is testable on a plain function:
!>     call ls%start(g0, g1)
!>     do while (ls%next(eta))
!>        ... evaluate g at eta ...
!>        call ls%update(g)
!>     end do
!> On exit the last evaluation was at ls%eta (1 when none was requested).
module pecplas_solve_line_search
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: line_search_t

   real(wp), parameter :: TOL = 0.8_wp, ETA_MIN = 0.1_wp, ETA_MAX = 2.0_wp
   integer, parameter :: MAX_EVALS = 6

   type :: line_search_t
      !> Current step (the last one evaluated, or the one requested by next).
      real(wp) :: eta = 1.0_wp
      !> Extra residual evaluations made.
      integer :: evals = 0
      real(wp), private :: g0 = 0.0_wp, lo = 0.0_wp, glo = 0.0_wp, hi = 1.0_wp, ghi = 0.0_wp
      real(wp), private :: best = 1.0_wp, gbest = 0.0_wp
      integer, private :: side = 0
      logical, private :: bracketed = .false., done = .true., pending = .false.
   contains
      procedure :: start => ls_start
      procedure :: next => ls_next
      procedure :: update => ls_update
   end type line_search_t

contains

   subroutine ls_start(this, g0, g1)
      class(line_search_t), intent(inout) :: this
      real(wp), intent(in) :: g0, g1
      this%eta = 1.0_wp
      this%evals = 0
      this%g0 = g0
      this%best = 1.0_wp
      this%gbest = g1
      this%side = 0
      this%pending = .false.
      ! not a descent direction, or the full step is good enough: no search
      this%done = .not. (g0 > 0.0_wp) .or. abs(g1) <= TOL*abs(g0) .or. g1 /= g1
      if (this%done) return
      this%lo = 0.0_wp
      this%glo = g0
      this%hi = 1.0_wp
      this%ghi = g1
      this%bracketed = g1 < 0.0_wp
      if (.not. this%bracketed .and. g1 >= g0) then
         ! the slope does not fall along du: no secant to follow, keep the full step
         this%done = .true.
         return
      end if
      call propose(this)
   end subroutine ls_start

   !> True when g is wanted at `eta`.
   logical function ls_next(this, eta) result(more)
      class(line_search_t), intent(inout) :: this
      real(wp), intent(out) :: eta
      more = this%pending
      eta = this%eta
   end function ls_next

   subroutine ls_update(this, g)
      class(line_search_t), intent(inout) :: this
      real(wp), intent(in) :: g
      this%pending = .false.
      this%evals = this%evals + 1
      if (this%done) return
      if (g /= g) then
         ! a failed evaluation: halve towards the last good end
         this%hi = this%eta
         this%ghi = -abs(this%g0)
         this%bracketed = .true.
      else
         if (abs(g) < abs(this%gbest)) then
            this%best = this%eta
            this%gbest = g
         end if
         if (abs(g) <= TOL*abs(this%g0)) then
            this%done = .true.
            return
         end if
         if (this%bracketed) then
            if (g < 0.0_wp) then
               this%hi = this%eta
               this%ghi = g
               if (this%side == -1) this%glo = 0.5_wp*this%glo
               this%side = -1
            else
               this%lo = this%eta
               this%glo = g
               if (this%side == 1) this%ghi = 0.5_wp*this%ghi
               this%side = 1
            end if
         else if (g < 0.0_wp) then
            this%bracketed = .true.
            this%lo = this%hi
            this%glo = this%ghi
            this%hi = this%eta
            this%ghi = g
         else
            this%lo = this%hi
            this%glo = this%ghi
            this%hi = this%eta
            this%ghi = g
            if (g >= this%glo .or. this%eta >= ETA_MAX) then
               call finish(this)
               return
            end if
         end if
      end if
      if (this%evals >= MAX_EVALS) then
         call finish(this)
         return
      end if
      call propose(this)
   end subroutine ls_update

   !> Next trial: regula falsi in the bracket, else secant extrapolation beyond hi.
   subroutine propose(this)
      type(line_search_t), intent(inout) :: this
      real(wp) :: eta
      if (this%bracketed) then
         eta = this%lo + (this%hi - this%lo)*this%glo/(this%glo - this%ghi)
         eta = min(max(eta, this%lo + 0.05_wp*(this%hi - this%lo)), &
            this%hi - 0.05_wp*(this%hi - this%lo))
      else
         eta = this%hi + (this%hi - this%lo)*this%ghi/(this%glo - this%ghi)
      end if
      this%eta = min(max(eta, ETA_MIN), ETA_MAX)
      this%pending = .true.
   end subroutine propose

   !> Ends on the best step seen; asks for it again when it was not the last evaluated.
   subroutine finish(this)
      type(line_search_t), intent(inout) :: this
      this%done = .true.
      if (this%best /= this%eta) then
         this%eta = this%best
         this%pending = .true.
      end if
   end subroutine finish

end module pecplas_solve_line_search
