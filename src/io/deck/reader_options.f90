!> Deck handlers for the keywords that set a value right away: *TITLE, *UNITS,
!> *ANALYSIS, *SOLVER, *OUTPUT, and *STEP (whose pattern names are resolved later).
module pecplas_io_deck_reader_options
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_deck_caps, only: MAX_INCREMENTS, MAX_ITERATIONS_CAP, MAX_CUTS_CAP, &
      MAX_LOAD_MAGNITUDE
   use pecplas_io_text_fields, only: deck_line_t, field_t, split_fields, field_real, &
      check_count, parse_real, parse_int, same_name, upper, add_name, itoa
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, raw_item_t, raw_step_t, &
      line_error, where_text, push_item
   use pecplas_model_type, only: model_t
   use pecplas_model_adapt_scope, only: adapt_refusal
   use pecplas_base_units, only: parse_units
   use pecplas_base_parallel, only: parallel_built
   use pecplas_model_adapt_request, only: parse_target, parse_goal_spec, goal_spec_t, &
      GOAL_NODE, GOAL_REACTION, goal_node_index
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC, LINEAR_SOLVERS, &
      NONLINEAR_METHODS, EXACT_NO, EXACT_ON_STOP, EXACT_ALWAYS, method_name, method_kind
   implicit none (type, external)
   private

   public :: read_text, read_units, read_analysis, read_solver, read_output, read_step, read_adapt, &
      resolve_adapt_goal

contains

   !> *TITLE / *UNITS -- exactly one data line, kept as written.
   subroutine read_text(state, block, text, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      character(len=:), allocatable, intent(out) :: text
      type(error_t), allocatable, intent(out) :: error
      call block%kw%check_keys(state%lines%get(block%at), [character(len=1) ::], error)
      if (allocated(error)) return
      if (block%last /= block%first) then
         call line_error(state, block%at, 'expected exactly one data line after '// &
            block%kw%name//', found '//itoa(block%last - block%first + 1), error)
         return
      end if
      text = state%lines%text(block%first)
   end subroutine read_text

   !> *UNITS -- one data line naming the length, force and stress units (module
   !> pecplas_base_units, doc/deck.md); kept as written and read into model%unit_system.
   subroutine read_units(state, model, block, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: message
      call read_text(state, block, model%units, error)
      if (allocated(error)) return
      call parse_units(model%units, model%unit_system, message)
      if (len(message) > 0) call line_error(state, block%first, message, error)
   end subroutine read_units

   !> *ANALYSIS, TYPE=PLANE_STRAIN|AXISYMMETRIC [, THICKNESS=t] (thickness: plane strain)
   subroutine read_analysis(state, model, block, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      character(len=:), allocatable :: kind
      logical :: found
      kwline = state%lines%get(block%at)
      associate (kw => block%kw)
         call kw%check_keys(kwline, [character(len=9) :: 'TYPE', 'THICKNESS'], error)
         if (allocated(error)) return
         call kw%require(kwline, 'TYPE', kind, error)
         if (allocated(error)) return
         select case (upper(kind))
         case ('PLANE_STRAIN')
            model%analysis%kind = PLANE_STRAIN
         case ('AXISYMMETRIC')
            model%analysis%kind = AXISYMMETRIC
            if (kw%has('THICKNESS')) then
               call line_error(state, block%at, 'THICKNESS is only for PLANE_STRAIN; an '// &
                  'AXISYMMETRIC model is computed over the full circle (2*pi*r)', error)
               return
            end if
         case default
            call line_error(state, block%at, "unknown analysis type '"//kind// &
               "'; known types: PLANE_STRAIN AXISYMMETRIC", error)
            return
         end select
         call param_real(state, block, 'THICKNESS', model%analysis%thickness, found, error)
         if (allocated(error)) return
         if (found .and. .not. (model%analysis%thickness > 0.0_wp)) then
            call line_error(state, block%at, 'THICKNESS must be positive', error)
            return
         end if
      end associate
   end subroutine read_analysis

   !> *SOLVER [, LINEAR=..] [, METHOD=..] [, TOLERANCE=..] [, MAX_ITERATIONS=..] [, MAX_CUTS=..]
   !>    [, FALLBACK=YES|NO] [, LINE_SEARCH=YES|NO] [, LIMIT_PROBE=n] [, THREADS=n]
   subroutine read_solver(state, model, block, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      logical :: found
      character(len=:), allocatable :: method
      call block%kw%check_keys(state%lines%get(block%at), [character(len=14) :: 'LINEAR', &
         'METHOD', 'TOLERANCE', 'MAX_ITERATIONS', 'MAX_CUTS', 'FALLBACK', 'LINE_SEARCH', &
         'LIMIT_PROBE', 'THREADS'], error)
      if (allocated(error)) return
      call param_choice(state, block, 'LINEAR', LINEAR_SOLVERS, model%solver%linear, error)
      if (allocated(error)) return
      if (model%solver%linear == 'MUMPS' .and. .not. parallel_built()) then
         call line_error(state, block%at, 'LINEAR=MUMPS: this build has no MUMPS; build '// &
            'with make build-mpi (CMake -DPECPLAS_MPI=ON, doc/mpi.md) and run with mpirun, '// &
            'or choose LINEAR=AUTO, CHOLMOD or UMFPACK', error)
         return
      end if
      method = method_name(model%solver%method)
      call param_choice(state, block, 'METHOD', NONLINEAR_METHODS, method, error)
      if (allocated(error)) return
      model%solver%method = method_kind(method)
      call param_real(state, block, 'TOLERANCE', model%solver%tolerance, found, error)
      if (allocated(error)) return
      if (found .and. .not. (model%solver%tolerance > 0.0_wp .and. &
         model%solver%tolerance < 1.0_wp)) then
         call line_error(state, block%at, 'TOLERANCE must be between 0 and 1', error)
         return
      end if
      call param_int(state, block, 'MAX_ITERATIONS', 1, model%solver%max_iterations, error, &
         MAX_ITERATIONS_CAP, 'a cap against runs that never end')
      if (allocated(error)) return
      call param_int(state, block, 'MAX_CUTS', 0, model%solver%max_cuts, error, &
         MAX_CUTS_CAP, 'each cut halves the increment')
      if (allocated(error)) return
      call param_yes_no(state, block, 'FALLBACK', model%solver%fallback, error)
      if (allocated(error)) return
      call param_yes_no(state, block, 'LINE_SEARCH', model%solver%line_search, error)
      if (allocated(error)) return
      call param_int(state, block, 'LIMIT_PROBE', 0, model%solver%limit_probe, error)
      if (allocated(error)) return
      call param_int(state, block, 'THREADS', 1, model%solver%threads, error)
   end subroutine read_solver

   !> *OUTPUT [, FILE=path] [, EVERY=n] [, STRESSES=YES|NO] [, STRAINS=..] [, REACTIONS=..]
   !> [, ERROR_ESTIMATE=YES|NO] [, EXACT_RESTART=ON_STOP|ALWAYS|NO]
   subroutine read_output(state, model, block, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: file, exact
      logical :: found
      call block%kw%check_keys(state%lines%get(block%at), [character(len=14) :: 'FILE', 'EVERY', &
         'STRESSES', 'STRAINS', 'REACTIONS', 'ERROR_ESTIMATE', 'EXACT_RESTART'], error)
      if (allocated(error)) return
      call block%kw%get('FILE', file, found)
      if (found) model%output%file = file
      call param_int(state, block, 'EVERY', 1, model%output%every, error)
      if (allocated(error)) return
      call param_yes_no(state, block, 'STRESSES', model%output%stresses, error)
      if (allocated(error)) return
      call param_yes_no(state, block, 'STRAINS', model%output%strains, error)
      if (allocated(error)) return
      call param_yes_no(state, block, 'REACTIONS', model%output%reactions, error)
      if (allocated(error)) return
      call param_yes_no(state, block, 'ERROR_ESTIMATE', model%output%error_estimate, error)
      if (allocated(error)) return
      if (allocated(error)) return
      exact = 'ON_STOP'
      call param_choice(state, block, 'EXACT_RESTART', [character(len=7) :: 'ON_STOP', &
         'ALWAYS', 'NO'], exact, error)
      select case (exact)
      case ('ALWAYS')
         model%output%exact_restart = EXACT_ALWAYS
      case ('NO')
         model%output%exact_restart = EXACT_NO
      case default
         model%output%exact_restart = EXACT_ON_STOP
      end select
   end subroutine read_output

   !> *ADAPT, TARGET=1% [, GOAL=energy|node:N:x|y|reaction:SET[:x|y]|limit] [, MAX_DOFS=n]:
   !> `pecplas DECK` runs the
   !> adaptive loop (the command line's --target-error, --goal, --max-dofs win over it).
   subroutine read_adapt(state, model, block, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text, msg
      real(wp) :: value
      type(goal_spec_t) :: goal
      logical :: found
      call block%kw%check_keys(state%lines%get(block%at), [character(len=8) :: 'TARGET', 'GOAL', &
         'MAX_DOFS'], error)
      if (allocated(error)) return
      if (model%adapt%given) then
         call line_error(state, block%at, '*ADAPT is given twice', error)
         return
      end if
      call block%kw%get('TARGET', text, found)
      if (.not. found) then
         call line_error(state, block%at, 'expected TARGET=<relative error>, e.g. TARGET=1%', &
            error)
         return
      end if
      call parse_target(text, value, msg)
      if (allocated(msg)) then
         call line_error(state, block%at, 'TARGET: '//msg, error)
         return
      end if
      model%adapt%target = text
      model%adapt%goal = ''
      call block%kw%get('GOAL', text, found)
      if (found) then
         call parse_goal_spec(text, goal, msg)
         if (allocated(msg)) then
            call line_error(state, block%at, 'GOAL: '//msg, error)
            return
         end if
         model%adapt%goal = text
      end if
      call param_int(state, block, 'MAX_DOFS', 1, model%adapt%max_dofs, error)
      if (allocated(error)) return
      model%adapt%given = .true.
      model%adapt%at = block%at
   end subroutine read_adapt

   !> Once the mesh is built: the node or node set that *ADAPT's GOAL names exists.
   subroutine resolve_adapt_goal(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      type(goal_spec_t) :: goal
      character(len=:), allocatable :: msg
      integer :: inode
      if (.not. model%adapt%given) return
      ! what the adaptive loop refuses (pecplas_model_adapt_scope), named at the *ADAPT line
      msg = adapt_refusal(model)
      if (len(msg) > 0) then
         call line_error(state, model%adapt%at, msg//'; expected a deck without *ADAPT', error)
         return
      end if
      call parse_goal_spec(model%adapt%goal, goal, msg)
      select case (goal%kind)
      case (GOAL_NODE)
         call goal_node_index(goal, model%mesh, inode, msg)
         if (inode == 0) call line_error(state, model%adapt%at, 'GOAL: '//msg, error)
      case (GOAL_REACTION)
         if (model%mesh%find_nset(goal%set) == 0) call line_error(state, model%adapt%at, &
            "GOAL: expected reaction:SET with SET a node set of the deck (*NSET), no set '"// &
            goal%set//"'", error)
      end select
   end subroutine resolve_adapt_goal

   !> *STEP [, NAME=name] [, INCREMENTS=n] [, CONTROL=LOAD|ARC_LENGTH] -- data: pattern,
   !> target_factor. Arc-length options: MAX_INCREMENTS=m, ITERATIONS=i (wanted per
   !> increment), MIN_LENGTH=, MAX_LENGTH= (multiples of the first length), NODE=id|node_set
   !> (of one node), DOF=1|2|X|Y|R|Z, DISPLACEMENT=v (stop when the node gets there).
   subroutine read_step(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(raw_step_t) :: step
      type(raw_step_t), allocatable :: tmp(:)
      type(field_t), allocatable :: f(:)
      type(raw_item_t) :: item
      logical :: found
      integer :: i, n
      call block%kw%check_keys(state%lines%get(block%at), [character(len=19) :: 'NAME', &
         'INCREMENTS', 'CONTROL', 'MAX_INCREMENTS', 'ITERATIONS', 'MIN_LENGTH', 'MAX_LENGTH', &
         'NODE', 'DOF', 'DISPLACEMENT', 'RESET_DISPLACEMENTS', 'MSF_STEP', 'RESOLUTION'], error)
      if (allocated(error)) return
      if (.not. allocated(state%steps)) allocate (state%steps(0))
      n = size(state%steps)
      call block%kw%get('NAME', step%name, found)
      if (.not. found) step%name = 'Step-'//itoa(n + 1)
      do i = 1, n
         if (same_name(state%steps(i)%name, step%name)) then
            call line_error(state, block%at, "step '"//step%name//"' is defined twice "// &
               '(first at '//where_text(state, state%steps(i)%at)//')', error)
            return
         end if
      end do
      call param_int(state, block, 'INCREMENTS', 1, step%increments, error, MAX_INCREMENTS, &
         'a cap against runs of hours: split the step or use fewer increments')
      if (allocated(error)) return
      call read_step_control(state, block, step, error)
      if (allocated(error)) return
      call param_yes_no(state, block, 'RESET_DISPLACEMENTS', step%reset_displacements, error)
      if (allocated(error)) return
      step%at = block%at
      ! a step without "pattern, target_factor" lines is a nil step (doc/deck.md, Phases)
      allocate (step%changes(0))
      do i = block%first, block%last
         call split_fields(state%lines%text(i), f)
         call check_count(state%lines%get(i), f, 2, 2, 'pattern, target_factor', error)
         if (allocated(error)) return
         item%target = f(1)%s
         item%at = i
         call field_real(state%lines%get(i), f, 2, 'target factor', item%value(1), error)
         if (allocated(error)) return
         if (abs(item%value(1)) > MAX_LOAD_MAGNITUDE) then
            call line_error(state, i, 'target factor above 1e100 in magnitude (see '// &
               'doc/deck.md, Limits)', error)
            return
         end if
         call push_item(step%items, step%n, item)
      end do
      allocate (tmp(n + 1))
      tmp(1:n) = state%steps
      tmp(n + 1) = step
      call move_alloc(tmp, state%steps)
      state%open_step = n + 1
   end subroutine read_step

   !> CONTROL= and the arc-length options of *STEP.
   subroutine read_step_control(state, block, step, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      type(raw_step_t), intent(inout) :: step
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: control
      logical :: found, has_node, has_disp
      integer :: i
      character(len=14), parameter :: ARC_KEYS(7) = [character(len=14) :: 'MAX_INCREMENTS', &
         'ITERATIONS', 'MIN_LENGTH', 'MAX_LENGTH', 'NODE', 'DOF', 'DISPLACEMENT']
      character(len=10), parameter :: SAFETY_KEYS(2) = [character(len=10) :: 'MSF_STEP', &
         'RESOLUTION']
      step%node = ''
      control = 'LOAD'
      call param_choice(state, block, 'CONTROL', [character(len=10) :: 'LOAD', 'ARC_LENGTH', &
         'SAFETY'], control, error)
      if (allocated(error)) return
      step%arc_length = control == 'ARC_LENGTH'
      step%safety = control == 'SAFETY'
      do i = 1, 2
         call block%kw%get(trim(SAFETY_KEYS(i)), control, found)
         if (found .and. .not. step%safety) then
            call line_error(state, block%at, trim(SAFETY_KEYS(i))//'= is an option of '// &
               'CONTROL=SAFETY', error)
            return
         end if
      end do
      if (step%safety) then
         call read_safety_control(state, block, step, error)
         return
      end if
      if (.not. step%arc_length) then
         do i = 1, size(ARC_KEYS)
            call block%kw%get(trim(ARC_KEYS(i)), control, found)
            if (found) then
               call line_error(state, block%at, trim(ARC_KEYS(i))//'= is an option of '// &
                  'CONTROL=ARC_LENGTH (this step is load-controlled)', error)
               return
            end if
         end do
         return
      end if
      step%max_increments = 10*step%increments
      call param_int(state, block, 'MAX_INCREMENTS', 1, step%max_increments, error)
      if (allocated(error)) return
      call param_int(state, block, 'ITERATIONS', 1, step%iterations_wanted, error)
      if (allocated(error)) return
      call param_real(state, block, 'MIN_LENGTH', step%min_length, found, error)
      if (allocated(error)) return
      call param_real(state, block, 'MAX_LENGTH', step%max_length, found, error)
      if (allocated(error)) return
      if (.not. (step%min_length > 0.0_wp .and. step%min_length <= 1.0_wp .and. &
          step%max_length >= 1.0_wp .and. step%max_length < huge(1.0_wp))) then
         call line_error(state, block%at, 'expected 0 < MIN_LENGTH <= 1 <= MAX_LENGTH '// &
            '(multiples of the first increment length)', error)
         return
      end if
      ! NODE= a node id or a node set of one node (resolved with the mesh), DOF= 1, 2, X, Y,
      ! R or Z
      call block%kw%get('NODE', step%node, has_node)
      if (.not. has_node) step%node = ''
      call block%kw%get('DOF', control, found)
      if (found) then
         step%dof = dof_word(control)
         if (step%dof == 0) then
            call line_error(state, block%at, "expected DOF=1 or X (x or r), DOF=2 or Y (y "// &
               "or z), or R, Z, found '"//control//"'", error)
            return
         end if
      end if
      call param_real(state, block, 'DISPLACEMENT', step%displacement, has_disp, error)
      if (allocated(error)) return
      if (has_node .neqv. (has_disp .and. step%dof > 0)) then
         call line_error(state, block%at, 'a displacement target needs NODE=id|node_set, '// &
            'DOF=1|2|X|Y|R|Z and DISPLACEMENT=value together', error)
         return
      end if
   end subroutine read_step_control

   !> The options of CONTROL=SAFETY: MSF_STEP= (first and largest Msf increment, > 0),
   !> RESOLUTION= (smallest, 0 < RESOLUTION <= MSF_STEP), MAX_INCREMENTS= (default 100),
   !> NODE=, DOF= (the displacement of the Msf curve); no arc-length option, no pattern line.
   subroutine read_safety_control(state, block, step, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      type(raw_step_t), intent(inout) :: step
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      logical :: found, has_node
      integer :: i
      character(len=14), parameter :: NOT_HERE(5) = [character(len=14) :: 'ITERATIONS', &
         'MIN_LENGTH', 'MAX_LENGTH', 'DISPLACEMENT', 'INCREMENTS']
      do i = 1, size(NOT_HERE)
         call block%kw%get(trim(NOT_HERE(i)), text, found)
         if (found) then
            call line_error(state, block%at, trim(NOT_HERE(i))//'= is no option of '// &
               'CONTROL=SAFETY (MSF_STEP=, RESOLUTION=, MAX_INCREMENTS=, NODE=, DOF=)', error)
            return
         end if
      end do
      step%max_increments = 100
      call param_int(state, block, 'MAX_INCREMENTS', 1, step%max_increments, error, &
         MAX_INCREMENTS, 'a cap against runs of hours')
      if (allocated(error)) return
      call param_real(state, block, 'MSF_STEP', step%msf_step, found, error)
      if (allocated(error)) return
      call param_real(state, block, 'RESOLUTION', step%resolution, found, error)
      if (allocated(error)) return
      if (.not. (step%msf_step > 0.0_wp .and. step%msf_step <= 10.0_wp .and. &
          step%resolution > 0.0_wp .and. step%resolution <= step%msf_step)) then
         call line_error(state, block%at, 'expected 0 < RESOLUTION <= MSF_STEP <= 10', error)
         return
      end if
      call block%kw%get('NODE', step%node, has_node)
      if (.not. has_node) step%node = ''
      call block%kw%get('DOF', text, found)
      if (found) then
         step%dof = dof_word(text)
         if (step%dof == 0) then
            call line_error(state, block%at, "expected DOF=1 or X (x or r), DOF=2 or Y (y "// &
               "or z), or R, Z, found '"//text//"'", error)
            return
         end if
      end if
      if (has_node .neqv. step%dof > 0) then
         call line_error(state, block%at, 'the displacement of the safety curve needs '// &
            'NODE=id|node_set and DOF=1|2|X|Y|R|Z together', error)
         return
      end if
   end subroutine read_safety_control

   !> 1 for 1, X, R; 2 for 2, Y, Z (any letter case); 0 otherwise.
   pure integer function dof_word(text) result(dof)
      character(len=*), intent(in) :: text
      select case (upper(trim(adjustl(text))))
      case ('1', 'X', 'R')
         dof = 1
      case ('2', 'Y', 'Z')
         dof = 2
      case default
         dof = 0
      end select
   end function dof_word

   subroutine param_real(state, block, key, value, found, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      character(len=*), intent(in) :: key
      real(wp), intent(inout) :: value
      logical, intent(out) :: found
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      real(wp) :: v
      logical :: ok
      call block%kw%get(key, text, found)
      if (.not. found) return
      call parse_real(text, v, ok)
      if (.not. ok) then
         call line_error(state, block%at, 'expected '//key//"=<number>, found '"//text// &
            "'", error)
         return
      end if
      value = v
   end subroutine param_real

   !> Integer parameter, kept unchanged when absent; error below `minimum`.
   subroutine param_int(state, block, key, minimum, value, error, maximum, why)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      character(len=*), intent(in) :: key
      integer, intent(in) :: minimum
      integer, intent(inout) :: value
      type(error_t), allocatable, intent(out) :: error
      !> Documented cap (doc/deck.md, Limits) and the reason given with the error.
      integer, intent(in), optional :: maximum
      character(len=*), intent(in), optional :: why
      character(len=:), allocatable :: text
      integer :: v
      logical :: ok, found
      call block%kw%get(key, text, found)
      if (.not. found) return
      call parse_int(text, v, ok)
      if (.not. ok) then
         call line_error(state, block%at, 'expected '//key//"=<integer>, found '"//text// &
            "'", error)
         return
      end if
      if (v < minimum) then
         call line_error(state, block%at, key//' must be >= '//itoa(minimum)//', found '// &
            itoa(v), error)
         return
      end if
      if (present(maximum)) then
         if (v > maximum) then
            call line_error(state, block%at, key//' must be <= '//itoa(maximum)//', found '// &
               itoa(v)//' ('//why//'; see doc/deck.md, Limits)', error)
            return
         end if
      end if
      value = v
   end subroutine param_int

   subroutine param_choice(state, block, key, choices, value, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      character(len=*), intent(in) :: key, choices(:)
      character(len=:), allocatable, intent(inout) :: value
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text, list
      logical :: found
      integer :: i
      call block%kw%get(key, text, found)
      if (.not. found) return
      if (any(choices == upper(text))) then
         value = upper(text)
         return
      end if
      list = ''
      do i = 1, size(choices)
         call add_name(list, trim(choices(i)))
      end do
      call line_error(state, block%at, 'bad value '//key//'='//text//'; expected one of:'// &
         list, error)
   end subroutine param_choice

   subroutine param_yes_no(state, block, key, value, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      character(len=*), intent(in) :: key
      logical, intent(inout) :: value
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      logical :: found
      call block%kw%get(key, text, found)
      if (.not. found) return
      select case (upper(text))
      case ('YES')
         value = .true.
      case ('NO')
         value = .false.
      case default
         call line_error(state, block%at, 'bad value '//key//'='//text// &
            '; expected YES or NO', error)
      end select
   end subroutine param_yes_no

end module pecplas_io_deck_reader_options
