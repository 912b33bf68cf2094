!> Integration-point state of the plate sets: converged values (end of the last converged
!> increment) and trial values (current iterate), committed and rolled back with the massif.
!> Arrays are (component, point, element): generalized strains e and resultants s
!> (pecplas_structures_beam, NGEN), the section history (pecplas_structures_section, NHIST).
module pecplas_structures_state
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: plate_set_state_t, plate_state_t

   type :: plate_set_state_t
      integer :: npoint = 0
      real(wp), allocatable :: e(:, :, :), s(:, :, :), hist(:, :, :)
      real(wp), allocatable :: e_trial(:, :, :), s_trial(:, :, :), hist_trial(:, :, :)
      !> Consistent tangent of the last trial update (NGEN, NGEN, np, nel).
      real(wp), allocatable :: tangent(:, :, :, :)
      !> Phases: whether the plate is part of the model.
      logical :: active = .true.
   end type plate_set_state_t

   type :: plate_state_t
      !> One entry per plate set, in model%plates order (none without plates).
      type(plate_set_state_t), allocatable :: sets(:)
   contains
      procedure :: commit => plate_state_commit
      procedure :: rollback => plate_state_rollback
   end type plate_state_t

contains

   !> Accepts the trial values of every point.
   subroutine plate_state_commit(this)
      class(plate_state_t), intent(inout) :: this
      integer :: s
      if (.not. allocated(this%sets)) return
      do s = 1, size(this%sets)
         associate (st => this%sets(s))
            st%e = st%e_trial
            st%s = st%s_trial
            st%hist = st%hist_trial
         end associate
      end do
   end subroutine plate_state_commit

   !> Discards the trial values.
   subroutine plate_state_rollback(this)
      class(plate_state_t), intent(inout) :: this
      integer :: s
      if (.not. allocated(this%sets)) return
      do s = 1, size(this%sets)
         associate (st => this%sets(s))
            st%e_trial = st%e
            st%s_trial = st%s
            st%hist_trial = st%hist
         end associate
      end do
   end subroutine plate_state_rollback

end module pecplas_structures_state
