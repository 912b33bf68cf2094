!> Integration-point state of the joint sets: converged values (end of the last converged
!> increment) and trial values (current iterate), like the massif state
!> (pecplas_fe_state), kept out of the model so that the model stays intent(in).
!> Arrays are (component, point, element); eps and sigma are the law's vectors
!> (eps_n closure positive, sigma_n compression positive).
module pecplas_joints_state
   use pecplas_base_kinds, only: wp
   use pecplas_joints_laws_type, only: MODE_SLIP, MODE_OPEN
   implicit none (type, external)
   private

   public :: joint_set_state_t, joint_state_t

   type :: joint_set_state_t
      integer :: npoint = 0, nstate = 0
      !> Converged law strain eps(2, np, nel), stress sigma(2, np, nel), history
      !> hist(nstate, np, nel) and contact mode(np, nel).
      real(wp), allocatable :: eps(:, :, :), sigma(:, :, :), hist(:, :, :)
      integer, allocatable :: mode(:, :)
      !> Trial values of the current iterate.
      real(wp), allocatable :: eps_trial(:, :, :), sigma_trial(:, :, :), hist_trial(:, :, :)
      integer, allocatable :: mode_trial(:, :)
      !> Consistent tangent d sigma / d eps of the last trial update (2, 2, np, nel).
      real(wp), allocatable :: tangent(:, :, :, :)
      !> Phases: whether the set is active, and the index in model%laws of a law given by
      !> *CHANGE_LAW (0: the *JOINTS one).
      logical :: active = .true.
      integer :: law = 0
      !> Groundwater: the steady pore pressure at each point (np, nel), compression positive;
      !> the law works on the effective normal stress, the element's forces take
      !> sigma_n + p (pecplas_fe_pore). Unallocated in a model without water.
      real(wp), allocatable :: pore(:, :)
      !> Lobatto line joints (pecplas_joints_consistent): the consistent less the lumped
      !> nodal forces (2 nnode, nel) of the initial stresses (sigma0_fix) and of the steady
      !> pore pressures (pore_fix), added to the element's forces; unallocated otherwise.
      real(wp), allocatable :: sigma0_fix(:, :), pore_fix(:, :)
   end type joint_set_state_t

   type :: joint_state_t
      !> One entry per joint set, in model%joint_sets order.
      type(joint_set_state_t), allocatable :: sets(:)
   contains
      procedure :: commit => joint_state_commit
      procedure :: rollback => joint_state_rollback
      procedure :: count_modes => joint_state_count_modes
   end type joint_state_t

contains

   !> Accepts the trial values of every point.
   subroutine joint_state_commit(this)
      class(joint_state_t), intent(inout) :: this
      integer :: s
      if (.not. allocated(this%sets)) return
      do s = 1, size(this%sets)
         associate (st => this%sets(s))
            st%eps = st%eps_trial
            st%sigma = st%sigma_trial
            st%hist = st%hist_trial
            st%mode = st%mode_trial
         end associate
      end do
   end subroutine joint_state_commit

   !> Discards the trial values (an increment that is cut).
   subroutine joint_state_rollback(this)
      class(joint_state_t), intent(inout) :: this
      integer :: s
      if (.not. allocated(this%sets)) return
      do s = 1, size(this%sets)
         associate (st => this%sets(s))
            st%eps_trial = st%eps
            st%sigma_trial = st%sigma
            st%hist_trial = st%hist
            st%mode_trial = st%mode
         end associate
      end do
   end subroutine joint_state_rollback

   !> Converged points in slip and in separation over all joint sets.
   pure subroutine joint_state_count_modes(this, nslip, nopen)
      class(joint_state_t), intent(in) :: this
      integer, intent(out) :: nslip, nopen
      integer :: s
      nslip = 0; nopen = 0
      if (.not. allocated(this%sets)) return
      do s = 1, size(this%sets)
         nslip = nslip + count(this%sets(s)%mode == MODE_SLIP)
         nopen = nopen + count(this%sets(s)%mode == MODE_OPEN)
      end do
   end subroutine joint_state_count_modes

end module pecplas_joints_state
