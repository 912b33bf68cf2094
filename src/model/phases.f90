!> What a phase changes in the model (doc/deck.md, Phases): a *STEP may, at its start,
!> deactivate or activate element sets, joint sets, load patterns and named supports, change the material of an element
!> set or the law of a joint set, and reset the displacements. The action (applying the
!> changes to a run's state) is in pecplas_phases_start.
module pecplas_model_phases
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: phase_change_t
   public :: CHANGE_DEACTIVATE, CHANGE_ACTIVATE, CHANGE_MATERIAL, CHANGE_LAW, CHANGE_NAMES
   public :: TARGET_ELEMENTS, TARGET_JOINTS, TARGET_PATTERNS, TARGET_SUPPORTS, TARGET_NAMES
   public :: TARGET_PLATES, TARGET_ANCHORS, CHANGE_PRESTRESS
   public :: START_ZERO, START_WISHED

   !> Kinds of change, and their deck keywords CHANGE_NAMES(kind).
   integer, parameter :: CHANGE_DEACTIVATE = 1, CHANGE_ACTIVATE = 2, CHANGE_MATERIAL = 3, &
      CHANGE_LAW = 4, CHANGE_PRESTRESS = 5
   character(len=*), parameter :: CHANGE_NAMES(5) = [character(len=16) :: '*DEACTIVATE', &
      '*ACTIVATE', '*CHANGE_MATERIAL', '*CHANGE_LAW', '*PRESTRESS']
   !> What a change acts on: an element set (model%mesh%esets), a joint set
   !> (model%joint_sets), a load pattern (model%patterns), a named support group
   !> (model%supports%names), a plate set (model%plates: activated and deactivated only) or
   !> an anchor set (model%anchors: activated, deactivated, prestressed).
   !> TARGET_NAMES(target) names each in messages. A new kind of
   !> thing that phases switch adds its value here, its lookup in the deck reader
   !> (pecplas_io_deck_reader_phases) and its action in pecplas_phases_start.
   integer, parameter :: TARGET_ELEMENTS = 1, TARGET_JOINTS = 2, TARGET_PATTERNS = 3, &
      TARGET_SUPPORTS = 4, TARGET_PLATES = 5, TARGET_ANCHORS = 6
   character(len=*), parameter :: TARGET_NAMES(6) = [character(len=12) :: 'element set', &
      'joint set', 'load pattern', 'support', 'plate set', 'anchor']
   !> How an activated element set starts: stress-free, or with the initial (*INITIAL_STRESS)
   !> stress of the ground it replaces ("wished in place").
   integer, parameter :: START_ZERO = 0, START_WISHED = 1

   !> One change of a phase, resolved to indices.
   type :: phase_change_t
      integer :: kind = 0
      integer :: target = TARGET_ELEMENTS
      !> Index of the element set, joint set, pattern or support group (by `target`).
      integer :: set = 0
      !> CHANGE_MATERIAL: index in model%materials; CHANGE_LAW: index in model%laws.
      integer :: new = 0
      !> CHANGE_ACTIVATE of an element set: START_ZERO or START_WISHED.
      integer :: start = START_ZERO
      !> CHANGE_PRESTRESS: the prestress force of one anchor [force].
      real(wp) :: value = 0.0_wp
      !> Names as written (messages, results) and deck position.
      character(len=:), allocatable :: set_name, new_name
      character(len=:), allocatable :: file
      integer :: line = 0
   end type phase_change_t

end module pecplas_model_phases
