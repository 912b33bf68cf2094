!> Joint patch test through the whole program (`run_deck`, decks of test/data/joints/
!> written by make_patch_decks.py): two blocks pressed together by a pressure P = 100, one
!> elastic material. Exact solution: uniform uniaxial stress sigma_yy = -P in both blocks,
!> so every joint point carries sigma_n = P cos^2 a and tau = -P sin a cos a (a = joint
!> inclination), to round-off, for every joint type, explicit and generated doublets, plane
!> strain and axisymmetric, Gauss and Lobatto points, modified and full Newton.
!> The results file holds the same joint fields and passes tools/pecplas_py/checks/check_results.py.
module test_pecjoin_patch
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use pecplas_fe_joint_initial, only: initial_joint_stress
   implicit none (type, external)
   private
   public :: collect_pecjoin_patch, run_patch

   character(len=*), parameter :: DIR = 'build/test_out/pecjoin'
   character(len=*), parameter :: DATA = 'test/data/joints/'
   real(wp), parameter :: P = 100.0_wp, PI = acos(-1.0_wp)
   !> Relative tolerance of the patch test (the solution is exact to round-off).
   real(wp), parameter :: RTOL = 1.0e-8_wp

contains

   subroutine collect_pecjoin_patch(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('spring', test_spring), &
               new_unittest('goodman4', test_goodman4), &
               new_unittest('goodman6', test_goodman6), &
               new_unittest('thin_layer', test_thin_layer), &
               new_unittest('lobatto_plane', test_lobatto), &
               new_unittest('inclined_30', test_inclined), &
               new_unittest('full_newton', test_newton), &
               new_unittest('initial_stress_projection', test_initial), &
               new_unittest('results_file', test_results)]
   end subroutine collect_pecjoin_patch

   !> Runs `deck` and checks every joint point against (sigma_n, tau) and every massif
   !> point against sigma_yy = -P (relative RTOL of P).
   subroutine run_patch(deck, sigma_n, tau, error)
      character(len=*), intent(in) :: deck
      real(wp), intent(in) :: sigma_n, tau
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code, s
      real(wp) :: worst
      character(len=160) :: buf
      call make_directories(DIR)
      code = run_deck(DATA//deck, DIR//'/patch.h5', .true., model, problem)
      if (code /= 0) then
         write (buf, '(a,i0)') ': run_deck exit code ', code
         call fatal_error(error, deck//trim(buf))
         return
      end if
      call check(error, size(problem%state%joints%sets) == 1, deck//': one joint set')
      if (allocated(error)) return
      associate (st => problem%state%joints%sets(1))
         call check(error, size(st%sigma) >= 4, deck//': joint points exist')
         if (allocated(error)) return
         worst = max(maxval(abs(st%sigma(1, :, :) - sigma_n)), maxval(abs(st%sigma(2, :, :) - tau)))
         write (buf, '(a,es9.2,a,2f10.4)') ': worst joint stress error ', worst, &
            ' for (sigma_n, tau) = ', sigma_n, tau
         call check(error, worst <= RTOL*P, deck//trim(buf))
         if (allocated(error)) return
      end associate
      do s = 1, size(problem%state%sets)
         worst = maxval(abs(problem%state%sets(s)%stress(2, :, :) + P))
         write (buf, '(a,es9.2)') ': massif sigma_yy differs from -P by ', worst
         call check(error, worst <= RTOL*P, deck//trim(buf))
         if (allocated(error)) return
      end do
   end subroutine run_patch

   !> The four decks of one joint type: plane / axisymmetric, explicit / generated.
   subroutine four(jtype, error)
      character(len=*), intent(in) :: jtype
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: tags(4) = [character(len=9) :: 'plane', 'plane_gen', &
         'axi', 'axi_gen']
      integer :: k
      do k = 1, 4
         call run_patch('patch_'//jtype//'_'//trim(tags(k))//'.inp', P, 0.0_wp, error)
         if (allocated(error)) return
      end do
   end subroutine four

   subroutine test_spring(error)
      type(error_t), allocatable, intent(out) :: error
      call four('spring', error)
   end subroutine test_spring

   subroutine test_goodman4(error)
      type(error_t), allocatable, intent(out) :: error
      call four('goodman4', error)
   end subroutine test_goodman4

   subroutine test_goodman6(error)
      type(error_t), allocatable, intent(out) :: error
      call four('goodman6', error)
   end subroutine test_goodman6

   subroutine test_thin_layer(error)
      type(error_t), allocatable, intent(out) :: error
      call four('thin_layer', error)
   end subroutine test_thin_layer

   subroutine test_lobatto(error)
      type(error_t), allocatable, intent(out) :: error
      call run_patch('patch_goodman4_plane_lobatto.inp', P, 0.0_wp, error)
      if (allocated(error)) return
      call run_patch('patch_goodman6_plane_lobatto.inp', P, 0.0_wp, error)
   end subroutine test_lobatto

   !> Joint at 30 degrees under a vertical uniaxial stress: traction on the upper block
   !> sigma.(-n) with n = (-sin a, cos a) gives sigma_n = P cos^2 a, tau = -P sin a cos a.
   subroutine test_inclined(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: types(4) = [character(len=10) :: 'spring', 'goodman4', &
         'goodman6', 'thin_layer']
      real(wp) :: a
      integer :: k
      a = PI/6.0_wp
      do k = 1, 4
         call run_patch('patch_'//trim(types(k))//'_inclined.inp', P*cos(a)**2, &
            -P*sin(a)*cos(a), error)
         if (allocated(error)) return
      end do
      ! springs with their direction given (ANGLE=30) instead of taken from the edges
      call run_patch('patch_spring_inclined_angle.inp', P*cos(a)**2, -P*sin(a)*cos(a), error)
   end subroutine test_inclined

   !> Full Newton assembles the joints' consistent tangents (here the elastic ones).
   subroutine test_newton(error)
      type(error_t), allocatable, intent(out) :: error
      call run_patch('patch_goodman6_newton.inp', P, 0.0_wp, error)
   end subroutine test_newton

   !> Uniaxial massif stress sigma_yy = -P (what the patch test computes in both blocks).
   function uniaxial(x) result(stress)
      real(wp), intent(in) :: x(2)
      real(wp) :: stress(4)
      stress = [0.0_wp, -P, 0.0_wp, 0.0_wp] + 0.0_wp*x(1)
   end function uniaxial

   !> The initial-stress projection sigma_n = -n.sigma.n, tau = t.sigma.n of the massif
   !> stress gives, at every point of the inclined joints, the stress the finite elements
   !> compute in equilibrium with that massif stress (sign conventions agree).
   subroutine test_initial(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), allocatable :: computed(:, :, :)
      character(len=*), parameter :: types(4) = [character(len=10) :: 'spring', 'goodman4', &
         'goodman6', 'thin_layer']
      integer :: k, code
      call make_directories(DIR)
      do k = 1, 4
         code = run_deck(DATA//'patch_'//trim(types(k))//'_inclined.inp', DIR//'/init.h5', &
            .true., model, problem)
         call check(error, code == 0, trim(types(k))//' inclined runs')
         if (allocated(error)) return
         computed = problem%state%joints%sets(1)%sigma
         call initial_joint_stress(model, problem%state%joints, uniaxial, error)
         if (allocated(error)) return
         call check(error, maxval(abs(problem%state%joints%sets(1)%sigma - computed)) <= &
            RTOL*P .and. maxval(abs(problem%state%joints%sets(1)%sigma_trial - &
            problem%state%joints%sets(1)%sigma)) < tiny(1.0_wp), trim(types(k))// &
            ': projected initial stress = computed joint stress')
         if (allocated(error)) return
      end do
   end subroutine test_initial

   !> The joint datasets of the results file equal the final state; the checker passes.
   subroutine test_results(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: rd
      real(wp), allocatable :: stress(:, :, :), eps(:, :, :), xy(:, :, :)
      integer, allocatable :: mode(:, :), conn(:, :)
      character(len=:), allocatable :: etype, out
      integer :: code, stat
      call make_directories(DIR)
      out = DIR//'/patch_results.h5'
      code = run_deck(DATA//'patch_spring_axi_gen.inp', out, .true., model, problem)
      call check(error, code == 0, 'patch_spring_axi_gen.inp runs')
      if (allocated(error)) return
      call rd%open(out, error)
      if (allocated(error)) return
      call rd%dataset('/increments/000002/joints/joint/stress', stress, error)
      if (.not. allocated(error)) call rd%dataset( &
         '/increments/000002/joints/joint/relative_displacement', eps, error)
      if (.not. allocated(error)) call rd%dataset('/increments/000002/joints/joint/mode', &
         mode, error)
      if (.not. allocated(error)) call rd%dataset('/mesh/joint_sets/joint/connectivity', conn, &
         error)
      if (.not. allocated(error)) call rd%dataset('/mesh/joint_sets/joint/point_coordinates', &
         xy, error)
      if (.not. allocated(error)) call rd%attribute('/mesh/joint_sets/joint', 'etype', etype, &
         error)
      call rd%close()
      if (allocated(error)) return
      associate (st => problem%state%joints%sets(1), set => model%joint_sets(1))
         call check(error, all(shape(stress) == shape(st%sigma)) .and. &
            all(shape(eps) == shape(st%eps)), 'joint dataset shapes')
         if (allocated(error)) return
         call check(error, maxval(abs(stress - st%sigma)) < tiny(1.0_wp) .and. &
            maxval(abs(eps - st%eps)) < tiny(1.0_wp) .and. all(mode == 1) .and. &
            all(conn == set%conn - 1) .and. etype == 'SPRING', &
            'joint stress, relative displacement, mode (stick), connectivity as computed')
         if (allocated(error)) return
         call check(error, maxval(abs(xy(:, 1, :) - model%mesh%x(:, set%conn(1, :)))) < &
            tiny(1.0_wp), 'spring points at their face-1 nodes')
         if (allocated(error)) return
      end associate
      ! the tools' package from tools/ (the test runs in the project root), whoever runs it
      call execute_command_line('PYTHONPATH=tools${PYTHONPATH:+:$PYTHONPATH} python3 -m '// &
         'pecplas_py.checks.check_results '//out//' --expect-status completed > '//DIR// &
         '/check.log 2>&1', exitstat=stat)
      call check(error, stat == 0, 'tools/pecplas_py/checks/check_results.py passes (see '//DIR//'/check.log)')
   end subroutine test_results

end module test_pecjoin_patch
