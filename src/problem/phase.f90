!> Where a phased run stands (doc/theory.md, Phases): the phase whose changes are in force,
!> the load each element set holds while it is active, and the out-of-balance carried from
!> the start of the current phase. Not used (empty) by a deck that is not phased.
module pecplas_problem_phase
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: phase_state_t, HOLD_NONE, HOLD_WEIGHT, PROCEDURE_NONE, PROCEDURE_K0, PROCEDURE_GRAVITY, PROCEDURE_NAMES

   !> How the initial stresses of a phased run come about: none (no *INITIAL_STRESS and no
   !> gravity pattern), the K0 procedure (*INITIAL_STRESS: the stresses are the state, the
   !> weight of the active sets the load), gravity loading (a GRAVITY pattern applied by
   !> the steps, no *INITIAL_STRESS).
   integer, parameter :: PROCEDURE_NONE = 0, PROCEDURE_K0 = 1, PROCEDURE_GRAVITY = 2
   character(len=*), parameter :: PROCEDURE_NAMES(0:2) = [character(len=15) :: 'none', &
      'K0 procedure', 'gravity loading']

   !> phase_state_t%hold values (a positive value indexes phase_state_t%homogeneous).
   integer, parameter :: HOLD_NONE = 0, HOLD_WEIGHT = -1

   type :: phase_state_t
      !> The deck is phased (pecplas_model_phase_plan's is_phased).
      logical :: phased = .false.
      !> Step whose phase changes have been applied (0: none yet).
      integer :: index = 0
      integer :: procedure = PROCEDURE_NONE
      !> What each element set holds while it is active (nset): HOLD_NONE, HOLD_WEIGHT (its
      !> weight: a GEOSTATIC initial stress) or k > 0, the nodal forces of its HOMOGENEOUS
      !> initial stress, kept in homogeneous(:, :, k) (2, nnode, number of such sets).
      integer, allocatable :: hold(:)
      real(wp), allocatable :: homogeneous(:, :, :)
      !> The out-of-balance of the K0 state (2, nnode): the nodal forces of the initial
      !> stresses of the whole model (every set and joint active) less what the sets hold.
      !> Held with the load, as without phases, until the first nil step (no pattern line,
      !> no change) releases it (`released`).
      real(wp), allocatable :: unbalanced(:, :)
      logical :: released = .false.
      !> The norm of the force entries of the held load of the initial state on the free
      !> equations (its weight, the water on its faces and plates): the scale the held
      !> out-of-balance is measured against (pecplas_solve_held_warning).
      real(wp) :: held0_norm = 0.0_wp
      !> The reactions of the K0 state (2, nnode; zero on the free equations): the reference of
      !> the convergence test measures the reactions from them, as a deck without phases does
      !> (pecplas_solve_residual's free_residual), so that the weight does not loosen it.
      real(wp), allocatable :: base_reaction(:, :)
      !> The out-of-balance of the phase start (2, nnode), on the free equations: added to
      !> the external load at the start of the step and taken to zero along the step's load
      !> path (pecplas_solve_residual's load_vectors).
      real(wp), allocatable :: carried(:, :)
      !> Whether each load pattern and each named support (model%supports%names) is active
      !> in the phase in force (pecplas_model_phase_plan's target_activity).
      logical, allocatable :: patterns_on(:), supports_on(:)
      !> The displacements at which the active supports hold their dofs (2, nnode): those
      !> of the nodes when the support was activated (zero for a support active from the
      !> start); added to the imposed displacements (pecplas_solve_residual's load_vectors).
      real(wp), allocatable :: held_u(:, :)
      !> The equations were numbered again at the start of the phase in force (a support
      !> activated or released): vectors of the old numbering are void.
      logical :: renumbered = .false.
      !> The contact forces (2, ndoublet) of the Katona doublets in the initial state (before
      !> the sets inactive at the start go off): where a set activated with
      !> STRESS=WISHED_IN_PLACE starts.
      real(wp), allocatable :: katona_f0(:, :)
      !> Under gravity loading with groundwater: the GRAVITY pattern the water comes in with
      !> (doc/theory.md, Groundwater): the held load holds the forces of the steady pore
      !> pressures, and this pattern's vector carries the water on the faces less them, so
      !> that the pore pressures act in proportion to its factor (0: none, the water held).
      integer :: water_pattern = 0
   end type phase_state_t

end module pecplas_problem_phase
