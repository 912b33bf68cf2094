!> The water standing on a plate before the first step is part of the K0 state's
!> out-of-balance, which a phased run holds until its first nil step (doc/theory.md §10): until
!> then it does not load the plate, and the plate's section forces in the results must not
!> take it off either. Registered in the water suite (test_water).
module test_water_held
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_base_strings, only: itoa
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_testing, only: check, check_close
   use fixtures_water, only: write_wall
   use fixtures_runs, only: run_completes
   implicit none (type, external)
   private
   public :: test_held_plate_water

   character(len=*), parameter :: OUT = 'build/test_out/water/'

contains

   !> The wall of water_on_a_wall (x = 0, 0 <= y <= 10, ten 2-node plate elements, clamped
   !> at its base, water on its left to y = 6 from the start) with a first step that is not
   !> nil (a pattern line, a zero tip force): the K0 out-of-balance, which holds the water,
   !> is not released, the wall carries nothing (u = 0) and its section forces are zero
   !> (the results said the water's consistent end forces at the base: a shear of 28.46 and a
   !> moment of 4.648; and 104.23, 182.32 half-way through the release where 90, 180 are
   !> due). Then a nil step in two increments releases it:
   !> half of gamma_w h^2/2 = 180 and gamma_w h^3/6 = 360 at the base after the first, the
   !> whole after the second, the free top without moment. Tolerance 1e-8 of the base shear
   !> and moment (as water_on_a_wall: the linear solve of ten elements, displacements
   !> ~ 1e-2, relative round-off 1e-13 amplified by the stiffness).
   subroutine test_held_plate_water(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: file
      real(wp), allocatable :: nf(:, :), u(:, :)
      real(wp) :: share
      character(len=*), parameter :: deck = OUT//'wall_held.inp'
      integer :: k
      call make_directories(OUT)
      call write_wall(deck, 'water on a wall held by the K0 out-of-balance', 10, '6', &
         [character(len=40) :: '*PLATE_WATER', 'wall, LEFT', '*LOAD, NAME=tip, TYPE=FORCE', &
         '11, X, 0', '*STEP, NAME=held, INCREMENTS=1', 'tip, 1', '*END STEP', &
         '*STEP, NAME=release, INCREMENTS=2', '*END STEP'])
      call run_completes(error, deck, OUT//'wall_held.h5', model, problem, 'held wall')
      if (allocated(error)) return
      call file%open(OUT//'wall_held.h5', error)
      if (allocated(error)) return
      do k = 1, 3
         call file%dataset('/increments/'//key(k)//'/plates/wall/node_forces', nf, error)
         if (allocated(error)) return
         share = 0.5_wp*(k - 1)
         call check_close(error, abs(nf(2, 1)), share*180.0_wp, 0.0_wp, 'base shear after '// &
            'increment '//itoa(k)//' = '//itoa(nint(100*share))//' % of gamma_w h^2 / 2', &
            atol=1.0e-8_wp*180.0_wp)
         if (allocated(error)) return
         call check_close(error, abs(nf(3, 1)), share*360.0_wp, 0.0_wp, 'base moment after '// &
            'increment '//itoa(k)//' = '//itoa(nint(100*share))//' % of gamma_w h^3 / 6', &
            atol=1.0e-8_wp*360.0_wp)
         if (allocated(error)) return
         call check_close(error, maxval(abs(nf(:, 11))), 0.0_wp, 0.0_wp, 'free top without '// &
            'forces after increment '//itoa(k), atol=1.0e-8_wp*360.0_wp)
         if (allocated(error)) return
         if (k == 1) then
            call file%dataset('/increments/'//key(k)//'/displacement', u, error)
            if (allocated(error)) return
            call check_close(error, maxval(abs(u)), 0.0_wp, 0.0_wp, 'the held water does '// &
               'not move the wall', atol=1.0e-12_wp)
            if (allocated(error)) return
         end if
      end do
      call file%close()
   end subroutine test_held_plate_water

   pure function key(k) result(s)
      integer, intent(in) :: k
      character(len=6) :: s
      write (s, '(i6.6)') k
   end function key

end module test_water_held
