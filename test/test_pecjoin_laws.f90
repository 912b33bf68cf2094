!> PECJOIN classical laws through the factory: unknown types and bad parameters are deck
!> errors naming file and line; every frictional law is elastic–perfectly plastic at a point
!> with the plateau exactly c + sigma_n tan(phi) (c only, phi only, both).
module test_pecjoin_laws
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use pecplas_joints_laws_type, only: interface_law_t, MODE_STICK, MODE_SLIP
   use pecplas_joints_laws_coulomb, only: ST_SLIP
   use pecplas_joints_laws_factory, only: law_registry_t, default_law_registry
   use fixtures_pecjoin, only: law_params, make_law, DECK_FILE
   implicit none (type, external)
   private
   public :: collect_pecjoin_laws

   real(wp), parameter :: PI = acos(-1.0_wp)

contains

   subroutine collect_pecjoin_laws(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('unknown_law_lists_known', test_unknown_law), &
               new_unittest('bad_parameters_name_file_line', test_bad_parameters), &
               new_unittest('defaults_and_coefficients', test_defaults), &
               new_unittest('plateau_goodman', test_plateau_goodman), &
               new_unittest('plateau_spring', test_plateau_spring), &
               new_unittest('plateau_ghaboussi', test_plateau_ghaboussi), &
               new_unittest('plateau_mohr_coulomb', test_plateau_mohr_coulomb)]
   end subroutine collect_pecjoin_laws

   subroutine test_unknown_law(error)
      type(error_t), allocatable, intent(out) :: error
      type(law_registry_t) :: registry
      class(interface_law_t), allocatable :: law
      type(error_t), allocatable :: e
      character(len=:), allocatable :: t
      registry = default_law_registry()
      call registry%new_law('COULOMB', 'j', law_params(['KN'], [1.0_wp]), law, e)
      call check(error, allocated(e), 'an unknown law type must be an error')
      if (allocated(error)) return
      t = e%text()
      call check(error, index(t, DECK_FILE//':7') > 0 .and. index(t, 'COULOMB') > 0 .and. &
         index(t, 'ELASTIC') > 0 .and. index(t, 'GOODMAN') > 0 .and. index(t, 'SPRING') > 0 &
         .and. index(t, 'GHABOUSSI') > 0 .and. index(t, 'MOHR_COULOMB') > 0, &
         'message names file:line and lists the known laws: '//t)
   end subroutine test_unknown_law

   !> Each bad parameter set is refused with file:line and the offending key in the text.
   subroutine test_bad_parameters(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=8), parameter :: K4(4) = [character(len=8) :: 'KN', 'KT', 'PHI', 'C']
      character(len=8), parameter :: K5(5) = [character(len=8) :: 'KN', 'KT', 'PHI', 'PSI', 'C']
      call expect(error, 'MOHR_COULOMB', K4, [-5.0_wp, 1.0_wp, 30.0_wp, 0.0_wp], 'KN')
      if (allocated(error)) return
      call expect(error, 'MOHR_COULOMB', K4, [5.0_wp, 0.0_wp, 30.0_wp, 0.0_wp], 'KT')
      if (allocated(error)) return
      call expect(error, 'MOHR_COULOMB', K4, [5.0_wp, 1.0_wp, 90.0_wp, 0.0_wp], 'PHI')
      if (allocated(error)) return
      call expect(error, 'MOHR_COULOMB', K4, [5.0_wp, 1.0_wp, -1.0_wp, 0.0_wp], 'PHI')
      if (allocated(error)) return
      call expect(error, 'MOHR_COULOMB', K5, [5.0_wp, 1.0_wp, 30.0_wp, 31.0_wp, 0.0_wp], 'PSI')
      if (allocated(error)) return
      call expect(error, 'MOHR_COULOMB', K5, [5.0_wp, 1.0_wp, 30.0_wp, -1.0_wp, 0.0_wp], 'PSI')
      if (allocated(error)) return
      call expect(error, 'MOHR_COULOMB', K4, [5.0_wp, 1.0_wp, 30.0_wp, -2.0_wp], 'C')
      if (allocated(error)) return
      call expect(error, 'MOHR_COULOMB', ['KN ', 'KT ', 'PHI', 'KNN'], &
         [5.0_wp, 1.0_wp, 30.0_wp, 1.0_wp], 'KNN')
      if (allocated(error)) return
      ! PHI is required for Mohr–Coulomb
      call expect(error, 'MOHR_COULOMB', ['KN', 'KT'], [5.0_wp, 1.0_wp], 'PHI')
      if (allocated(error)) return
      call expect(error, 'GOODMAN', [K4, 'KT_RATIO'], [5.0_wp, 1.0_wp, 30.0_wp, 0.0_wp, &
         2.0_wp], 'KT_RATIO')
      if (allocated(error)) return
      call expect(error, 'GOODMAN', K4, [-5.0_wp, 1.0_wp, 30.0_wp, 0.0_wp], 'KN')
      if (allocated(error)) return
      call expect(error, 'GHABOUSSI', [K4, 'GAMMA'], [5.0_wp, 1.0_wp, 50.0_wp, 0.0_wp, &
         40.0_wp], 'PHI + GAMMA')
      if (allocated(error)) return
      call expect(error, 'GHABOUSSI', K4, [5.0_wp, 1.0_wp, 90.0_wp, 0.0_wp], 'PHI')
      if (allocated(error)) return
      call expect(error, 'SPRING', ['KN   ', 'E_RYG'], [5.0_wp, 2.0_wp], 'E_RYG')
      if (allocated(error)) return
      call expect(error, 'SPRING', ['KN', 'KT'], [-5.0_wp, 1.0_wp], 'KN')
      if (allocated(error)) return
      ! an unknown key lists the known ones
      call expect(error, 'SPRING', ['KN ', 'PSI'], [5.0_wp, 2.0_wp], 'known parameters: KN KT')
   end subroutine test_bad_parameters

   subroutine expect(error, type_name, keys, values, fragment)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: type_name, keys(:), fragment
      real(wp), intent(in) :: values(:)
      class(interface_law_t), allocatable :: law
      type(error_t), allocatable :: e
      character(len=:), allocatable :: t
      call make_law(type_name, keys, values, law, e)
      if (.not. allocated(e)) then
         call fatal_error(error, type_name//': bad parameters accepted (expected an error '// &
            'about '//fragment//')')
         return
      end if
      t = e%text()
      call check(error, index(t, DECK_FILE//':7: [*INTERFACE_LAW]') == 1 .and. &
         index(t, fragment) > 0, type_name//': message must start with file:line [keyword] '// &
         'and name '//fragment//': '//t)
   end subroutine expect

   !> Defaults (C = 0, PSI = 0, KT_RATIO = 1e-3, TENSION = 0) and the kernel coefficients.
   subroutine test_defaults(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      real(wp) :: state(6), sigma(2), tangent(2, 2)
      integer :: mode
      call make_law('MOHR_COULOMB', ['KN ', 'KT ', 'PHI'], [100.0_wp, 50.0_wp, 30.0_wp], law, &
         error)
      if (allocated(error)) return
      call check(error, law%nstate() == 6 .and. .not. law%symmetric_tangent(), &
         'MC: 6 state variables; PSI = 0 /= PHI: non-symmetric tangent')
      if (allocated(error)) return
      ! C = 0 and TENSION = 0 by default: any normal tension opens the point
      call law%init_state([0.0_wp, 0.0_wp], state)
      call law%update([0.0_wp, 0.0_wp], [-1.0e-9_wp, 0.0_wp], state, sigma, tangent, mode, error)
      if (allocated(error)) return
      call check(error, mode == 3 .and. all(sigma == 0.0_wp), 'default TENSION = 0')
      if (allocated(error)) return
      call make_law('MOHR_COULOMB', ['KN ', 'KT ', 'PHI', 'PSI'], [100.0_wp, 50.0_wp, &
         30.0_wp, 30.0_wp], law, error)
      if (allocated(error)) return
      call check(error, law%symmetric_tangent(), 'MC with PSI = PHI is associated: symmetric')
      if (allocated(error)) return
      call make_law('GOODMAN', ['KN ', 'KT ', 'PHI'], [100.0_wp, 50.0_wp, 0.0_wp], law, error)
      if (allocated(error)) return
      call check(error, law%symmetric_tangent(), 'Goodman with PHI = 0: symmetric tangent')
   end subroutine test_defaults

   subroutine test_plateau_goodman(error)
      type(error_t), allocatable, intent(out) :: error
      call plateau_cases(error, 'GOODMAN')
   end subroutine test_plateau_goodman

   subroutine test_plateau_spring(error)
      type(error_t), allocatable, intent(out) :: error
      call plateau_cases(error, 'SPRING')
   end subroutine test_plateau_spring

   subroutine test_plateau_ghaboussi(error)
      type(error_t), allocatable, intent(out) :: error
      call plateau_cases(error, 'GHABOUSSI')
   end subroutine test_plateau_ghaboussi

   subroutine test_plateau_mohr_coulomb(error)
      type(error_t), allocatable, intent(out) :: error
      call plateau_cases(error, 'MOHR_COULOMB')
   end subroutine test_plateau_mohr_coulomb

   !> c only (phi = 0), phi only (c = 0), and both.
   subroutine plateau_cases(error, type_name)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: type_name
      call plateau(error, type_name, 0.0_wp, 12.0_wp)
      if (allocated(error)) return
      call plateau(error, type_name, 30.0_wp, 0.0_wp)
      if (allocated(error)) return
      call plateau(error, type_name, 25.0_wp, 7.5_wp)
   end subroutine plateau_cases

   !> Normal compression to sigma_n, then eps_t increments at fixed eps_n: tau = K_t eps_t
   !> (stick) up to tau_bar = c + sigma_n tan(phi), then tau = tau_bar exactly (1e-12), the
   !> plastic slip = eps_t - tau_bar/K_t, sigma_n unchanged (no dilatancy), and an unloading
   !> increment is elastic (tau drops by K_t d eps_t).
   subroutine plateau(error, type_name, phi, c)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: type_name
      real(wp), intent(in) :: phi, c
      class(interface_law_t), allocatable :: law
      real(wp), parameter :: KN = 2.0e4_wp, KT = 8.0e3_wp
      real(wp) :: state(6), sigma(2), sigma_old(2), tangent(2, 2), tau_bar, sn, d, eps_t
      integer :: mode, i
      character(len=64) :: what
      write (what, '(a,a,f4.1,a,f4.1)') type_name, ' phi=', phi, ' c=', c
      call make_law(type_name, ['KN ', 'KT ', 'PHI', 'C  '], [KN, KT, phi, c], law, error)
      if (allocated(error)) return
      call law%init_state([0.0_wp, 0.0_wp], state)
      call law%update([0.0_wp, 0.0_wp], [3.0e-3_wp, 0.0_wp], state, sigma, tangent, mode, error)
      if (allocated(error)) return
      sn = sigma(1)
      call check_close(error, sn, KN*3.0e-3_wp, 1.0e-14_wp, trim(what)//' compression')
      if (allocated(error)) return
      tau_bar = c + sn*tan(phi*PI/180.0_wp)
      d = tau_bar/(KT*20.0_wp)
      eps_t = 0.0_wp
      do i = 1, 60
         sigma_old = sigma
         call law%update(sigma_old, [0.0_wp, d], state, sigma, tangent, mode, error)
         if (allocated(error)) return
         eps_t = eps_t + d
         if (i < 20) then
            call check(error, mode == MODE_STICK, trim(what)//' stick below the strength')
            if (allocated(error)) return
            call check_close(error, sigma(2), KT*eps_t, 1.0e-12_wp, trim(what)//' elastic tau')
         else if (i > 20) then
            call check(error, mode == MODE_SLIP, trim(what)//' slip on the plateau')
            if (allocated(error)) return
            call check_close(error, sigma(2), tau_bar, 1.0e-12_wp, trim(what)//' plateau')
            if (allocated(error)) return
            call check_close(error, state(ST_SLIP), eps_t - tau_bar/KT, 1.0e-10_wp, &
               trim(what)//' plastic slip')
         end if
         if (allocated(error)) return
         call check(error, sigma(1) == sn, trim(what)//' sigma_n constant at fixed eps_n')
         if (allocated(error)) return
      end do
      sigma_old = sigma
      call law%update(sigma_old, [0.0_wp, -d], state, sigma, tangent, mode, error)
      if (allocated(error)) return
      call check(error, mode == MODE_STICK, trim(what)//' unloading is elastic')
      if (allocated(error)) return
      call check_close(error, sigma(2), tau_bar - KT*d, 1.0e-12_wp, trim(what)//' unloading')
   end subroutine plateau

end module test_pecjoin_laws
