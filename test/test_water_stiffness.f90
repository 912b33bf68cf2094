!> The pore water's stiffness (K_w/n) m m^T outside the assembly (doc/theory.md §14): the
!> default penalty of spring joints on undrained soil takes R_max with it (closed form on the
!> Q4 patch), and the error estimate of an elastic undrained set is that of the drained
!> material with the undrained bulk modulus K_u = K' + K_w/n (the same D, the same stresses).
module test_water_stiffness
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_fe_joint_penalty, only: massif_rmax
   use pecplas_estimate_estimator, only: error_estimate_t, estimate_error
   use pecplas_testing, only: check, check_close
   use fixtures_runs, only: run_completes, check_default_penalty
   implicit none (type, external)
   private
   public :: test_undrained_penalty, test_undrained_estimator

   character(len=*), parameter :: OUT = 'build/test_out/water/'
   character(len=*), parameter :: DATA = 'test/data/water/'

contains

   !> Spring joints without KN, KT between two layers of two unit-square Q4 elements of
   !> UNDRAINED_A soil (E' = 1e4, nu' = 0.3, KW_N = 5e4): the largest diagonal term of the
   !> elastic massif stiffness is that of a node shared by two elements, 2 (D11 + G)/3 with
   !> the undrained D11 = D'11 + K_w/n (the drained soil's 2 (D'11 + G)/3 = 11538 is 3.9 times
   !> smaller), and K = 1e5 E_RYG R_max / (2/3) with E_RYG = 0.5 and the springs' tributaries
   !> 1/2, 1, 1/2. Both are a few floating-point operations on the same numbers: 1e-12.
   subroutine test_undrained_penalty(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: E = 1.0e4_wp, NU = 0.3_wp, KWN = 5.0e4_wp
      real(wp) :: rmax, expect, d11, g
      d11 = E*(1.0_wp - NU)/((1.0_wp + NU)*(1.0_wp - 2.0_wp*NU))
      g = E/(2.0_wp*(1.0_wp + NU))
      expect = 2.0_wp*(d11 + KWN + g)/3.0_wp
      call make_directories(OUT)
      call run_completes(error, DATA//'penalty_spring_undrained.inp', &
         OUT//'penalty_undrained.h5', model, problem, 'penalty_spring_undrained.inp')
      if (allocated(error)) return
      call massif_rmax(model, problem%system%rules, rmax, error)
      if (allocated(error)) return
      call check_close(error, rmax, expect, 1.0e-12_wp, "R_max = 2 (D'11 + K_w/n + G)/3")
      if (allocated(error)) return
      call check_default_penalty(error, model, expect, ', R_max with the pore water')
   end subroutine test_undrained_penalty

   !> The smooth rigid footing of footing_q8r_mesh.inc (200 Q8R) on elastic UNDRAINED_A clay
   !> (G = 5000, K' = 10833.3, K_w/n = 37500) and on the drained material with
   !> K_u = K' + K_w/n (E = 14500, nu = 0.45), pushed 1 cm: D' + (K_w/n) m m^T is the
   !> drained D, so the two runs have the same displacements and sigma' - p_excess m equals
   !> the drained sigma, and the estimate eta and the energy norm are the same. They differ
   !> by the rounding of the two D (a few ulps) amplified by the condition number of K; the
   !> tolerance 1e-6 lies far above that (measured 1e-15) and far below the gap of an
   !> estimate that left the water out (C'^-1 on sigma': eta 0.965, energy norm 0.903 of the
   !> drained K_u values).
   subroutine test_undrained_estimator(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(error_estimate_t) :: und, dra
      call make_directories(OUT)
      call run_completes(error, DATA//'estimator_undrained.inp', OUT//'estimator_undrained.h5', &
         model, problem, 'estimator_undrained.inp')
      if (allocated(error)) return
      call estimate_error(model, problem, und, error)
      if (allocated(error)) return
      call run_completes(error, DATA//'estimator_drained_ku.inp', &
         OUT//'estimator_drained_ku.h5', model, problem, 'estimator_drained_ku.inp')
      if (allocated(error)) return
      call estimate_error(model, problem, dra, error)
      if (allocated(error)) return
      write (*, '(a,2es23.15)') '        undrained eta, energy ', und%eta, und%energy
      write (*, '(a,2es23.15)') '        drained K_u eta, energy', dra%eta, dra%energy
      call check(error, dra%eta > 0.0_wp, 'the footing has a discretisation error to estimate')
      if (allocated(error)) return
      call check_close(error, und%eta, dra%eta, 1.0e-6_wp, 'undrained eta = drained K_u eta')
      if (allocated(error)) return
      call check_close(error, und%energy, dra%energy, 1.0e-6_wp, &
         'undrained energy norm = drained K_u energy norm')
      if (allocated(error)) return
      call check_close(error, maxval(abs(und%sets(1)%eta - dra%sets(1)%eta)), 0.0_wp, 0.0_wp, &
         'element indicators equal', atol=1.0e-6_wp*maxval(dra%sets(1)%eta))
   end subroutine test_undrained_estimator

end module test_water_stiffness
