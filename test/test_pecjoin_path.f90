!> The point driver: CNL keeps sigma_n (1e-10) and reaches the plateau sigma_n0 tan(phi);
!> CND raises sigma_n at exactly K_n tan(psi) per unit plastic slip; CNS at K* tan(psi),
!> K* = K_n KS/(K_n + KS), between the two; cyclic turning points; the example deck end to
!> end (CSV + HDF5); path-deck errors with file:line.
module test_pecjoin_path
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_files, only: make_directories, remove_file
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use pecplas_joints_laws_type, only: interface_law_t, MODE_SLIP, MODE_STICK
   use pecplas_studies_path_deck, only: path_deck_t, read_path_deck, PATH_CNL, PATH_CND, PATH_CNS
   use pecplas_studies_path_driver, only: path_result_t, run_path
   use pecplas_cmd_path, only: run_path_deck
   use fixtures_pecjoin, only: make_law
   use fixtures_runs, only: file_exists
   implicit none (type, external)
   private
   public :: collect_pecjoin_path

   real(wp), parameter :: DEG = acos(-1.0_wp)/180.0_wp
   real(wp), parameter :: KN = 1000.0_wp, KT = 500.0_wp, PHI = 30.0_wp, PSI = 10.0_wp
   character(len=*), parameter :: DIR = 'build/test_out/path'

contains

   subroutine collect_pecjoin_path(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('cnl_plateau', test_cnl), &
               new_unittest('cnd_dilatancy_rate', test_cnd), &
               new_unittest('cns_between', test_cns), &
               new_unittest('cyclic_turning_points', test_cyclic), &
               new_unittest('deck_end_to_end', test_deck_run), &
               new_unittest('deck_errors', test_deck_errors)]
   end subroutine collect_pecjoin_path

   subroutine mc_law(law, error)
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      call make_law('MOHR_COULOMB', ['KN ', 'KT ', 'PHI', 'PSI'], [KN, KT, PHI, PSI], law, error)
   end subroutine mc_law

   !> First row in slip (the rates are checked from there to the end).
   integer function first_slip(res) result(k)
      type(path_result_t), intent(in) :: res
      do k = 0, ubound(res%mode, 1)
         if (res%mode(k) == MODE_SLIP) return
      end do
      k = -1
   end function first_slip

   !> CNL at 100 kPa: sigma_n = 100 on every row (1e-10), plateau 100 tan(30) (1e-10), and
   !> under constant sigma_n the normal displacement is purely plastic:
   !> d eps_n = -tan(psi) d(plastic slip).
   subroutine test_cnl(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      type(path_result_t) :: res
      integer :: n, k
      call mc_law(law, error)
      if (allocated(error)) return
      call run_path(law, PATH_CNL, [100.0_wp, 0.0_wp], 0.0_wp, [2.0_wp], 200, res, error)
      if (allocated(error)) return
      n = ubound(res%tau, 1)
      call check(error, n == 200 .and. all(abs(res%sigma_n - 100.0_wp) <= 1.0e-10_wp*100.0_wp), &
         'CNL: sigma_n constant to 1e-10 on all 201 rows')
      if (allocated(error)) return
      call check_close(error, res%tau(n), 100.0_wp*tan(PHI*DEG), 1.0e-10_wp, 'plateau')
      if (allocated(error)) return
      call check_close(error, res%eps_t(n), 2.0_wp, 0.0_wp, 'eps_t reaches the target exactly')
      if (allocated(error)) return
      k = first_slip(res)
      call check(error, k > 0 .and. res%mode(n) == MODE_SLIP, 'slips at the end')
      if (allocated(error)) return
      call check_close(error, (res%eps_n(n) - res%eps_n(k))/(res%slip(n) - res%slip(k)), &
         -tan(PSI*DEG), 1.0e-9_wp, 'dilation rate -tan(psi)')
   end subroutine test_cnl

   !> CND: eps_n = 0; on the cone tau = sigma_n tan(phi) and, from the exact return with
   !> d eps_n = 0 (see test_pecjoin_laws_mc), d sigma_n = K_n tan(psi) d(slip) and
   !> d sigma_n / d eps_t = K_n K_t tan(psi) / (K_t + K_n tan(phi) tan(psi)).
   subroutine test_cnd(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      type(path_result_t) :: res
      real(wp) :: tf, tp
      integer :: n, k
      tf = tan(PHI*DEG)
      tp = tan(PSI*DEG)
      call mc_law(law, error)
      if (allocated(error)) return
      call run_path(law, PATH_CND, [100.0_wp, 0.0_wp], 0.0_wp, [2.0_wp], 200, res, error)
      if (allocated(error)) return
      n = ubound(res%tau, 1)
      k = first_slip(res)
      call check(error, all(res%eps_n == 0.0_wp) .and. k > 0, 'CND: eps_n = 0, slips')
      if (allocated(error)) return
      call check_close(error, (res%sigma_n(n) - res%sigma_n(k))/(res%slip(n) - res%slip(k)), &
         KN*tp, 1.0e-12_wp, 'd sigma_n / d slip = K_n tan(psi)')
      if (allocated(error)) return
      call check_close(error, (res%sigma_n(n) - res%sigma_n(k))/(res%eps_t(n) - res%eps_t(k)), &
         KN*KT*tp/(KT + KN*tf*tp), 1.0e-10_wp, 'd sigma_n / d eps_t')
      if (allocated(error)) return
      call check_close(error, res%tau(n), res%sigma_n(n)*tf, 1.0e-12_wp, 'on the cone')
   end subroutine test_cnd

   !> CNS, KS = 200: sigma_n - sigma_n0 = -KS eps_n on every row, d sigma_n / d slip =
   !> K* tan(psi) with K* = K_n KS/(K_n + KS) (normal spring in series with the joint), and
   !> the final sigma_n lies strictly between the CNL and CND ones.
   subroutine test_cns(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      type(path_result_t) :: res, cnd
      real(wp), parameter :: KS = 200.0_wp
      integer :: n, k
      call mc_law(law, error)
      if (allocated(error)) return
      call run_path(law, PATH_CNS, [100.0_wp, 0.0_wp], KS, [2.0_wp], 200, res, error)
      if (allocated(error)) return
      call run_path(law, PATH_CND, [100.0_wp, 0.0_wp], 0.0_wp, [2.0_wp], 200, cnd, error)
      if (allocated(error)) return
      n = ubound(res%tau, 1)
      k = first_slip(res)
      call check(error, all(abs(res%sigma_n - 100.0_wp + KS*res%eps_n) <= 1.0e-10_wp* &
         res%sigma_n), 'CNS condition on every row')
      if (allocated(error)) return
      call check_close(error, (res%sigma_n(n) - res%sigma_n(k))/(res%slip(n) - res%slip(k)), &
         KN*KS/(KN + KS)*tan(PSI*DEG), 1.0e-9_wp, 'd sigma_n / d slip = K* tan(psi)')
      if (allocated(error)) return
      call check(error, res%sigma_n(n) > 100.0_wp .and. res%sigma_n(n) < cnd%sigma_n(n), &
         'CNS between CNL and CND')
   end subroutine test_cns

   !> Turning points 1, -1, 1: each segment ends on the plateau of its sign, the first
   !> increment after a reversal is elastic, and eps_n decreases at every slip (dilation
   !> in both directions, psi > 0).
   subroutine test_cyclic(error)
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      type(path_result_t) :: res
      real(wp) :: plateau
      integer :: seg, k
      call mc_law(law, error)
      if (allocated(error)) return
      call run_path(law, PATH_CNL, [100.0_wp, 0.0_wp], 0.0_wp, [1.0_wp, -1.0_wp, 1.0_wp], 50, &
         res, error)
      if (allocated(error)) return
      call check(error, ubound(res%tau, 1) == 150, '3 segments of 50 increments')
      if (allocated(error)) return
      plateau = 100.0_wp*tan(PHI*DEG)
      do seg = 1, 3
         k = 50*seg
         call check_close(error, res%tau(k), merge(plateau, -plateau, mod(seg, 2) == 1), &
            1.0e-10_wp, 'end of segment on the plateau')
         if (allocated(error)) return
         call check_close(error, res%eps_t(k), merge(1.0_wp, -1.0_wp, mod(seg, 2) == 1), &
            0.0_wp, 'turning point reached exactly')
         if (allocated(error)) return
         if (seg > 1) then
            call check(error, res%mode(k - 49) == MODE_STICK, 'elastic after a reversal')
            if (allocated(error)) return
         end if
      end do
      call check(error, all(res%eps_n(1:) - res%eps_n(:149) <= 0.0_wp), &
         'eps_n never increases (dilation only)')
   end subroutine test_cyclic

   !> The CNL example deck through run_path_deck: exit 0, a CSV with a header and 201 rows
   !> whose last tau is the plateau, and an HDF5 file.
   subroutine test_deck_run(error)
      type(error_t), allocatable, intent(out) :: error
      type(path_result_t) :: res
      character(len=256) :: line, last
      integer :: code, u, ios, nlines
      logical :: ok
      real(wp) :: tau
      call make_directories(DIR)
      call remove_file(DIR//'/cnl.csv')
      call remove_file(DIR//'/cnl.h5')
      code = run_path_deck('input/paths/cnl_mohr_coulomb.inp', DIR//'/cnl', .true., res)
      call check(error, code == 0, 'example CNL deck runs (exit 0)')
      if (allocated(error)) return
      inquire (file=DIR//'/cnl.h5', exist=ok)
      call check(error, ok, 'HDF5 file written')
      if (allocated(error)) return
      open (newunit=u, file=DIR//'/cnl.csv', status='old', action='read', iostat=ios)
      call check(error, ios == 0, 'CSV written')
      if (allocated(error)) return
      read (u, '(a)') line
      nlines = 0
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         nlines = nlines + 1
         last = line
      end do
      close (u)
      call check(error, nlines == 201, 'CSV: 201 rows (increments 0..200)')
      if (allocated(error)) return
      ! columns step,eps_t,eps_n,sigma_n,tau,...: tau is the 5th field
      read (last, *) tau, tau, tau, tau, tau
      call check_close(error, tau, 100.0_wp*tan(PHI*DEG), 1.0e-10_wp, 'CSV plateau')
   end subroutine test_deck_run

   !> Bad path decks: each error names the file and the line, and says what is wrong.
   subroutine test_deck_errors(error)
      type(error_t), allocatable, intent(out) :: error
      type(path_result_t) :: res
      character(len=*), parameter :: NL = new_line('a')
      character(len=*), parameter :: LAW = '*INTERFACE_LAW, NAME=j, TYPE=MOHR_COULOMB'//NL
      character(len=*), parameter :: PATH = '*PATH, TYPE=CNL, SIGMA_N0=100'//NL//'1'//NL
      integer :: code
      call make_directories(DIR)
      call bad(error, 'type', '*INTERFACE_LAW, NAME=j, TYPE=COULOMB'//NL//'KN = 1'//NL//PATH, &
         ':2:', 'MOHR_COULOMB')
      if (allocated(error)) return
      call bad(error, 'kn', LAW//'KT = 5, PHI = 30'//NL//'KN = -5'//NL//PATH, ':2:', 'KN = -5')
      if (allocated(error)) return
      call bad(error, 'phi', LAW//'KN = 5, KT = 5, PHI = 90'//NL//PATH, ':2:', 'PHI')
      if (allocated(error)) return
      call bad(error, 'psi', LAW//'KN = 5, KT = 5, PHI = 30, PSI = 40'//NL//PATH, ':2:', 'PSI')
      if (allocated(error)) return
      call bad(error, 'pathtype', LAW//'KN = 5, KT = 5, PHI = 30'//NL// &
         '*PATH, TYPE=CNX, SIGMA_N0=100'//NL//'1'//NL, ':3:', 'CNL')
      if (allocated(error)) return
      call bad(error, 'cns', LAW//'KN = 5, KT = 5, PHI = 30'//NL// &
         '*PATH, TYPE=CNS, SIGMA_N0=100'//NL//'1'//NL, ':3:', 'KS')
      if (allocated(error)) return
      call bad(error, 'notarget', LAW//'KN = 5, KT = 5, PHI = 30'//NL// &
         '*PATH, TYPE=CND, SIGMA_N0=100'//NL, ':3:', 'target')
      if (allocated(error)) return
      call bad(error, 'badtarget', LAW//'KN = 5, KT = 5, PHI = 30'//NL// &
         '*PATH, TYPE=CND, SIGMA_N0=100'//NL//'1, x'//NL, ':4:', 'target value')
      if (allocated(error)) return
      call bad(error, 'tau0', LAW//'KN = 5, KT = 5, PHI = 30'//NL// &
         '*PATH, TYPE=CNL, SIGMA_N0=100, TAU0=80'//NL//'1'//NL, ':3:', 'initial stress')
      if (allocated(error)) return
      call bad(error, 'keyword', LAW//'KN = 5, KT = 5, PHI = 30'//NL//PATH//'*STEP'//NL, &
         ':5:', '*INTERFACE_LAW *PATH *OUTPUT')
      if (allocated(error)) return
      call bad(error, 'nopath', LAW//'KN = 5, KT = 5, PHI = 30'//NL, 'nopath.inp', '*PATH')
      if (allocated(error)) return
      call bad(error, 'spring', '*INTERFACE_LAW, NAME=s, TYPE=SPRING'//NL//'PHI = 20'//NL// &
         PATH, ':2:', 'penalty')
      if (allocated(error)) return
      ! the command returns 2 and writes nothing
      call remove_file(DIR//'/kn_out.csv')
      code = run_path_deck(DIR//'/kn.inp', DIR//'/kn_out', .true., res)
      call check(error, code == 2 .and. .not. file_exists(DIR//'/kn_out.csv'), &
         'bad deck: exit 2, no output')
   end subroutine test_deck_errors

   !> Writes DIR/<name>.inp with `text`; reading it must fail naming the file, `where`
   !> (':line:') and `fragment`.
   subroutine bad(error, name, text, where, fragment)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: name, text, where, fragment
      type(path_deck_t) :: deck
      type(error_t), allocatable :: e
      character(len=:), allocatable :: file, t
      integer :: u
      file = DIR//'/'//name//'.inp'
      open (newunit=u, file=file, status='replace', action='write', access='stream', &
         form='unformatted')
      write (u) text
      close (u)
      call read_path_deck(file, deck, e)
      if (.not. allocated(e)) then
         call fatal_error(error, name//': bad deck accepted')
         return
      end if
      t = e%text()
      call check(error, index(t, file) == 1 .and. index(t, where) > 0 .and. &
         index(t, fragment) > 0, name//': expected '//where//' and '//fragment//' in: '//t)
   end subroutine bad

end module test_pecjoin_path
