!> Advice mode (`pecplas --advise DECK`): a quick study of a deck's first loading
!> step under cheaper and finer configurations, run in-process, and the cheapest one whose
!> error is below 1 % and below 5 %.
!>
!> Variants on the deck's mesh: the nonlinear method (MODIFIED_NEWTON, NEWTON; Katona decks run
!> their contact iteration inside either) times the number of increments of every step (x1/2,
!> x1, x2), run up to the end of the first loading step (the first one that applies more than
!> gravity). One mesh level more: the deck's model refined uniformly once (h/2,
!> pecplas_model_refine) with NEWTON x1 and x2. The reference is the finest, NEWTON x2 on the
!> refined mesh, so the errors of the deck's mesh include its discretisation error; when the
!> model cannot be refined (point loads on both ends of an edge, supports across the body) the
!> mesh level is not varied (a one-line reason) and the reference is NEWTON x2 on the deck's
!> mesh; the same when the refined reference does not complete the step. The error of a
!> variant is |u - u_ref| / |u_ref| at the monitored node, at the end of the first step: the
!> node of the deck (refinement keeps its ids and numbers) with the largest free (not imposed)
!> displacement of the reference, or a node given by id; only the free components of its
!> displacement count (an imposed one is the same in every run). Each run writes a scratch
!> results file (the driver writes as it goes) that is deleted afterwards; its writing time is
!> not counted.
module pecplas_driver_advise
   use pecplas_kinds, only: wp, ik8
   use pecplas_error, only: error_t, input_error, EXIT_OK, EXIT_INPUT
   use pecplas_version, only: VERSION
   use pecplas_model, only: model_t
   use pecplas_model_refine, only: refine_model
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_driver_problem, only: problem_t
   use pecplas_driver_prepare, only: prepare_run
   use pecplas_driver_increments, only: run_increments
   use pecplas_driver_gauss, only: gauss_coordinates
   use pecplas_io_results_increment, only: joint_points_t
   use pecplas_io_results_file, only: results_file_t
   use pecplas_driver_timers, only: wall_time
   use pecplas_files, only: path_stem
   use pecplas_command, only: command_error
   use pecplas_strings, only: itoa, decimal_text
   implicit none (type, external)
   private

   public :: advise_row_t, advise_deck, advise_main, ADVISE_METHODS, ADVISE_FACTORS, &
      ADVISE_FINE_FACTORS

   !> Nonlinear methods tried (model%solver%method).
   character(len=*), parameter :: ADVISE_METHODS(2) = [character(len=15) :: 'MODIFIED_NEWTON', &
      'NEWTON']
   !> Factors on the number of increments of every step (at least one increment).
   real(wp), parameter :: ADVISE_FACTORS(3) = [0.5_wp, 1.0_wp, 2.0_wp]
   !> Factors tried with NEWTON on the refined mesh (the last one is the reference).
   real(wp), parameter :: ADVISE_FINE_FACTORS(2) = [1.0_wp, 2.0_wp]

   !> One configuration and what it gave.
   type :: advise_row_t
      character(len=15) :: method = ''
      real(wp) :: factor = 1.0_wp
      !> On the refined mesh (h/2) rather than the deck's.
      logical :: fine = .false.
      !> Increments of the first step, wall time [s] without result writing, relative error.
      integer :: increments = 0
      real(wp) :: wall = 0.0_wp, err = huge(1.0_wp)
      !> The run completed its first step.
      logical :: ok = .false.
      character(len=:), allocatable :: status
   end type advise_row_t

contains

   !> Runs the variants of `deck`; `node_id` > 0 monitors that node, else the node of largest
   !> reference displacement (`monitored` returns its id). `ref` is the reference row, `best`
   !> the cheapest row within 1 % and within 5 % (0 when none). `mesh_note` is allocated with
   !> the reason when the mesh level is not varied.
   subroutine advise_deck(deck, node_id, rows, ref, best, monitored, error, mesh_note)
      character(len=*), intent(in) :: deck
      integer, intent(in) :: node_id
      type(advise_row_t), allocatable, intent(out) :: rows(:)
      integer, intent(out) :: ref, best(2), monitored
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable, intent(out), optional :: mesh_note
      real(wp), allocatable :: u(:, :, :)
      logical, allocatable :: free(:, :)
      type(model_t) :: model, fine
      character(len=:), allocatable :: reason
      integer :: m, f, i, n, inode, nn0
      real(wp) :: uref(2)
      real(wp), parameter :: TOL(2) = [0.01_wp, 0.05_wp]

      ! the deck's own mesh fixes which nodes may be monitored, and whether it refines
      call read_deck(deck, model, error)
      if (allocated(error)) return
      nn0 = model%mesh%nnode()
      call refine_model(model, fine, reason)
      if (present(mesh_note) .and. allocated(reason)) mesh_note = reason
      n = size(ADVISE_METHODS)*size(ADVISE_FACTORS)
      if (.not. allocated(reason)) n = n + size(ADVISE_FINE_FACTORS)
      allocate (rows(n))
      n = 0
      do m = 1, size(ADVISE_METHODS)
         do f = 1, size(ADVISE_FACTORS)
            n = n + 1
            rows(n)%method = ADVISE_METHODS(m)
            rows(n)%factor = ADVISE_FACTORS(f)
         end do
      end do
      if (.not. allocated(reason)) then
         do f = 1, size(ADVISE_FINE_FACTORS)
            n = n + 1
            rows(n)%method = 'NEWTON'
            rows(n)%factor = ADVISE_FINE_FACTORS(f)
            rows(n)%fine = .true.
         end do
      end if
      ref = n
      ! the reference first: it fixes the monitored node
      call one_run(deck, n, n, rows(ref), model, u, error, free)
      if (allocated(error)) return
      if (.not. rows(ref)%ok .and. rows(ref)%fine) then
         ! the refined model stops (e.g. a limit load reached earlier): the deck's mesh only
         reason = 'the refined reference stopped ('//rows(ref)%status//')'
         if (present(mesh_note)) mesh_note = reason
         n = size(ADVISE_METHODS)*size(ADVISE_FACTORS)
         rows = rows(1:n)
         ref = n
         deallocate (u)
         call one_run(deck, n, n, rows(ref), model, u, error, free)
         if (allocated(error)) return
      end if
      if (.not. rows(ref)%ok) then
         call input_error(error, 'advise: the reference run ('//row_name(rows(ref))// &
            ') did not complete its first step ('//rows(ref)%status//'): no advice')
         return
      end if
      if (node_id > 0) then
         inode = findloc(model%mesh%node_id(1:nn0), node_id, dim=1)
         if (inode == 0) then
            call input_error(error, 'advise: --advise-node: no node '//itoa(node_id)// &
               ' in the mesh')
            return
         end if
      else
         ! imposed displacements say nothing of the accuracy: the free components count
         if (.not. any(free(:, 1:nn0) .and. u(:, 1:nn0, ref) /= 0.0_wp)) free = .true.
         inode = maxloc(norm2(merge(u(:, 1:nn0, ref), 0.0_wp, free(:, 1:nn0)), dim=1), dim=1)
      end if
      if (.not. any(free(:, inode))) free(:, inode) = .true.
      monitored = model%mesh%node_id(inode)
      uref = merge(u(:, inode, ref), 0.0_wp, free(:, inode))
      do i = 1, n - 1
         call one_run(deck, i, n, rows(i), model, u, error)
         if (allocated(error)) return
      end do
      do i = 1, n
         if (.not. rows(i)%ok) cycle
         rows(i)%err = norm2(merge(u(:, inode, i), 0.0_wp, free(:, inode)) - uref)/ &
            max(norm2(uref), tiny(1.0_wp))
      end do
      rows(ref)%err = 0.0_wp
      do m = 1, 2
         best(m) = 0
         do i = 1, n
            if (.not. rows(i)%ok .or. .not. rows(i)%err < TOL(m)) cycle
            if (best(m) == 0) then
               best(m) = i
            else if (rows(i)%wall < rows(best(m))%wall) then
               best(m) = i
            end if
         end do
      end do
   end subroutine advise_deck

   !> Reads `deck` afresh (refined once for a row on the fine mesh), keeps its steps up to the
   !> first loading step, applies the configuration of `row` and runs it quietly to a scratch
   !> results file (deleted); u(:, 1:nnode, i) = the displacements at the end (u allocated for
   !> `nvar` variants by the first run, the reference: the largest mesh).
   subroutine one_run(deck, i, nvar, row, model, u, error, free)
      character(len=*), intent(in) :: deck
      integer, intent(in) :: i, nvar
      type(advise_row_t), intent(inout) :: row
      type(model_t), intent(out) :: model
      real(wp), allocatable, intent(inout) :: u(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      !> The free displacement components (not supported nor imposed).
      logical, allocatable, intent(out), optional :: free(:, :)
      type(problem_t) :: problem
      type(results_file_t) :: results
      type(joint_points_t), allocatable :: jpoints(:)
      type(error_t), allocatable :: run_err
      character(len=:), allocatable :: status, message, scratch
      real(wp) :: w0
      integer :: nflipped, last, s
      type(model_t) :: coarse
      character(len=:), allocatable :: reason

      if (row%fine) then
         call read_deck(deck, coarse, error)
         if (allocated(error)) return
         call refine_model(coarse, model, reason)
         if (allocated(reason)) then
            call input_error(error, 'advise: the refinement failed: '//reason)
            return
         end if
      else
         call read_deck(deck, model, error)
      end if
      if (allocated(error)) return
      if (size(model%steps) < 1) then
         call input_error(error, 'advise: the deck has no *STEP')
         return
      end if
      last = first_loading_step(model)
      model%steps = model%steps(1:last)
      do s = 1, last
         model%steps(s)%increments = max(1, nint(row%factor*model%steps(s)%increments))
      end do
      row%increments = model%steps(last)%increments
      model%solver%method = trim(row%method)
      model%output%every = huge(1)
      w0 = wall_time()
      call prepare_run(model, problem, nflipped, jpoints, error)
      if (allocated(error)) return
      if (.not. allocated(u)) allocate (u(2, size(problem%state%u, 2), nvar), source=0.0_wp)
      scratch = scratch_name(deck, i)
      call results%create(scratch, model, VERSION, gauss_coordinates(model, problem), error, &
         jpoints)
      if (allocated(error)) then
         call input_error(error, 'advise: cannot write the scratch file '//scratch//': '// &
            error%text())
         return
      end if
      call run_increments(model, problem, results, .true., status, message, run_err)
      row%wall = wall_time() - w0 - problem%time%output
      if (allocated(run_err)) status = 'failed'
      call results%discard()
      row%status = status
      row%ok = status == 'completed'
      if (row%ok) u(:, 1:size(problem%state%u, 2), i) = problem%state%u
      if (present(free)) free = problem%dofs%eq > 0
   end subroutine one_run

   !> The first step that applies something else than gravity (a geostatic step only sets the
   !> initial state up); the last step when every step is gravity only.
   integer function first_loading_step(model) result(s)
      type(model_t), intent(in) :: model
      integer :: j
      do s = 1, size(model%steps)
         associate (st => model%steps(s))
            do j = 1, size(st%pattern)
               if (model%patterns(st%pattern(j))%kind /= 'GRAVITY') return
            end do
         end associate
      end do
      s = size(model%steps)
   end function first_loading_step

   !> `pecplas --advise DECK [--advise-node N]`: prints the table and the two advice lines;
   !> exit code 0, or 2 when the deck or the reference run fails.
   integer function advise_main(deck, node_id) result(code)
      character(len=*), intent(in) :: deck
      integer, intent(in) :: node_id
      type(advise_row_t), allocatable :: rows(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: note
      integer :: ref, best(2), monitored, i
      character(len=*), parameter :: FMT = '(2x,a15,2x,a4,2x,a5,2x,i10,2x,f10.4,2x,a12,2x,a)'
      call advise_deck(deck, node_id, rows, ref, best, monitored, error, note)
      if (allocated(error)) then
         code = command_error('pecplas', error%exit_code(), error%text())
         return
      end if
      write (*, '(a)') 'pecplas --advise '//deck//': first loading step, monitored node '// &
         itoa(monitored)//', reference '//row_name(rows(ref))
      if (allocated(note)) write (*, '(a)') 'mesh level not varied: '//note
      write (*, '(2x,a15,2x,a4,2x,a5,2x,a10,2x,a10,2x,a12,2x,a)') 'method', 'mesh', 'incr.', &
         'increments', 'wall [s]', 'error', 'status'
      do i = 1, size(rows)
         write (*, FMT) rows(i)%method, merge('h/2 ', 'deck', rows(i)%fine), &
            decimal_text(rows(i)%factor, 2), rows(i)%increments, rows(i)%wall, err_text(rows(i)), &
            rows(i)%status
      end do
      write (*, '(a)') advice_line('1 %', rows, best(1))
      write (*, '(a)') advice_line('5 %', rows, best(2))
      code = EXIT_OK
   end function advise_main

   function advice_line(what, rows, b) result(line)
      character(len=*), intent(in) :: what
      type(advise_row_t), intent(in) :: rows(:)
      integer, intent(in) :: b
      character(len=:), allocatable :: line
      if (b == 0) then
         line = 'advice (error < '//what//'): none of the configurations'
         return
      end if
      line = 'advice (error < '//what//'): METHOD='//trim(rows(b)%method)//', INCREMENTS='// &
         itoa(rows(b)%increments)//' in the first loading step (x'// &
         decimal_text(rows(b)%factor, 2)//')'
      if (rows(b)%fine) line = line//', mesh refined once (h/2)'
      line = line//', error '//err_text(rows(b))
   end function advice_line

   !> 'deck' (the deck's mesh) or 'h/2' (refined once).
   pure function mesh_text(row) result(s)
      type(advise_row_t), intent(in) :: row
      character(len=:), allocatable :: s
      s = merge('h/2 ', 'deck', row%fine)
      s = trim(s)
   end function mesh_text

   !> The configuration in words, e.g. 'NEWTON x2 increments, mesh h/2'.
   function row_name(row) result(s)
      type(advise_row_t), intent(in) :: row
      character(len=:), allocatable :: s
      s = trim(row%method)//' x'//decimal_text(row%factor, 2)//' increments, mesh '//mesh_text(row)
   end function row_name

   !> '0.5', '1', '2': the factor with no trailing zeros.

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

   !> A scratch results path unique to this run (TMPDIR or /tmp, deck stem, clock, variant).
   function scratch_name(deck, i) result(path)
      character(len=*), intent(in) :: deck
      integer, intent(in) :: i
      character(len=:), allocatable :: path
      character(len=512) :: dir
      integer(ik8) :: count
      integer :: n, stat
      call get_environment_variable('TMPDIR', dir, n, stat)
      if (stat /= 0 .or. n == 0) dir = '/tmp'
      call system_clock(count)
      path = trim(dir)//'/pecplas_advise_'//path_stem(deck)//'_'//itoa(int(mod(count, &
         1000000000_ik8)))//'_'//itoa(i)//'.h5'
   end function scratch_name

end module pecplas_driver_advise
