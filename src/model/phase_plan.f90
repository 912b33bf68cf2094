!> The plan of a phased run, from the model alone: which element and joint sets are active
!> before each step, which nodes an active element or joint holds, and whether the deck is
!> phased at all. Used by the deck reader (to check the phases) and by pecplas_phases_start
!> (to apply them).
module pecplas_model_phase_plan
   use pecplas_model_type, only: model_t
   use pecplas_model_phases, only: CHANGE_DEACTIVATE, CHANGE_ACTIVATE, TARGET_ELEMENTS, &
      TARGET_JOINTS, TARGET_PATTERNS, TARGET_SUPPORTS, TARGET_PLATES, TARGET_ANCHORS
   implicit none (type, external)
   private

   public :: is_phased, initial_activity, step_activity, attached_nodes, massif_nodes, &
      target_activity, target_count, plate_activity, initial_anchor_activity

contains

   !> A deck is phased when a step changes the model (a phase change or
   !> RESET_DISPLACEMENTS) or drives no pattern (a nil step; a safety step, which drives none
   !> either, does not count: it starts from whatever state the steps before left). A deck
   !> that is not phased runs as before phases existed, to the last bit.
   pure logical function is_phased(model)
      type(model_t), intent(in) :: model
      integer :: i
      is_phased = .false.
      if (.not. allocated(model%steps)) return
      ! groundwater: the pore pressures of each phase come in through its start
      is_phased = model%water%used()
      do i = 1, size(model%steps)
         associate (st => model%steps(i))
            if (st%safety%on) cycle
            if (st%reset_displacements) is_phased = .true.
            if (allocated(st%changes)) then
               if (size(st%changes) > 0) is_phased = .true.
            end if
            if (allocated(st%pattern)) then
               if (size(st%pattern) == 0) is_phased = .true.
            end if
         end associate
      end do
   end function is_phased

   !> Activity before the first step: a set whose first mention in the steps is an
   !> *ACTIVATE is inactive until then; every other set is active.
   pure subroutine initial_activity(model, eactive, jactive)
      type(model_t), intent(in) :: model
      logical, allocatable, intent(out) :: eactive(:), jactive(:)
      logical, allocatable :: eseen(:), jseen(:)
      integer :: i, c, nj
      nj = 0
      if (allocated(model%joint_sets)) nj = size(model%joint_sets)
      allocate (eactive(size(model%mesh%esets)), eseen(size(model%mesh%esets)), source=.false.)
      allocate (jactive(nj), jseen(nj), source=.false.)
      eactive = .true.
      jactive = .true.
      if (.not. allocated(model%steps)) return
      do i = 1, size(model%steps)
         if (.not. allocated(model%steps(i)%changes)) cycle
         do c = 1, size(model%steps(i)%changes)
            associate (ch => model%steps(i)%changes(c))
               if (ch%set < 1) cycle
               if (ch%target == TARGET_ELEMENTS) then
                  if (.not. eseen(ch%set)) eactive(ch%set) = ch%kind /= CHANGE_ACTIVATE
                  eseen(ch%set) = .true.
               else if (ch%target == TARGET_JOINTS) then
                  if (.not. jseen(ch%set)) jactive(ch%set) = ch%kind /= CHANGE_ACTIVATE
                  jseen(ch%set) = .true.
               end if
            end associate
         end do
      end do
   end subroutine initial_activity

   !> How many things of kind `target` the model has (element sets, joint sets, load
   !> patterns, named supports).
   pure integer function target_count(model, target) result(n)
      type(model_t), intent(in) :: model
      integer, intent(in) :: target
      n = 0
      select case (target)
      case (TARGET_ELEMENTS)
         n = size(model%mesh%esets)
      case (TARGET_JOINTS)
         if (allocated(model%joint_sets)) n = size(model%joint_sets)
      case (TARGET_PATTERNS)
         if (allocated(model%patterns)) n = size(model%patterns)
      case (TARGET_SUPPORTS)
         if (allocated(model%supports%names)) n = size(model%supports%names)
      case (TARGET_PLATES)
         if (allocated(model%plates)) n = size(model%plates)
      case (TARGET_ANCHORS)
         if (allocated(model%anchors)) n = size(model%anchors)
      end select
   end function target_count

   !> Whether each thing of kind `target` is active in step `istep` once its changes are
   !> applied (istep = 0: before the first step). A thing whose first mention in the steps
   !> is an *ACTIVATE is inactive until then; every other one is active. (Joint sets that a
   !> deactivation leaves hanging are not followed here: step_activity.)
   pure function target_activity(model, target, istep) result(on)
      type(model_t), intent(in) :: model
      integer, intent(in) :: target, istep
      logical, allocatable :: on(:), seen(:)
      integer :: i, c
      allocate (on(target_count(model, target)), source=.true.)
      allocate (seen(size(on)), source=.false.)
      if (.not. allocated(model%steps)) return
      do i = 1, size(model%steps)
         if (.not. allocated(model%steps(i)%changes)) cycle
         do c = 1, size(model%steps(i)%changes)
            associate (ch => model%steps(i)%changes(c))
               if (ch%target /= target .or. ch%set < 1) cycle
               if (ch%kind /= CHANGE_ACTIVATE .and. ch%kind /= CHANGE_DEACTIVATE) cycle
               if (.not. seen(ch%set)) on(ch%set) = ch%kind /= CHANGE_ACTIVATE
               seen(ch%set) = .true.
            end associate
         end do
      end do
      do i = 1, min(istep, size(model%steps))
         if (.not. allocated(model%steps(i)%changes)) cycle
         do c = 1, size(model%steps(i)%changes)
            associate (ch => model%steps(i)%changes(c))
               if (ch%target /= target .or. ch%set < 1) cycle
               if (ch%kind /= CHANGE_ACTIVATE .and. ch%kind /= CHANGE_DEACTIVATE) cycle
               on(ch%set) = ch%kind == CHANGE_ACTIVATE
            end associate
         end do
      end do
   end function target_activity

   !> Applies the activations and deactivations of step `istep` to the masks. A joint set
   !> one of whose nodes loses its last active massif element (a node that had one) is
   !> deactivated with it: `dropped(j)` is true for those joint sets (not named by the step).
   pure subroutine step_activity(model, istep, eactive, jactive, dropped)
      type(model_t), intent(in) :: model
      integer, intent(in) :: istep
      logical, intent(inout) :: eactive(:), jactive(:)
      logical, allocatable, intent(out) :: dropped(:)
      logical, allocatable :: held(:), massif(:)
      integer :: c, j
      allocate (dropped(size(jactive)), source=.false.)
      if (.not. allocated(model%steps(istep)%changes)) return
      do c = 1, size(model%steps(istep)%changes)
         associate (ch => model%steps(istep)%changes(c))
            if (ch%kind /= CHANGE_ACTIVATE .and. ch%kind /= CHANGE_DEACTIVATE) cycle
            if (ch%target == TARGET_ELEMENTS) then
               eactive(ch%set) = ch%kind == CHANGE_ACTIVATE
            else if (ch%target == TARGET_JOINTS) then
               jactive(ch%set) = ch%kind == CHANGE_ACTIVATE
            end if
         end associate
      end do
      if (size(jactive) == 0) return
      massif = massif_nodes(model)
      held = attached_nodes(model, eactive, [(.false., j=1, size(jactive))])
      do j = 1, size(jactive)
         if (.not. jactive(j)) cycle
         if (any(massif(nodes_of(model%joint_sets(j)%conn)) .and. &
                 .not. held(nodes_of(model%joint_sets(j)%conn)))) then
            jactive(j) = .false.
            dropped(j) = .true.
         end if
      end do
   end subroutine step_activity

   !> Nodes of an active element of an active element set, of an active joint set or of an
   !> active plate set (`pactive`; absent: every plate), and of an active anchor set when
   !> `aactive` is given.
   pure function attached_nodes(model, eactive, jactive, pactive, aactive) result(held)
      type(model_t), intent(in) :: model
      logical, intent(in) :: eactive(:), jactive(:)
      logical, intent(in), optional :: pactive(:), aactive(:)
      logical, allocatable :: held(:)
      integer :: s
      allocate (held(model%mesh%nnode()), source=.false.)
      do s = 1, size(model%mesh%esets)
         if (eactive(s)) held(nodes_of(model%mesh%esets(s)%conn)) = .true.
      end do
      do s = 1, size(jactive)
         if (jactive(s)) held(nodes_of(model%joint_sets(s)%conn)) = .true.
      end do
      if (present(aactive)) then
         do s = 1, size(aactive)
            if (aactive(s)) held(nodes_of(model%anchors(s)%conn)) = .true.
         end do
      end if
      if (.not. allocated(model%plates)) return
      do s = 1, size(model%plates)
         if (present(pactive)) then
            if (.not. pactive(s)) cycle
         end if
         held(nodes_of(model%plates(s)%conn)) = .true.
      end do
   end function attached_nodes

   !> Activity of the plate sets in step `istep` (target_activity of TARGET_PLATES).
   pure function plate_activity(model, istep) result(pactive)
      type(model_t), intent(in) :: model
      integer, intent(in) :: istep
      logical, allocatable :: pactive(:)
      pactive = target_activity(model, TARGET_PLATES, istep)
   end function plate_activity

   !> Activity of the anchor sets before the first step (target_activity of TARGET_ANCHORS).
   pure function initial_anchor_activity(model) result(aactive)
      type(model_t), intent(in) :: model
      logical, allocatable :: aactive(:)
      aactive = target_activity(model, TARGET_ANCHORS, 0)
   end function initial_anchor_activity

   !> Nodes of any massif element (active or not).
   pure function massif_nodes(model) result(held)
      type(model_t), intent(in) :: model
      logical, allocatable :: held(:)
      integer :: s
      allocate (held(model%mesh%nnode()), source=.false.)
      do s = 1, size(model%mesh%esets)
         held(nodes_of(model%mesh%esets(s)%conn)) = .true.
      end do
   end function massif_nodes

   !> The node numbers of a connectivity table (no zero entries).
   pure function nodes_of(conn) result(nodes)
      integer, intent(in) :: conn(:, :)
      integer, allocatable :: nodes(:)
      nodes = pack(conn, conn > 0)
   end function nodes_of

end module pecplas_model_phase_plan
