!> Load patterns, supports and load steps.
!> A pattern is a fixed spatial distribution (forces, pressures, body forces, imposed
!> displacements); a step drives the factor of each pattern it names linearly to a target
!> over its increments. Patterns a step does not name keep their factor.
module pecplas_model_loads
   use pecplas_base_kinds, only: wp
   use pecplas_model_phases, only: phase_change_t
   use pecplas_model_safety, only: safety_plan_t
   implicit none (type, external)
   private

   public :: load_pattern_t, step_t, support_t
   public :: LOAD_KINDS, load_kind

   !> Kinds of pattern; LOAD_KINDS(k) is the deck word of kind k (*LOAD, TYPE=...).
   enum, bind(c)
      enumerator :: LOAD_FORCE = 1, LOAD_PRESSURE, LOAD_BODY_FORCE, LOAD_GRAVITY, LOAD_DISPLACEMENT
      enumerator :: LOAD_PLATE
   end enum
   public :: LOAD_FORCE, LOAD_PRESSURE, LOAD_BODY_FORCE, LOAD_GRAVITY, LOAD_DISPLACEMENT
   public :: LOAD_PLATE
   character(len=*), parameter :: LOAD_KINDS(6) = [character(len=12) :: 'FORCE', 'PRESSURE', &
      'BODY_FORCE', 'GRAVITY', 'DISPLACEMENT', 'PLATE_LOAD']

   type :: load_pattern_t
      character(len=:), allocatable :: name
      !> LOAD_FORCE, LOAD_PRESSURE, LOAD_BODY_FORCE, LOAD_GRAVITY or LOAD_DISPLACEMENT.
      integer :: kind = 0
      !> FORCE / DISPLACEMENT: one entry per (node, dof): value = force or displacement
      !> at factor 1. dof 1 = x (r), 2 = y (z), 3 = rotation of a plate node (a moment, an
      !> imposed rotation).
      integer, allocatable :: node(:), dof(:)
      real(wp), allocatable :: value(:)
      !> PRESSURE: edges (3, n) as in edge_set_t (third node 0 for 2-node edges) and the
      !> pressure of each edge (positive = pushing into the body): p_ref + gradient (y_ref - y)
      !> with p_ref = pressure(k), gradient = pressure_gradient(k), y_ref = pressure_y_ref(k)
      !> (gradient 0: uniform; the gradient arrays may be absent: all uniform), and when
      !> `floored`, max(p_min, p).
      integer, allocatable :: edge(:, :)
      real(wp), allocatable :: pressure(:), pressure_gradient(:), pressure_y_ref(:)
      logical :: floored = .false.
      real(wp) :: p_min = 0.0_wp
      !> BODY_FORCE: element sets and force per unit volume (2, n);
      !> GRAVITY: element sets and unit direction (2, n), magnitude = material unit weight.
      integer, allocatable :: eset(:)
      real(wp), allocatable :: vector(:, :)
      !> PLATE_LOAD: plate sets (index in model%plates) and the load per unit length of
      !> plate (2, n), global x, y; GRAVITY naming a plate set: the set and the unit
      !> direction (2, n), magnitude the plate's weight w.
      integer, allocatable :: plate(:)
      real(wp), allocatable :: plate_vector(:, :)
   end type load_pattern_t

   !> Length of a support group's name.
   integer, parameter, public :: SUPPORT_NAME_LEN = 64

   !> Fixed (zero) displacements, one entry per (node, dof) and group; dof 3: the rotation
   !> of a plate node.
   type :: support_t
      integer, allocatable :: node(:), dof(:)
      !> Group of each entry: 0 for an unnamed *BOUNDARY (always active), g > 0 for the
      !> *BOUNDARY, NAME=names(g) that a phase may activate or deactivate. May be absent
      !> (every entry permanent).
      integer, allocatable :: group(:)
      character(len=SUPPORT_NAME_LEN), allocatable :: names(:)
   end type support_t

   type :: step_t
      character(len=:), allocatable :: name
      integer :: increments = 1
      !> Arc-length control (the load factor of the step is an unknown of each increment);
      !> else load control (fixed fractions of the step).
      logical :: arc_length = .false.
      !> Arc-length: the most increments of the step, the iterations an increment should take
      !> (its length adapts to them), the length bounds as multiples of the first one.
      integer :: max_increments = 0, iterations_wanted = 6
      real(wp) :: min_length = 1.0e-4_wp, max_length = 10.0_wp
      !> Arc-length: stop when node `node` (internal index; 0 none) reaches displacement
      !> `displacement` along `dof` (1 = x/r, 2 = y/z).
      integer :: node = 0, dof = 0
      real(wp) :: displacement = 0.0_wp
      !> Patterns named in the step and their factor at its end.
      integer, allocatable :: pattern(:)
      real(wp), allocatable :: target(:)
      !> Phase changes at the start of the step (*DEACTIVATE, *ACTIVATE, *CHANGE_MATERIAL,
      !> *CHANGE_LAW: pecplas_model_phases), in deck order; none for an ordinary step.
      type(phase_change_t), allocatable :: changes(:)
      !> RESET_DISPLACEMENTS=YES: the displacements restart at zero at the step start
      !> (stresses and histories kept).
      logical :: reset_displacements = .false.
      !> CONTROL=SAFETY: a strength-reduction step (pecplas_model_safety).
      type(safety_plan_t) :: safety
      !> Deck position of the step (for messages).
      character(len=:), allocatable :: file
      integer :: line = 0
   end type step_t

contains

   !> The kind whose deck word is `word` (upper case, as in LOAD_KINDS); 0 for none.
   pure integer function load_kind(word) result(kind)
      character(len=*), intent(in) :: word
      integer :: k
      kind = 0
      do k = 1, size(LOAD_KINDS)
         if (trim(LOAD_KINDS(k)) == trim(word)) kind = k
      end do
   end function load_kind

end module pecplas_model_loads
