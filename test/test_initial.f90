!> Initial stresses (*INITIAL_STRESS): a geostatic state is in equilibrium by itself (no
!> displacement, stresses unchanged) and superposes with the response to later loads.
module test_initial
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_massif_element_matrices, only: massif_gauss_coordinates
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_initial

contains

   subroutine collect_initial(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('geostatic_column_superposition', test_column), &
               new_unittest('undefined_set_names_line', test_bad_set)]
   end subroutine collect_initial

   subroutine test_column(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: gamma = 20.0_wp, k0 = 0.5_wp, q = 100.0_wp, e = 3.0e4_wp, &
         nu = 0.25_wp
      real(wp) :: m, xg(2, 4), sv, expect(4), worst
      integer :: code, el, g
      call make_directories('build/test_out/initial')
      code = run_deck('test/data/initial/geostatic_column.inp', &
         'build/test_out/initial/column.h5', .true., model, problem)
      call check(error, code == 0, 'geostatic column runs')
      if (allocated(error)) return
      m = e*(1.0_wp - nu)/((1.0_wp + nu)*(1.0_wp - 2.0_wp*nu))
      ! the weight is in the initial state: only the surcharge moves the column
      call check_close(error, problem%state%u(2, 10), -q*4.0_wp/m, 1.0e-10_wp, &
         'top settlement = -q H / M (surcharge only)')
      if (allocated(error)) return
      worst = 0.0_wp
      do el = 1, 4
         call massif_gauss_coordinates(problem%system%rules(1), &
            model%mesh%x(:, model%mesh%esets(1)%conn(:, el)), xg)
         do g = 1, 4
            sv = gamma*(0.0_wp - xg(2, g))
            expect = [-k0*sv - nu/(1.0_wp - nu)*q, -sv - q, -k0*sv - nu/(1.0_wp - nu)*q, 0.0_wp]
            worst = max(worst, maxval(abs(problem%state%sets(1)%stress(:, g, el) - expect)))
         end do
      end do
      ! exact: geostatic at the Gauss point + uniform oedometric response to q
      call check_close(error, worst, 0.0_wp, 0.0_wp, 'stresses = geostatic + surcharge', &
         atol=1.0e-9_wp*q)
      if (allocated(error)) return
      call check(error, problem%stats%iterations == 2, 'the rest step needs no iteration, the '// &
         'surcharge one per increment')
   end subroutine test_column

   subroutine test_bad_set(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(model_t) :: model
      call read_deck('test/data/initial/bad_set.inp', model, e)
      call check(error, allocated(e), 'undefined set must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'bad_set.inp:36') > 0 .and. &
         index(e%text(), '*INITIAL_STRESS') > 0 .and. index(e%text(), "'clay'") > 0 .and. &
         index(e%text(), 'SOIL') + index(e%text(), 'soil') > 0, 'message: '//e%text())
   end subroutine test_bad_set

end module test_initial
