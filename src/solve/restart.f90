!> Restart: the driver's state after a converged increment, packed for the results file's
!> /restart group (pecplas_io_results_restart) and read back into a freshly prepared problem
!> so that `pecplas DECK --restart OLD.h5` continues the step loop where OLD.h5 stopped.
!> Packed: the position in the step loop (pecplas_problem_position) and the run counters,
!> displacements, pattern factors, converged internal forces, the massif's stresses,
!> strains and histories, the joints' law strains, stresses, histories and modes, and the
!> Katona doublets' states and multipliers, the walk of a safety step under way (pack_safety),
!> and the matrices factorised during the run that its next iterations solve with (item
!> `operators`: see pack_restart).
module pecplas_solve_restart
   use pecplas_base_kinds, only: wp
   use pecplas_model_loads, only: LOAD_DISPLACEMENT
   use pecplas_base_error, only: error_t, input_error, fatal_error
   use pecplas_base_strings, only: itoa
   use pecplas_model_type, only: model_t
   use pecplas_problem_type, only: problem_t
   use pecplas_problem_counts, only: NCOUNT, whole_counts
   use pecplas_solve_katona_increment, only: update_flexibility
   use pecplas_base_parallel, only: parallel_rank, parallel_size, parallel_sum
   use pecplas_problem_linear, only: K_SOLVER, K_TSOLVER
   use pecplas_problem_arc_trace, only: PATH_NONE, PATH_STEP, PATH_PROBE, ARC_VECTOR, &
      ARC_VECTOR_V1, ARC_VECTOR_V2
   use pecplas_solve_stiffness, only: factorise_values, partitioned, factorise_stiffness
   use pecplas_phases_start, only: replay_phases
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_io_results_restart, only: restart_data_t, read_restart_group
   use pecplas_io_results_checksum, only: deck_checksum
   use pecplas_base_signals, only: crash_guard_begin, crash_guard_end
   implicit none (type, external)
   private

   public :: pack_restart, restore_restart

   !> Layout version of the packed data (a file with another one is refused).
   real(wp), parameter :: LAYOUT = 1.0_wp
   integer, parameter :: NPOS = 13

contains

   !> The restart data of the last converged increment (problem%position must be recorded).
   !> `fields`: the increment is written with its fields, filled from this same state
   !> (pecplas_solve_output): the displacements and the massif's stresses, strains and
   !> histories are then given by reference to them (the results file links its datasets)
   !> instead of copied.
   !> The next increment's first iteration solves with the last factorisation (full Newton:
   !> the tangent of the last iterate that refactorised; a full-Newton fallback: its own
   !> solver's). Its matrix is packed (`operator`, `tangent_operator`; the item `operators`
   !> says which, the Katona augmentation factor and whether the data are exact) unless it
   !> is the set-up stiffness, which the restarted run factorises anyway, so that the
   !> restarted run solves with the same factorisations. Only when problem%position%exact
   !> (*OUTPUT, EXACT_RESTART=: with the increment the run stops after, with every one, or
   !> never), and not in a run whose ranks each hold a part of the matrix.
   function pack_restart(model, problem, fields) result(data)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      logical, intent(in) :: fields
      type(restart_data_t) :: data
      real(wp) :: ops(4)
      integer :: s
      logical :: tangents
      associate (p => problem%position, st => problem%state, kt => problem%katona)
         call data%add('position', [LAYOUT, real(p%istep, wp), real(p%inc_in_step, wp), &
            real(p%level, wp), p%tau, p%dt, p%k_first, p%k_conv, real(problem%stats%increments, wp), &
            real(problem%stats%iterations, wp), real(problem%stats%cuts, wp), kt%force_scale, &
            kt%max_penetration])
         ! the whole run's other counts, for the summary of a run restarted from here
         call data%add('counters', real(whole_counts(problem), wp))
         ! Katona contact: whether the flexibility G belongs to the last factorisation (the
         ! next increment uses it as it is; a restarted run builds it again before resuming,
         ! outside the whole run's counts)
         if (kt%active) call data%add('katona_flexibility', &
            [merge(1.0_wp, 0.0_wp, kt%g_stamp == problem%stats%factorisations)])
         call data%add('f0', p%f0)
         call data%add('fint_conv', reshape(p%fint_conv, [size(p%fint_conv)]))
         ! the arc-length path under way, and the last increment's displacement increment
         ! that directs it (a limit probe's first length, an arc predictor's sign)
         if (allocated(p%du_prev)) call data%add('du_prev', p%du_prev)
         call data%add('lead', [real(p%lead, wp)])
         call data%add('dtau_prev', [p%dtau_prev])
         call data%add('s_step0', [p%s_step0])
         call data%add('arc', [real(p%path, wp), p%arc%to_vector()])
         if (p%path /= PATH_NONE) then
            call data%add('arc_peak_factors', p%arc%res%peak_factors)
            call data%add('arc_why', text_codes(p%arc%req%why))
         end if
         ! (with plates the rotations are no part of the displacement field: lend copied the
         ! node columns and kept u; without them u is lent to the fields, not allocated here,
         ! and no size of it may be asked)
         if (fields .and. .not. allocated(st%u)) then
            call data%add_field('u', 'displacement', 0)
         else
            call data%add('u', reshape(st%u, [size(st%u)]))
         end if
         call data%add('factors', st%factors)
         ! a phased run: the phase in force and its carried out-of-balance (the sets it
         ! has inactive hold nothing a later phase reads: not stored)
         if (problem%phase%phased) then
            call data%add('phase', [real(problem%phase%index, wp)])
            if (allocated(problem%phase%carried)) call data%add('phase_carried', &
               reshape(problem%phase%carried, [size(problem%phase%carried)]))
            ! gravity loading with water: the held forces of the steady pore pressures and
            ! the water coming in with the gravity pattern, computed at the phase's start from
            ! the state of then (replayed from another state, they would differ by roundoff)
            if (problem%phase%water_pattern > 0) then
               call data%add('phase_held', reshape(problem%system%initial_force, &
                  [size(problem%system%initial_force)]))
               call data%add('phase_water', reshape(problem%system%pattern_force(:, :, &
                  problem%phase%water_pattern), [size(problem%system%initial_force)]))
            end if
         end if
         tangents = tangents_carried(model, problem)
         do s = 1, size(st%sets)
            if (.not. st%sets(s)%active) cycle
            if (tangents .and. allocated(st%sets(s)%tangent)) &
               call data%add('tangent_'//itoa(s), reshape(st%sets(s)%tangent, &
               [size(st%sets(s)%tangent)]))
            if (fields) then
               call data%add_field('stress_'//itoa(s), 'stress', s)
               call data%add_field('strain_'//itoa(s), 'strain', s)
               call data%add_field('hist_'//itoa(s), 'state', s)
            else
               call data%add('stress_'//itoa(s), flat3(st%sets(s)%stress))
               call data%add('strain_'//itoa(s), flat3(st%sets(s)%strain))
               call data%add('hist_'//itoa(s), flat3(st%sets(s)%hist))
            end if
            ! groundwater: the excess pore pressures (the steady ones follow from the phase)
            if (st%sets(s)%pore%on()) call data%add('pore_excess_'//itoa(s), &
               reshape(st%sets(s)%pore%excess, [size(st%sets(s)%pore%excess)]))
         end do
         if (allocated(st%joints%sets)) then
            do s = 1, size(st%joints%sets)
               if (.not. st%joints%sets(s)%active) cycle
               associate (j => st%joints%sets(s))
                  call data%add('joint_eps_'//itoa(s), flat3(j%eps))
                  call data%add('joint_sigma_'//itoa(s), flat3(j%sigma))
                  call data%add('joint_hist_'//itoa(s), flat3(j%hist))
                  call data%add('joint_mode_'//itoa(s), real(reshape(j%mode, [size(j%mode)]), wp))
                  if (tangents .and. allocated(j%tangent)) call data%add('joint_tangent_'// &
                     itoa(s), reshape(j%tangent, [size(j%tangent)]))
               end associate
            end do
         end if
         if (allocated(st%plates%sets)) then
            do s = 1, size(st%plates%sets)
               if (.not. st%plates%sets(s)%active) cycle
               associate (pl => st%plates%sets(s))
                  call data%add('plate_e_'//itoa(s), flat3(pl%e))
                  call data%add('plate_s_'//itoa(s), flat3(pl%s))
                  call data%add('plate_hist_'//itoa(s), flat3(pl%hist))
                  if (tangents) call data%add('plate_tangent_'//itoa(s), &
                     reshape(pl%tangent, [size(pl%tangent)]))
               end associate
            end do
         end if
         ! anchors: activity, prestress, force, plastic and reference elongations
         if (allocated(st%anchors%sets)) then
            do s = 1, size(st%anchors%sets)
               associate (a => st%anchors%sets(s))
                  call data%add('anchor_'//itoa(s), [merge(1.0_wp, 0.0_wp, a%active), &
                     merge(1.0_wp, 0.0_wp, a%prestressing), a%prestress, a%force, a%plastic, &
                     a%e0])
                  ! the forces a prestress phase started from (optional on reading)
                  call data%add('anchor_start_'//itoa(s), a%force_start)
               end associate
            end do
         end if
         if (kt%active) then
            call data%add('katona_mode', real(kt%mode, wp))
            call data%add('katona_sign', real(kt%sgn, wp))
            call data%add('katona_broken', merge(1.0_wp, 0.0_wp, kt%broken))
            call data%add('katona_force', reshape(kt%f, [size(kt%f)]))
            call data%add('katona_z', reshape(kt%z, [size(kt%z)]))
            call data%add('katona_anchor', kt%anchor)
            ! phases: a reactivated doublet measures its gap from its reactivation
            if (problem%phase%phased) call data%add('katona_gap0', kt%gap0)
         end if
         ! a deck with a safety step: the walk of that step, once under way (pack_safety)
         if (model%steps(size(model%steps))%safety%on) call pack_safety(problem, data)
         ops = [0.0_wp, 0.0_wp, kt%alpha, merge(1.0_wp, 0.0_wp, p%exact)]
         if (p%exact) then
            if (problem%linear%solver_moved .and. problem%linear%k_owner == K_SOLVER) then
               call add_operator(model, data, 'operator', problem%linear%k%values)
               ops(1) = 1.0_wp
            else if (problem%linear%tangent_factorised .and. problem%linear%k_owner == K_TSOLVER) then
               call add_operator(model, data, 'tangent_operator', problem%linear%k%values)
               ops(2) = 1.0_wp
            end if
         end if
         call data%add('operators', ops)
      end associate
   end function pack_restart

   !> Reads the restart data of `path` into `problem` (set up and initialised for `model`,
   !> the same deck) and marks its position to be resumed. Input errors (exit 2): no restart
   !> data, another deck, data that does not fit.
   subroutine restore_restart(path, model, problem, error)
      character(len=*), intent(in) :: path
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      type(restart_data_t) :: data
      character(len=:), allocatable :: names(:), msg
      real(wp) :: deck_sum
      logical :: guarded
      integer :: nj, np
      character(len=64), allocatable :: anames(:)

      nj = 0
      if (allocated(problem%state%joints%sets)) nj = size(problem%state%joints%sets)
      np = 0
      if (allocated(problem%state%plates%sets)) np = size(problem%state%plates%sets)
      names = restart_names(size(problem%state%sets), nj, np)
      ! anchors (each set's activity, prestress, forces, elongations)
      if (allocated(problem%state%anchors%sets)) then
         allocate (anames(size(names) + 2*size(problem%state%anchors%sets)))
         anames(1:size(names)) = names
         do np = 1, size(problem%state%anchors%sets)
            anames(size(names) + np) = 'anchor_'//itoa(np)
         end do
         ! and the forces a prestress phase started from (optional)
         do np = 1, size(problem%state%anchors%sets)
            anames(size(names) + size(problem%state%anchors%sets) + np) = 'anchor_start_'//itoa(np)
         end do
         deallocate (names)
         allocate (character(len=64) :: names(size(anames)))
         names = anames
      end if
      ! a damaged file may crash the HDF5 library itself: an input error, not a crash
      guarded = crash_guard_begin('pecplas: error: cannot restart from '//path// &
         ': the HDF5 library crashed reading it (the file is damaged)')
      call read_restart_group(path, names, data, deck_sum, error)
      if (guarded) call crash_guard_end()
      if (allocated(error)) then
         msg = error%text()
         call input_error(error, 'cannot restart from '//path//': '//msg)
         return
      end if
      if (.not. allocated(model%deck_text)) then
         call input_error(error, 'cannot restart: the deck text is unknown')
         return
      end if
      ! the paths of the files read do not count (pecplas_io_results_checksum, deck_identity)
      if (deck_sum /= deck_checksum(model%deck_text)) then
         call input_error(error, 'cannot restart from '//path//': it was written by another '// &
            'deck (its deck text differs from '//model%deck_file//'); restart with the deck '// &
            'that wrote it')
         return
      end if
      if (safety_unknown(data, model)) then
         call input_error(error, 'cannot restart from '//path//': its restart data were '// &
            'written by an earlier version, which did not keep the state of a safety step, '// &
            "and they may be of an increment of step '"//model%steps(size(model%steps))%name// &
            "' (its strength reduction) as well as of the end of the step before; run the "// &
            'deck again')
         return
      end if
      call unpack_data(data, model, problem, error)
      ! the stiffness of the phase in force (the set-up's is that of the first)
      if (.not. allocated(error) .and. problem%phase%phased) then
         call factorise_stiffness(model, problem, .false., error)
         problem%state%converged_tangents = tangents_carried(model, problem)
      end if
      if (.not. allocated(error)) call restore_operators(data, model, problem, error)
      if (.not. allocated(error)) call restore_flexibility(data, problem, error)
      if (allocated(error)) then
         msg = error%text()
         call input_error(error, 'cannot restart from '//path// &
            ': its restart data does not fit this deck ('//msg//')')
      end if
   end subroutine restore_restart

   !> Katona contact: builds the flexibility G again from the restored factorisation when
   !> the interrupted run's G belonged to it (item `katona_flexibility`), as a part of the
   !> restore: its build and solves are the restart's, not the run's (the restarted run's
   !> summary counts the whole run's, pecplas_problem_counts), and the run goes on with the
   !> same G as the uninterrupted one, built from the same factorisation.
   subroutine restore_flexibility(data, problem, error)
      type(restart_data_t), intent(in) :: data
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: v(:)
      if (.not. problem%katona%active .or. .not. data%has('katona_flexibility')) return
      call data%get('katona_flexibility', 1, v, error)
      if (allocated(error)) return
      if (v(1) /= 0.0_wp) call update_flexibility(problem, error)
   end subroutine restore_flexibility

   !> Puts the restart data into `problem` and marks its position to be resumed.
   subroutine unpack_data(data, model, problem, error)
      type(restart_data_t), intent(in) :: data
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: v(:)
      logical :: tangents
      integer :: s, nj
      nj = 0
      if (allocated(problem%state%joints%sets)) nj = size(problem%state%joints%sets)
      associate (p => problem%position, st => problem%state, kt => problem%katona)
         call data%get('position', NPOS, v, error)
         if (allocated(error)) return
         if (v(1) /= LAYOUT) then
            call fatal_error(error, 'restart data of another layout version')
            return
         end if
         p%istep = nint(v(2)); p%inc_in_step = nint(v(3)); p%level = nint(v(4))
         p%tau = v(5); p%dt = v(6); p%k_first = v(7); p%k_conv = v(8)
         problem%stats%increments = nint(v(9)); problem%stats%iterations = nint(v(10))
         problem%stats%cuts = nint(v(11)); kt%force_scale = v(12); kt%max_penetration = v(13)
         problem%stats%restarted = .true.
         problem%stats%resumed_after = problem%stats%increments
         ! the run's other counts (data of an earlier version hold none: the summary then
         ! says which of its numbers are this process's)
         if (data%has('counters')) then
            call data%get('counters', NCOUNT, v, error)
            if (allocated(error)) return
            problem%stats%earlier = nint(v)
         end if
         if (p%istep < 1 .or. p%istep > size(model%steps)) then
            call fatal_error(error, 'restart step '//itoa(p%istep)//' is not a step of the deck')
            return
         end if
         call data%get('f0', size(st%factors), p%f0, error)
         if (allocated(error)) return
         call unpack_path(data, problem, error)
         if (allocated(error)) return
         p%exact = .false.
         if (data%has('operators')) then
            call data%get('operators', 4, v, error)
            if (allocated(error)) return
            p%exact = v(4) /= 0.0_wp
         end if
         ! (datasets of an earlier state may remain in the group: read only what this one
         ! wrote)
         tangents = tangents_carried(model, problem)
         call data%get('fint_conv', size(st%u), v, error)
         if (allocated(error)) return
         p%fint_conv = reshape(v, shape(st%u))
         call data%get('u', size(st%u), v, error)
         if (allocated(error)) return
         st%u = reshape(v, shape(st%u))
         call data%get('factors', size(st%factors), v, error)
         if (allocated(error)) return
         st%factors = v
         ! a phased run: its phases up to the one in force applied again (activity,
         ! materials, laws, the sizes of the histories), then its carried out-of-balance
         if (problem%phase%phased) then
            call data%get('phase', 1, v, error)
            if (allocated(error)) return
            if (nint(v(1)) < 0 .or. nint(v(1)) > size(model%steps)) then
               call fatal_error(error, 'restart phase '//itoa(nint(v(1)))//' is not a step of '// &
                  'the deck')
               return
            end if
            call replay_phases(model, problem, nint(v(1)), error)
            if (allocated(error)) return
            if (allocated(p%du_prev)) then
               if (size(p%du_prev) /= problem%system%dofs%neq) deallocate (p%du_prev)
            end if
            if (data%has('phase_carried')) then
               call data%get('phase_carried', size(st%u), v, error)
               if (allocated(error)) return
               problem%phase%carried = reshape(v, shape(st%u))
            end if
            ! (restart data of an earlier version: the replayed ones)
            if (problem%phase%water_pattern > 0 .and. data%has('phase_held') .and. &
                data%has('phase_water')) then
               associate (sys => problem%system)
                  call data%get('phase_held', size(sys%initial_force), v, error)
                  if (allocated(error)) return
                  sys%initial_force = reshape(v, shape(sys%initial_force))
                  call data%get('phase_water', size(sys%initial_force), v, error)
                  if (allocated(error)) return
                  sys%pattern_force(:, :, problem%phase%water_pattern) = &
                     reshape(v, shape(sys%initial_force))
               end associate
            end if
            call data%get('u', size(st%u), v, error)
            if (allocated(error)) return
            st%u = reshape(v, shape(st%u))
         end if
         do s = 1, size(st%sets)
            if (.not. st%sets(s)%active) cycle
            if (tangents .and. data%has('tangent_'//itoa(s)) .and. &
                allocated(st%sets(s)%tangent)) &
               call get4(data, 'tangent_'//itoa(s), st%sets(s)%tangent, error)
            if (allocated(error)) return
            call get3(data, 'stress_'//itoa(s), st%sets(s)%stress, error)
            if (.not. allocated(error)) call get3(data, 'strain_'//itoa(s), st%sets(s)%strain, error)
            if (.not. allocated(error)) call get3(data, 'hist_'//itoa(s), st%sets(s)%hist, error)
            if (allocated(error)) return
            if (st%sets(s)%pore%on() .and. data%has('pore_excess_'//itoa(s))) then
               associate (pe => st%sets(s)%pore)
                  call data%get('pore_excess_'//itoa(s), size(pe%excess), v, error)
                  if (allocated(error)) return
                  pe%excess = reshape(v, shape(pe%excess))
                  pe%excess_trial = pe%excess
               end associate
            end if
         end do
         do s = 1, nj
            if (.not. st%joints%sets(s)%active) cycle
            associate (j => st%joints%sets(s))
               call get3(data, 'joint_eps_'//itoa(s), j%eps, error)
               if (.not. allocated(error)) call get3(data, 'joint_sigma_'//itoa(s), j%sigma, error)
               if (.not. allocated(error)) call get3(data, 'joint_hist_'//itoa(s), j%hist, error)
               if (.not. allocated(error)) call data%get('joint_mode_'//itoa(s), size(j%mode), v, &
                  error)
               if (allocated(error)) return
               j%mode = reshape(nint(v), shape(j%mode))
               if (tangents .and. data%has('joint_tangent_'//itoa(s)) .and. &
                   allocated(j%tangent)) &
                  call get4(data, 'joint_tangent_'//itoa(s), j%tangent, error)
               if (allocated(error)) return
            end associate
         end do
         if (allocated(st%plates%sets)) then
            do s = 1, size(st%plates%sets)
               if (.not. st%plates%sets(s)%active) cycle
               associate (pl => st%plates%sets(s))
                  call get3(data, 'plate_e_'//itoa(s), pl%e, error)
                  if (.not. allocated(error)) call get3(data, 'plate_s_'//itoa(s), pl%s, error)
                  if (.not. allocated(error)) call get3(data, 'plate_hist_'//itoa(s), pl%hist, &
                     error)
                  if (allocated(error)) return
                  if (tangents .and. data%has('plate_tangent_'//itoa(s))) &
                     call get4(data, 'plate_tangent_'//itoa(s), pl%tangent, error)
                  if (allocated(error)) return
               end associate
            end do
         end if
         if (allocated(st%anchors%sets)) then
            do s = 1, size(st%anchors%sets)
               associate (a => st%anchors%sets(s))
                  call data%get('anchor_'//itoa(s), 3 + 3*size(a%force), v, error)
                  if (allocated(error)) return
                  a%active = v(1) /= 0.0_wp
                  a%prestressing = v(2) /= 0.0_wp
                  a%prestress = v(3)
                  a%force = v(4:3 + size(a%force))
                  a%plastic = v(4 + size(a%force):3 + 2*size(a%force))
                  a%e0 = v(4 + 2*size(a%force):)
                  a%force_start = a%force
                  if (data%has('anchor_start_'//itoa(s))) then
                     call data%get('anchor_start_'//itoa(s), size(a%force), v, error)
                     if (allocated(error)) return
                     a%force_start = v
                  end if
               end associate
            end do
         end if
         if (model%steps(size(model%steps))%safety%on) then
            call unpack_safety(data, model, problem, error)
            if (allocated(error)) return
         end if
         if (kt%active) then
            call data%get('katona_mode', kt%nd, v, error)
            if (allocated(error)) return
            kt%mode = nint(v)
            call data%get('katona_sign', kt%nd, v, error)
            if (allocated(error)) return
            kt%sgn = nint(v)
            call data%get('katona_broken', kt%nd, v, error)
            if (allocated(error)) return
            kt%broken = v /= 0.0_wp
            call data%get('katona_force', 2*kt%nd, v, error)
            if (allocated(error)) return
            kt%f = reshape(v, shape(kt%f))
            call data%get('katona_z', 2*kt%nd, v, error)
            if (allocated(error)) return
            kt%z = reshape(v, shape(kt%z))
            call data%get('katona_anchor', kt%nd, kt%anchor, error)
            if (allocated(error)) return
            if (problem%phase%phased .and. data%has('katona_gap0')) then
               call data%get('katona_gap0', kt%nd, kt%gap0, error)
               if (allocated(error)) return
            end if
            call kt%begin_increment()
         end if
         ! trial = converged everywhere, as after a commit; the points' tangents are the
         ! converged state's when carried (else the set-up's: not those of the state)
         call st%rollback()
         st%converged_tangents = tangents
         p%resume = .true.
      end associate
   end subroutine unpack_data

   !> The arc-length path under way, the last displacement increment and the method the
   !> chain starts with (absent from restart data of an older version: no path, no
   !> increment, the run's method).
   subroutine unpack_path(data, problem, error)
      type(restart_data_t), intent(in) :: data
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: v(:), peak(:), why(:)
      associate (p => problem%position)
         if (data%has('du_prev')) then
            ! (a phased run numbers its equations for the phase in force: checked after
            ! its phases are replayed)
            if (problem%phase%phased) then
               call data%get('du_prev', data%length('du_prev'), p%du_prev, error)
            else
               call data%get('du_prev', problem%system%dofs%neq, p%du_prev, error)
            end if
            if (allocated(error)) return
         end if
         ! the last increment's step fraction (older restart data: none, no extrapolation)
         p%dtau_prev = 0.0_wp
         if (data%has('dtau_prev')) then
            call data%get('dtau_prev', 1, v, error)
            if (allocated(error)) return
            p%dtau_prev = v(1)
         end if
         ! q.u at the start of the step (older restart data: none, measured from u = 0)
         p%s_step0 = 0.0_wp
         if (data%has('s_step0')) then
            call data%get('s_step0', 1, v, error)
            if (allocated(error)) return
            p%s_step0 = v(1)
         end if
         ! the method the chain starts with (older restart data: the run's own)
         p%lead = 0
         if (data%has('lead')) then
            call data%get('lead', 1, v, error)
            if (allocated(error)) return
            p%lead = nint(v(1))
         end if
         p%path = PATH_NONE
         if (.not. data%has('arc')) return
         ! (restart data of an older version: ARC_VECTOR_V1 or ARC_VECTOR_V2 numbers)
         if (data%length('arc') == 1 + ARC_VECTOR_V1) then
            call data%get('arc', 1 + ARC_VECTOR_V1, v, error)
         else if (data%length('arc') == 1 + ARC_VECTOR_V2) then
            call data%get('arc', 1 + ARC_VECTOR_V2, v, error)
         else
            call data%get('arc', 1 + ARC_VECTOR, v, error)
         end if
         if (allocated(error)) return
         if (.not. any(v(1) == real([PATH_NONE, PATH_STEP, PATH_PROBE], wp))) then
            call fatal_error(error, 'restart data arc names no kind of path')
            return
         end if
         p%path = nint(v(1))
         if (p%path == PATH_NONE) return
         call data%get('arc_peak_factors', size(problem%state%factors), peak, error)
         if (allocated(error)) return
         call data%get('arc_why', max(1, data%length('arc_why')), why, error)
         if (allocated(error)) return
         call p%arc%from_vector(v(2:), peak, codes_text(why))
      end associate
   end subroutine unpack_path

   !> A text as reals: its length, then its character codes.
   pure function text_codes(text) result(v)
      character(len=:), allocatable, intent(in) :: text
      real(wp), allocatable :: v(:)
      integer :: i
      if (.not. allocated(text)) then
         v = [0.0_wp]
         return
      end if
      v = [real(len(text), wp), (real(ichar(text(i:i)), wp), i = 1, len(text))]
   end function text_codes

   pure function codes_text(v) result(text)
      real(wp), intent(in) :: v(:)
      character(len=:), allocatable :: text
      integer :: i, n
      n = max(0, min(nint(v(1)), size(v) - 1))
      allocate (character(len=n) :: text)
      do i = 1, n
         text(i:i) = achar(max(0, min(255, nint(v(i + 1)))))
      end do
   end function codes_text

   !> Factorises the matrices the interrupted run had factorised (see pack_restart); data
   !> without the item `operators` (written before it existed) restart from the set-up
   !> factorisation, and so does a run whose ranks each hold a part of the matrix (MUMPS
   !> on several ranks) unless the data were written by as many ranks (add_operator): each
   !> rank's part is on a pattern of its own, which no other number of ranks has.
   subroutine restore_operators(data, model, problem, error)
      type(restart_data_t), intent(in) :: data
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: ops(:), v(:)
      if (.not. data%has('operators')) return
      call data%get('operators', 4, ops, error)
      if (allocated(error)) return
      ! each rank its own part, from data written on as many ranks (else the set-up's); the
      ! parts of several ranks make no matrix of one
      if (partitioned(model)) then
         if (.not. own_parts(data)) return
      else if (data%has('operator_parts') .or. data%has('tangent_operator_parts')) then
         return
      end if
      if (ops(1) /= 0.0_wp) then
         call get_operator(data, model, 'operator', problem%linear%k, v, error)
         if (allocated(error)) return
         ! the matrix is augmented when the run's was (a Katona body held by its contacts)
         if (ops(3) > 0.0_wp) problem%katona%alpha = ops(3)
         call factorise_values(model, problem, v, .false., error)
      else if (ops(2) /= 0.0_wp) then
         call get_operator(data, model, 'tangent_operator', problem%linear%k, v, error)
         if (.not. allocated(error)) call factorise_values(model, problem, v, .true., error)
      end if
   end subroutine restore_operators

   !> The packed matrix `name` on the run's stiffness pattern k. Where this run stores the
   !> upper triangle (pecplas_solve_stiffness, upper_storage) and the data hold the whole
   !> matrix (written by a version that stored it whole), its upper triangle is taken. A run
   !> whose ranks each hold a part takes this rank's (add_operator).
   subroutine get_operator(data, model, name, k, v, error)
      type(restart_data_t), intent(in) :: data
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      type(csc_t), intent(in) :: k
      real(wp), allocatable, intent(out) :: v(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: whole(:)
      integer :: nw, r, first
      nw = k%whole_nnz()
      if (partitioned(model)) then
         ! this rank's part (own_parts: written by as many ranks)
         call data%get(name//'_parts', data%length(name//'_parts'), whole, error)
         if (allocated(error)) return
         r = parallel_rank() + 1
         first = parallel_size() + nint(sum(whole(1:r - 1)))
         if (nint(whole(r)) /= k%nnz()) then
            call fatal_error(error, 'restart data '//name//'_parts: rank '//itoa(r - 1)// &
               ' holds '//itoa(nint(whole(r)))//' values where its part of this deck''s '// &
               'matrix has '//itoa(k%nnz()))
            return
         end if
         v = whole(first + 1:first + k%nnz())
      else if (k%upper .and. data%length(name) == nw .and. nw /= k%nnz()) then
         call data%get(name, nw, whole, error)
         if (.not. allocated(error)) call k%upper_of_whole(whole, v)
      else
         call data%get(name, k%nnz(), v, error)
      end if
   end subroutine get_operator

   !> Adds the factorised matrix `name` of this run: its values; in a run whose ranks each
   !> assemble a part of it (MUMPS on several ranks, each part on a pattern of its own),
   !> `name`_parts instead: the number of values of each rank's part, then the parts in
   !> rank order, gathered on every rank (each a sum of one part and zeros: exact), so that
   !> a run restarted on as many ranks gives MUMPS the same parts. Collective there.
   subroutine add_operator(model, data, name, values)
      type(model_t), intent(in) :: model
      type(restart_data_t), intent(inout) :: data
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: values(:)
      real(wp), allocatable :: counts(:), parts(:)
      integer :: first
      if (.not. partitioned(model)) then
         call data%add(name, values)
         return
      end if
      allocate (counts(parallel_size()), source=0.0_wp)
      counts(parallel_rank() + 1) = real(size(values), wp)
      call parallel_sum(counts)
      first = nint(sum(counts(1:parallel_rank())))
      allocate (parts(nint(sum(counts))), source=0.0_wp)
      parts(first + 1:first + size(values)) = values
      call parallel_sum(parts)
      call data%add(name//'_parts', [counts, parts])
   end subroutine add_operator

   !> Whether the data hold the matrices of a run on as many ranks as this one, each rank's
   !> part (add_operator).
   logical function own_parts(data)
      type(restart_data_t), intent(in) :: data
      real(wp), allocatable :: v(:)
      type(error_t), allocatable :: error
      character(len=*), parameter :: NAMES(2) = [character(len=21) :: 'operator_parts', &
         'tangent_operator_parts']
      integer :: i
      own_parts = .false.
      do i = 1, 2
         if (data%length(trim(NAMES(i))) < parallel_size()) cycle
         call data%get(trim(NAMES(i)), data%length(trim(NAMES(i))), v, error)
         if (allocated(error)) return
         ! (the counts of as many ranks, then as many values as they say)
         if (size(v) /= parallel_size() + nint(sum(v(1:parallel_size())))) return
         own_parts = .true.
         return
      end do
   end function own_parts

   !> The walk of the safety step (pecplas_problem_safety, safety_walk_t) once it has
   !> converged an increment: item `safety` (1, increments, Msf reached, next Msf step, last
   !> displacement rate, smallest step, Msf sought again, wall time, curve points), the curve
   !> `safety_curve` (its Msf, then its displacements), the displacements at the step's start
   !> `safety_u0` and those of the last increments `safety_ulast`; before: `safety` = (0).
   subroutine pack_safety(problem, data)
      type(problem_t), intent(in) :: problem
      type(restart_data_t), intent(inout) :: data
      associate (w => problem%safety%walk, res => problem%safety)
         if (.not. w%on) then
            call data%add('safety', [0.0_wp])
            return
         end if
         call data%add('safety', [1.0_wp, real(w%inc, wp), w%msf, w%dm, w%rate_prev, &
            w%smallest, w%confirm_until, w%wall, real(size(res%msf), wp)])
         call data%add('safety_curve', [res%msf, res%displacement])
         call data%add('safety_u0', reshape(w%u0, [size(w%u0)]))
         call data%add('safety_ulast', reshape(w%ulast, [size(w%ulast)]))
      end associate
   end subroutine pack_safety

   !> The walk of the safety step from the restart data (pack_safety), when under way; it
   !> must then be the step of the position.
   subroutine unpack_safety(data, model, problem, error)
      type(restart_data_t), intent(in) :: data
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: v(:), curve(:)
      integer :: n, nu
      if (.not. data%has('safety')) return
      call data%get('safety', data%length('safety'), v, error)
      if (allocated(error)) return
      if (v(1) == 0.0_wp) return
      if (size(v) /= 9 .or. problem%position%istep /= size(model%steps)) then
         call fatal_error(error, 'restart item safety does not fit the safety step')
         return
      end if
      associate (w => problem%safety%walk, res => problem%safety)
         w%on = .true.
         w%inc = nint(v(2)); w%msf = v(3); w%dm = v(4); w%rate_prev = v(5)
         w%smallest = v(6); w%confirm_until = v(7); w%wall = v(8)
         n = nint(v(9))
         call data%get('safety_curve', 2*n, curve, error)
         if (allocated(error)) return
         res%msf = curve(1:n)
         res%displacement = curve(n + 1:)
         nu = size(problem%state%u)
         call data%get('safety_u0', nu, v, error)
         if (allocated(error)) return
         w%u0 = reshape(v, shape(problem%state%u))
         n = data%length('safety_ulast')
         if (n < nu .or. mod(n, nu) /= 0) then
            call fatal_error(error, 'restart item safety_ulast does not fit the displacements')
            return
         end if
         call data%get('safety_ulast', n, v, error)
         if (allocated(error)) return
         allocate (w%ulast(size(problem%state%u, 1), size(problem%state%u, 2), 0:n/nu - 1))
         w%ulast = reshape(v, shape(w%ulast))
      end associate
   end subroutine unpack_safety

   !> Restart data of a deck with a safety step written by a version that kept no state of
   !> it (no item `safety`) at the end of the step before it: the run may as well have been
   !> killed inside the safety step (its increments wrote their state there, with the
   !> position of the step before), so where it stands is unknown.
   logical function safety_unknown(data, model) result(unknown)
      type(restart_data_t), intent(in) :: data
      type(model_t), intent(in) :: model
      type(error_t), allocatable :: error
      real(wp), allocatable :: v(:)
      integer :: n
      unknown = .false.
      n = size(model%steps)
      if (.not. model%steps(n)%safety%on .or. data%has('safety')) return
      call data%get('position', NPOS, v, error)
      if (allocated(error)) return
      unknown = nint(v(2)) >= n - 1 .and. v(5) >= 1.0_wp - 1.0e-12_wp
   end function safety_unknown

   !> Names of the datasets a problem with `nsets` element sets and `njoint` joint sets reads.
   pure function restart_names(nsets, njoint, nplate) result(names)
      integer, intent(in) :: nsets, njoint, nplate
      character(len=:), allocatable :: names(:)
      character(len=32), allocatable :: list(:)
      integer :: s
      list = [character(len=32) :: 'position', 'f0', 'fint_conv', 'u', 'factors', &
         'katona_mode', 'katona_sign', 'katona_broken', 'katona_force', 'katona_z', &
         'katona_anchor', 'katona_gap0', 'operators', 'operator', 'tangent_operator', &
         'operator_parts', 'tangent_operator_parts', &
         'du_prev', 'arc', 'arc_peak_factors', 'arc_why', 'lead', 'dtau_prev', 'phase', &
         'phase_carried', 'phase_held', 'phase_water', 'safety', 'safety_curve', 'safety_u0', &
         'safety_ulast', 'counters', 'katona_flexibility']
      do s = 1, nsets
         list = [character(len=32) :: list, 'stress_'//itoa(s), 'strain_'//itoa(s), &
            'hist_'//itoa(s), 'tangent_'//itoa(s), 'pore_excess_'//itoa(s)]
      end do
      do s = 1, njoint
         list = [character(len=32) :: list, 'joint_eps_'//itoa(s), 'joint_sigma_'//itoa(s), &
            'joint_hist_'//itoa(s), 'joint_mode_'//itoa(s), 'joint_tangent_'//itoa(s)]
      end do
      do s = 1, nplate
         list = [character(len=32) :: list, 'plate_e_'//itoa(s), 'plate_s_'//itoa(s), &
            'plate_hist_'//itoa(s), 'plate_tangent_'//itoa(s)]
      end do
      names = list
   end function restart_names

   pure function flat3(a) result(v)
      real(wp), intent(in) :: a(:, :, :)
      real(wp), allocatable :: v(:)
      v = reshape(a, [size(a)])
   end function flat3

   subroutine get4(data, name, a, error)
      type(restart_data_t), intent(in) :: data
      character(len=*), intent(in) :: name
      real(wp), intent(inout) :: a(:, :, :, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: v(:)
      call data%get(name, size(a), v, error)
      if (allocated(error)) return
      a = reshape(v, shape(a))
   end subroutine get4

   !> The points' consistent tangents of the last update are carried when an arc-length path
   !> may follow: its predictor assembles the tangent from them before any update of the
   !> increment; and when the deck imposes displacements: the first iteration of an
   !> increment that moves them multiplies their change by the stiffness of those tangents
   !> (pecplas_solve_iterate). Other load-controlled increments update the points first, and
   !> their first solve uses the carried factorisation.
   logical function tangents_carried(model, problem) result(carried)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      integer :: i
      carried = .false.
      if (.not. problem%position%exact) return
      carried = problem%position%path /= PATH_NONE
      do i = problem%position%istep, size(model%steps)
         carried = carried .or. model%steps(i)%arc_length
      end do
      if (allocated(model%patterns)) carried = carried .or. &
         any([(model%patterns(i)%kind == LOAD_DISPLACEMENT, i=1, size(model%patterns))])
   end function tangents_carried

   subroutine get3(data, name, a, error)
      type(restart_data_t), intent(in) :: data
      character(len=*), intent(in) :: name
      real(wp), intent(inout) :: a(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: v(:)
      call data%get(name, size(a), v, error)
      if (allocated(error)) return
      a = reshape(v, shape(a))
   end subroutine get3

end module pecplas_solve_restart
