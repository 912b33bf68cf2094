!> One quiet run of the advice mode (pecplas_advise_advise): the deck cut to its first loading
!> step, a configuration (nonlinear method, factor on the increments) applied to a copy of a
!> mesh of the adaptive sequence, and the run to a scratch results file that is deleted
!> afterwards (its writing time is not counted).
module pecplas_advise_run
   use pecplas_base_kinds, only: wp, ik8
   use pecplas_model_loads, only: LOAD_GRAVITY
   use pecplas_base_run_status, only: RUN_NOT_RUN, RUN_COMPLETED, RUN_FAILED
   use pecplas_base_error, only: error_t, input_error
   use pecplas_base_version, only: VERSION
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: method_kind
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_model_phase_plan, only: is_phased
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_prepare, only: prepare_run
   use pecplas_solve_increments, only: run_increments
   use pecplas_solve_gauss, only: gauss_coordinates
   use pecplas_io_results_increment, only: joint_points_t
   use pecplas_io_results_file, only: results_file_t
   use pecplas_base_timers, only: wall_time
   use pecplas_base_files, only: path_stem
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private

   public :: advise_row_t, loading_model, run_configuration

   !> One configuration (method x increments x mesh level) and what it gave.
   type :: advise_row_t
      character(len=15) :: method = ''
      real(wp) :: factor = 1.0_wp
      !> Level of the adaptive sequence (1: the deck's mesh), its equations, the increments
      !> of the first loading step.
      integer :: level = 1, ndof = 0, increments = 0
      !> Wall time of the run [s] (result writing excluded); `cost`: the same configuration's
      !> runs on levels 1 .. level summed (what reaching this mesh adaptively costs).
      real(wp) :: wall = 0.0_wp, cost = 0.0_wp
      !> Goal value at the end of the first loading step, estimated relative error.
      real(wp) :: goal = 0.0_wp, err = huge(1.0_wp)
      !> The run completed its first loading step.
      logical :: ok = .false.
      !> How the run ended (pecplas_base_run_status; RUN_NOT_RUN before it ran).
      integer :: status = RUN_NOT_RUN
   end type advise_row_t

contains

   !> The deck's model with its steps up to the first loading step (the first one that
   !> applies more than gravity) and no intermediate output.
   subroutine loading_model(deck, model, error)
      character(len=*), intent(in) :: deck
      type(model_t), intent(out) :: model
      type(error_t), allocatable, intent(out) :: error
      call read_deck(deck, model, error)
      if (allocated(error)) return
      if (is_phased(model)) then
         call input_error(error, 'advise: not available for a phased deck (doc/deck.md, '// &
            'Phases): its trial runs would change with the phases; choose the method and '// &
            'increments phase by phase by hand')
         return
      end if
      if (allocated(model%plates)) then
         if (size(model%plates) > 0) then
            call input_error(error, 'advise: not available for a deck with plates (*PLATE): '// &
               'its mesh refinements do not carry plates along')
            return
         end if
      end if
      if (allocated(model%anchors)) then
         if (size(model%anchors) > 0) then
            call input_error(error, 'advise: not available for a deck with anchors (*ANCHOR): '// &
               'its mesh refinements do not carry anchors along')
            return
         end if
      end if
      if (size(model%steps) < 1) then
         call input_error(error, 'advise: the deck has no *STEP')
         return
      end if
      model%steps = model%steps(1:first_loading_step(model))
      model%output%every = huge(1)
   end subroutine loading_model

   !> Runs `base` (a loading model) under the configuration of `row` (method, factor on the
   !> increments of every step, at least one); fills row%increments, ndof, wall, status, ok.
   !> `problem` holds the final state. An error only when the scratch file cannot be written
   !> or the set-up fails; a run that stops is a row status.
   subroutine run_configuration(deck, base, row, tag, model, problem, error)
      character(len=*), intent(in) :: deck
      type(model_t), intent(in) :: base
      type(advise_row_t), intent(inout) :: row
      !> Makes the scratch name unique within the advice.
      integer, intent(in) :: tag
      !> The configured model that ran (for the estimator).
      type(model_t), intent(out) :: model
      type(problem_t), intent(out) :: problem
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: results
      type(joint_points_t), allocatable :: jpoints(:)
      type(error_t), allocatable :: run_err
      character(len=:), allocatable :: message, scratch
      real(wp) :: w0
      integer :: nflipped, s, status
      model = base
      do s = 1, size(model%steps)
         model%steps(s)%increments = max(1, nint(row%factor*model%steps(s)%increments))
      end do
      row%increments = model%steps(size(model%steps))%increments
      model%solver%method = method_kind(row%method)
      w0 = wall_time()
      call prepare_run(model, problem, nflipped, jpoints, error)
      if (allocated(error)) return
      row%ndof = problem%system%dofs%neq
      scratch = scratch_name(deck, tag)
      call results%create(scratch, model, VERSION, gauss_coordinates(model, problem), error, &
         jpoints)
      if (allocated(error)) then
         call input_error(error, 'advise: cannot write the scratch file '//scratch//': '// &
            error%text())
         return
      end if
      call run_increments(model, problem, results, .true., status, message, run_err)
      row%wall = wall_time() - w0 - problem%stats%time%output
      if (allocated(run_err)) status = RUN_FAILED
      call results%discard()
      row%status = status
      row%ok = status == RUN_COMPLETED
   end subroutine run_configuration

   !> The first step that applies something else than gravity (a geostatic step only sets the
   !> initial state up); the last step when every step is gravity only.
   integer function first_loading_step(model) result(s)
      type(model_t), intent(in) :: model
      integer :: j
      do s = 1, size(model%steps)
         associate (st => model%steps(s))
            do j = 1, size(st%pattern)
               if (model%patterns(st%pattern(j))%kind /= LOAD_GRAVITY) return
            end do
         end associate
      end do
      s = size(model%steps)
   end function first_loading_step

   !> A scratch results path unique to this run (TMPDIR or /tmp, deck stem, clock, tag).
   function scratch_name(deck, tag) result(path)
      character(len=*), intent(in) :: deck
      integer, intent(in) :: tag
      character(len=:), allocatable :: path
      character(len=512) :: dir
      integer(ik8) :: count
      integer :: n, stat
      call get_environment_variable('TMPDIR', dir, n, stat)
      if (stat /= 0 .or. n == 0) dir = '/tmp'
      call system_clock(count)
      path = trim(dir)//'/pecplas_advise_'//path_stem(deck)//'_'//itoa(int(mod(count, &
         1000000000_ik8)))//'_'//itoa(tag)//'.h5'
   end function scratch_name

end module pecplas_advise_run
