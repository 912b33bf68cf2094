!> The PECPLAS element type that an element name of another program means, for the message
!> of an unknown element type: an Abaqus user writes `CPE8R`, a PLAXIS user thinks of the
!> 6- or 15-node triangle. Only names with a true equivalent are mapped.
module pecplas_io_deck_element_aliases
   use pecplas_base_strings, only: upper
   implicit none (type, external)
   private

   public :: element_alias_hint

contains

   !> ' (Abaqus CPE8R is Q8R here)', or '' when `name` is no known name of another program.
   !> Abaqus plane strain (CPE), axisymmetric (CAX) and plane stress (CPS: PECPLAS has no
   !> plane stress; the analysis type is set by *ANALYSIS) continuum elements; the hybrid and
   !> incompatible-mode variants (H, I suffixes) have no equivalent.
   function element_alias_hint(name) result(hint)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: hint
      character(len=:), allocatable :: u, ours
      u = upper(name)
      hint = ''
      ours = ''
      if (len(u) < 4) return
      select case (u(4:))
      case ('3')
         ours = 'T3'
      case ('6')
         ours = 'T6'
      case ('4')
         ours = 'Q4'
      case ('8')
         ours = 'Q8'
      case ('8R')
         ours = 'Q8R'
      end select
      select case (u(1:3))
      case ('CPE', 'CAX', 'CPS')
      case default
         ours = ''
      end select
      if (len(ours) == 0) return
      hint = ' (Abaqus '//u//' is '//ours//' here; plane strain or axisymmetry is chosen by '// &
         '*ANALYSIS, TYPE=)'
   end function element_alias_hint

end module pecplas_io_deck_element_aliases
