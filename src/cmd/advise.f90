!> `pecplas --advise DECK [--goal node:N:x|y] [--advise-node N] [--max-dofs N]`: runs the
!> advice (pecplas_advise_advise) and prints the goal, the reference, the adaptive sequence,
!> one row per run and the two advice lines (1 % and 5 %). Writes no results file.
module pecplas_cmd_advise
   use pecplas_base_kinds, only: wp
   use pecplas_base_run_status, only: status_name
   use pecplas_base_error, only: error_t, EXIT_OK
   use pecplas_advise_advise, only: advice_t, advise_row_t, advise_deck, REF_TARGET
   use pecplas_cmd_command, only: command_error
   use pecplas_base_strings, only: itoa, decimal_text, g6
   implicit none (type, external)
   private

   public :: advise_main

contains

   !> Exit code 0, or 2 when the deck, the goal or the first reference run fails.
   integer function advise_main(deck, node_id, goal, max_dofs) result(code)
      character(len=*), intent(in) :: deck, goal
      integer, intent(in) :: node_id, max_dofs
      type(advice_t) :: adv
      type(error_t), allocatable :: error
      integer :: i, k
      character(len=:), allocatable :: line
      character(len=*), parameter :: FMT = &
         '(2x,i5,2x,i9,2x,a15,2x,a5,2x,i10,2x,f9.3,2x,f9.3,2x,es14.6,2x,a10,2x,a)'
      call advise_deck(deck, goal, node_id, max_dofs, adv, error)
      if (allocated(error)) then
         code = command_error('pecplas', error%exit_code(), error%text())
         return
      end if
      write (*, '(a)') 'pecplas --advise '//deck//': first loading step, goal: node '// &
         itoa(adv%node_id)//' '//merge('x', 'y', adv%dof == 1)//' displacement'
      line = 'adaptive sequence (NEWTON x2 increments on each level), DOFs:'
      do k = 1, adv%nlevels
         line = line//' '//itoa(adv%level_dofs(k))
      end do
      write (*, '(a)') line
      if (allocated(adv%stop_reason)) write (*, '(a)') 'the sequence ends: '//adv%stop_reason
      if (adv%nlevels >= 2) then
         write (*, '(a)') 'reference: level '//itoa(adv%nlevels)//', goal '// &
            g6(adv%reference)//', its own estimated error '//pct(adv%ref_error)// &
            ' (extrapolation over the levels; aimed at '//pct(REF_TARGET)//')'
      else
         write (*, '(a)') 'mesh level not varied: errors are those of the method and '// &
            'increments only (discretisation not assessed); reference '//g6(adv%reference)
      end if
      write (*, '(a)') 'error = |goal - reference| / |reference| + the reference''s own '// &
         'estimated error; cost = wall time of the same configuration on levels 1 .. level'
      write (*, '(2x,a5,2x,a9,2x,a15,2x,a5,2x,a10,2x,a9,2x,a9,2x,a14,2x,a10,2x,a)') 'level', &
         'DOFs', 'method', 'incr.', 'increments', 'wall [s]', 'cost [s]', 'goal', 'error', &
         'status'
      do i = 1, size(adv%rows)
         associate (r => adv%rows(i))
            write (*, FMT) r%level, r%ndof, r%method, decimal_text(r%factor, 2), r%increments, &
               r%wall, r%cost, merge(r%goal, 0.0_wp, r%ok), err_text(r), status_name(r%status)
         end associate
      end do
      write (*, '(a)') advice_line('1 %', adv, 1)
      write (*, '(a)') advice_line('5 %', adv, 2)
      code = EXIT_OK
   end function advise_main

   function advice_line(what, adv, m) result(line)
      character(len=*), intent(in) :: what
      type(advice_t), intent(in) :: adv
      integer, intent(in) :: m
      character(len=:), allocatable :: line
      line = 'advice (error < '//what//'): '
      if (adv%best(m) == 0) then
         line = line//'none of the configurations'
         if (adv%nlevels >= 2) line = line//' (the reference''s own estimated error is '// &
            pct(adv%ref_error)//'; a larger --max-dofs lets the sequence go further)'
         return
      end if
      associate (r => adv%rows(adv%best(m)))
         line = line//'METHOD='//trim(r%method)//', INCREMENTS='//itoa(r%increments)// &
            ' in the first loading step (x'//decimal_text(r%factor, 2)//'), mesh: '
         if (r%level == 1) then
            line = line//'the deck''s'
         else
            line = line//'adaptive level '//itoa(r%level)
         end if
         line = line//' ('//itoa(r%ndof)//' DOFs), estimated error '//err_text(r)// &
            ', wall '//decimal_text(r%wall, 3)//' s, cost '//decimal_text(r%cost, 3)//' s'
      end associate
   end function advice_line

   !> The relative error (es10.3), '-' for a run that did not complete.
   function err_text(row) result(s)
      type(advise_row_t), intent(in) :: row
      character(len=:), allocatable :: s
      character(len=12) :: buf
      if (.not. row%ok) then
         s = '-'
         return
      end if
      write (buf, '(es10.3)') row%err
      s = trim(adjustl(buf))
   end function err_text

   !> A relative error as a percentage, e.g. '0.183 %'.
   function pct(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      s = decimal_text(100.0_wp*x, 3)//' %'
   end function pct

end module pecplas_cmd_advise
