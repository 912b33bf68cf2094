!> Joints in the nonlinear solution: a pad pressed on a plane with Mohr–Coulomb joints
!> (mu = 0.3, doc/validation.md) sticks under T = 0.99 mu N — the run converges with the interface
!> forces in equilibrium, sum(tau dA) = T and sum(sigma_n dA) = N — and cannot be pushed
!> past mu N at T = 1.01 mu N; the spring (Frank) law without stiffnesses gets the default
!> penalty 1e5 E_ryg R_max / (mean tributary), with R_max checked against the Q4 stiffness,
!> and still passes the joint patch test.
module test_pecjoin_solver
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t
   use pecplas_joints_points, only: joint_set_element, joint_element_points
   use pecplas_fe_joint_penalty, only: massif_rmax
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use test_pecjoin_patch, only: run_patch
   use fixtures_runs, only: run_completes, check_default_penalty
   implicit none (type, external)
   private
   public :: collect_pecjoin_solver

   character(len=*), parameter :: DIR = 'build/test_out/pecjoin'
   character(len=*), parameter :: DATA = 'test/data/joints/'

contains

   subroutine collect_pecjoin_solver(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('pad_sticks_below_mu_n', test_stick), &
               new_unittest('pad_cannot_pass_mu_n', test_slip), &
               new_unittest('spring_default_penalty', test_penalty)]
   end subroutine collect_pecjoin_solver

   !> Resultants sum(sigma_n dA) and sum(tau dA) of joint set 1 (converged state).
   subroutine resultants(model, problem, fn, ft, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      real(wp), intent(out) :: fn, ft
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t), allocatable :: pts(:)
      integer :: e, ip
      fn = 0.0_wp; ft = 0.0_wp
      call joint_set_element(model%joint_sets(1), elem, error)
      if (allocated(error)) return
      allocate (pts(elem%npoint()))
      do e = 1, size(model%joint_sets(1)%conn, 2)
         call joint_element_points(model, model%joint_sets(1), elem, e, pts, error)
         if (allocated(error)) return
         do ip = 1, size(pts)
            fn = fn + problem%state%joints%sets(1)%sigma(1, ip, e)*pts(ip)%da
            ft = ft + problem%state%joints%sets(1)%sigma(2, ip, e)*pts(ip)%da
         end do
      end do
   end subroutine resultants

   subroutine test_stick(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp) :: fn, ft
      integer :: code
      call make_directories(DIR)
      code = run_deck(DATA//'pad_stick.inp', DIR//'/pad.h5', .true., model, problem)
      call check(error, code == 0, 'T = 0.99 mu N: the run completes')
      if (allocated(error)) return
      call resultants(model, problem, fn, ft, error)
      if (allocated(error)) return
      ! equilibrium of the pad to the solver tolerance (1e-8 of the load)
      call check_close(error, fn, 200.0_wp, 1.0e-6_wp, 'sum(sigma_n dA) = N = P x 2')
      if (allocated(error)) return
      call check_close(error, ft, 59.4_wp, 1.0e-6_wp, 'sum(tau dA) = T = 0.99 mu N')
      if (allocated(error)) return
      call check(error, all(abs(problem%state%joints%sets(1)%sigma(2, :, :)) <= 0.3_wp* &
         problem%state%joints%sets(1)%sigma(1, :, :)*(1.0_wp + 1.0e-12_wp)), &
         'every point within the Coulomb cone |tau| <= mu sigma_n')
   end subroutine test_stick

   !> The pad cannot carry more than mu N = 60: the run stops early, and its last converged
   !> push factor (of T = 60.6) stays at or below 60 / 60.6.
   subroutine test_slip(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call make_directories(DIR)
      code = run_deck(DATA//'pad_slip.inp', DIR//'/pad.h5', .true., model, problem)
      call check(error, code /= 0, 'T = 1.01 mu N: the run does not complete')
      if (allocated(error)) return
      ! the arc-length probe follows the limit itself: to the residual tolerance (1e-8 of
      ! the loads and reactions, ~200 kN here, i.e. 2e-6 kN)
      call check(error, problem%state%factors(2)*60.6_wp <= 60.0_wp + 2.0e-6_wp, &
         'no converged state carries more than mu N')
   end subroutine test_slip

   !> R_max of the patch mesh: a node shared by two unit-square Q4 elements, diagonal term
   !> 2 (D11 + G)/3 with D11 = E(1-nu)/((1+nu)(1-2nu)), G = E/(2(1+nu)); the springs'
   !> tributaries 1/2, 1, 1/2 (mean 2/3): K = 1e5 x 0.5 x R_max / (2/3).
   subroutine test_penalty(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp) :: rmax, d11, g, e, nu
      e = 1.0e4_wp; nu = 0.3_wp
      d11 = e*(1.0_wp - nu)/((1.0_wp + nu)*(1.0_wp - 2.0_wp*nu))
      g = e/(2.0_wp*(1.0_wp + nu))
      call run_patch('penalty_spring_plane.inp', 100.0_wp, 0.0_wp, error)
      if (allocated(error)) return
      call make_directories(DIR)
      call run_completes(error, DATA//'penalty_spring_plane.inp', DIR//'/penalty.h5', model, &
         problem, 'penalty_spring_plane.inp')
      if (allocated(error)) return
      call massif_rmax(model, problem%system%rules, rmax, error)
      if (allocated(error)) return
      call check_close(error, rmax, 2.0_wp*(d11 + g)/3.0_wp, 1.0e-12_wp, 'R_max = 2 (D11 + G)/3')
      if (allocated(error)) return
      call check_default_penalty(error, model, rmax, '')
   end subroutine test_penalty

end module test_pecjoin_solver
