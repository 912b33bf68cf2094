!> Advice mode (`pecplas --advise DECK`): a study of a deck's first loading step over
!> nonlinear method x increments x mesh, the mesh axis being the adaptive sequence of
!> pecplas_adapt_adapt (solve, estimate, bulk marking, local refinement), and the cheapest
!> configuration whose estimated error is below 1 % and below 5 %.
!>
!> Goal: one displacement component of one node at the end of the first loading step (the first
!> step that applies more than gravity): `--goal node:N:x|y`, else the node of `--advise-node`,
!> else the deck's node of largest free displacement in the first reference run, with its
!> larger free (not imposed) component.
!>
!> 1. Reference sequence: NEWTON with x2 increments on the deck's mesh, then on each mesh of
!>    the adaptive sequence, until the goal's estimated error (Aitken over the levels, the
!>    larger of the last two estimates, as the adaptive loop does) is below REF_TARGET (a fifth
!>    of the 1 % tolerance), or the DOF budget, the level limit, a refusal of the refiner or a
!>    run that stops ends it.
!> 2. Variants: every method x increment factor on every level of the sequence; a
!>    configuration that met 1 % at a level is not run on finer ones (they cost it more; the
!>    reference configuration has run on every level anyway).
!> 3. Error of a run: |q - q_ref| / |q_ref| + e_ref, q_ref the goal of the finest reference run
!>    and e_ref its own estimated error: a bound by the triangle inequality, never below what
!>    the reference resolves. With one level only (the deck's mesh is not refined) e_ref = 0
!>    and the errors are those of the method and increments alone (said in the output).
!> 4. Cost of a configuration at level k: its wall times on levels 1 .. k summed (reaching the
!>    mesh adaptively with that configuration); the advice is the cheapest by this cost.
module pecplas_advise_advise
   use pecplas_base_kinds, only: wp
   use pecplas_base_run_status, only: RUN_NOT_RUN, status_name
   use pecplas_base_error, only: error_t, input_error
   use pecplas_model_type, only: model_t
   use pecplas_model_refine_local, only: refine_marked
   use pecplas_model_refine_mark, only: bulk_marking
   use pecplas_model_adapt_request, only: parse_goal_spec, goal_spec_t, NODE_GOAL => GOAL_NODE, &
      find_goal_node => goal_node_index
   use pecplas_problem_type, only: problem_t
   use pecplas_estimate_estimator, only: error_estimate_t, estimate_error
   use pecplas_adapt_adapt, only: adapt_options_t, goal_extrapolation
   use pecplas_advise_run, only: advise_row_t, loading_model, run_configuration
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private

   public :: advise_row_t, advice_t, advise_deck, ADVISE_METHODS, ADVISE_FACTORS, REF_TARGET, &
      ADVISE_TOLERANCES

   !> Nonlinear methods tried (model%solver%method).
   character(len=*), parameter :: ADVISE_METHODS(2) = [character(len=15) :: 'MODIFIED_NEWTON', &
      'NEWTON']
   !> Factors on the number of increments of every step (at least one increment); the last
   !> one with the last method is the reference configuration.
   real(wp), parameter :: ADVISE_FACTORS(3) = [0.5_wp, 1.0_wp, 2.0_wp]
   !> Estimated error at which the reference sequence stops: a fifth of the 1 % tolerance.
   real(wp), parameter :: REF_TARGET = 0.002_wp
   real(wp), parameter :: ADVISE_TOLERANCES(2) = [0.01_wp, 0.05_wp]

   !> What the advice found.
   type :: advice_t
      !> Every run, by level then configuration.
      type(advise_row_t), allocatable :: rows(:)
      !> Rows of the cheapest configuration within 1 % and 5 % (0: none).
      integer :: best(2) = 0
      !> Goal: deck node id and component (1 x/r, 2 y/z).
      integer :: node_id = 0, dof = 0
      !> DOFs of each level of the sequence.
      integer, allocatable :: level_dofs(:)
      !> Levels of the sequence, the reference goal value (finest level, NEWTON x2) and its
      !> estimated relative error (0 with one level: discretisation not assessed).
      integer :: nlevels = 0
      real(wp) :: reference = 0.0_wp, ref_error = 0.0_wp
      !> Why the sequence ended.
      character(len=:), allocatable :: stop_reason
   end type advice_t

contains

   !> Runs the advice on `deck`. goal: '' or node:N:x|y; node_id: --advise-node (0: none);
   !> max_dofs: the sequence's DOF budget (0: the adaptive loop's default).
   subroutine advise_deck(deck, goal, node_id, max_dofs, adv, error)
      character(len=*), intent(in) :: deck, goal
      integer, intent(in) :: node_id, max_dofs
      type(advice_t), intent(out) :: adv
      type(error_t), allocatable, intent(out) :: error
      type(adapt_options_t) :: opts
      type(model_t), allocatable :: meshes(:)
      type(advise_row_t), allocatable :: refs(:)
      real(wp), allocatable :: q(:), cost(:, :)
      logical, allocatable :: met(:, :)
      integer :: inode, k, m, f, tag

      if (max_dofs > 0) opts%max_dofs = max_dofs
      allocate (meshes(opts%max_levels))
      call loading_model(deck, meshes(1), error)
      if (allocated(error)) return
      call goal_node(meshes(1), goal, node_id, inode, adv%dof, error)
      if (allocated(error)) return
      call reference_sequence(deck, opts, meshes, inode, adv, refs, error)
      if (allocated(error)) return
      q = refs%goal
      adv%level_dofs = refs%ndof
      adv%reference = q(adv%nlevels)
      if (adv%nlevels >= 3) then
         adv%ref_error = max(goal_extrapolation(q), goal_extrapolation(q(1:adv%nlevels - 1)))
      else if (adv%nlevels == 2) then
         adv%ref_error = goal_extrapolation(q)
      end if
      allocate (adv%rows(0))
      allocate (cost(size(ADVISE_FACTORS), size(ADVISE_METHODS)), source=0.0_wp)
      allocate (met(size(ADVISE_FACTORS), size(ADVISE_METHODS)), source=.false.)
      tag = adv%nlevels
      do k = 1, adv%nlevels
         do m = 1, size(ADVISE_METHODS)
            do f = 1, size(ADVISE_FACTORS)
               if (m == size(ADVISE_METHODS) .and. f == size(ADVISE_FACTORS)) then
                  adv%rows = [adv%rows, refs(k)]
               else if (met(f, m)) then
                  cycle
               else
                  tag = tag + 1
                  adv%rows = [adv%rows, config_row(m, f, k)]
                  call run_goal(deck, meshes(k), inode, adv%dof, tag, &
                     adv%rows(size(adv%rows)), error)
                  if (allocated(error)) return
               end if
               associate (row => adv%rows(size(adv%rows)))
                  cost(f, m) = cost(f, m) + row%wall
                  row%cost = cost(f, m)
                  if (row%ok) row%err = abs(row%goal - adv%reference)/ &
                     max(abs(adv%reference), tiny(1.0_wp)) + adv%ref_error
                  met(f, m) = row%ok .and. row%err < ADVISE_TOLERANCES(1)
               end associate
            end do
         end do
      end do
      adv%node_id = meshes(1)%mesh%node_id(inode)
      do m = 1, size(ADVISE_TOLERANCES)
         adv%best(m) = cheapest(adv%rows, ADVISE_TOLERANCES(m))
      end do
   end subroutine advise_deck

   !> NEWTON x2 on the deck's mesh and on each new mesh of the adaptive sequence (meshes(k)),
   !> until its goal error estimate is below REF_TARGET or the sequence cannot go on
   !> (adv%stop_reason). refs(k): the reference row of level k; inode and dof are chosen from
   !> the first run when not given (dof 0).
   subroutine reference_sequence(deck, opts, meshes, inode, adv, refs, error)
      character(len=*), intent(in) :: deck
      type(adapt_options_t), intent(in) :: opts
      type(model_t), intent(inout) :: meshes(:)
      integer, intent(inout) :: inode
      type(advice_t), intent(inout) :: adv
      type(advise_row_t), allocatable, intent(out) :: refs(:)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: ran
      type(problem_t) :: problem
      type(error_estimate_t) :: est
      character(len=:), allocatable :: reason
      real(wp) :: eref
      integer :: k, s
      allocate (refs(0))
      do k = 1, size(meshes)
         refs = [refs, config_row(size(ADVISE_METHODS), size(ADVISE_FACTORS), k)]
         call run_configuration(deck, meshes(k), refs(k), k, ran, problem, error)
         if (allocated(error)) return
         if (.not. refs(k)%ok) then
            if (k == 1) then
               call input_error(error, 'advise: the reference run (NEWTON x2 on the deck''s '// &
                  'mesh) did not complete its first loading step ('//status_name(refs(k)%status)// &
                  '): no advice')
               return
            end if
            adv%stop_reason = 'NEWTON x2 stopped on level '//itoa(k)//' ('//status_name(refs(k)%status)//')'
            refs = refs(1:k - 1)
            exit
         end if
         if (adv%dof == 0) call pick_goal(meshes(1)%mesh%nnode(), problem, inode, adv%dof)
         refs(k)%goal = problem%state%u(adv%dof, inode)
         adv%nlevels = k
         eref = -1.0_wp
         if (k >= 3) eref = max(goal_extrapolation(refs%goal), &
            goal_extrapolation(refs(1:k - 1)%goal))
         if (eref >= 0.0_wp .and. eref <= REF_TARGET) then
            adv%stop_reason = 'estimated error of the reference below the 0.2 % aimed at'
            exit
         end if
         if (k == size(meshes)) then
            adv%stop_reason = 'level limit ('//itoa(k)//')'
            exit
         end if
         call estimate_error(ran, problem, est, error)
         if (allocated(error)) return
         call refine_marked(meshes(k), bulk_marking([(est%sets(s)%eta, s=1, size(est%sets))], &
            opts%theta), meshes(k + 1), reason)
         if (allocated(reason)) then
            adv%stop_reason = 'the mesh of level '//itoa(k)//' is not refined: '//reason
            exit
         end if
         if (2*meshes(k + 1)%mesh%nnode() > opts%max_dofs) then
            adv%stop_reason = 'the next level would exceed the DOF budget ('// &
               itoa(opts%max_dofs)//', --max-dofs)'
            exit
         end if
      end do
   end subroutine reference_sequence

   !> The configuration (method m, factor f) on level k, not yet run.
   function config_row(m, f, k) result(row)
      integer, intent(in) :: m, f, k
      type(advise_row_t) :: row
      row%method = ADVISE_METHODS(m)
      row%factor = ADVISE_FACTORS(f)
      row%level = k
      row%status = RUN_NOT_RUN
   end function config_row

   !> Runs `row` on `mesh` and reads the goal.
   subroutine run_goal(deck, mesh, inode, dof, tag, row, error)
      character(len=*), intent(in) :: deck
      type(model_t), intent(in) :: mesh
      integer, intent(in) :: inode, dof, tag
      type(advise_row_t), intent(inout) :: row
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: ran
      type(problem_t) :: problem
      call run_configuration(deck, mesh, row, tag, ran, problem, error)
      if (allocated(error)) return
      if (row%ok) row%goal = problem%state%u(dof, inode)
   end subroutine run_goal

   !> The goal's internal node (0 when to be chosen) and component (0 when to be chosen)
   !> from --goal or --advise-node; an unknown node or a goal that is not a node's
   !> displacement is an input error.
   subroutine goal_node(model, goal, node_id, inode, dof, error)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: goal
      integer, intent(in) :: node_id
      integer, intent(out) :: inode, dof
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: msg
      type(goal_spec_t) :: spec
      integer :: id
      id = node_id
      dof = 0
      inode = 0
      if (len_trim(goal) > 0) then
         call parse_goal_spec(goal, spec, msg)
         ! --target-error takes other goals too; the advice only node goals, so a malformed
         ! or other goal gets the one message that names what the advice accepts
         if (allocated(msg) .or. spec%kind /= NODE_GOAL) msg = 'expected node:N:x or '// &
            'node:N:y, N a node id or a node set of one node (the advice takes node goals), '// &
            'got '''//trim(goal)//''''
         if (allocated(msg)) then
            call input_error(error, 'advise: --goal: '//msg)
            return
         end if
         dof = spec%dof
         call find_goal_node(spec, model%mesh, inode, msg)
         if (allocated(msg)) call input_error(error, 'advise: --goal: '//msg)
         return
      end if
      if (id == 0) return
      inode = findloc(model%mesh%node_id, id, 1)
      if (inode == 0) call input_error(error, 'advise: no node '//itoa(id)//' in the mesh')
   end subroutine goal_node

   !> The node of largest free displacement among the deck's nnode0 nodes (unless inode is
   !> given) and its larger free component; imposed components say nothing of the accuracy.
   subroutine pick_goal(nnode0, problem, inode, dof)
      integer, intent(in) :: nnode0
      type(problem_t), intent(in) :: problem
      integer, intent(inout) :: inode
      integer, intent(out) :: dof
      logical, allocatable :: free(:, :)
      real(wp), allocatable :: u(:, :)
      free = problem%system%dofs%eq(:, 1:nnode0) > 0
      if (.not. any(free .and. problem%state%u(:, 1:nnode0) /= 0.0_wp)) free = .true.
      u = merge(problem%state%u(:, 1:nnode0), 0.0_wp, free)
      if (inode == 0) inode = maxloc(norm2(u, dim=1), dim=1)
      if (.not. any(free(:, inode))) u(:, inode) = problem%state%u(:, inode)
      dof = maxloc(abs(u(:, inode)), dim=1)
   end subroutine pick_goal

   !> The completed row of least cost whose error is below tol (0: none).
   integer function cheapest(rows, tol) result(b)
      type(advise_row_t), intent(in) :: rows(:)
      real(wp), intent(in) :: tol
      integer :: i
      b = 0
      do i = 1, size(rows)
         if (.not. rows(i)%ok .or. .not. rows(i)%err < tol) cycle
         if (b == 0) then
            b = i
         else if (rows(i)%cost < rows(b)%cost) then
            b = i
         end if
      end do
   end function cheapest

end module pecplas_advise_advise
