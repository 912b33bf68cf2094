!> Run state of the anchors (pecplas_model_anchors): per bar the axial force N of one
!> anchor (tension positive), the plastic elongation, and the reference elongation e0 so
!> that N = (EA/L) (e - e0 - e_p); converged and trial values, like the joints' state.
!> During a phase that prestresses a set, its bars carry the prestress force P whatever
!> their elongation (no stiffness); at the start of the next phase e0 is set so that the
!> force goes on from P (pecplas_phases_anchors).
module pecplas_structures_anchor_state
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: anchor_set_state_t, anchor_state_t

   type :: anchor_set_state_t
      !> Whether the set acts (phases), and whether it is being prestressed to `prestress`.
      logical :: active = .true., prestressing = .false.
      real(wp) :: prestress = 0.0_wp
      !> Converged and trial force N of one anchor (nbar), plastic elongation, reference
      !> elongation e0, and the tangent dN/de of the last trial update.
      real(wp), allocatable :: force(:), force_trial(:), plastic(:), plastic_trial(:), &
         e0(:), tangent(:)
      !> During a prestress phase: the force N0 of each bar at the phase's start. The wall
      !> receives N0 + tau (P - N0) at step fraction tau (the rest is the phase's carried
      !> out-of-balance), which is the force the results report.
      real(wp), allocatable :: force_start(:)
   end type anchor_set_state_t

   type :: anchor_state_t
      !> One entry per anchor set, in model%anchors order (empty without anchors).
      type(anchor_set_state_t), allocatable :: sets(:)
   contains
      procedure :: commit => anchor_state_commit
      procedure :: rollback => anchor_state_rollback
   end type anchor_state_t

contains

   !> Accepts the trial values.
   subroutine anchor_state_commit(this)
      class(anchor_state_t), intent(inout) :: this
      integer :: s
      if (.not. allocated(this%sets)) return
      do s = 1, size(this%sets)
         this%sets(s)%force = this%sets(s)%force_trial
         this%sets(s)%plastic = this%sets(s)%plastic_trial
      end do
   end subroutine anchor_state_commit

   !> Discards the trial values.
   subroutine anchor_state_rollback(this)
      class(anchor_state_t), intent(inout) :: this
      integer :: s
      if (.not. allocated(this%sets)) return
      do s = 1, size(this%sets)
         this%sets(s)%force_trial = this%sets(s)%force
         this%sets(s)%plastic_trial = this%sets(s)%plastic
      end do
   end subroutine anchor_state_rollback

end module pecplas_structures_anchor_state
