!> `pecplas DECK --target-error E[%] [--goal GOAL] [--max-dofs N] [-o FILE]`: the
!> adaptive loop of pecplas_adapt_adapt from the command line. Prints a line per level and
!> writes the results of the last level (the one that met the target, or the last within
!> the DOF budget) to FILE (default output/<deck>.h5).
module pecplas_cmd_adapt
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, EXIT_OK, EXIT_INPUT, EXIT_STOPPED
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_model_adapt_scope, only: adapt_refusal
   use pecplas_model_geometry, only: check_geometry
   use pecplas_model_mesh_tools, only: check_elements
   use pecplas_problem_type, only: problem_t
   use pecplas_adapt_adapt, only: adapt_options_t, adapt_level_t, adapt_model
   use pecplas_base_files, only: make_directories, path_stem, path_dir
   use pecplas_cmd_command, only: command_error
   use pecplas_base_strings, only: itoa
   use pecplas_linalg_threads, only: thread_setting_t, resolve_threads, apply_threads
   use pecplas_model_adapt_request, only: parse_target, parse_goal, parse_goal_spec, goal_node_index, &
      goal_spec_t, GOAL_NODE, GOAL_REACTION, GOAL_LIMIT
   implicit none (type, external)
   private

   public :: adapt_main, parse_target, parse_goal

contains

   integer function adapt_main(deck, target, goal, max_dofs, outfile_in, strict) result(code)
      character(len=*), intent(in) :: deck, target, goal, outfile_in
      integer, intent(in) :: max_dofs
      !> Any warning of the deck is an input error (exit 2, no results file).
      logical, intent(in) :: strict
      type(model_t) :: model
      type(problem_t) :: problem
      type(adapt_options_t) :: opts
      type(adapt_level_t), allocatable :: levels(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: msg
      type(goal_spec_t) :: spec
      type(thread_setting_t) :: threads
      integer :: n, nflipped
      call parse_target(target, opts%target, msg)
      if (allocated(msg)) then
         code = command_error('pecplas', EXIT_INPUT, 'option --target-error: '//msg)
         return
      end if
      call parse_goal_spec(goal, spec, msg)
      if (allocated(msg)) then
         code = command_error('pecplas', EXIT_INPUT, 'option --goal: '//msg)
         return
      end if
      call read_deck(deck, model, error)
      if (allocated(error)) then
         code = command_error('pecplas', error%exit_code(), error%text())
         return
      end if
      if (len(adapt_refusal(model)) > 0) then
         code = command_error('pecplas', EXIT_INPUT, deck//': '//adapt_refusal(model)// &
            ' (--target-error, *ADAPT)')
         return
      end if
      ! the deck's warnings (reading, element shapes, joints) once, before the first level, as
      ! for one run; the refined levels' meshes are the program's own
      call check_elements(model%mesh, nflipped, error)
      if (.not. allocated(error)) call check_geometry(model, error)
      if (allocated(error)) deallocate (error)   ! the first level reports it, with its place
      call model%warnings%print(0)
      if (strict) call model%warnings%as_error(error)
      if (allocated(error)) then
         code = command_error('pecplas', error%exit_code(), error%text())
         return
      end if
      ! the deck's *SOLVER THREADS= or OMP_NUM_THREADS, else one thread, as for one run
      threads = resolve_threads(model%solver%threads)
      call apply_threads(threads)
      model%solver%threads = threads%n
      model%solver%threads_used = threads
      opts%goal_kind = spec%kind
      opts%goal_dof = spec%dof
      msg = 'the energy norm'
      select case (spec%kind)
      case (GOAL_NODE)
         call goal_node_index(spec, model%mesh, opts%goal_node, msg)
         if (opts%goal_node == 0) then
            code = command_error('pecplas', EXIT_INPUT, 'option --goal: '//msg)
            return
         end if
         msg = 'node '//itoa(model%mesh%node_id(opts%goal_node))//' '// &
            merge('x', 'y', opts%goal_dof == 1)
      case (GOAL_REACTION)
         if (model%mesh%find_nset(spec%set) == 0) then
            code = command_error('pecplas', EXIT_INPUT, 'option --goal: expected reaction:SET '// &
               "with SET a node set of the deck (*NSET), no set '"//spec%set//"'")
            return
         end if
         opts%goal_set = spec%set
         msg = "the reaction on node set '"//spec%set//"' (the loaded direction)"
         if (spec%dof > 0) msg = "the reaction on node set '"//spec%set//"' ("// &
            merge('x', 'y', spec%dof == 1)//')'
      case (GOAL_LIMIT)
         msg = 'the limit load'
      end select
      if (max_dofs > 0) opts%max_dofs = max_dofs
      opts%scratch = outfile_in
      if (len(opts%scratch) == 0) opts%scratch = 'output/'//path_stem(deck)//'.h5'
      if (len(path_dir(opts%scratch)) > 0) call make_directories(path_dir(opts%scratch))
      opts%keep = .true.
      opts%verbose = .true.
      write (*, '(a)') 'pecplas '//deck//': adaptive refinement to '//trim(target)//' on '// &
         msg//', at most '//itoa(opts%max_dofs)//' DOFs'
      write (*, '(2x,a5,2x,a10,2x,a9,2x,a10,2x,a14,2x,a12,2x,a9)') 'level', 'DOFs', &
         'elements', 'eta/|s| %', 'goal', 'goal error %', 'wall [s]'
      call adapt_model(model, opts, levels, problem, error)
      if (allocated(error)) then
         code = command_error('pecplas', EXIT_STOPPED, error%text())
         return
      end if
      n = size(levels)
      if (levels(n)%goal_error >= 0.0_wp .and. levels(n)%goal_error <= opts%target) then
         write (*, '(a)') 'target met at level '//itoa(n)//'; results of that level: '// &
            opts%scratch
         code = EXIT_OK
      else
         write (*, '(a)') 'target not met within the DOF budget (or the level limit); '// &
            'results of the last level: '//opts%scratch
         code = EXIT_STOPPED
      end if
   end function adapt_main

end module pecplas_cmd_adapt
