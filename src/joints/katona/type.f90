!> Katona contact (doc/theory.md §6.5, thesis (I.12)–(I.14)): the node doublets of every joint
!> set held by Katona contact (joint_set_t%is_katona, a law of TYPE=KATONA), their contact
!> states and multipliers, and the run counters. Held by the driver's problem_t; built by
!> pecplas_joints_katona_doublets, solved by pecplas_solve_katona_increment.
!>
!> Conventions are the laws' (pecplas_joints_laws_type): per doublet k the relative displacement
!> z = (eps_n, eps_t) = Dk U with eps_n = -g_n closure positive, and the multipliers are the
!> contact forces f = (N, T), N compression positive, so that the equilibrium reads
!> R U + D^T f = F (D^T f is the interface's internal force, like joint_force).
module pecplas_joints_katona_type
   use pecplas_base_kinds, only: wp
   use pecplas_joints_laws_type, only: MODE_STICK, MODE_SLIP, MODE_OPEN
   implicit none (type, external)
   private

   public :: katona_t

   type :: katona_t
      !> True when the model has at least one Katona doublet.
      logical :: active = .false.
      !> Number of doublets.
      integer :: nd = 0
      !> Face-1 and face-2 node of each doublet (2, nd), its joint set.
      integer, allocatable :: node(:, :), set_of(:)
      !> Unit tangent t (2, nd) (n = (-t_y, t_x) from face 1 into face 2), tributary measure
      !> (length x thickness, or area), initial gap along n (>= 0; 0 for coincident nodes).
      real(wp), allocatable :: t(:, :), area(:), gap0(:)
      !> Per doublet: friction coefficient, cohesive force c A, tensile strength force T A.
      real(wp), allocatable :: mu(:), cohesion(:), tension(:)
      !> Converged state: mode (stick / slip / open), slip sign, broken bond, contact force
      !> f(2, nd) = (N, T), relative displacement z(2, nd), stick anchor of eps_t.
      integer, allocatable :: mode(:), sgn(:)
      logical, allocatable :: broken(:)
      real(wp), allocatable :: f(:, :), z(:, :), anchor(:)
      !> Doublets of a joint set a phase has deactivated: open, no force, whatever their
      !> relative displacement (pecplas_phases_start).
      logical, allocatable :: off(:)
      !> Trial values of the current increment.
      integer, allocatable :: mode_trial(:), sgn_trial(:)
      real(wp), allocatable :: f_trial(:, :), z_trial(:, :), anchor_trial(:)
      !> Augmentation alpha of R_a = R + alpha D^T D (0: R alone is regular).
      real(wp) :: alpha = 0.0_wp
      !> Flexibility G = D R_a^-1 D^T (2 nd, 2 nd) and the factorisation count it belongs to.
      real(wp), allocatable :: g(:, :)
      integer :: g_stamp = -1
      !> Counters: state iterations (total and largest in one increment), flexibility builds,
      !> frozen (chattering) doublets, state iterations of the last increment.
      integer :: state_iterations = 0, max_state_iterations = 0, g_builds = 0
      integer :: frozen = 0, last_state_iterations = 0
      !> Largest interpenetration (eps_n - gap0 of a doublet in contact) over converged
      !> increments, and the largest over open doublets (should be <= 0).
      real(wp) :: max_penetration = 0.0_wp
      !> Largest force reference of the converged increments (loads, reactions, contact
      !> forces): the scale of the roundoff floor of the residual.
      real(wp) :: force_scale = 0.0_wp
      !> Wall time spent building G and in the state iterations (dense solves).
      real(wp) :: time_flexibility = 0.0_wp, time_states = 0.0_wp
   contains
      procedure :: allocate_states => katona_allocate_states
      procedure :: begin_increment => katona_begin_increment
      procedure :: commit => katona_commit
      procedure :: count_modes => katona_count_modes
   end type katona_t

contains

   !> Allocates the state arrays for nd doublets: bonded, unbroken, zero force.
   subroutine katona_allocate_states(this)
      class(katona_t), intent(inout) :: this
      integer :: n
      n = this%nd
      allocate (this%mode(n), source=MODE_STICK)
      allocate (this%sgn(n), source=0)
      allocate (this%broken(n), source=.false.)
      allocate (this%f(2, n), this%z(2, n), source=0.0_wp)
      allocate (this%anchor(n), source=0.0_wp)
      allocate (this%off(n), source=.false.)
      this%mode_trial = this%mode
      this%sgn_trial = this%sgn
      this%f_trial = this%f
      this%z_trial = this%z
      this%anchor_trial = this%anchor
   end subroutine katona_allocate_states

   !> Trial state = converged state (start of an increment, also after a cut).
   subroutine katona_begin_increment(this)
      class(katona_t), intent(inout) :: this
      this%mode_trial = this%mode
      this%sgn_trial = this%sgn
      this%f_trial = this%f
      this%z_trial = this%z
      this%anchor_trial = this%anchor
   end subroutine katona_begin_increment

   !> Accepts the trial state. The anchor of a doublet not in stick follows it, so that the
   !> slip of the next increment is measured from where it ends this one.
   subroutine katona_commit(this)
      class(katona_t), intent(inout) :: this
      where (this%mode_trial /= MODE_STICK) this%anchor_trial = this%z_trial(2, :)
      ! a bond breaks when an increment ends with the doublet open, not when an iterate of
      ! the state iteration opens it
      where (this%mode_trial == MODE_OPEN) this%broken = .true.
      this%mode = this%mode_trial
      this%sgn = this%sgn_trial
      this%f = this%f_trial
      this%z = this%z_trial
      this%anchor = this%anchor_trial
   end subroutine katona_commit

   !> Converged doublets in each mode.
   pure subroutine katona_count_modes(this, nstick, nslip, nopen)
      class(katona_t), intent(in) :: this
      integer, intent(out) :: nstick, nslip, nopen
      nstick = 0; nslip = 0; nopen = 0
      if (.not. allocated(this%mode)) return
      nstick = count(this%mode == MODE_STICK)
      nslip = count(this%mode == MODE_SLIP)
      nopen = count(this%mode == MODE_OPEN)
   end subroutine katona_count_modes

end module pecplas_joints_katona_type
