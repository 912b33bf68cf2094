!> Scene S1, the shear box of the thesis (figs II.1–II.5), through the whole program with the
!> decks of input/s1/ (tools/pecplas_py/decks/make_s1_decks.py): plateaus of the cohesive and frictional
!> joints, the limit load under force control, the effect of dilatancy with stiff and soft
!> K_n, and an opening–closing cycle.
module test_s1
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_joints_laws_type, only: MODE_SLIP, MODE_OPEN
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_s1

   character(len=*), parameter :: DIR = 'build/test_out/s1', DECKS = 'input/s1/'
   real(wp), parameter :: TAN30 = 0.57735026918962576_wp

contains

   subroutine collect_s1(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('cohesive_plateau_c', test_cohesive), &
               new_unittest('cohesive_limit_load', test_cohesive_limit), &
               new_unittest('frictional_plateau', test_friction), &
               new_unittest('dilatancy_ordering', test_dilatancy), &
               new_unittest('open_close_cycle', test_open_close)]
   end subroutine collect_s1

   !> Runs input/s1/<name>.inp; `code` is the exit code.
   subroutine run(name, model, problem, code)
      character(len=*), intent(in) :: name
      type(model_t), intent(out) :: model
      type(problem_t), intent(out) :: problem
      integer, intent(out) :: code
      call make_directories(DIR)
      code = run_deck(DECKS//name//'.inp', DIR//'/'//name//'.h5', .true., model, problem)
   end subroutine run

   !> Displacement control: every joint point slips at tau = c = 1 kPa (1e-6).
   subroutine test_cohesive(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call run('s1_cohesive_disp', model, problem, code)
      call check(error, code == 0, 's1_cohesive_disp completes')
      if (allocated(error)) return
      associate (j => problem%state%joints%sets(1))
         call check(error, all(j%mode == MODE_SLIP), 'every joint point slips')
         if (allocated(error)) return
         call check_close(error, maxval(abs(j%sigma(2, :, :) - 1.0_wp)), 0.0_wp, 0.0_wp, &
            'tau = c at every point', atol=1.0e-6_wp)
      end associate
   end subroutine test_cohesive

   !> Force control: the run stops with a limit load at shear factor c L / 1 kN = 1, to the
   !> increment resolution (1/30 of 1.5, halved 5 times) from below; the arc-length probe
   !> that establishes the plateau converges on it to the residual tolerance (1e-4).
   subroutine test_cohesive_limit(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call run('s1_cohesive', model, problem, code)
      call check(error, code == 3, 'force control beyond c L stops (exit 3)')
      if (allocated(error)) return
      call check(error, problem%state%factors(1) <= 1.0_wp + 1.0e-4_wp .and. &
         problem%state%factors(1) >= 1.0_wp - 1.5_wp/30.0_wp/32.0_wp, &
         'last converged shear factor is the limit c L')
   end subroutine test_cohesive_limit

   !> psi = 0, K_n = 5e6: at the end every point slips at tau = sigma_n tan(30) (1e-6).
   subroutine test_friction(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call run('s1_friction_psi0_kn5e6', model, problem, code)
      call check(error, code == 0, 's1_friction_psi0_kn5e6 completes')
      if (allocated(error)) return
      associate (j => problem%state%joints%sets(1))
         call check(error, all(j%mode == MODE_SLIP), 'every joint point slips')
         if (allocated(error)) return
         call check_close(error, maxval(abs(j%sigma(2, :, :)/(j%sigma(1, :, :)*TAN30) - &
            1.0_wp)), 0.0_wp, 0.0_wp, 'tau = sigma_n tan(phi) at every point', atol=1.0e-6_wp)
      end associate
   end subroutine test_friction

   !> Mean joint shear after 5 mm: rises with psi; the rise above the psi = 0 plateau is much
   !> larger with the stiff joint (K_n = 5e6) than with K_n = 5000 (dilatancy blocked by a
   !> stiff joint raises sigma_n more).
   subroutine test_dilatancy(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: tau(3, 2)
      character(len=*), parameter :: kn(2) = ['5e6', '5e3']
      character(len=2), parameter :: psi(3) = ['0 ', '3 ', '30']
      character(len=200) :: buf
      integer :: i, k
      do k = 1, 2
         do i = 1, 3
            call mean_tau('s1_friction_psi'//trim(psi(i))//'_kn'//kn(k), tau(i, k), error)
            if (allocated(error)) return
         end do
      end do
      write (buf, '(a,6f8.4)') ' mean tau (psi 0,3,30; K_n 5e6 then 5e3):', tau
      write (*, '(a)') '       '//trim(buf)
      call check(error, all(tau(2, :) > tau(1, :)) .and. all(tau(3, :) > tau(2, :)), &
         'shear rises with psi'//trim(buf))
      if (allocated(error)) return
      call check(error, all(tau(2:3, 1) - tau(1, 1) > 1.5_wp*(tau(2:3, 2) - tau(1, 2))), &
         'the stiff joint raises the shear much more'//trim(buf))
   end subroutine test_dilatancy

   subroutine mean_tau(name, tau, error)
      character(len=*), intent(in) :: name
      real(wp), intent(out) :: tau
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call run(name, model, problem, code)
      tau = 0.0_wp
      if (code /= 0) then
         call fatal_error(error, name//' did not complete')
         return
      end if
      tau = sum(problem%state%joints%sets(1)%sigma(2, :, :))/ &
         size(problem%state%joints%sets(1)%sigma(2, :, :))
   end subroutine mean_tau

   !> K_n = 1e5: completes, and after the re-closing the joint is compressed again (the open
   !> state during the lift is checked on the results file by test/python/test_s1.py).
   subroutine test_open_close(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call run('s1_open_close_kn1e5', model, problem, code)
      call check(error, code == 0, 's1_open_close_kn1e5 completes')
      if (allocated(error)) return
      associate (j => problem%state%joints%sets(1))
         call check(error, all(j%mode /= MODE_OPEN) .and. all(j%sigma(1, :, :) > 0.0_wp), &
            'closed and compressed after re-contact')
      end associate
   end subroutine test_open_close

end module test_s1
