!> Katona contact with Coulomb friction through the whole program: the NAFEMS CGS-4-type
!> inclined plane, the stick/slip threshold of a pad at 0.99 / 1.01 mu N (the decks of the
!> Mohr–Coulomb tests with TYPE=KATONA only), and the convergence of the penalty method
!> (Frank springs, the same deck with TYPE=SPRING) to the Katona solution as K grows.
module test_pecjoin_katona_friction
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_joints_laws_type, only: MODE_SLIP, MODE_STICK
   use doc_report, only: report
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_pecjoin_katona_friction

   character(len=*), parameter :: DIR = 'build/test_out/katona', DATA = 'test/data/katona/'

contains

   subroutine collect_pecjoin_katona_friction(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('inclined_plane_cgs4', test_inclined_plane), &
               new_unittest('pad_stick_099', test_pad_stick), &
               new_unittest('pad_slip_101', test_pad_slip), &
               new_unittest('penalty_to_lagrange', test_penalty_limit)]
   end subroutine collect_pecjoin_katona_friction

   subroutine run(deck, name, model, problem, code)
      character(len=*), intent(in) :: deck, name
      type(model_t), intent(out) :: model
      type(problem_t), intent(out) :: problem
      integer, intent(out) :: code
      call make_directories(DIR)
      code = run_deck(deck, DIR//'/'//name//'.h5', .true., model, problem)
   end subroutine run

   !> Slip up the slope at F/G = (tan a + mu)/(1 - mu tan a) = 0.412371 (0.1 %): force
   !> control stops there (the pad, held only by its contacts, slides away).
   subroutine test_inclined_plane(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: ta = 0.1_wp, mu = 0.3_wp
      integer :: code
      call run(DATA//'inclined_plane.inp', 'inclined_plane', model, problem, code)
      call check(error, code == 3, 'force control beyond the slip limit stops (exit 3)')
      if (allocated(error)) return
      call report('cgs4/katona_f_over_g', problem%state%factors(2))
      call check_close(error, problem%state%factors(2), (ta + mu)/(1.0_wp - mu*ta), 1.0e-3_wp, &
         'F/G at the limit = (tan a + mu)/(1 - mu tan a)')
   end subroutine test_inclined_plane

   !> T = 0.99 mu N: converges, and the contact forces balance the loads exactly (1e-9):
   !> sum T = 3 x 19.8, sum N = 100 x 2; no doublet exceeds its friction limit.
   subroutine test_pad_stick(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call run(DATA//'pad_stick.inp', 'pad_stick', model, problem, code)
      call check(error, code == 0, 'T = 0.99 mu N converges')
      if (allocated(error)) return
      associate (kt => problem%katona)
         call check_close(error, sum(kt%f(2, :)), 3.0_wp*19.8_wp, 1.0e-9_wp, 'sum T = push')
         if (allocated(error)) return
         call check_close(error, sum(kt%f(1, :)), 200.0_wp, 1.0e-9_wp, 'sum N = p x width')
         if (allocated(error)) return
         call check(error, all(abs(kt%f(2, :)) <= kt%mu*kt%f(1, :)*(1.0_wp + 1.0e-9_wp)), &
            '|T| <= mu N at every doublet')
      end associate
   end subroutine test_pad_stick

   !> T = 1.01 mu N: no equilibrium, the run stops (exit 3) before the full push.
   subroutine test_pad_slip(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      call run(DATA//'pad_slip.inp', 'pad_slip', model, problem, code)
      call check(error, code == 3, 'T = 1.01 mu N stops (exit 3)')
      if (allocated(error)) return
      call check(error, problem%state%factors(2) < 1.0_wp, 'the push is not carried')
   end subroutine test_pad_slip

   !> One mesh (disp_spring_plane.inp, imposed shortening, two materials) with friction
   !> PHI = 15 deg: Katona, then Frank penalty springs with K = 1e6 ... 1e9 (the law's TYPE
   !> and stiffness are the only change). The penalty error is O(1/K): the relative error of
   !> the contact resultant sum N and the largest interpenetration fall by >= 5 per decade
   !> of K, and at K = 1e9 the resultant agrees to 1e-4 while Katona's penetration is nil.
   subroutine test_penalty_limit(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      character(len=*), parameter :: kvals(4) = ['1e6', '1e7', '1e8', '1e9']
      real(wp) :: n_katona, n_pen(4), pen(4), err(4)
      character(len=200) :: buf
      integer :: code, i, e
      call variant('KATONA', '1', 'katona_friction', error)
      if (allocated(error)) return
      call run(DIR//'/katona_friction.inp', 'katona_friction', model, problem, code)
      call check(error, code == 0, 'Katona with friction completes')
      if (allocated(error)) return
      call check(error, any(problem%katona%mode == MODE_SLIP) .and. &
         any(problem%katona%mode == MODE_STICK), 'the interface partly sticks and partly slips')
      if (allocated(error)) return
      n_katona = sum(problem%katona%f(1, :))
      call check(error, problem%katona%max_penetration <= 1.0e-15_wp, 'Katona: no penetration')
      if (allocated(error)) return
      do i = 1, size(kvals)
         call variant('SPRING', kvals(i), 'penalty_'//kvals(i), error)
         if (allocated(error)) return
         call run(DIR//'/penalty_'//kvals(i)//'.inp', 'penalty_'//kvals(i), model, problem, code)
         call check(error, code == 0, 'penalty K = '//kvals(i)//' completes')
         if (allocated(error)) return
         associate (set => model%joint_sets(1), st => problem%state%joints%sets(1))
            n_pen(i) = 0.0_wp
            do e = 1, size(set%conn, 2)
               n_pen(i) = n_pen(i) + st%sigma(1, 1, e)*set%tributary(e)
            end do
            pen(i) = maxval(st%eps(1, 1, :))
         end associate
         err(i) = abs(n_pen(i) - n_katona)/abs(n_katona)
      end do
      write (buf, '(a,4es9.2,a,4es9.2)') ' resultant errors', err, ' penetrations', pen
      write (*, '(a)') '       '//trim(buf)
      call report('katona/penalty_resultant_errors', err)
      call report('katona/penalty_penetrations', pen)
      call check(error, all(err(2:) <= err(:3)/5.0_wp) .and. all(pen(2:) <= pen(:3)/5.0_wp), &
         'penalty error O(1/K):'//trim(buf))
      if (allocated(error)) return
      call check(error, err(4) <= 1.0e-4_wp .and. all(pen > 0.0_wp), &
         'penalty resultant -> Katona resultant'//trim(buf))
   end subroutine test_penalty_limit

   !> Writes DIR/<name>.inp: disp_spring_plane.inp with the law TYPE=<law>, KN = KT = <k>,
   !> PHI = 15, solved by full Newton (the penalty law's consistent tangent).
   subroutine variant(law, k, name, error)
      character(len=*), intent(in) :: law, k, name
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: old = '*INTERFACE_LAW, NAME=contact, TYPE=KATONA'// &
         new_line('a')//'MU = 0'
      character(len=:), allocatable :: text
      integer :: u, n, at
      call make_directories(DIR)
      open (newunit=u, file=DATA//'disp_spring_plane.inp', access='stream', form='unformatted', &
         status='old', action='read')
      inquire (unit=u, size=n)
      allocate (character(len=n) :: text)
      read (u) text
      close (u)
      at = index(text, old)
      if (at == 0) then
         call fatal_error(error, 'disp_spring_plane.inp: law block not found')
         return
      end if
      text = text(:at - 1)//'*INTERFACE_LAW, NAME=contact, TYPE='//law//new_line('a')// &
         'KN = '//k//', KT = '//k//', PHI = 15'//text(at + len(old):)// &
         '*SOLVER, METHOD=NEWTON, TOLERANCE=1e-10, MAX_ITERATIONS=60'//new_line('a')
      open (newunit=u, file=DIR//'/'//name//'.inp', access='stream', form='unformatted', &
         status='replace', action='write')
      write (u) text
      close (u)
   end subroutine variant

end module test_pecjoin_katona_friction
