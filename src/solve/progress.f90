!> The progress line of a long run, in the user's quantities: the step, the factor of each
!> pattern the step drives with its value (resultant force, imposed displacement, pressure),
!> the displacement of an arc-length step's stop node, and a time estimate only where one can
!> be made: from the step fraction under load control, from the distance to the stop
!> displacement under arc-length control with a NODE= target. An arc-length step without one
!> may peak before its target load, so its time left is "unknown". The clock is passed in
!> (`now`), so that the line is testable with a fake one.
module pecplas_solve_progress
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: AXISYMMETRIC
   use pecplas_model_loads, only: LOAD_FORCE, LOAD_PRESSURE, LOAD_DISPLACEMENT
   use pecplas_base_progress_eta, only: progress_eta_t, duration
   use pecplas_base_strings, only: itoa, decimal_text
   implicit none (type, external)
   private

   public :: begin_progress, progress_text, step_measure, pattern_value, step_end_text

contains

   !> The measure of the way done in step `istep` at step fraction `tau` with displacements
   !> `u`, and its value at the step's end. `estimable`: the measure moves towards `target`
   !> as the step goes on (false under arc-length without a stop node: the load may peak).
   subroutine step_measure(model, istep, tau, u, m, target, estimable)
      type(model_t), intent(in) :: model
      integer, intent(in) :: istep
      real(wp), intent(in) :: tau, u(:, :)
      real(wp), intent(out) :: m, target
      logical, intent(out) :: estimable
      associate (step => model%steps(istep))
         m = tau
         target = 1.0_wp
         estimable = .not. step%arc_length
         if (step%arc_length .and. step%node > 0 .and. step%dof > 0) then
            if (step%node <= size(u, 2) .and. step%dof <= size(u, 1)) then
               m = u(step%dof, step%node)
               target = step%displacement
               estimable = .true.
            end if
         end if
      end associate
   end subroutine step_measure

   !> Starts the estimate of step `istep` at clock `now`, from step fraction `tau0` and the
   !> displacements `u` of the state it starts from.
   subroutine begin_progress(model, istep, tau0, u, now, eta)
      type(model_t), intent(in) :: model
      integer, intent(in) :: istep
      real(wp), intent(in) :: tau0, u(:, :), now
      type(progress_eta_t), intent(inout) :: eta
      real(wp) :: m, target
      logical :: estimable
      call step_measure(model, istep, tau0, u, m, target, estimable)
      call eta%begin_step(istep, now, m)
   end subroutine begin_progress

   !> The line after increment `inc` of step `istep` (at step fraction `tau`, pattern factors
   !> `factors`, displacements `u`; `arc`: the increment was arc-length controlled) at clock
   !> `now`, e.g.
   !>   step 2 'push' (arc-length), increment 63 of at most 200: push = 0.734 (of 1;
   !>   resultant F_y = -73.4 kN), node 1849 u_y = -0.0123 m (stops at -0.05 m, 25 %);
   !>   9.4 min elapsed; about 28 min left in this step (from the distance to the stop
   !>   displacement)
   function progress_text(model, istep, inc, tau, factors, u, arc, eta, now) result(s)
      type(model_t), intent(in) :: model
      integer, intent(in) :: istep, inc
      real(wp), intent(in) :: tau, factors(:), u(:, :), now
      logical, intent(in) :: arc
      type(progress_eta_t), intent(in) :: eta
      character(len=:), allocatable :: s
      real(wp) :: m, target, left
      logical :: estimable
      integer :: i, p, nsteps
      associate (step => model%steps(istep))
         s = 'step '//itoa(istep)//' '''//step%name//''''
         if (step%safety%on) then
            ! strength reduction: no load path, no estimate (the Msf lines say where it is)
            s = s//' (safety), increment '//itoa(inc)//' of at most '// &
               itoa(step%safety%max_increments)//'; '//duration(now - eta%t0)// &
               ' elapsed; time left unknown (the factor is not known before failure)'
            return
         end if
         if (step%arc_length) then
            s = s//' (arc-length), increment '//itoa(inc)//' of at most '// &
               itoa(step%max_increments)
         else
            s = s//', increment '//itoa(inc)//' ('//itoa(step%increments)//' planned), '// &
               'fraction '//num(tau)//' of the step'
            if (arc) s = s//' (limit probe by arc-length)'
         end if
         s = s//':'
         do i = 1, size(step%pattern)
            p = step%pattern(i)
            if (i > 1) s = s//','
            s = s//' '//model%patterns(p)%name//' = '//num(factors(p))//' (of '// &
               num(step%target(i))//pattern_value(model, p, factors(p))//')'
         end do
         if (step%arc_length .and. step%node > 0 .and. step%dof > 0) then
            if (size(step%pattern) > 0) s = s//','
            s = s//' node '//itoa(node_id(model, step%node))//' '// &
               dof_name(model, step%dof)//' = '//num(u(step%dof, step%node))// &
               length_unit(model)//' (stops at '//num(step%displacement)//length_unit(model)
            call step_measure(model, istep, tau, u, m, target, estimable)
            if (target /= eta%m_start .and. eta%step == istep) s = s//', '// &
               itoa(nint(100.0_wp*max(0.0_wp, (m - eta%m_start)/(target - eta%m_start))))//' %'
            s = s//')'
         end if
         ! a step that drives nothing (a nil step of a phase) lists nothing after the colon
         if (s(len(s):) == ':') s = s(1:len(s) - 1)
         s = s//'; '//duration(now - eta%t0)//' elapsed; '
         call step_measure(model, istep, tau, u, m, target, estimable)
         if (arc .and. .not. step%arc_length) estimable = .false.
         if (.not. estimable) then
            if (step%arc_length) then
               s = s//'time left unknown (arc-length without NODE=: the load may peak '// &
                  'before its target)'
            else
               s = s//'time left unknown (the probe ends at a limit or past the failed load)'
            end if
         else
            left = -1.0_wp
            if (eta%step == istep) left = eta%step_left(m, target, now)
            if (left < 0.0_wp) then
               s = s//'time left not known yet'
            else
               s = s//'about '//duration(left)//' left in this step'
               if (step%arc_length) s = s//' (from the distance to the stop displacement)'
            end if
         end if
         nsteps = size(model%steps)
         if (istep < nsteps) then
            s = s//', then '//itoa(nsteps - istep)//' more step'
            if (nsteps - istep > 1) s = s//'s'
         end if
      end associate
   end function progress_text

   !> '; resultant F_y = -73.4 kN', '; imposed u_y = -0.012 m at 21 nodes', '; p = 73.4 kPa'
   !> (nothing for gravity and body forces, whose factor is their value).
   function pattern_value(model, p, factor) result(s)
      type(model_t), intent(in) :: model
      integer, intent(in) :: p
      real(wp), intent(in) :: factor
      character(len=:), allocatable :: s
      integer :: d, n
      s = ''
      associate (pat => model%patterns(p))
         select case (pat%kind)
         case (LOAD_FORCE)
            if (.not. allocated(pat%value)) return
            do d = 1, 2
               if (.not. any(pat%dof == d)) cycle
               s = s//trim(merge('; resultant ', ',           ', len(s) == 0))//' F_'// &
                  axis(model, d)//' = '//num(factor*sum(pat%value, mask=pat%dof == d))// &
                  unit(model, 'force')
            end do
         case (LOAD_DISPLACEMENT)
            if (.not. allocated(pat%value)) return
            do d = 1, 2
               n = count(pat%dof == d)
               if (n == 0) cycle
               s = s//trim(merge('; imposed ', ',         ', len(s) == 0))//' '// &
                  dof_name(model, d)
               if (maxval(pat%value, mask=pat%dof == d) == &
                   minval(pat%value, mask=pat%dof == d)) then
                  s = s//' = '//num(factor*maxval(pat%value, mask=pat%dof == d))// &
                     length_unit(model)
               else
                  s = s//' from '//num(factor*minval(pat%value, mask=pat%dof == d))//' to '// &
                     num(factor*maxval(pat%value, mask=pat%dof == d))//length_unit(model)
               end if
               if (n > 1) s = s//' at '//itoa(n)//' nodes'
            end do
         case (LOAD_PRESSURE)
            if (.not. allocated(pat%pressure)) return
            if (size(pat%pressure) == 0) return
            if (maxval(pat%pressure) == minval(pat%pressure)) then
               s = '; p = '//num(factor*pat%pressure(1))//unit(model, 'stress')
            else
               s = '; p from '//num(factor*minval(pat%pressure))//' to '// &
                  num(factor*maxval(pat%pressure))//unit(model, 'stress')
            end if
         end select
      end associate
   end function pattern_value

   !> What a step reached, in the deck's quantities, for the line printed at its end: each
   !> pattern the step drives with its factor and value (a force's resultant, a pressure, an
   !> imposed displacement with the sum of the reactions that impose it: the footing's load
   !> under a settlement, the shear force of a shear box), then the largest displacement and
   !> its node: "step 1 'push': settle = 1 (imposed u_y = -0.2 m at 17 nodes, reaction
   !> F_y = 251.3 kN); largest displacement 0.2 m at node 12 (x = 0, y = 0)".
   !> `reaction`: F_int - F_ext (2, ncolumns), counted from the initial state.
   function step_end_text(model, istep, factors, u, reaction) result(s)
      type(model_t), intent(in) :: model
      integer, intent(in) :: istep
      real(wp), intent(in) :: factors(:), u(:, :), reaction(:, :)
      character(len=:), allocatable :: s, value
      integer :: i, p, d, k, n, big
      real(wp) :: r, m
      associate (step => model%steps(istep))
         s = 'step '//itoa(istep)//' '''//step%name//''''
         do i = 1, size(step%pattern)
            p = step%pattern(i)
            s = s//merge(': ', ', ', i == 1)//model%patterns(p)%name//' = '// &
               num(factors(p))
            value = pattern_value(model, p, factors(p))
            associate (pat => model%patterns(p))
               if (len(value) > 2) s = s//' ('//value(3:)
               if (pat%kind == LOAD_DISPLACEMENT .and. allocated(pat%node)) then
                  do d = 1, 2
                     if (.not. any(pat%dof == d)) cycle
                     r = 0.0_wp
                     do k = 1, size(pat%node)
                        if (pat%dof(k) == d .and. pat%node(k) <= size(reaction, 2)) &
                           r = r + reaction(d, pat%node(k))
                     end do
                     s = s//', reaction F_'//axis(model, d)//' = '//num(r)//unit(model, 'force')
                  end do
               end if
               if (len(value) > 2) s = s//')'
            end associate
         end do
      end associate
      n = min(model%mesh%nnode(), size(u, 2))
      if (n == 0) return
      big = 1
      m = -1.0_wp
      do k = 1, n
         if (norm2(u(1:2, k)) > m) then
            m = norm2(u(1:2, k))
            big = k
         end if
      end do
      s = s//'; largest displacement '//num(m)//length_unit(model)//' at node '// &
         itoa(node_id(model, big))//' ('//axis(model, 1)//' = '//num(model%mesh%x(1, big))// &
         ', '//axis(model, 2)//' = '//num(model%mesh%x(2, big))//')'
   end function step_end_text

   !> 'x'/'y', or 'r'/'z' in axisymmetry.
   function axis(model, d) result(s)
      type(model_t), intent(in) :: model
      integer, intent(in) :: d
      character(len=1) :: s
      if (model%analysis%kind == AXISYMMETRIC) then
         s = merge('r', 'z', d == 1)
      else
         s = merge('x', 'y', d == 1)
      end if
   end function axis

   function dof_name(model, d) result(s)
      type(model_t), intent(in) :: model
      integer, intent(in) :: d
      character(len=:), allocatable :: s
      s = 'u_'//axis(model, d)
   end function dof_name

   integer function node_id(model, node)
      type(model_t), intent(in) :: model
      integer, intent(in) :: node
      node_id = node
      if (allocated(model%mesh%node_id)) then
         if (node <= size(model%mesh%node_id)) node_id = model%mesh%node_id(node)
      end if
   end function node_id

   !> ' kN' for the stated unit of `quantity`; '' when the deck states none.
   function unit(model, quantity) result(s)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: quantity
      character(len=:), allocatable :: s
      s = ''
      if (.not. model%unit_system%stated) return
      s = ' '//model%unit_system%of(quantity)
   end function unit

   function length_unit(model) result(s)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: s
      s = unit(model, 'length')
   end function length_unit

   !> Four significant digits, without trailing zeros: '0.734', '-73.4', '1.235e-05'.
   pure function num(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=40) :: buf
      if (x == 0.0_wp) then
         s = '0'
      else if (abs(x) >= 1.0e-3_wp .and. abs(x) < 1.0e6_wp) then
         s = decimal_text(x, max(0, 3 - floor(log10(abs(x)))))
      else
         write (buf, '(es10.3e2)') x
         s = trim(adjustl(buf))
      end if
   end function num

end module pecplas_solve_progress
