!> Coulomb friction through the whole program, NAFEMS CGS-4 type: a pad on a plane inclined
!> at tan(a) = 0.1 with mu = 0.3, weight then a horizontal push under force control; the
!> run must stop with a limit load at F/G = (tan a + mu)/(1 - mu tan a) = 0.412371 (0.1 %).
module test_pecjoin_friction
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use doc_report, only: report
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_pecjoin_friction

contains

   subroutine collect_pecjoin_friction(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('inclined_plane_cgs4', test_inclined_plane)]
   end subroutine collect_pecjoin_friction

   subroutine test_inclined_plane(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: ta = 0.1_wp, mu = 0.3_wp
      integer :: code
      call make_directories('build/test_out/friction')
      code = run_deck('test/data/joints/inclined_plane.inp', &
         'build/test_out/friction/inclined_plane.h5', .true., model, problem)
      call check(error, code == 3, 'force control beyond the slip limit stops (exit 3)')
      if (allocated(error)) return
      call report('cgs4/penalty_f_over_g', problem%state%factors(2))
      ! pattern 2 (push) is F/G: F = 10 kN * factor, G = 10 kN
      call check_close(error, problem%state%factors(2), (ta + mu)/(1.0_wp - mu*ta), 1.0e-3_wp, &
         'F/G at the limit = (tan a + mu)/(1 - mu tan a)')
   end subroutine test_inclined_plane

end module test_pecjoin_friction
