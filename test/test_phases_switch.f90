!> Phases that switch supports, load patterns and Katona contact (doc/deck.md, Phases;
!> doc/theory.md §10): a K0 column loaded on top, propped there by a named support, unloaded
!> (the pattern deactivated), the prop released (its reaction released over the step) and
!> the load activated again, each stage against the oedometric closed form; the same release
!> in 1 and 10 increments and restarted in the middle; a Katona contact set activated with
!> the contact forces of the initial stresses carries its block at once; bad decks stop with
!> file:line.
module test_phases_switch
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_base_strings, only: itoa
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_bad_decks, only: check_refused
   use pecplas_cmd_adapt, only: adapt_main
   use pecplas_advise_advise, only: advice_t, advise_deck
   use pecplas_linalg_solver, only: mumps_available
   use pecplas_problem_phase, only: PROCEDURE_GRAVITY
   use test_phases, only: write_column, write_block, oedometric, H, GAMMA, ELASTIC
   implicit none (type, external)
   private
   public :: collect_phases_switch

   character(len=*), parameter :: OUT = 'build/test_out/phases_switch/'
   !> Column of 20 elements (nodes 1..42, top nodes 41, 42 at y = H); q on top.
   integer, parameter :: NEL = 20, NNODE = 2*NEL + 2
   real(wp), parameter :: Q = 100.0_wp
   character(len=1), parameter :: NL = new_line('a')

contains

   subroutine collect_phases_switch(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('support_and_load_switched', test_switched), &
               new_unittest('support_release_increments', test_release_increments), &
               new_unittest('support_release_restart', test_release_restart), &
               new_unittest('katona_wished_in_place', test_katona_wished), &
               new_unittest('bad_switch_decks', test_bad_decks), &
               new_unittest('adapt_and_advise_refused', test_refused), &
               new_unittest('switched_other_solvers', test_solvers), &
               new_unittest('reset_displacements', test_reset), &
               new_unittest('gravity_loading_then_dig', test_gravity), &
               new_unittest('strict_phase_warning', test_strict), &
               new_unittest('joints_follow_their_elements', test_joints_follow)]
   end subroutine collect_phases_switch

   !> The column deck with a top load q (pattern 'q', FORCE q/2 on each top node) and a prop
   !> 'cap' on the top nodes (*BOUNDARY, NAME=cap, Y): load; prop installed (a nil step);
   !> load deactivated; prop released in `nrel` increments; load activated again.
   subroutine write_switched(path, nrel, solver)
      character(len=*), intent(in) :: path
      integer, intent(in) :: nrel
      character(len=*), intent(in), optional :: solver
      character(len=:), allocatable :: extra
      extra = ''
      if (present(solver)) extra = '*SOLVER, LINEAR='//solver//NL
      call write_column(path, NEL, 0, [integer ::], 1, ELASTIC, steps=extra// &
         '*NSET, NAME=topn'//NL//itoa(NNODE - 1)//', '//itoa(NNODE)//NL// &
         '*LOAD, NAME=q, TYPE=FORCE'//NL//'topn, Y, -50'//NL// &
         '*BOUNDARY, NAME=cap'//NL//'topn, Y'//NL// &
         '*STEP, NAME=load'//NL//'q, 1'//NL// &
         '*STEP, NAME=prop'//NL//'*ACTIVATE'//NL//'cap'//NL// &
         '*STEP, NAME=unload'//NL//'*DEACTIVATE'//NL//'q'//NL// &
         '*STEP, NAME=release, INCREMENTS='//itoa(nrel)//NL//'*DEACTIVATE'//NL//'cap'//NL// &
         '*STEP, NAME=reload'//NL//'*ACTIVATE'//NL//'q')
   end subroutine write_switched

   !> Largest |u - u_expected| over the column, u_expected = (0, -s q y / M).
   real(wp) function misfit(model, problem, s) result(worst)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: s
      integer :: n
      worst = 0.0_wp
      do n = 1, NNODE
         worst = max(worst, abs(problem%state%u(1, n)), &
            abs(problem%state%u(2, n) + s*Q*model%mesh%x(2, n)/oedometric()))
      end do
   end function misfit

   !> Each stage of write_switched (one increment each) against the closed form: loaded, the
   !> column settles q y / M; the prop installed moves nothing; the load deactivated with the
   !> prop in place moves nothing (the column is held top and bottom: its uniform strain
   !> stays, the prop takes q); the prop released, the column springs back to the K0 state
   !> (zero displacement, geostatic stresses); the load activated again, it settles q y / M
   !> again. Elastic and exact for Q4 (uniform strain): 1e-10 of the settlement q H / M and
   !> of gamma H (round-off of a 20-element solve).
   subroutine test_switched(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: p(5)
      character(len=*), parameter :: deck = OUT//'switched.inp'
      character(len=*), parameter :: stage(5) = [character(len=8) :: 'load', 'prop', 'unload', &
         'release', 'reload']
      real(wp), parameter :: expect(5) = [1.0_wp, 1.0_wp, 1.0_wp, 0.0_wp, 1.0_wp]
      real(wp) :: settle
      integer :: k, code
      call make_directories(OUT)
      call write_switched(deck, 1)
      settle = Q*H/oedometric()
      do k = 1, 5
         if (k < 5) then
            code = run_deck(deck, OUT//'switched_'//itoa(k)//'.h5', .true., model, p(k), &
               stop_after=k)
            call check(error, code == 4, trim(stage(k))//': stopped after it (exit '// &
               itoa(code)//')')
         else
            code = run_deck(deck, OUT//'switched_5.h5', .true., model, p(k))
            call check(error, code == 0, 'reload: runs to the end (exit '//itoa(code)//')')
         end if
         if (allocated(error)) return
         call check_close(error, misfit(model, p(k), expect(k)), 0.0_wp, 0.0_wp, &
            trim(stage(k))//': u = '//trim(merge('(0, -q y / M)', '0            ', &
            expect(k) > 0.0_wp)), atol=1.0e-10_wp*settle)
         if (allocated(error)) return
      end do
      ! the stresses: q carried by the prop after unloading, the K0 state after the release
      call check_close(error, maxval(abs(p(3)%state%sets(1)%stress - p(1)%state%sets(1)%stress)), &
         0.0_wp, 0.0_wp, 'unload with the prop in place: stresses unchanged', &
         atol=1.0e-10_wp*GAMMA*H)
      if (allocated(error)) return
      call check_close(error, maxval(abs(p(1)%state%sets(1)%stress(2, :, :) - &
         p(4)%state%sets(1)%stress(2, :, :))), Q, 1.0e-10_wp, &
         'release: the vertical stress is q less than loaded (geostatic again)')
      if (allocated(error)) return
      ! the equations follow the prop: top y dofs constrained while it stands
      call check(error, p(2)%system%dofs%eq(2, NNODE) == 0 .and. p(4)%system%dofs%eq(2, NNODE) > 0 &
         .and. p(4)%system%dofs%neq == p(1)%system%dofs%neq .and. &
         p(2)%system%dofs%neq == p(1)%system%dofs%neq - 2, 'the prop takes its two equations '// &
         'out of the system and gives them back')
   end subroutine test_switched

   !> The prop released in 10 increments ends where one increment does (elastic), and after
   !> 3 of 10 increments the column has recovered 3/10 of its settlement: the reaction is
   !> released linearly over the step (1e-10 of q H / M).
   subroutine test_release_increments(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: one, ten, part
      real(wp) :: settle
      integer :: code
      call make_directories(OUT)
      settle = Q*H/oedometric()
      call write_switched(OUT//'release_1.inp', 1)
      call write_switched(OUT//'release_10.inp', 10)
      code = run_deck(OUT//'release_1.inp', OUT//'release_1.h5', .true., model, one, &
         stop_after=4)
      call check(error, code == 4, 'released in one increment')
      if (allocated(error)) return
      code = run_deck(OUT//'release_10.inp', OUT//'release_10.h5', .true., model, ten, &
         stop_after=13)
      call check(error, code == 4, 'released in ten increments')
      if (allocated(error)) return
      call check_close(error, maxval(abs(ten%state%u - one%state%u)), 0.0_wp, 0.0_wp, &
         '10 increments = 1 increment', atol=1.0e-10_wp*settle)
      if (allocated(error)) return
      code = run_deck(OUT//'release_10.inp', OUT//'release_3.h5', .true., model, part, &
         stop_after=6)
      call check(error, code == 4, '3 of 10 release increments')
      if (allocated(error)) return
      call check_close(error, misfit(model, part, 0.7_wp), 0.0_wp, 0.0_wp, &
         'after 3/10 of the release: u = 0.7 of the settlement', atol=1.0e-10_wp*settle)
   end subroutine test_release_increments

   !> A run interrupted in the release phase (the equations numbered without the prop) and
   !> restarted equals the uninterrupted run (1e-12 of the settlement).
   subroutine test_release_restart(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: whole, resumed
      character(len=*), parameter :: deck = OUT//'restart.inp'
      real(wp) :: settle
      integer :: code
      call make_directories(OUT)
      settle = Q*H/oedometric()
      call write_switched(deck, 4)
      code = run_deck(deck, OUT//'restart_whole.h5', .true., model, whole)
      call check(error, code == 0, 'uninterrupted run')
      if (allocated(error)) return
      code = run_deck(deck, OUT//'restart_part.h5', .true., model, resumed, stop_after=5)
      call check(error, code == 4, 'interrupted in the release (exit '//itoa(code)//')')
      if (allocated(error)) return
      code = run_deck(deck, OUT//'restart_resumed.h5', .true., model, resumed, &
         restart=OUT//'restart_part.h5')
      call check(error, code == 0, 'restarted (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check_close(error, maxval(abs(resumed%state%u - whole%state%u)), 0.0_wp, 0.0_wp, &
         'restarted = uninterrupted', atol=1.0e-12_wp*settle)
      if (allocated(error)) return
      call check_close(error, misfit(model, resumed, 1.0_wp), 0.0_wp, 0.0_wp, &
         'restarted run ends at q y / M', atol=1.0e-10_wp*settle)
   end subroutine test_release_restart

   !> A K0 column (y 0..7.5) and a block on it (7.5..10) on a Katona contact set, both not
   !> active at the start, installed in two increments by the first step, the block with its
   !> K0 stress (STRESS=WISHED_IN_PLACE). Doublets in stick hold the block rigidly: nothing
   !> moves either way (1e-10 of the settlement gamma 2.5 7.5 / M the block's weight would
   !> cause on the column). What differs is their force: activated with STRESS=
   !> WISHED_IN_PLACE they carry the block's weight gamma 2.5 (width 1) from the first
   !> increment on (the contact forces of the initial stresses); activated without force,
   !> their force builds up with the out-of-balance released over the step: half the weight
   !> after the first of the two increments (1e-10).
   subroutine test_katona_wished(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: wished, zero
      real(wp) :: scale
      integer :: code
      call make_directories(OUT)
      call write_block(OUT//'katona_wished.inp', ', STRESS=WISHED_IN_PLACE')
      call write_block(OUT//'katona_zero.inp', '')
      scale = GAMMA*2.5_wp*7.5_wp/oedometric()
      code = run_deck(OUT//'katona_zero.inp', OUT//'katona_zero.h5', .true., model, zero, &
         stop_after=1)
      call check(error, code == 4, 'doublets installed without force (exit '//itoa(code)//')')
      if (allocated(error)) return
      code = run_deck(OUT//'katona_wished.inp', OUT//'katona_wished.h5', .true., model, wished, &
         stop_after=1)
      call check(error, code == 4, 'doublets installed wished in place (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check_close(error, maxval(abs(wished%state%u)), 0.0_wp, 0.0_wp, &
         'wished in place: nothing moves', atol=1.0e-10_wp*scale)
      if (allocated(error)) return
      call check_close(error, maxval(abs(zero%state%u)), 0.0_wp, 0.0_wp, &
         'without force: nothing moves (stick)', atol=1.0e-10_wp*scale)
      if (allocated(error)) return
      call check_close(error, sum(wished%katona%f(1, :)), GAMMA*2.5_wp, 1.0e-10_wp, &
         'wished in place: the doublets carry the block''s weight at once')
      if (allocated(error)) return
      call check_close(error, sum(zero%katona%f(1, :)), 0.5_wp*GAMMA*2.5_wp, 1.0e-10_wp, &
         'without force: half the weight after half the step')
      if (allocated(error)) return
      code = run_deck(OUT//'katona_zero.inp', OUT//'katona_zero_all.h5', .true., model, zero)
      call check(error, code == 0, 'installation without force to the end')
      if (allocated(error)) return
      call check_close(error, sum(zero%katona%f(1, :)), GAMMA*2.5_wp, 1.0e-10_wp, &
         'without force: the whole weight at the end of the step')
   end subroutine test_katona_wished

   !> Bad decks that switch supports and patterns: exit 2, file:line and what is wrong in the
   !> message, no results file.
   subroutine test_bad_decks(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: head = '*NSET, NAME=topn|41, 42|*LOAD, NAME=q, TYPE=FORCE|'// &
         'topn, Y, -50|*LOAD, NAME=pull, TYPE=DISPLACEMENT|topn, X, 0.001|'// &
         '*BOUNDARY, NAME=cap|topn, Y|'
      character(len=*), parameter :: cases(7) = [character(len=120) :: &
         '*STEP, NAME=a|*DEACTIVATE|cap|*STEP, NAME=b|*ACTIVATE|cap|*STEP, NAME=c|*ACTIVATE|cap', &
         '*STEP, NAME=a|*DEACTIVATE|cap|*STEP, NAME=b|*DEACTIVATE|cap', &
         '*STEP, NAME=a|*DEACTIVATE|q|*STEP, NAME=b|*DEACTIVATE|q', &
         '*STEP, NAME=a|*DEACTIVATE|q|*STEP, NAME=b|*ACTIVATE|q|*STEP, NAME=c|*ACTIVATE|q', &
         '*STEP, NAME=a|q, 1|*STEP, NAME=b|*DEACTIVATE|pull', &
         '*STEP, NAME=a|*DEACTIVATE|q|*STEP, NAME=b|*ACTIVATE, STRESS=WISHED_IN_PLACE|q', &
         '*STEP, NAME=a|*DEACTIVATE|q|*STEP, NAME=b|q, 0']
      character(len=*), parameter :: expect(7) = [character(len=56) :: &
         "support 'cap' is already active", "support 'cap' is not active", &
         "load pattern 'q' is not active", "'q' is already active", &
         "imposes displacements", "STRESS=WISHED_IN_PLACE is for", &
         "which is not active in it"]
      character(len=*), parameter :: marker(7) = [character(len=40) :: 'cap', 'cap', 'q', 'q', &
         'pull', 'q', '*STEP, NAME=b']
      character(len=:), allocatable :: deck, steps
      integer :: k, i
      call make_directories(OUT)
      do k = 1, size(cases)
         steps = head//trim(cases(k))
         do i = 1, len(steps)
            if (steps(i:i) == '|') steps(i:i) = NL
         end do
         deck = OUT//'bad'//itoa(k)//'.inp'
         call write_column(deck, NEL, 0, [integer ::], 1, ELASTIC, steps=steps)
         call check_refused(error, deck, trim(marker(k)), trim(expect(k)), OUT//'bad.h5', &
            'bad deck '//itoa(k))
         if (allocated(error)) return
      end do
   end subroutine test_bad_decks

   !> Adaptive refinement (--target-error, *ADAPT) and --advise refuse a phased deck: exit 2
   !> (input error), the reason in the message, no results file.
   subroutine test_refused(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(advice_t) :: adv
      type(error_t), allocatable :: e
      character(len=*), parameter :: deck = OUT//'refused.inp', with_adapt = OUT//'refused_adapt.inp'
      character(len=:), allocatable :: text
      integer :: code, u
      logical :: exists
      call make_directories(OUT)
      call write_switched(deck, 1)
      code = adapt_main(deck, '10%', '', 0, OUT//'refused.h5', .false.)
      inquire (file=OUT//'refused.h5', exist=exists)
      call check(error, code == 2 .and. .not. exists, '--target-error refuses a phased deck '// &
         '(exit '//itoa(code)//')')
      if (allocated(error)) return
      call advise_deck(deck, '', 0, 0, adv, e)
      call check(error, allocated(e), '--advise refuses a phased deck')
      if (allocated(error)) return
      text = e%text()
      call check(error, index(text, 'not available for a phased deck') > 0 .and. &
         e%exit_code() == 2, '--advise says why, exit 2: '//text)
      if (allocated(error)) return
      ! *ADAPT in the deck goes the way of --target-error
      call write_switched(with_adapt, 1)
      open (newunit=u, file=with_adapt, status='old', position='append', action='write')
      write (u, '(a)') '*ADAPT, TARGET=10%'
      close (u)
      code = run_deck(with_adapt, OUT//'refused_adapt.h5', .true., model, problem)
      inquire (file=OUT//'refused_adapt.h5', exist=exists)
      call check(error, code == 2 .and. .not. exists, '*ADAPT refuses a phased deck (exit '// &
         itoa(code)//')')
   end subroutine test_refused

   !> The stages of test_switched (prop installed and released: the equations numbered
   !> again, the solver's analysis done afresh) with UMFPACK, and with MUMPS where the build
   !> has it (the MPI build): the end state is the closed form q y / M (1e-10 of q H / M).
   subroutine test_solvers(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: p
      character(len=8), allocatable :: names(:)
      integer :: k, code
      call make_directories(OUT)
      names = [character(len=8) :: 'UMFPACK']
      if (mumps_available()) names = [character(len=8) :: names, 'MUMPS']
      do k = 1, size(names)
         call write_switched(OUT//'solver_'//trim(names(k))//'.inp', 3, trim(names(k)))
         code = run_deck(OUT//'solver_'//trim(names(k))//'.inp', OUT//'solver_'// &
            trim(names(k))//'.h5', .true., model, p)
         call check(error, code == 0, trim(names(k))//' runs (exit '//itoa(code)//')')
         if (allocated(error)) return
         call check_close(error, misfit(model, p, 1.0_wp), 0.0_wp, 0.0_wp, trim(names(k))// &
            ': ends at q y / M', atol=1.0e-10_wp*Q*H/oedometric())
         if (allocated(error)) return
      end do
   end subroutine test_solvers

   !> RESET_DISPLACEMENTS: the column loaded by q, its displacements reset (a nil step:
   !> nothing moves, u = 0 but for round-off, the stresses kept), then unloaded: it heaves q y / M from
   !> the reset and its stresses are the geostatic ones again (1e-10 of q H / M and gamma H).
   subroutine test_reset(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: loaded, reset, unloaded
      character(len=*), parameter :: deck = OUT//'reset.inp'
      integer :: code
      call make_directories(OUT)
      call write_column(deck, NEL, 0, [integer ::], 1, ELASTIC, steps= &
         '*NSET, NAME=topn'//NL//itoa(NNODE - 1)//', '//itoa(NNODE)//NL// &
         '*LOAD, NAME=q, TYPE=FORCE'//NL//'topn, Y, -50'//NL// &
         '*STEP, NAME=load'//NL//'q, 1'//NL// &
         '*STEP, NAME=reset, RESET_DISPLACEMENTS=YES'//NL// &
         '*STEP, NAME=unload'//NL//'q, 0')
      code = run_deck(deck, OUT//'reset_1.h5', .true., model, loaded, stop_after=1)
      call check(error, code == 4, 'loaded')
      if (allocated(error)) return
      code = run_deck(deck, OUT//'reset_2.h5', .true., model, reset, stop_after=2)
      call check(error, code == 4, 'reset')
      if (allocated(error)) return
      call check_close(error, maxval(abs(reset%state%u)), 0.0_wp, 0.0_wp, &
         'after the reset: u = 0', atol=1.0e-10_wp*Q*H/oedometric())
      if (allocated(error)) return
      call check_close(error, maxval(abs(reset%state%sets(1)%stress - loaded%state%sets(1)%stress)), &
         0.0_wp, 0.0_wp, 'the reset keeps the stresses', atol=1.0e-10_wp*GAMMA*H)
      if (allocated(error)) return
      code = run_deck(deck, OUT//'reset_3.h5', .true., model, unloaded)
      call check(error, code == 0, 'unloaded (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check_close(error, misfit(model, unloaded, -1.0_wp), 0.0_wp, 0.0_wp, &
         'unloaded after the reset: u = (0, +q y / M)', atol=1.0e-10_wp*Q*H/oedometric())
      if (allocated(error)) return
      call check_close(error, maxval(abs(unloaded%state%sets(1)%stress(2, :, :) - &
         loaded%state%sets(1)%stress(2, :, :))), Q, 1.0e-10_wp, &
         'unloaded: the vertical stress is q less than loaded (geostatic)')
   end subroutine test_reset

   !> Gravity loading as the initial procedure: the column (no *INITIAL_STRESS) takes its
   !> weight in a first phase, one GRAVITY pattern per layer, and settles
   !> gamma (H y - y^2 / 2) / M (1-D: the nodal values of linear elements are exact); its top
   !> layer (h = 2.5) is then removed and the rest heaves gamma h y / M from there (1e-10 of
   !> gamma H^2 / M).
   subroutine test_gravity(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: weighed, dug
      character(len=*), parameter :: deck = OUT//'gravity.inp'
      real(wp) :: scale, y, worst, m
      integer :: code, n, u, i
      call make_directories(OUT)
      open (newunit=u, file=deck, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'column under gravity loading, then dug', '*NODES'
      do i = 0, NEL
         write (u, '(i0,a,es23.16)') 2*i + 1, ', 0.0, ', i*H/NEL
         write (u, '(i0,a,es23.16)') 2*i + 2, ', 1.0, ', i*H/NEL
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=rest'
      do i = 1, NEL
         if (i == NEL - 4) write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=top'
         write (u, '(i0,4(", ",i0))') i, 2*i - 1, 2*i, 2*i + 2, 2*i + 1
      end do
      write (u, '(a)') ELASTIC, '*SECTION, SET=rest, MATERIAL=soil', &
         '*SECTION, SET=top, MATERIAL=soil', '*NSET, NAME=base', '1, 2', &
         '*NSET, NAME=sides, GENERATE', '1, '//itoa(NNODE), '*BOUNDARY', 'base, XY', 'sides, X', &
         '*LOAD, NAME=w_rest, TYPE=GRAVITY', 'rest', '*LOAD, NAME=w_top, TYPE=GRAVITY', 'top', &
         '*STEP, NAME=weigh', 'w_rest, 1', 'w_top, 1', '*STEP, NAME=dig', '*DEACTIVATE', 'top'
      close (u)
      m = oedometric()
      scale = GAMMA*H*H/m
      code = run_deck(deck, OUT//'gravity_1.h5', .true., model, weighed, stop_after=1)
      call check(error, code == 4, 'weight applied')
      if (allocated(error)) return
      call check(error, weighed%phase%procedure == PROCEDURE_GRAVITY, 'gravity loading procedure')
      if (allocated(error)) return
      worst = 0.0_wp
      do n = 1, NNODE
         y = model%mesh%x(2, n)
         worst = max(worst, abs(weighed%state%u(1, n)), &
            abs(weighed%state%u(2, n) + GAMMA*(H*y - 0.5_wp*y*y)/m))
      end do
      call check_close(error, worst, 0.0_wp, 0.0_wp, 'settlement gamma (H y - y^2/2) / M', &
         atol=1.0e-10_wp*scale)
      if (allocated(error)) return
      code = run_deck(deck, OUT//'gravity_2.h5', .true., model, dug)
      call check(error, code == 0, 'dug (exit '//itoa(code)//')')
      if (allocated(error)) return
      worst = 0.0_wp
      do n = 1, 2*(NEL - 5) + 2
         worst = max(worst, maxval(abs(dug%state%u(:, n) - weighed%state%u(:, n) - &
            [0.0_wp, GAMMA*2.5_wp*model%mesh%x(2, n)/m])))
      end do
      call check_close(error, worst, 0.0_wp, 0.0_wp, 'top layer removed: heave gamma h y / M', &
         atol=1.0e-10_wp*scale)
   end subroutine test_gravity

   !> --strict: a phase change that changes nothing (a material changed to the one the set
   !> has; a load pattern activated at factor 0 that its step does not drive) is a warning,
   !> an input error under --strict (exit 2, no results file).
   subroutine test_strict(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      character(len=*), parameter :: deck = OUT//'strict.inp'
      type(error_t), allocatable :: e
      integer :: code, i
      logical :: exists, found
      call make_directories(OUT)
      call write_column(deck, NEL, 0, [integer ::], 1, ELASTIC, steps='*STEP, NAME=same'//NL// &
         '*CHANGE_MATERIAL'//NL//'rest, soil')
      code = run_deck(deck, OUT//'strict_lax.h5', .true., model, problem)
      call check(error, code == 0 .and. model%warnings%count() > 0, 'without --strict: a '// &
         'warning, the run goes on (exit '//itoa(code)//')')
      if (allocated(error)) return
      code = run_deck(deck, OUT//'strict.h5', .true., model, problem, strict=.true.)
      inquire (file=OUT//'strict.h5', exist=exists)
      call check(error, code == 2 .and. .not. exists, '--strict: exit 2, no results file '// &
         '(exit '//itoa(code)//')')
      if (allocated(error)) return
      ! a pattern activated at factor 0 that its step does not drive loads nothing
      call write_column(deck, NEL, 0, [integer ::], 1, ELASTIC, steps= &
         '*NSET, NAME=topn'//NL//itoa(NNODE - 1)//', '//itoa(NNODE)//NL// &
         '*LOAD, NAME=q, TYPE=FORCE'//NL//'topn, Y, -50'//NL// &
         '*STEP, NAME=idle'//NL//'*ACTIVATE'//NL//'q')
      call read_deck(deck, model, e)
      call check(error, .not. allocated(e), 'the deck reads')
      if (allocated(error)) return
      found = .false.
      do i = 1, model%warnings%count()
         if (index(model%warnings%line(i), "'q' is activated at factor 0") > 0) found = .true.
      end do
      call check(error, found, 'a pattern activated at factor 0 and not driven: a warning')
      if (allocated(error)) return
      code = run_deck(deck, OUT//'strict.h5', .true., model, problem, strict=.true.)
      inquire (file=OUT//'strict.h5', exist=exists)
      call check(error, code == 2 .and. .not. exists, '--strict: a pattern activated at '// &
         'factor 0 and not driven (exit '//itoa(code)//')')
   end subroutine test_strict

   !> A Goodman joint set between the K0 column and the block on it: deactivating the block
   !> alone takes the joint set with it (its block-side nodes lose their last element; the
   !> phase list says so) and the column heaves gamma h y / M, h = 2.5, as when both are
   !> deactivated (1e-10 of the heave: the joint's uniform traction is integrated exactly).
   subroutine test_joints_follow(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: p
      character(len=*), parameter :: deck = OUT//'follow.inp'
      real(wp) :: heave, worst
      integer :: code, n
      call make_directories(OUT)
      call write_block(deck, '', law='TYPE=GOODMAN'//NL//'KN = 2e+07, KT = 40000, PHI = 35, C = 0', &
         steps='*STEP, NAME=remove, INCREMENTS=2'//NL//'*DEACTIVATE'//NL//'block')
      code = run_deck(deck, OUT//'follow.h5', .true., model, p)
      call check(error, code == 0, 'block removed (exit '//itoa(code)//')')
      if (allocated(error)) return
      call check(error, .not. p%state%joints%sets(1)%active, 'the joint set went with the block')
      if (allocated(error)) return
      heave = GAMMA*2.5_wp*7.5_wp/oedometric()
      worst = 0.0_wp
      do n = 1, 62
         worst = max(worst, abs(p%state%u(1, n)), &
            abs(p%state%u(2, n) - GAMMA*2.5_wp*model%mesh%x(2, n)/oedometric()))
      end do
      call check_close(error, worst, 0.0_wp, 0.0_wp, 'the column heaves gamma h y / M', &
         atol=1.0e-10_wp*heave)
   end subroutine test_joints_follow

end module test_phases_switch
