!> What the deck (`*ADAPT`) or the command line (`--target-error`, `--goal`, `--max-dofs`) asks
!> of the adaptive loop (pecplas_driver_adapt), and the parsing of its values, shared by both.
module pecplas_model_adapt_request
   use pecplas_kinds, only: wp
   implicit none (type, external)
   private

   public :: adapt_request_t, parse_target, parse_goal

   type :: adapt_request_t
      !> True when the deck has *ADAPT.
      logical :: given = .false.
      !> TARGET and GOAL as written ('' goal: the energy norm); MAX_DOFS (0: the default).
      character(len=:), allocatable :: target, goal
      integer :: max_dofs = 0
   end type adapt_request_t

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

   !> "" or "energy" (node_id 0) or "node:N:x|y|r|z|1|2".
   subroutine parse_goal(text, node_id, dof, msg)
      character(len=*), intent(in) :: text
      integer, intent(out) :: node_id, dof
      character(len=:), allocatable, intent(out) :: msg
      integer :: p, q, ios
      node_id = 0
      dof = 0
      if (len_trim(text) == 0 .or. trim(text) == 'energy') return
      msg = "expected node:N:x, node:N:y (r, z, 1, 2 too) or energy, got '"//trim(text)//"'"
      if (index(text, 'node:') /= 1) return
      p = 6
      q = index(text(p:), ':')
      if (q == 0) return
      read (text(p:p + q - 2), *, iostat=ios) node_id
      if (ios /= 0 .or. node_id <= 0) return
      select case (trim(text(p + q:)))
      case ('x', 'X', 'r', 'R', '1')
         dof = 1
      case ('y', 'Y', 'z', 'Z', '2')
         dof = 2
      case default
         return
      end select
      deallocate (msg)
   end subroutine parse_goal

end module pecplas_model_adapt_request
