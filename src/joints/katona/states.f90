!> Contact-state iteration of the Katona doublets for one linearised step (an active-set
!> loop on a dense system the size of the doublet unknowns).
!>
!> With R_a = R + alpha D^T D factorised (alpha = 0 when R is regular), a step du from u_j
!> with total contact forces f solves R du + D^T f = r. Writing h = f - alpha D du:
!>     du = R_a^-1 (r - D^T h),   D du = w - G h,   w = D R_a^-1 r,  G = D R_a^-1 D^T,
!>     f = h + alpha (w - G h),   z = z_j + w - G h,
!> which is the same solution for any alpha (a change of unknowns, not a penalty). One
!> equation per doublet row, by state:
!>     stick  z_n = g0,  z_t = anchor
!>     slip   z_n = g0,  T = s (c A + mu N)          (s = slip sign)
!>     open   N = 0,     T = 0
!> The dense system (2 nd) is row-equilibrated, LU-factorised (LAPACK dgetrf) and its
!> condition estimated (dgecon): a singular system means a mechanism under the current
!> states (a body sliding away under force control), reported as a run error so the
!> increment is cut. States are then checked: stick -> open when N < -T_ten, stick -> slip
!> when |T| > c A + mu N, slip -> open likewise, slip -> stick when the slip since the anchor
!> reverses (its sign only, when the strength c A + mu N is nil), open -> contact when the
!> doublet interpenetrates: a doublet open at the start of the increment sticks where it
!> touches; one in contact at the start (opened by an iterate only) is measured from its
!> converged anchor again, and slips in the direction it has moved from it, if it has. The
!> states are those of the end of the increment (backward Euler): an iterate's opening does
!> not break the bond (pecplas_joints_katona_type's commit does, for a doublet that ends
!> open). A doublet that has changed state MAX_FLIPS times in the increment is frozen
!> (chattering guard) and counted; if a frozen doublet's state is still rejected when no
!> other changes, the set is inconsistent and the step fails (a run error: the increment is
!> cut). A doublet row on supported dofs only (G(i, i) = 0) has a zero multiplier: its
!> supports carry the force.
module pecplas_joints_katona_states
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, run_error, singular_error
   use pecplas_linalg_lapack, only: dgetrf, dgetrs
   use pecplas_joints_laws_type, only: MODE_STICK, MODE_SLIP, MODE_OPEN
   use pecplas_joints_katona_type, only: katona_t
   implicit none (type, external)
   private

   public :: solve_states, MAX_STATE_ITERATIONS, MAX_FLIPS

   !> State iterations allowed in one linearised step, and state changes of one doublet in
   !> one increment before it is frozen.
   integer, parameter :: MAX_STATE_ITERATIONS = 30, MAX_FLIPS = 4
   !> Reciprocal condition (1-norm, row-equilibrated) below which the system is singular.
   real(wp), parameter :: RCOND_MIN = 1.0e-13_wp
   !> Relative tolerances of the force and gap checks.
   real(wp), parameter :: FORCE_TOL = 1.0e-9_wp, GAP_TOL = 1.0e-9_wp

   interface
      !> Reciprocal condition number of a general matrix from its LU factors.
      subroutine dgecon(norm, n, a, lda, anorm, rcond, work, iwork, info)
         import :: wp
         character(len=1), intent(in) :: norm
         integer, intent(in) :: n, lda
         real(wp), intent(in) :: a(lda, *), anorm
         real(wp), intent(out) :: rcond, work(*)
         integer, intent(out) :: iwork(*), info
      end subroutine dgecon

      !> Minimum-norm least-squares solution with a rank-revealing QR (complete orthogonal
      !> factorisation).
      subroutine dgelsy(m, n, nrhs, a, lda, b, ldb, jpvt, rcond, rank, work, lwork, info)
         import :: wp
         integer, intent(in) :: m, n, nrhs, lda, ldb, lwork
         real(wp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(inout) :: jpvt(*)
         real(wp), intent(in) :: rcond
         integer, intent(out) :: rank, info
         real(wp), intent(out) :: work(*)
      end subroutine dgelsy
   end interface

contains

   !> Iterates the trial states of kt until none changes; on return kt%f_trial, z_trial hold
   !> the forces and relative displacements, h the unknowns for du = R_a^-1 (r - D^T h).
   !> `flips` counts state changes per doublet in the increment; `nit` the iterations.
   subroutine solve_states(kt, w, zj, h, flips, nit, error)
      type(katona_t), intent(inout) :: kt
      real(wp), intent(in) :: w(:), zj(:)
      real(wp), intent(out) :: h(:)
      integer, intent(inout) :: flips(:)
      integer, intent(out) :: nit
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: a(:, :), gh(:)
      real(wp) :: ftol, gtol
      integer :: changed, held, n2
      character(len=160) :: buf
      n2 = 2*kt%nd
      allocate (a(n2, n2), gh(n2))
      nit = 0
      do
         nit = nit + 1
         call build_system(kt, w, zj, a, h)
         call solve_dense_checked(a, h, error)
         if (allocated(error)) return
         gh = matmul(kt%g, h)
         kt%z_trial = reshape(zj + w - gh, [2, kt%nd])
         kt%f_trial = reshape(h + kt%alpha*(w - gh), [2, kt%nd])
         ftol = FORCE_TOL*max(maxval(abs(kt%f_trial)), maxval(kt%cohesion), tiny(1.0_wp))
         gtol = GAP_TOL*max(maxval(abs(kt%z_trial)), maxval(kt%gap0), tiny(1.0_wp))
         call update_states(kt, ftol, gtol, flips, changed, held)
         if (changed == 0 .and. held > 0) then
            write (buf, '(a,i0,a,i0,a)') 'Katona contact: ', held, ' doublets changed state ', &
               MAX_FLIPS, ' times and their states still do not hold (stick, slip and open do '// &
               'not settle)'
            call run_error(error, trim(buf))
            return
         end if
         if (changed == 0) return
         if (nit >= MAX_STATE_ITERATIONS) then
            write (buf, '(a,i0,a,i0,a)') 'Katona contact: states still changing after ', nit, &
               ' iterations (', changed, ' doublets)'
            call run_error(error, trim(buf))
            return
         end if
      end do
   end subroutine solve_states

   !> Rows of the state equations in the unknowns h (module header).
   subroutine build_system(kt, w, zj, a, b)
      type(katona_t), intent(in) :: kt
      real(wp), intent(in) :: w(:), zj(:)
      real(wp), intent(out) :: a(:, :), b(:)
      real(wp) :: s
      integer :: k, in, it
      associate (g => kt%g, alpha => kt%alpha)
         do k = 1, kt%nd
            in = 2*k - 1
            it = 2*k
            select case (kt%mode_trial(k))
            case (MODE_STICK, MODE_SLIP)
               a(in, :) = -g(in, :)
               b(in) = kt%gap0(k) - zj(in) - w(in)
            case default
               a(in, :) = -alpha*g(in, :)
               a(in, in) = a(in, in) + 1.0_wp
               b(in) = -alpha*w(in)
            end select
            select case (kt%mode_trial(k))
            case (MODE_STICK)
               a(it, :) = -g(it, :)
               b(it) = kt%anchor_trial(k) - zj(it) - w(it)
            case (MODE_SLIP)
               s = real(kt%sgn_trial(k), wp)*kt%mu(k)
               a(it, :) = -alpha*(g(it, :) - s*g(in, :))
               a(it, it) = a(it, it) + 1.0_wp
               a(it, in) = a(it, in) - s
               b(it) = real(kt%sgn_trial(k), wp)*kt%cohesion(k) - alpha*(w(it) - s*w(in))
            case default
               a(it, :) = -alpha*g(it, :)
               a(it, it) = a(it, it) + 1.0_wp
               b(it) = -alpha*w(it)
            end select
         end do
         ! A row acting on no free equation (both nodes held in that direction) has
         ! G(i, i) = 0: the supports take its force, its multiplier is 0.
         do k = 1, 2*kt%nd
            if (g(k, k) > 0.0_wp) cycle
            a(k, :) = 0.0_wp
            a(k, k) = 1.0_wp
            b(k) = 0.0_wp
         end do
      end associate
   end subroutine build_system

   !> b <- a^-1 b with row equilibration, LU and a condition check.
   subroutine solve_dense_checked(a, b, error)
      real(wp), intent(inout) :: a(:, :), b(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: work(:)
      integer, allocatable :: ipiv(:), iwork(:)
      real(wp), allocatable :: a0(:, :), b0(:)
      real(wp) :: scale, anorm, rcond
      integer :: n, i, info
      logical :: consistent
      character(len=80) :: buf
      n = size(a, 1)
      do i = 1, n
         scale = maxval(abs(a(i, :)))
         if (.not. (scale > 0.0_wp)) then
            call run_error(error, 'Katona contact: a constraint row is empty (a doublet '// &
               'whose nodes are all fixed?)')
            return
         end if
         a(i, :) = a(i, :)/scale
         b(i) = b(i)/scale
      end do
      anorm = maxval(sum(abs(a), dim=1))
      a0 = a
      b0 = b
      allocate (ipiv(n), work(4*n), iwork(n))
      call dgetrf(n, n, a, n, ipiv, info)
      rcond = 0.0_wp
      if (info == 0) call dgecon('1', n, a, n, anorm, rcond, work, iwork, info)
      if (info /= 0 .or. .not. (rcond >= RCOND_MIN)) then
         ! Singular: either redundant constraints (e.g. three bonded doublets closing a loop
         ! where interfaces meet), a consistent system whose minimum-norm solution is a valid
         ! set of contact forces, or a mechanism, which has no solution: tell them apart by
         ! the residual of the rank-revealing least-squares solution.
         call consistent_solution(a0, b0, b, consistent)
         if (consistent) return
         write (buf, '(a,es9.2,a)') ' (rcond ', rcond, ')'
         call singular_error(error, 'Katona contact: the constrained system is singular under '// &
            'the current contact states: a body can move freely (sliding away)'//trim(buf))
         return
      end if
      call dgetrs('N', n, 1, a, n, ipiv, b, n, info)
   end subroutine solve_dense_checked

   !> Minimum-norm solution x of the (row-equilibrated) singular system a x = b by dgelsy;
   !> consistent when its residual is at round-off level, ||a x - b|| <= 1e-9 ||b||.
   subroutine consistent_solution(a, b, x, consistent)
      real(wp), intent(in) :: a(:, :), b(:)
      real(wp), intent(out) :: x(:)
      logical, intent(out) :: consistent
      real(wp), allocatable :: aw(:, :), bw(:, :), work(:)
      integer, allocatable :: jpvt(:)
      integer :: n, rank, info
      n = size(a, 1)
      aw = a
      allocate (bw(n, 1), jpvt(n), work(max(1, 4*n + 64*n)))
      bw(:, 1) = b
      jpvt = 0
      call dgelsy(n, n, 1, aw, n, bw, n, jpvt, 1.0e-12_wp, rank, work, size(work), info)
      x = bw(:, 1)
      consistent = info == 0 .and. rank < n .and. &
         norm2(matmul(a, x) - b) <= 1.0e-9_wp*max(norm2(b), tiny(1.0_wp))
      if (.not. consistent) x = b
   end subroutine consistent_solution

   !> Applies the state checks of the module header; `changed` counts the doublets changed,
   !> `held` the frozen doublets whose state the checks reject (an inconsistent set).
   subroutine update_states(kt, ftol, gtol, flips, changed, held)
      type(katona_t), intent(inout) :: kt
      real(wp), intent(in) :: ftol, gtol
      integer, intent(inout) :: flips(:)
      integer, intent(out) :: changed, held
      real(wp) :: nf, tf, tlim, limit, anchor, slip
      integer :: k, new_mode, new_sgn
      changed = 0
      held = 0
      do k = 1, kt%nd
         ! a deactivated doublet stays open
         if (allocated(kt%off)) then
            if (kt%off(k)) cycle
         end if
         nf = kt%f_trial(1, k)
         tf = kt%f_trial(2, k)
         tlim = kt%tension(k)
         if (kt%broken(k)) tlim = 0.0_wp
         limit = kt%cohesion(k) + kt%mu(k)*nf
         new_mode = kt%mode_trial(k)
         new_sgn = kt%sgn_trial(k)
         anchor = kt%anchor_trial(k)
         select case (kt%mode_trial(k))
         case (MODE_STICK)
            if (nf < -tlim - ftol) then
               new_mode = MODE_OPEN
            else if (abs(tf) > limit + ftol) then
               new_mode = MODE_SLIP
               new_sgn = int(sign(1.0_wp, tf))
            end if
         case (MODE_SLIP)
            if (nf < -tlim - ftol) then
               new_mode = MODE_OPEN
            else if (real(kt%sgn_trial(k), wp)*(kt%z_trial(2, k) - kt%anchor_trial(k)) &
                     < -gtol) then
               if (limit <= ftol) then
                  ! no strength (frictionless, or N = 0): T = 0 either way, the sign is moot
                  kt%sgn_trial(k) = -kt%sgn_trial(k)
                  new_sgn = kt%sgn_trial(k)
               else
                  new_mode = MODE_STICK
               end if
            end if
         case default
            if (kt%z_trial(1, k) - kt%gap0(k) > gtol) then
               new_mode = MODE_STICK
               if (kt%mode(k) == MODE_OPEN) then
                  ! open at the start of the increment: it touches here and sticks there
                  anchor = kt%z_trial(2, k)
               else
                  ! in contact at the start, opened by an iterate only: its slip is still
                  ! measured from the converged anchor, and it slips if it has moved
                  anchor = kt%anchor(k)
                  slip = kt%z_trial(2, k) - anchor
                  if (abs(slip) > gtol) then
                     new_mode = MODE_SLIP
                     new_sgn = int(sign(1.0_wp, slip))
                  end if
               end if
            end if
         end select
         if (new_mode == kt%mode_trial(k) .and. new_sgn == kt%sgn_trial(k)) cycle
         if (flips(k) >= MAX_FLIPS) then
            held = held + 1
            cycle
         end if
         flips(k) = flips(k) + 1
         if (flips(k) == MAX_FLIPS) kt%frozen = kt%frozen + 1
         changed = changed + 1
         kt%mode_trial(k) = new_mode
         kt%sgn_trial(k) = new_sgn
         kt%anchor_trial(k) = anchor
      end do
   end subroutine update_states

end module pecplas_joints_katona_states
