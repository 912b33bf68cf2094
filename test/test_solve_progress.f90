!> The progress line of a long run (pecplas_solve_progress) speaks the user's quantities under
!> load, displacement and arc-length control, with a fake clock: the pattern's factor and
!> value, the stop node's displacement, and a time estimate only where one can be made.
!> Decks in test/data/progress/ (one Q4 block, units kN, m, kPa).
module test_solve_progress
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_model_type, only: model_t
   use pecplas_base_progress_eta, only: progress_eta_t
   use pecplas_solve_progress, only: begin_progress, progress_text, step_end_text
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_solve_progress

   character(len=*), parameter :: DIR = 'test/data/progress/'

contains

   subroutine collect_solve_progress(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('load_control', test_load), &
               new_unittest('displacement_control', test_displacement), &
               new_unittest('arc_length_stop_node', test_arc_node), &
               new_unittest('arc_length_unknown', test_arc_unknown), &
               new_unittest('step_estimate', test_step_left), &
               new_unittest('step_end', test_step_end)]
   end subroutine collect_solve_progress

   !> Force step 'first' at fraction 0.25 after 30 s (clock 100 -> 130): factor 0.25 of 1,
   !> resultant 0.25 x 2 x (-10) = -5 kN; the rest of the step at the same rate is
   !> 30 x 0.75/0.25 = 90 s; one more step follows.
   subroutine test_load(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(progress_eta_t) :: eta
      real(wp), allocatable :: u(:, :)
      character(len=:), allocatable :: line
      call setup(error, 'load', 1, 100.0_wp, 8, model, u, eta)
      if (allocated(error)) return
      line = progress_text(model, 1, 1, 0.25_wp, [0.25_wp], u, .false., eta, 130.0_wp)
      call expect(error, line, [character(len=60) :: "step 1 'first', increment 1 (4 planned)", &
         'fraction 0.25 of the step', 'push = 0.25 (of 1; resultant F_y = -5 kN)', &
         '30 s elapsed', 'about 90 s left in this step', 'then 1 more step'])
      if (allocated(error)) return
      call check(error, index(line, '%') == 0, 'no percentage of planned increments: '//line)
      if (allocated(error)) return
      ! the last step: its own start and fraction; 2 x 2 x (-10) kN at its end
      call begin_progress(model, 2, 0.0_wp, u, 200.0_wp, eta)
      line = progress_text(model, 2, 2, 0.5_wp, [1.5_wp], u, .false., eta, 220.0_wp)
      call expect(error, line, [character(len=60) :: "step 2 'second'", &
         'push = 1.5 (of 2; resultant F_y = -30 kN)', '2.0 min elapsed', &
         'about 20 s left in this step'])
      if (allocated(error)) return
      call check(error, index(line, 'more step') == 0, 'no step after the last: '//line)
   end subroutine test_load

   !> Imposed settlement of the top (two nodes, -0.01 m at factor 1) at fraction 0.4 after
   !> 8 s: u_y = -0.004 m, 12 s left.
   subroutine test_displacement(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(progress_eta_t) :: eta
      real(wp), allocatable :: u(:, :)
      character(len=:), allocatable :: line
      call setup(error, 'settle', 1, 0.0_wp, 10, model, u, eta)
      if (allocated(error)) return
      line = progress_text(model, 1, 4, 0.4_wp, [0.4_wp], u, .false., eta, 8.0_wp)
      call expect(error, line, [character(len=60) :: "step 1 'sink', increment 4 (10 planned)", &
         'settle = 0.4 (of 1; imposed u_y = -0.004 m at 2 nodes)', 'about 12 s left in this step'])
   end subroutine test_displacement

   !> Arc-length step with NODE=4, DISPLACEMENT=-0.02: 63 increments (more than the 10 the
   !> step starts with: no '154 %'), node 4 at -0.005 m after 180 s from 0 at the step's
   !> start: 25 % of the way, 180 x 0.75/0.25 s = 9.0 min left; the pressure's factor and
   !> value (0.734 x 50 = 36.7 kPa).
   subroutine test_arc_node(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(progress_eta_t) :: eta
      real(wp), allocatable :: u(:, :)
      character(len=:), allocatable :: line
      call setup(error, 'arc', 1, 1000.0_wp, 20, model, u, eta)
      if (allocated(error)) return
      u(2, 4) = -0.005_wp
      line = progress_text(model, 1, 63, 0.734_wp, [0.734_wp], u, .true., eta, 1180.0_wp)
      call expect(error, line, [character(len=70) :: &
         "step 1 'push' (arc-length), increment 63 of at most 200", &
         'pressure = 0.734 (of 3; p = 36.7 kPa)', &
         'node 4 u_y = -0.005 m (stops at -0.02 m, 25 %)', '3.0 min elapsed', &
         'about 9.0 min left in this step (from the distance to the stop displacement)'])
      if (allocated(error)) return
      ! the node moved away from its target: no estimate (not a negative time)
      u(2, 4) = 0.001_wp
      line = progress_text(model, 1, 64, 0.5_wp, [0.5_wp], u, .true., eta, 1190.0_wp)
      call expect(error, line, [character(len=40) :: 'time left not known yet'])
   end subroutine test_arc_node

   !> Arc-length step without a stop node: the load may peak before its target, so no
   !> estimate is made from the load factor, however far it has gone.
   subroutine test_arc_unknown(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(progress_eta_t) :: eta
      real(wp), allocatable :: u(:, :)
      character(len=:), allocatable :: line
      call setup(error, 'arc', 2, 0.0_wp, 20, model, u, eta)
      if (allocated(error)) return
      line = progress_text(model, 2, 30, 0.9_wp, [3.0_wp + 0.9_wp*3.0_wp], u, .true., eta, &
         600.0_wp)
      call expect(error, line, [character(len=70) :: "step 2 'beyond' (arc-length)", &
         'pressure = 5.7 (of 6; p = 285 kPa)', '10.0 min elapsed', 'time left unknown'])
      if (allocated(error)) return
      call check(error, index(line, 'left in this step') == 0, 'no estimate: '//line)
   end subroutine test_arc_unknown

   !> The estimate itself: linear in the measure of the way done since the step's start.
   subroutine test_step_left(error)
      type(error_t), allocatable, intent(out) :: error
      type(progress_eta_t) :: eta
      call eta%begin_step(3, 50.0_wp, 0.2_wp)
      call check(error, eta%step_left(0.2_wp, 1.0_wp, 60.0_wp) < 0.0_wp, 'no way done: unknown')
      if (allocated(error)) return
      ! 0.2 -> 0.4 of 0.2 -> 1 (a quarter) in 10 s: 30 s left (a few operations on numbers
      ! of order 1 to 60: round-off below 1e-13; 1e-9 leaves room)
      call check(error, abs(eta%step_left(0.4_wp, 1.0_wp, 60.0_wp) - 30.0_wp) < 1.0e-9_wp, &
         'a quarter in 10 s leaves 30 s')
      if (allocated(error)) return
      call check(error, eta%step_left(1.2_wp, 1.0_wp, 60.0_wp) == 0.0_wp, 'past the target: 0')
      if (allocated(error)) return
      call check(error, eta%step_left(0.1_wp, 1.0_wp, 60.0_wp) < 0.0_wp, 'moved back: unknown')
   end subroutine test_step_left

   !> The line at the end of a step: the imposed settlement of the top (nodes 3, 4: -0.01 m)
   !> with the sum of the reactions there (-3 - 4 = -7 kN: what a footing's settlement took,
   !> the force a user reads the bearing capacity from), the base's reactions left out, and the
   !> largest displacement (node 3: |(0.003, -0.01)| = 0.01044 m, against 0.01 at node 4).
   subroutine test_step_end(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      real(wp), allocatable :: u(:, :), reaction(:, :)
      character(len=:), allocatable :: line
      call read_deck(DIR//'settle.inp', model, error)
      if (allocated(error)) return
      allocate (u(2, 4), reaction(2, 4), source=0.0_wp)
      u(:, 3) = [0.003_wp, -0.01_wp]
      u(:, 4) = [0.0_wp, -0.01_wp]
      reaction(2, :) = [5.0_wp, 2.0_wp, -3.0_wp, -4.0_wp]
      line = step_end_text(model, 1, [1.0_wp], u, reaction)
      call expect(error, line, [character(len=60) :: "step 1 'sink': settle = 1 (", &
         'imposed u_y = -0.01 m at 2 nodes, reaction F_y = -7 kN)', &
         'largest displacement 0.01044 m at node 3 (x = 1, y = 1)'])
   end subroutine test_step_end

   !> Deck DIR/<deck>.inp read into `model`, no displacement (u of its 4 nodes zero), the
   !> progress clock started at `t0` with `planned` increments and step `istep` begun there.
   subroutine setup(error, deck, istep, t0, planned, model, u, eta)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: deck
      integer, intent(in) :: istep, planned
      real(wp), intent(in) :: t0
      type(model_t), intent(out) :: model
      real(wp), allocatable, intent(out) :: u(:, :)
      type(progress_eta_t), intent(out) :: eta
      call read_deck(DIR//deck//'.inp', model, error)
      if (allocated(error)) return
      allocate (u(2, 4), source=0.0_wp)
      call eta%start(t0, planned)
      call begin_progress(model, istep, 0.0_wp, u, t0, eta)
   end subroutine setup

   !> Every piece of `want` in `line`.
   subroutine expect(error, line, want)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: line, want(:)
      integer :: i
      do i = 1, size(want)
         call check(error, index(line, trim(want(i))) > 0, 'expected "'//trim(want(i))// &
            '" in: '//line)
         if (allocated(error)) return
      end do
   end subroutine expect

end module test_solve_progress
