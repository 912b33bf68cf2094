!> BFGS acceleration of modified Newton (Matthies & Strang 1979, in the two-loop form of
!> Nocedal 1980): the factorised stiffness K stays the initial inverse H0 = K^-1 and each
!> iteration adds one pair s = Δu (the step taken), y = Δf_int (the change of the internal
!> forces on the free equations). The direction for a residual r is H r with
!>     H_{k+1} = (I - rho s y^T) H_k (I - rho y s^T) + rho s s^T,   rho = 1 / (y . s).
!> Stored per iteration: two vectors of the free equations (2 n reals); applying H costs
!> one solve with K plus 4 n m multiply-adds for m stored pairs. Pairs whose curvature
!> y . s is not positive (unloading, a sign change of the tangent) are skipped: BFGS keeps
!> H positive definite only with y . s > 0.
module pecplas_solve_bfgs
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: bfgs_t

   type :: bfgs_t
      !> Stored pairs s(:, i), y(:, i) and rho(i) = 1 / (y . s), i = 1 .. m.
      real(wp), allocatable :: s(:, :), y(:, :), rho(:)
      integer :: m = 0
      !> Pairs refused for their curvature (for the history).
      integer :: skipped = 0
   contains
      procedure :: reset => bfgs_reset
      procedure :: push => bfgs_push
      procedure :: first_loop => bfgs_first_loop
      procedure :: second_loop => bfgs_second_loop
   end type bfgs_t

   !> A pair is kept when y . s > CURVATURE_MIN |y| |s| (a nearly orthogonal pair makes
   !> rho huge and the update ill-conditioned).
   real(wp), parameter :: CURVATURE_MIN = 1.0e-8_wp

contains

   !> Forgets every pair; room for `capacity` pairs of length n.
   subroutine bfgs_reset(this, n, capacity)
      class(bfgs_t), intent(inout) :: this
      integer, intent(in) :: n, capacity
      if (allocated(this%s)) then
         if (size(this%s, 1) /= n .or. size(this%s, 2) < capacity) deallocate (this%s, this%y, &
            this%rho)
      end if
      if (.not. allocated(this%s)) allocate (this%s(n, capacity), this%y(n, capacity), &
         this%rho(capacity))
      this%m = 0
      this%skipped = 0
   end subroutine bfgs_reset

   !> Adds the pair (s, y); `kept` false when its curvature is refused or memory is full
   !> (then the oldest pair is dropped first, as in limited-memory BFGS).
   subroutine bfgs_push(this, s, y, kept)
      class(bfgs_t), intent(inout) :: this
      real(wp), intent(in) :: s(:), y(:)
      logical, intent(out) :: kept
      real(wp) :: ys
      ys = dot_product(y, s)
      kept = ys > CURVATURE_MIN*norm2(y)*norm2(s) .and. ys > 0.0_wp
      if (.not. kept) then
         this%skipped = this%skipped + 1
         return
      end if
      if (this%m == size(this%s, 2)) then
         this%s(:, 1:this%m - 1) = this%s(:, 2:this%m)
         this%y(:, 1:this%m - 1) = this%y(:, 2:this%m)
         this%rho(1:this%m - 1) = this%rho(2:this%m)
         this%m = this%m - 1
      end if
      this%m = this%m + 1
      this%s(:, this%m) = s
      this%y(:, this%m) = y
      this%rho(this%m) = 1.0_wp/ys
   end subroutine bfgs_push

   !> First loop of H r: q = r projected through the stored pairs, newest first; alpha(i)
   !> are kept for the second loop. Then the caller solves z = K^-1 q.
   subroutine bfgs_first_loop(this, q, alpha)
      class(bfgs_t), intent(in) :: this
      real(wp), intent(inout) :: q(:)
      real(wp), intent(out) :: alpha(:)
      integer :: i
      do i = this%m, 1, -1
         alpha(i) = this%rho(i)*dot_product(this%s(:, i), q)
         q = q - alpha(i)*this%y(:, i)
      end do
   end subroutine bfgs_first_loop

   !> Second loop: z = K^-1 q on entry, H r on exit.
   subroutine bfgs_second_loop(this, alpha, z)
      class(bfgs_t), intent(in) :: this
      real(wp), intent(in) :: alpha(:)
      real(wp), intent(inout) :: z(:)
      real(wp) :: beta
      integer :: i
      do i = 1, this%m
         beta = this%rho(i)*dot_product(this%y(:, i), z)
         z = z + (alpha(i) - beta)*this%s(:, i)
      end do
   end subroutine bfgs_second_loop

end module pecplas_solve_bfgs
