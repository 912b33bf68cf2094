!> Tangent of every interface law against central differences of its own `update`, in the
!> elastic (stick) and the plastic (slip) regime, away from corners: random stress points
!> and increment directions from a fixed seed. Within one regime the update is affine in
!> deps, so the differences are exact up to round-off and the tolerance is 1e-6 relative.
!> The only documented departure: stiffness-adaptation laws (Goodman) add K_t KT_RATIO to
!> d tau / d eps_t in slip while the capped stress does not move: it is subtracted here.
module test_pecjoin_laws_tangent
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_testing, only: unittest_t, new_unittest, check
   use pecplas_joints_laws_type, only: interface_law_t, MODE_STICK, MODE_SLIP, MODE_NAMES
   use pecplas_joints_laws_coulomb, only: coulomb_law_t
   use fixtures_pecjoin, only: make_law, lcg_uniform, fd_tangent, max_rel_diff
   implicit none (type, external)
   private
   public :: collect_pecjoin_laws_tangent

   real(wp), parameter :: DEG = acos(-1.0_wp)/180.0_wp, TOL = 1.0e-6_wp
   real(wp), parameter :: KN = 1.0e4_wp, KT = 3.0e3_wp
   integer, parameter :: NPOINTS = 12
   integer, parameter :: I8 = selected_int_kind(18)

contains

   subroutine collect_pecjoin_laws_tangent(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('elastic', test_elastic), &
               new_unittest('goodman', test_goodman), &
               new_unittest('spring', test_spring), &
               new_unittest('ghaboussi_flat', test_ghaboussi_flat), &
               new_unittest('ghaboussi_asperities', test_ghaboussi_asperities), &
               new_unittest('mohr_coulomb', test_mohr_coulomb), &
               new_unittest('mohr_coulomb_associated', test_mohr_coulomb_associated)]
   end subroutine collect_pecjoin_laws_tangent

   subroutine test_elastic(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      call make_law('ELASTIC', ['KN', 'KT'], [KN, KT], law, error)
      if (allocated(error)) return
      call check_law(error, law, 'ELASTIC', 0.0_wp, 0.0_wp, .false.)
   end subroutine test_elastic

   subroutine test_goodman(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      call make_law('GOODMAN', ['KN ', 'KT ', 'PHI', 'C  '], [KN, KT, 30.0_wp, 5.0_wp], law, &
         error)
      if (allocated(error)) return
      call check_law(error, law, 'GOODMAN', tan(30.0_wp*DEG), 5.0_wp, .true.)
   end subroutine test_goodman

   subroutine test_spring(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      call make_law('SPRING', ['KN ', 'KT ', 'PHI', 'C  '], [KN, KT, 20.0_wp, 2.0_wp], law, &
         error)
      if (allocated(error)) return
      call check_law(error, law, 'SPRING', tan(20.0_wp*DEG), 2.0_wp, .true.)
   end subroutine test_spring

   subroutine test_ghaboussi_flat(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      call make_law('GHABOUSSI', ['KN ', 'KT ', 'PHI', 'C  '], [KN, KT, 25.0_wp, 3.0_wp], law, &
         error)
      if (allocated(error)) return
      call check_law(error, law, 'GHABOUSSI', tan(25.0_wp*DEG), 3.0_wp, .true.)
   end subroutine test_ghaboussi_flat

   !> gamma = 12: strength tan(phi+gamma) and c cos(phi)/cos(phi+gamma) (Patton).
   subroutine test_ghaboussi_asperities(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      call make_law('GHABOUSSI', ['KN   ', 'KT   ', 'PHI  ', 'C    ', 'GAMMA'], [KN, KT, &
         25.0_wp, 3.0_wp, 12.0_wp], law, error)
      if (allocated(error)) return
      call check_law(error, law, 'GHABOUSSI gamma=12', tan(37.0_wp*DEG), &
         3.0_wp*cos(25.0_wp*DEG)/cos(37.0_wp*DEG), .true.)
   end subroutine test_ghaboussi_asperities

   subroutine test_mohr_coulomb(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      call make_law('MOHR_COULOMB', ['KN ', 'KT ', 'PHI', 'PSI', 'C  '], [KN, KT, 30.0_wp, &
         10.0_wp, 5.0_wp], law, error)
      if (allocated(error)) return
      call check_law(error, law, 'MOHR_COULOMB', tan(30.0_wp*DEG), 5.0_wp, .true.)
   end subroutine test_mohr_coulomb

   subroutine test_mohr_coulomb_associated(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      call make_law('MOHR_COULOMB', ['KN ', 'KT ', 'PHI', 'PSI'], [KN, KT, 35.0_wp, 35.0_wp], &
         law, error)
      if (allocated(error)) return
      call check_law(error, law, 'MOHR_COULOMB associated', tan(35.0_wp*DEG), 0.0_wp, .true.)
      if (allocated(error)) return
      call check(error, law%symmetric_tangent(), 'associated: symmetric_tangent()')
   end subroutine test_mohr_coulomb_associated

   !> NPOINTS elastic and (if `plastic`) NPOINTS slipping points of a law with strength
   !> tau_bar = c + mu sigma_n: the update must be in the expected mode and its tangent
   !> must match central differences.
   subroutine check_law(error, law, what, mu, c, plastic)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), intent(in) :: law
      character(len=*), intent(in) :: what
      real(wp), intent(in) :: mu, c
      logical, intent(in) :: plastic
      integer(I8) :: seed
      real(wp) :: state0(law%nstate()), state(law%nstate()), s0(2), deps(2), sigma(2)
      real(wp) :: t(2, 2), fd(2, 2), sn, tau_bar, theta, size_, s, r
      integer :: i, regime, mode, expected
      character(len=160) :: msg
      seed = 20240607_I8
      do regime = 1, merge(2, 1, plastic)
         do i = 1, NPOINTS
            sn = 20.0_wp + 180.0_wp*lcg_uniform(seed)
            tau_bar = c + mu*sn
            s = merge(1.0_wp, -1.0_wp, lcg_uniform(seed) < 0.5_wp)
            if (regime == 1) then
               ! inside, small increment in any direction: stays elastic
               s0 = [sn, s*(2.0_wp*lcg_uniform(seed) - 1.0_wp)*0.5_wp*tau_bar]
               theta = 2.0_wp*acos(-1.0_wp)*lcg_uniform(seed)
               size_ = 0.1_wp*max(tau_bar, 1.0_wp)/(KT + KN*mu + KN)
               deps = size_*[cos(theta), sin(theta)]
               expected = MODE_STICK
            else
               ! on or inside the cone, a large tangential push and a moderate normal one
               s0 = [sn, s*(0.5_wp + 0.5_wp*lcg_uniform(seed))*tau_bar]
               deps = [(0.2_wp*lcg_uniform(seed) - 0.1_wp)*sn/KN, &
                  s*(2.0_wp + lcg_uniform(seed))*tau_bar/KT]
               expected = MODE_SLIP
            end if
            call law%init_state(s0, state0)
            state = state0
            call law%update(s0, deps, state, sigma, t, mode, error)
            if (allocated(error)) return
            write (msg, '(a,a,i0,a,2es12.4,a,2es12.4)') what, ' point ', i, ' sigma0', s0, &
               ' deps', deps
            if (mode /= expected) then
               call fatal_error(error, trim(msg)//': mode '//trim(MODE_NAMES(mode))// &
                  ', expected '//trim(MODE_NAMES(expected)))
               return
            end if
            if (mode == MODE_SLIP) then
               select type (law)
               class is (coulomb_law_t)
                  t(2, 2) = t(2, 2) - law%kt_slip
               end select
            end if
            call fd_tangent(law, s0, state0, deps, 1.0e-6_wp*maxval(abs(deps)), fd, error)
            if (allocated(error)) return
            r = max_rel_diff(t, fd)
            if (.not. r < TOL) then
               write (msg, '(a,a,es9.2)') trim(msg), ': tangent vs central differences, '// &
                  'relative error', r
               call fatal_error(error, trim(msg))
               return
            end if
         end do
      end do
   end subroutine check_law

end module test_pecjoin_laws_tangent
