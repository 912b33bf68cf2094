!> The batch command `pecplas DECK [-o FILE] [--quiet]`: reads the deck, sets the problem
!> up, factorises, runs the steps and writes the results. Returns the exit code
!> (0 done, 2 input error, 3 run stopped early or results not writable, 4 interrupted by
!> SIGTERM/SIGINT/SIGHUP, 1 internal error) so tests can call it.
module pecplas_cmd_pecplas
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error, fatal_error, EXIT_OK, EXIT_INPUT, EXIT_STOPPED, EXIT_INTERNAL, &
      EXIT_INTERRUPTED
   use pecplas_base_version, only: PROGRAM_NAME, VERSION
   use pecplas_base_run_status, only: RUN_COMPLETED, RUN_FAILED, RUN_INTERRUPTED, status_name
   use pecplas_base_files, only: make_directories, path_stem, path_dir, same_file, exit_now
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: method_name
   use pecplas_model_loads, only: LOAD_FORCE
   use pecplas_base_strings, only: decimal_text, itoa
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_problem_counts, only: NCOUNT, whole_counts, whole_known, C_FACTORISATIONS, &
      C_SOLVES, C_LINE_SEARCHES, C_SINGULAR, C_ARC, C_METHOD, C_STATE_ITERATIONS, &
      C_MAX_STATE_ITERATIONS, C_G_BUILDS, C_FROZEN, C_RECLOSURE
   use pecplas_solve_prepare, only: prepare_run
   use pecplas_solve_stiffness, only: linear_solver_name
   use pecplas_solve_increments, only: run_increments
   use pecplas_solve_progress, only: force_unit
   use pecplas_solve_gauss, only: gauss_coordinates
   use pecplas_solve_sanity, only: large_displacement_warning
   use pecplas_solve_held_warning, only: held_start_warning, held_end_warning
   use pecplas_io_results_increment, only: joint_points_t
   use pecplas_cmd_advise, only: advise_main
   use pecplas_cmd_adapt, only: adapt_main
   use pecplas_io_results_file, only: results_file_t
   use pecplas_io_results_xdmf, only: xdmf_path
   use pecplas_base_signals, only: install_signal_handlers, interrupt_signal
   use pecplas_base_timers, only: wall_time
   use pecplas_cmd_command, only: command_error
   use pecplas_cmd_args, only: arg_parser_t, VALUE_POSITIVE_INTEGER
   use pecplas_solve_restart, only: restore_restart
   use pecplas_base_provenance, only: version_lines
   use pecplas_linalg_threads, only: thread_setting_t, resolve_threads, apply_threads, &
      parts_text
   use pecplas_base_parallel, only: parallel_rank, parallel_size, parallel_any
   implicit none (type, external)
   private

   !> Program name in error messages.
   character(len=*), parameter :: COMMAND = 'pecplas'

   public :: pecplas_main, run_deck, pecplas_command_line, force_notes

contains

   !> The options of pecplas: one analysis, --advise, --target-error.
   subroutine pecplas_command_line(cli)
      type(arg_parser_t), intent(out) :: cli
      call cli%init(COMMAND, 'Runs the keyword deck DECK (doc/deck.md) and writes HDF5 '// &
         'results with an XDMF sidecar; or refines the mesh adaptively (--target-error, '// &
         'doc/adapt.md); or advises a method, increments and mesh (--advise).', pecplas_version)
      call cli%add_usage('pecplas DECK [-o FILE.h5] [--quiet] [--restart OLD.h5] [--strict]')
      call cli%add_usage('pecplas --advise DECK [--goal node:N:x|y | --advise-node N] '// &
         '[--max-dofs N]')
      call cli%add_usage('pecplas DECK --target-error E% [--goal node:N:x|y | '// &
         'reaction:SET[:x|y] | limit] [--max-dofs N] [-o FILE.h5]')
      call cli%add_positional('DECK', 'deck', 'the keyword deck', 1, 1)
      call cli%add_option('-o --output', 'FILE.h5', 'results file (default: the deck''s '// &
         '*OUTPUT file, else output/<deck>.h5)')
      call cli%add_flag('--quiet -q', 'no banner, no line per increment, no summary')
      call cli%add_option('--restart', 'OLD.h5', 'continue from the last converged '// &
         'increment of OLD.h5, a results file of the same deck (give -o NEW.h5)')
      call cli%add_flag('--strict', 'any warning (printed as "file:line: warning: ...") is '// &
         'an input error: exit 2, no results file')
      call cli%add_option('--target-error', 'E', 'adaptive refinement (solve, estimate, '// &
         'refine the elements with the largest indicators, re-solve) until the estimated '// &
         'error of the goal is below E (1% or 0.01), or --max-dofs is reached; writes the '// &
         'last level')
      call cli%add_option('--goal', 'GOAL', 'the goal of --target-error: node:N:x|y a '// &
         'displacement, reaction:SET[:x|y] the support reactions on a node set, limit the '// &
         'limit load (default: the energy norm); of --advise: node:N:x|y only')
      call cli%add_option('--max-dofs', 'N', 'DOF budget of --target-error and --advise '// &
         '(default 100000)', VALUE_POSITIVE_INTEGER)
      call cli%add_flag('--advise', 'runs the first loading step under MODIFIED_NEWTON/'// &
         'NEWTON and x1/2, x1, x2 increments on each mesh of the adaptive sequence '// &
         '(reference: NEWTON x2, refined until the goal''s estimated error is 0.2 %), '// &
         'prints their cost and error and the cheapest within 1 % and 5 %; writes no results')
      call cli%add_option('--advise-node', 'N', 'the goal of --advise: the larger free '// &
         'displacement component of node N (default: the node that moves most)', &
         VALUE_POSITIVE_INTEGER)
      ! test hook: stop as if interrupted after N converged increments in all
      call cli%add_option('--stop-after-increments', 'N', 'stop as interrupted after N '// &
         'increments', VALUE_POSITIVE_INTEGER, hidden=.true.)
      call cli%add_note('Exit codes: 0 completed, 2 input error, 3 run stopped early '// &
         '(or results not writable), 4 interrupted (SIGTERM, SIGINT, SIGHUP).')
   end subroutine pecplas_command_line

   !> Runs the program for the command-line words `args`; returns the exit code.
   integer function pecplas_main(args) result(code)
      character(len=*), intent(in) :: args(:)
      type(arg_parser_t) :: cli
      character(len=:), allocatable :: deck, target, goal
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: max_dofs
      logical :: done

      call pecplas_command_line(cli)
      call cli%parse(args, code, done)
      if (done) return
      deck = cli%positional(1)
      target = cli%text('--target-error')
      goal = cli%text('--goal')
      max_dofs = cli%int_value('--max-dofs', 0)
      if (cli%given('--advise')) then
         code = advise_main(deck, cli%int_value('--advise-node', 0), goal, max_dofs)
         return
      end if
      if (len(target) > 0) then
         code = adapt_main(deck, target, goal, max_dofs, cli%text('-o'), cli%given('--strict'))
         return
      else if (len(goal) > 0 .or. max_dofs > 0) then
         code = cli%usage_error('--goal and --max-dofs need --target-error')
         return
      end if
      code = run_deck(deck, cli%text('-o'), cli%given('--quiet'), model, problem, &
         cli%text('--restart'), cli%int_value('--stop-after-increments', 0), &
         cli%given('--strict'))
   end function pecplas_main

   !> Runs `deck`, writing `outfile` (empty: the deck's *OUTPUT file or output/<deck>.h5).
   !> Returns the exit code; `model` and `problem` hold the final state (for tests).
   !> restart: a results file of the same deck to continue from (its last converged
   !> increment); stop_after: stop as interrupted after that many increments (test hook);
   !> strict: warnings found before the run are input errors (exit 2, no results file).
   integer function run_deck(deck, outfile_in, quiet, model, problem, restart, stop_after, &
         strict) result(code)
      character(len=*), intent(in) :: deck, outfile_in
      logical, intent(in) :: quiet
      character(len=*), intent(in), optional :: restart
      integer, intent(in), optional :: stop_after
      logical, intent(in), optional :: strict
      type(model_t), intent(out) :: model
      type(problem_t), intent(out) :: problem
      type(results_file_t) :: results
      type(joint_points_t), allocatable :: jpoints(:)
      type(error_t), allocatable :: error
      type(thread_setting_t) :: threads
      character(len=:), allocatable :: message, outfile, warning, plateau, input, failure, held
      integer :: status
      real(wp) :: t0, t1, w0
      integer :: nflipped
      logical :: adaptive, is_strict

      is_strict = .false.
      if (present(strict)) is_strict = strict
      call cpu_time(t0)
      w0 = wall_time()
      ! Everything that can be checked is checked before a results file exists.
      call read_deck(deck, model, error)
      if (.not. allocated(error) .and. model%adapt%given) then
         ! *ADAPT in the deck: the adaptive loop instead of one analysis (not for a restart)
         adaptive = .not. present(restart)
         if (.not. adaptive) adaptive = len(restart) == 0
         if (adaptive) then
            code = adapt_main(deck, model%adapt%target, model%adapt%goal, &
               model%adapt%max_dofs, outfile_in, is_strict)
            return
         end if
      end if
      if (.not. allocated(error)) then
         threads = resolve_threads(model%solver%threads)
         call apply_threads(threads)
         model%solver%threads = threads%n
         model%solver%threads_used = threads
      end if
      if (.not. allocated(error)) call prepare_run(model, problem, nflipped, jpoints, error)
      if (.not. allocated(error)) then
         ! plate water held with the initial out-of-balance by a deck without a nil step
         warning = held_start_warning(model, problem)
         if (len(warning) > 0) call model%warnings%add(warning)
      end if
      if (.not. allocated(error)) call model%warnings%print(0)
      if (.not. allocated(error) .and. is_strict) call model%warnings%as_error(error)
      if (.not. allocated(error) .and. present(restart)) then
         if (len(restart) > 0) call restore_restart(restart, model, problem, error)
      end if
      if (present(stop_after)) problem%position%stop_after = stop_after
      if (allocated(error)) then
         code = command_error(COMMAND, error%exit_code(), error%text())
         return
      end if
      problem%stats%time%setup = wall_time() - w0 - problem%stats%time%assembly - problem%stats%time%factorisation
      outfile = outfile_in
      if (len(outfile) == 0) then
         if (allocated(model%output%file)) then
            outfile = model%output%file
         else
            outfile = 'output/'//path_stem(deck)//'.h5'
         end if
      end if
      if (present(restart)) then
         if (same_file(restart, outfile)) then
            code = command_error(COMMAND, EXIT_INPUT, 'the restarted run must write another '// &
               'file than '//restart//' (give -o NEW.h5)')
            return
         end if
      end if
      input = input_named(model, outfile)
      if (len(input) == 0) input = input_named(model, xdmf_path(outfile))
      if (len(input) > 0) then
         code = command_error(COMMAND, EXIT_INPUT, 'the results file '//outfile//' (or its .xmf) '// &
            'would overwrite the input file '//input//' of this run; choose another name with -o')
         return
      end if
      call make_directories(path_dir(outfile))
      if (.not. quiet) call banner(model, problem, deck, outfile)
      if (.not. quiet .and. nflipped > 0) write (*, '(a,i0,a)') ' note: ', nflipped, &
         ' clockwise elements renumbered counter-clockwise (harmless: the results are '// &
         'the same; a Gmsh surface whose curve loop runs clockwise gives such elements)'

      ! an MPI run (doc/mpi.md): every rank runs the analysis, rank 0 alone writes the file
      results%detached = parallel_rank() > 0
      call results%create(outfile, model, VERSION, gauss_coordinates(model, problem), error, &
         jpoints)
      ! all ranks stop when rank 0 cannot create the file (the others would wait for ever)
      if (parallel_any(allocated(error)) .and. .not. allocated(error)) call fatal_error(error, &
         'rank 0 could not create the results file (its message is on its standard error)')
      if (allocated(error)) then
         code = command_error(COMMAND, EXIT_INPUT, 'cannot write results: '//error%text())
         if (results%is_broken()) call exit_now(code)
         return
      end if
      ! from here a termination signal ends the run between increments, as RUN_INTERRUPTED
      if (.not. install_signal_handlers() .and. .not. quiet) write (*, '(a)') &
         ' note: no handler for SIGTERM/SIGINT/SIGHUP; a signal ends the run at once'
      call run_increments(model, problem, results, quiet, status, message, error, &
         warning=plateau)
      if (allocated(error)) then
         status = RUN_FAILED
         message = error%text()
         plateau = ''
         ! the run's error is its status: the file keeps what converged and says why it ended
         deallocate (error)
      end if
      ! a warning keeps the status and exit code; it goes to stderr, the message and the file
      ! (a step that ended on a plateau of its load-displacement path, a large displacement)
      if (len(plateau) > 0) then
         write (0, '(a)') COMMAND//': warning: '//plateau
         if (len(message) > 0) message = message//'; '
         message = message//'warning: '//plateau
         call model%warnings%add(plateau)
      end if
      warning = large_displacement_warning(model%mesh%x, problem%state%u)
      if (len(warning) > 0) then
         write (0, '(a)') COMMAND//': warning: '//warning
         if (len(message) > 0) message = message//'; '
         message = message//'warning: '//warning
         call model%warnings%add(warning)
      end if
      ! the initial state's out-of-balance held to the end (no nil step released it)
      held = held_end_warning(model, problem)
      if (len(held) > 0) then
         write (0, '(a)') COMMAND//': warning: '//held
         call model%warnings%add(held)
      end if
      if (len(plateau) > 0 .or. len(warning) > 0 .or. len(held) > 0) &
         call results%warnings(model%warnings%lines(), error)
      failure = results%write_failure()
      if (.not. allocated(error)) then
         if (len(failure) > 0) message = 'cannot write results: '//failure
         call results%finish(status, message, error)
      end if
      if (allocated(error)) then
         ! the warnings or the end of the run could not be written: what was written stays
         call results%free()
         if (len(failure) == 0) failure = error%text()
         code = command_error(COMMAND, EXIT_STOPPED, 'cannot write results: '//failure// &
            '; the increments written before are in '// &
            results%working_path()//' (status running); '//outfile//' is untouched')
         ! the HDF5 library's exit handler would crash on a file it could not write
         if (results%is_broken()) call exit_now(code)
         return
      end if
      call cpu_time(t1)
      call summary(problem, threads, status, message, outfile, t1 - t0, wall_time() - w0, quiet)
      code = EXIT_OK
      if (status /= RUN_COMPLETED) code = EXIT_STOPPED
      if (status == RUN_FAILED) code = EXIT_INTERNAL
      if (len(failure) > 0) code = EXIT_STOPPED
      if (status == RUN_INTERRUPTED) code = EXIT_INTERRUPTED
   end function run_deck

   !> What --version prints: version, commit, compiler, linked library versions.
   subroutine pecplas_version(lines)
      character(len=:), allocatable, intent(out) :: lines(:)
      lines = version_lines()
   end subroutine pecplas_version

   !> The input file of the run (deck or *INCLUDE, as listed in the deck text) that is the
   !> file `output` (same file, whatever the spelling); '' if none.
   function input_named(model, output) result(input)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: output
      character(len=:), allocatable :: input
      character(len=*), parameter :: MARK = '** ---- file: '
      integer :: start, eol, k
      input = ''
      if (.not. allocated(model%deck_text)) return
      associate (text => model%deck_text)
         ! from one marker line to the next (a deck of 1e6 nodes has 1.5e6 lines, few markers)
         start = 1
         if (text(1:min(len(text), len(MARK))) /= MARK) start = marker_after(1)
         do while (start > 0)
            eol = index(text(start:), new_line('a'))
            if (eol == 0) eol = len(text) - start + 2
            if (same_file(text(start + len(MARK):start + eol - 2), output)) then
               input = text(start + len(MARK):start + eol - 2)
               return
            end if
            start = marker_after(start + eol - 1)
         end do
      end associate
   contains
      !> Start of the first marker line after position `from` of the deck text (0: none).
      integer function marker_after(from)
         integer, intent(in) :: from
         k = index(model%deck_text(from:), new_line('a')//MARK)
         marker_after = 0
         if (k > 0) marker_after = from + k
      end function marker_after
   end function input_named

   subroutine banner(model, problem, deck, outfile)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      character(len=*), intent(in) :: deck, outfile
      character(len=:), allocatable :: title, units, notes
      integer :: i
      title = '(untitled)'
      if (allocated(model%title)) title = model%title
      units = '(not stated)'
      if (allocated(model%units)) units = model%units
      write (*, '(a)') PROGRAM_NAME//' '//VERSION//'  deck '//deck//'  ->  '//outfile
      write (*, '(a)') ' title: '//title//'   units: '//units
      write (*, '(a,i0,a,i0,a,i0,a,i0,a,a,a,a)') ' nodes ', model%mesh%nnode(), '  elements ', &
         model%mesh%nelem(), '  equations ', problem%system%dofs%neq, '  steps ', size(model%steps), &
         '  solver ', linear_solver_name(model), ' / ', method_name(model%solver%method)
      notes = force_notes(model)
      do while (len(notes) > 0)
         i = index(notes, new_line('a'))
         if (i == 0) i = len(notes) + 1
         write (*, '(a)') ' note: '//notes(1:i - 1)
         notes = notes(min(i + 1, len(notes) + 1):)
      end do
      if (allocated(model%laws)) then
         do i = 1, size(model%laws)
            if (len(model%laws(i)%law%describe()) > 0) write (*, '(a)') ' law '// &
               model%laws(i)%law%describe()
         end do
      end if
      if (.not. allocated(model%joint_sets)) return
      do i = 1, size(model%joint_sets)
         associate (js => model%joint_sets(i))
            write (*, '(a,i0,a)') ' joints '//js%name//': ', size(js%conn, 2), ' '//js%type_name()// &
               ', law '//js%law
         end associate
      end do
   end subroutine banner

   !> A FORCE pattern on several nodes puts its value on each of them (doc/deck.md, Nodes): the
   !> banner's notes say what that makes in all, at factor 1, so that a force meant as a
   !> resultant is seen at once. One line per pattern and direction (new_line separated), ''
   !> when every FORCE pattern acts on one node per direction.
   function force_notes(model) result(text)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: text
      integer :: p, d, n
      character(len=:), allocatable :: force
      text = ''
      if (.not. allocated(model%patterns)) return
      force = force_unit(model)
      do p = 1, size(model%patterns)
         associate (pat => model%patterns(p))
            if (pat%kind /= LOAD_FORCE .or. .not. allocated(pat%dof)) cycle
            do d = 1, 2
               n = count(pat%dof == d)
               if (n < 2) cycle
               if (len(text) > 0) text = text//new_line('a')
               text = text//'load pattern '''//pat%name//''' (FORCE) acts on '//itoa(n)// &
                  ' nodes along '//trim(merge('x', 'y', d == 1))//', each with its value: '// &
                  decimal_text(sum(pat%value, mask=pat%dof == d), 4)//force//' in all at '// &
                  'factor 1 (for a resultant spread over a surface, use a PRESSURE)'
            end do
         end associate
      end do
   end function force_notes

   subroutine summary(problem, threads, status, message, outfile, cpu, wall, quiet)
      type(problem_t), intent(in) :: problem
      type(thread_setting_t), intent(in) :: threads
      integer, intent(in) :: status
      character(len=*), intent(in) :: message, outfile
      real(wp), intent(in) :: cpu, wall
      logical, intent(in) :: quiet
      integer :: c(NCOUNT)
      character(len=:), allocatable :: own, mine, counted, partial
      if (status /= RUN_COMPLETED) write (0, '(a)') 'pecplas: run stopped ('// &
         status_name(status)//'): '//message
      flush (0)
      if (quiet) return
      ! the counts are the whole run's, a restarted one's too (its restart data carry those of
      ! the run before it); times and the solver's own statistics are this process's, and
      ! say so when the run was restarted
      c = whole_counts(problem)
      own = ''
      mine = ''
      counted = ''
      partial = ''
      if (problem%stats%restarted) then
         own = ' of this process (restarted after increment '// &
            itoa(problem%stats%resumed_after)//')'
         mine = ' (this process)'
         ! restart data of an earlier version hold no counts but increments, iterations, cuts
         if (.not. whole_known(problem)) then
            counted = ' (factorisations and solves: this process)'
            partial = mine
         end if
      end if
      write (*, '(a,i0,a,i0,a,i0,a,i0,a,i0,a,a,a,a)') ' summary: ', problem%stats%increments, &
         ' increments, ', problem%stats%iterations, ' iterations, ', problem%stats%cuts, ' cuts, ', &
         c(C_FACTORISATIONS), ' factorisations, ', c(C_SOLVES), ' solves'//counted//', ', &
         sec(cpu), ' s CPU', own
      ! which method converged the increments (doc/theory.md §4, the chain)
      write (*, '(a,3(i0,a),i0,a,i0,a,i0,a,i0,a)') ' methods: increments by modified Newton ', &
         c(C_METHOD), ', quasi-Newton ', c(C_METHOD + 1), ', Newton ', &
         c(C_METHOD + 2), '; under arc-length ', c(C_ARC), &
         '; line-search residuals ', c(C_LINE_SEARCHES), '; singular tangents ', &
         c(C_SINGULAR), ' (elastic stiffness used); re-closure limits ', c(C_RECLOSURE), partial
      associate (t => problem%stats%time)
         write (*, '(a,8(a,a))') ' wall time [s]'//own//':', ' read+setup ', sec(t%setup), &
            '  assembly ', sec(t%assembly), '  factorisation ', sec(t%factorisation), &
            '  solve ', sec(t%solve), '  residual ', sec(t%residual), ' (laws ', &
            sec(t%laws)//')', '  output ', sec(t%output), '  total ', sec(wall)
      end associate
      associate (t => problem%stats%time)
         if (t%rank_wall_max > 0.0_wp) write (*, '(a,i0,a)') ' ranks: ', parallel_size(), &
            ', each assembles the stiffness of its own elements: wall '// &
            sec(t%rank_wall_min)//' to '//sec(t%rank_wall_max)//' s, CPU '// &
            sec(t%rank_cpu_min)//' to '//sec(t%rank_cpu_max)//' s'//mine
      end associate
      write (*, '(a,i0,a)') ' threads: ', threads%n, ' ('//threads%source//'; OpenMP '// &
         trim(merge('on ', 'off', threads%openmp))//'; '//parts_text(threads)//')'
      if (allocated(problem%linear%solver)) write (*, '(a)') ' linear solver'//mine//': '// &
         problem%linear%solver%report()
      if (problem%katona%active) then
         associate (k => problem%katona)
            write (*, '(a,i0,a,i0,a,i0,a,i0,a,i0,a,es9.2,a,es9.2,a,a,a,a)') ' katona: ', k%nd, &
               ' doublets, ', c(C_STATE_ITERATIONS), ' state iterations (max ', &
               c(C_MAX_STATE_ITERATIONS), ' per increment), ', c(C_G_BUILDS), &
               ' flexibility builds, ', c(C_FROZEN), ' frozen doublets'// &
               partial//', max penetration ', &
               k%max_penetration, ', augmentation ', k%alpha, ', time'//mine//' flexibility ', &
               sec(k%time_flexibility), ' s, states ', sec(k%time_states)//' s'
         end associate
      end if
      write (*, '(a)') ' status: '//status_name(status)//'  results: '//outfile
   end subroutine summary

   !> Seconds with 3 decimals and a leading zero ("0.012").
   function sec(t) result(s)
      real(wp), intent(in) :: t
      character(len=:), allocatable :: s
      character(len=24) :: buf
      write (buf, '(f12.3)') t
      s = trim(adjustl(buf))
   end function sec

end module pecplas_cmd_pecplas
