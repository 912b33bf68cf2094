!> The anchors at the start of a phase (doc/theory.md, Anchors): a set prestressed in the
!> phase before goes on from its prestress (e0 set so that N = P at the current
!> elongation); then the step's anchor changes in deck order:
!>   *ACTIVATE    the bars start without force, their elongation measured from the current
!>                displacements, no plastic elongation;
!>   *DEACTIVATE  the bars stop acting (their force becomes the phase's out-of-balance);
!>   *PRESTRESS   the bars carry the prestress force P through the step, whatever their
!>                elongation (no stiffness), so that N = P at its end;
!> and RESET_DISPLACEMENTS shifts e0 with the elongations, so that the forces stay.
module pecplas_phases_anchors
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_model_phases, only: CHANGE_ACTIVATE, CHANGE_DEACTIVATE, CHANGE_PRESTRESS, &
      TARGET_ANCHORS
   use pecplas_fe_state, only: fe_state_t
   use pecplas_structures_anchor, only: bar_elongation
   implicit none (type, external)
   private

   public :: start_anchors

contains

   !> Applies the anchor part of step istep's phase to `st` (converged state of the step
   !> before); `changed`: the stiffness changes; `add_line` receives one line per change.
   subroutine start_anchors(model, st, istep, changed, lines)
      type(model_t), intent(in) :: model
      type(fe_state_t), intent(inout) :: st
      integer, intent(in) :: istep
      logical, intent(out) :: changed
      character(len=*), allocatable, intent(inout) :: lines(:)
      character(len=32) :: buf
      integer :: s, c, i
      changed = .false.
      if (.not. allocated(model%anchors)) return
      if (size(model%anchors) == 0) return
      ! a prestress of the phase before: the bars go on from P
      do s = 1, size(model%anchors)
         associate (set => model%anchors(s), a => st%anchors%sets(s))
            if (.not. (a%active .and. a%prestressing)) cycle
            do i = 1, set%nbar()
               a%e0(i) = bar_elongation(set, i, st%u) - a%plastic(i) - &
                  a%prestress*set%length(i)/set%ea
            end do
            a%prestressing = .false.
            changed = .true.
         end associate
      end do
      do c = 1, size(model%steps(istep)%changes)
         associate (ch => model%steps(istep)%changes(c))
            if (ch%target /= TARGET_ANCHORS) cycle
            changed = .true.
            associate (set => model%anchors(ch%set), a => st%anchors%sets(ch%set))
               select case (ch%kind)
               case (CHANGE_ACTIVATE)
                  a%active = .true.
                  a%prestressing = .false.
                  a%force = 0.0_wp
                  a%plastic = 0.0_wp
                  do i = 1, set%nbar()
                     a%e0(i) = bar_elongation(set, i, st%u)
                  end do
                  call push(lines, 'activate anchor '//set%name//' (without force)')
               case (CHANGE_DEACTIVATE)
                  a%active = .false.
                  a%prestressing = .false.
                  a%force = 0.0_wp
                  call push(lines, 'deactivate anchor '//set%name)
               case (CHANGE_PRESTRESS)
                  ! the force it starts from: reached is N0 + tau (P - N0) at fraction tau
                  if (.not. a%prestressing) a%force_start = a%force
                  a%prestressing = .true.
                  a%prestress = ch%value
                  write (buf, '(g0.6)') ch%value
                  call push(lines, 'prestress anchor '//set%name//' to '//trim(adjustl(buf))// &
                     ' (force of one anchor, reached at the end of the step)')
               end select
               a%force_trial = a%force
               a%plastic_trial = a%plastic
            end associate
         end associate
      end do
      if (.not. model%steps(istep)%reset_displacements) return
      do s = 1, size(model%anchors)
         associate (set => model%anchors(s), a => st%anchors%sets(s))
            do i = 1, set%nbar()
               a%e0(i) = a%e0(i) - bar_elongation(set, i, st%u)
            end do
         end associate
      end do
   end subroutine start_anchors

   subroutine push(lines, text)
      character(len=*), allocatable, intent(inout) :: lines(:)
      character(len=*), intent(in) :: text
      lines = [character(len=len(lines)) :: lines, text]
   end subroutine push

end module pecplas_phases_anchors
