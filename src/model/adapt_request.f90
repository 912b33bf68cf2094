!> What the deck (`*ADAPT`) or the command line (`--target-error`, `--goal`, `--max-dofs`) asks
!> of the adaptive loop (pecplas_adapt_adapt), and the parsing of its values, shared by both.
module pecplas_model_adapt_request
   use pecplas_base_kinds, only: wp
   use pecplas_model_mesh, only: mesh_t
   implicit none (type, external)
   private

   public :: adapt_request_t, goal_spec_t, parse_target, parse_goal, parse_goal_spec, &
      goal_node_index
   public :: GOAL_ENERGY, GOAL_NODE, GOAL_REACTION, GOAL_LIMIT, GOAL_FORMS

   !> Goal kinds: the energy norm, a node's displacement component, the resultant of the
   !> reactions on a node set, the limit load of the run.
   integer, parameter :: GOAL_ENERGY = 0, GOAL_NODE = 1, GOAL_REACTION = 2, GOAL_LIMIT = 3

   !> The accepted goal forms, for error messages.
   character(len=*), parameter :: GOAL_FORMS = 'energy, node:N:x, node:N:y, reaction:SET, '// &
      'reaction:SET:x, reaction:SET:y (r, z, 1, 2 for x, y) or limit'

   type :: adapt_request_t
      !> True when the deck has *ADAPT.
      logical :: given = .false.
      !> TARGET and GOAL as written ('' goal: the energy norm); MAX_DOFS (0: the default).
      character(len=:), allocatable :: target, goal
      integer :: max_dofs = 0
      !> Deck line index of *ADAPT (for errors found once the mesh is known).
      integer :: at = 0
   end type adapt_request_t

   !> A parsed goal: its kind, the node's deck id (node goal; 0 when the node is named by a
   !> node set of one node), the node set's name (reaction goal, or node goal by set) and
   !> the component (1 x/r, 2 y/z; 0 for a reaction: the loaded direction).
   type :: goal_spec_t
      integer :: kind = GOAL_ENERGY
      integer :: node_id = 0, dof = 0
      character(len=:), allocatable :: set
   end type goal_spec_t

contains

   !> "1%", "1 %" or "0.01": a relative error in (0, 1).
   subroutine parse_target(text, value, msg)
      character(len=*), intent(in) :: text
      real(wp), intent(out) :: value
      character(len=:), allocatable, intent(out) :: msg
      integer :: ios, p
      p = index(text, '%')
      value = 0.0_wp
      if (p > 0) then
         read (text(1:p - 1), *, iostat=ios) value
         value = value/100.0_wp
      else
         read (text, *, iostat=ios) value
      end if
      if (ios /= 0 .or. .not. (value > 0.0_wp .and. value < 1.0_wp)) msg = &
         "expected a relative error such as 1% or 0.01, got '"//trim(text)//"'"
   end subroutine parse_target

   !> "" or "energy", "node:N:d" (N a node id or a set name), "reaction:SET" or
   !> "reaction:SET:d" (d one of x y r z 1 2),
   !> "limit". `msg` names the accepted forms when `text` is none of them.
   subroutine parse_goal_spec(text, goal, msg)
      character(len=*), intent(in) :: text
      type(goal_spec_t), intent(out) :: goal
      character(len=:), allocatable, intent(out) :: msg
      character(len=:), allocatable :: t, rest
      integer :: q, ios
      t = trim(adjustl(text))
      if (len(t) == 0 .or. t == 'energy' .or. t == 'ENERGY') return
      if (t == 'limit' .or. t == 'LIMIT') then
         goal%kind = GOAL_LIMIT
         return
      end if
      msg = 'expected '//GOAL_FORMS//", got '"//t//"' (N: a node id or a node set of one "// &
         'node)'
      if (index(t, 'node:') == 1) then
         rest = t(6:)
         q = index(rest, ':')
         if (q < 2) return
         if (verify(rest(1:q - 1), '0123456789') == 0) then
            read (rest(1:q - 1), *, iostat=ios) goal%node_id
            if (ios /= 0 .or. goal%node_id <= 0) return
         else
            ! a node set of one node, resolved with the mesh (goal_node_index)
            goal%set = rest(1:q - 1)
            if (scan(goal%set, ' ,=') > 0) return
         end if
         goal%dof = component(rest(q + 1:))
         if (goal%dof == 0) return
         goal%kind = GOAL_NODE
      else if (index(t, 'reaction:') == 1) then
         rest = t(10:)
         q = index(rest, ':')
         if (q == 0) then
            goal%set = rest
         else
            goal%set = rest(1:q - 1)
            goal%dof = component(rest(q + 1:))
            if (goal%dof == 0) return
         end if
         if (len(goal%set) == 0 .or. scan(goal%set, ' ,=') > 0) return
         goal%kind = GOAL_REACTION
      else
         return
      end if
      deallocate (msg)
   end subroutine parse_goal_spec

   !> 1 for x, r, 1; 2 for y, z, 2; 0 otherwise.
   pure integer function component(text) result(dof)
      character(len=*), intent(in) :: text
      select case (text)
      case ('x', 'X', 'r', 'R', '1')
         dof = 1
      case ('y', 'Y', 'z', 'Z', '2')
         dof = 2
      case default
         dof = 0
      end select
   end function component

   !> The internal node of a node goal: its node id, or the node of its node set of one
   !> node (mesh_t%node_of). inode = 0 and `msg` (naming the goal) when the mesh has none.
   subroutine goal_node_index(goal, mesh, inode, msg)
      type(goal_spec_t), intent(in) :: goal
      type(mesh_t), intent(in) :: mesh
      integer, intent(out) :: inode
      character(len=:), allocatable, intent(out) :: msg
      character(len=12) :: buf
      if (allocated(goal%set)) then
         call mesh%node_of(goal%set, inode, msg)
      else
         write (buf, '(i0)') goal%node_id
         call mesh%node_of(trim(buf), inode, msg)
         if (allocated(msg)) msg = 'the deck has no node '//trim(buf)
      end if
   end subroutine goal_node_index

   !> The node and energy goals only (node_id 0: energy), for callers that take no other
   !> goal; `msg` is set for every other text.
   subroutine parse_goal(text, node_id, dof, msg)
      character(len=*), intent(in) :: text
      integer, intent(out) :: node_id, dof
      character(len=:), allocatable, intent(out) :: msg
      type(goal_spec_t) :: goal
      call parse_goal_spec(text, goal, msg)
      node_id = goal%node_id
      dof = goal%dof
      if (.not. allocated(msg) .and. goal%kind /= GOAL_NODE .and. goal%kind /= GOAL_ENERGY) &
         msg = "expected node:N:x, node:N:y (r, z, 1, 2 too) or energy, got '"//trim(text)//"'"
   end subroutine parse_goal

end module pecplas_model_adapt_request
