!> Re-closure limit of a full Newton step (doc/theory.md §4, "Re-closure limit"). A joint
!> point that is open at the iterate has no normal stiffness in the tangent, so the Newton
!> correction du knows nothing of its contact: when the full step closes it again, the part
!> of du past the closure presses it into the penalty K_n that the tangent never saw. Where
!> the point's neighbourhood is soft (a joint end held by the corner of a single triangle)
!> that part is large: the point re-closes with a normal stress far above the converged
!> ones, the residual jumps, the point re-opens at the next iteration, and the open/closed
!> states can cycle until the increment is cut.
!>
!> Along the step the law strain of a point is linear in eta, eps(eta) = eps_0 +
!> eta (eps_1 - eps_0) (the joint kinematics are linear), so with d = eps_n,1 - eps_n,0 > 0
!> and S > 0 the normal stress the full step gives a point that was open, the closure lies
!> at eta_c = 1 - S/(K_n d) (exact for a point that sticks, or slips without dilatancy;
!> dilatancy only adds normal stress, so eta_c is never placed too late), and the stress past
!> it is K_n d (eta - eta_c). reclosure_limit returns
!>     eta = min over the points open at the iterate and closed by the full step of
!>           max(eta_c + RECLOSE_FRACTION (1 - eta_c), ETA_MIN),
!> the step at which each of them carries RECLOSE_FRACTION of the stress S the full step
!> gave it, just past its closure, but never less than ETA_MIN of the step (the line
!> search's floor, pecplas_solve_line_search). pecplas_solve_iterate scales du by eta only
!> when the full step raised the residual norm more than RESIDUAL_GROWTH times (the
!> signature of the overshoot; a re-closure that Newton absorbs is left alone). The limit
!> changes the iterates, never the
!> convergence test nor the state an increment starts from: a converged increment is one
!> by the same criterion as without it.
module pecplas_solve_reclosure
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_joints_state, only: joint_state_t
   use pecplas_joints_laws_type, only: MODE_OPEN
   implicit none (type, external)
   private

   public :: joint_snapshot_t, take_snapshot, reclosure_limit, RESIDUAL_GROWTH

   !> Share of the full step's normal stress a re-closing point keeps (module header): the
   !> point lands just past its closure, closed, so that the next tangent sees its contact;
   !> the step keeps at least ETA_MIN of du. Measured on doc/theory.md's example: 0.05 and
   !> 0.1 converge it in 44-45 iterations without a cut, 0.2 takes 112 with a cut, 0.5 106.
   real(wp), parameter :: RECLOSE_FRACTION = 0.05_wp, ETA_MIN = 0.1_wp
   !> The limit applies when the full step multiplied the residual norm by more than this.
   !> Measured: the re-closures that Newton absorbed in the example and test decks with
   !> joints grew it at most 49 times (mostly below 10), the overshoots of doc/theory.md's
   !> example 240 to 510 times; the example converges alike with 10 to 200.
   real(wp), parameter :: RESIDUAL_GROWTH = 100.0_wp

   !> Normal law strain and contact mode of every point of one joint set at an iterate.
   type :: set_snapshot_t
      real(wp), allocatable :: eps_n(:, :)
      integer, allocatable :: mode(:, :)
   end type set_snapshot_t

   !> The joint points' normal strains and modes at the iterate a step starts from (law
   !> sets only: a Katona set iterates its own contact states).
   type :: joint_snapshot_t
      type(set_snapshot_t), allocatable :: sets(:)
   end type joint_snapshot_t

contains

   !> Records the trial normal strains and modes of the active law-based joint sets.
   subroutine take_snapshot(model, joints, snap)
      type(model_t), intent(in) :: model
      type(joint_state_t), intent(in) :: joints
      type(joint_snapshot_t), intent(inout) :: snap
      integer :: s
      if (.not. allocated(joints%sets)) return
      if (.not. allocated(snap%sets)) allocate (snap%sets(size(joints%sets)))
      do s = 1, size(joints%sets)
         if (model%joint_sets(s)%is_katona() .or. .not. joints%sets(s)%active) cycle
         snap%sets(s)%eps_n = joints%sets(s)%eps_trial(1, :, :)
         snap%sets(s)%mode = joints%sets(s)%mode_trial
      end do
   end subroutine take_snapshot

   !> The step fraction eta in [ETA_MIN, 1] at which every point open in `before` and closed
   !> by the full step (the trial state of `joints`) carries RECLOSE_FRACTION of the normal
   !> stress the full step gave it (module header); 1 when none re-closes.
   pure real(wp) function reclosure_limit(model, joints, before) result(eta)
      type(model_t), intent(in) :: model
      type(joint_state_t), intent(in) :: joints
      type(joint_snapshot_t), intent(in) :: before
      real(wp) :: s_n, d, kn, eta_c
      integer :: s, e, ip
      eta = 1.0_wp
      if (.not. allocated(joints%sets) .or. .not. allocated(before%sets)) return
      do s = 1, size(joints%sets)
         if (model%joint_sets(s)%is_katona() .or. .not. joints%sets(s)%active) cycle
         if (.not. allocated(before%sets(s)%mode)) cycle
         associate (st => joints%sets(s), b => before%sets(s))
            do e = 1, size(st%mode_trial, 2)
               do ip = 1, size(st%mode_trial, 1)
                  if (b%mode(ip, e) /= MODE_OPEN .or. st%mode_trial(ip, e) == MODE_OPEN) cycle
                  s_n = st%sigma_trial(1, ip, e)
                  d = st%eps_trial(1, ip, e) - b%eps_n(ip, e)
                  kn = st%tangent(1, 1, ip, e)
                  if (.not. (s_n > 0.0_wp .and. d > 0.0_wp .and. kn > 0.0_wp)) cycle
                  eta_c = max(0.0_wp, 1.0_wp - s_n/(kn*d))
                  eta = min(eta, max(eta_c + RECLOSE_FRACTION*(1.0_wp - eta_c), ETA_MIN))
               end do
            end do
         end associate
      end do
   end function reclosure_limit

end module pecplas_solve_reclosure
