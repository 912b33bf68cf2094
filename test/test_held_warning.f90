!> The warnings about the initial state's out-of-balance held by a phased deck that has no nil
!> step without changes (pecplas_solve_held_warning; doc/deck.md, Phases, "Warnings about the
!> held out-of-balance"). Registered in the water suite (test_water).
module test_held_warning
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_held_warning, only: held_start_warning, held_end_warning, &
      initial_plate_water
   use pecplas_testing, only: check, check_close
   use fixtures_water, only: write_wall
   use fixtures_runs, only: run_completes
   implicit none (type, external)
   private
   public :: test_held_warning_without_nil, test_no_held_warning_with_nil

   character(len=*), parameter :: OUT = 'build/test_out/water/'

contains

   !> The wall of water_on_a_wall (x = 0, 0 <= y <= 10, clamped base, water on its left to
   !> y = 6 from the start) whose only step has a pattern line: the water is held and never
   !> loads the wall; both warnings come, the one at the end with the water's size. The
   !> water's nodal forces sum to gamma_w h^2 / 2 = 180 (consistent loads keep the
   !> resultant; tolerance 1e-12 of it: a sum of ten element integrals, round-off).
   subroutine test_held_warning_without_nil(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      character(len=:), allocatable :: text
      character(len=*), parameter :: deck = OUT//'wall_held_warn.inp'
      real(wp), allocatable :: w(:, :)
      call make_directories(OUT)
      call write_wall(deck, 'plate water held, no nil step', 10, '6', &
         [character(len=40) :: '*PLATE_WATER', 'wall, LEFT', '*LOAD, NAME=tip, TYPE=FORCE', &
         '11, X, 0', '*STEP, NAME=held, INCREMENTS=1', 'tip, 1', '*END STEP'])
      call run_completes(error, deck, OUT//'wall_held_warn.h5', model, problem, 'held wall')
      if (allocated(error)) return
      w = initial_plate_water(model)
      call check_close(error, abs(sum(w(1, 1:model%mesh%nnode()))), 180.0_wp, 0.0_wp, &
         'the held water is gamma_w h^2 / 2', atol=1.0e-12_wp*180.0_wp)
      if (allocated(error)) return
      text = held_start_warning(model, problem)
      call check(error, index(text, 'this deck has none') > 0, 'start warning: '//text)
      if (allocated(error)) return
      text = held_end_warning(model, problem)
      call check(error, index(text, 'no nil step without changes released it') > 0 .and. &
         index(text, 'the water standing on plates alone') > 0, 'end warning: '//text)
   end subroutine test_held_warning_without_nil

   !> The same wall with a nil step first: the water is released (and loads the wall), no
   !> warning.
   subroutine test_no_held_warning_with_nil(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      character(len=*), parameter :: deck = OUT//'wall_released.inp'
      call make_directories(OUT)
      call write_wall(deck, 'plate water released by a nil step', 10, '6', &
         [character(len=40) :: '*PLATE_WATER', 'wall, LEFT', '*LOAD, NAME=tip, TYPE=FORCE', &
         '11, X, 0', '*STEP, NAME=release, INCREMENTS=1', '*END STEP', &
         '*STEP, NAME=held, INCREMENTS=1', 'tip, 1', '*END STEP'])
      call run_completes(error, deck, OUT//'wall_released.h5', model, problem, 'released wall')
      if (allocated(error)) return
      call check(error, len(held_start_warning(model, problem)) == 0, 'no start warning: '// &
         held_start_warning(model, problem))
      if (allocated(error)) return
      call check(error, len(held_end_warning(model, problem)) == 0, 'no end warning: '// &
         held_end_warning(model, problem))
   end subroutine test_no_held_warning_with_nil

end module test_held_warning
