!> MODJOIN identification, the closed forms and the tools: (III.20) makes R_m(gamma) = 1 and
!> dR_m/dk(gamma) = 0 to 1e-12; (III.18) gives the thesis's beta = 1.52 / 1.81 / 1.26 mm
!> for tables III.2 / III.5 / III.6; k0 from R_m(k0) = R0; least-squares line and cubic
!> extremum and hyperbola exact on exact data; CSV curves in the point driver's and a comment
!> form, and their errors (file:line).
module test_pecjoin_identify
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_files, only: make_directories
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use pecplas_studies_identify_closed_forms, only: rm_value, rm_slope, beta_from_slope, ab_from_peak, &
      k0_from_r0
   use pecplas_studies_identify_fits, only: line_fit, smooth_max, origin_slope_upto, end_value, &
      hyperbola_fit
   use pecplas_studies_identify_curves, only: test_curve_t, read_test_curve
   implicit none (type, external)
   private
   public :: collect_pecjoin_identify

   real(wp), parameter :: RAD = acos(-1.0_wp)/180.0_wp
   character(len=*), parameter :: DIR = 'build/test_out/identify'

contains

   subroutine collect_pecjoin_identify(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('ab_closed_form', test_ab), &
               new_unittest('beta_thesis_tables', test_beta), &
               new_unittest('k0_from_r0', test_k0), &
               new_unittest('fits_exact', test_fits), &
               new_unittest('csv_curves', test_csv), &
               new_unittest('csv_errors', test_csv_errors)]
   end subroutine collect_pecjoin_identify

   !> Over alpha in {0.5, 0.7, 0.84, 1}, s in {0.3, 0.84, 2} mm and gamma in {1, 2.4, 4} mm
   !> (the hyperbola alone is below 1 there since alpha <= 1), (III.20)'s A, B satisfy both
   !> conditions of (III.19, corrected) to 1e-12, and B gamma > 2 (A > 0). The thesis's example
   !> (alpha 0.7, beta 1.5 mm, sigma_n0 56 kPa, gamma 2.4 mm) gives B = 0.95 mm^-1 (doc/theory.md §6.4;
   !> table III.2 prints the three-test mean 0.96).
   subroutine test_ab(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: ALPHAS(4) = [0.5_wp, 0.7_wp, 0.84_wp, 1.0_wp]
      real(wp), parameter :: SS(3) = [0.3_wp, 0.84_wp, 2.0_wp], GAMMAS(3) = [1.0_wp, 2.4_wp, 4.0_wp]
      type(error_t), allocatable :: err
      real(wp) :: a, b
      integer :: i, j, k, n
      n = 0
      do i = 1, size(ALPHAS)
         do j = 1, size(SS)
            do k = 1, size(GAMMAS)
               if (ALPHAS(i)*GAMMAS(k)/(SS(j) + GAMMAS(k)) >= 1.0_wp) cycle
               call ab_from_peak(GAMMAS(k), ALPHAS(i), SS(j), a, b, error)
               if (allocated(error)) return
               call check_close(error, rm_value(GAMMAS(k), ALPHAS(i), SS(j), a, b), 1.0_wp, &
                  1.0e-12_wp, 'R_m(gamma) = 1')
               if (allocated(error)) return
               call check_close(error, rm_slope(GAMMAS(k), ALPHAS(i), SS(j), a, b), 0.0_wp, &
                  0.0_wp, 'dR_m/dk(gamma) = 0', atol=1.0e-12_wp)
               if (allocated(error)) return
               call check(error, b*GAMMAS(k) > 2.0_wp .and. a > 0.0_wp, 'B gamma > 2, A > 0')
               if (allocated(error)) return
               n = n + 1
            end do
         end do
      end do
      call check(error, n == 36, 'all 36 combinations were checked')
      if (allocated(error)) return
      call ab_from_peak(2.4_wp, 0.7_wp, 1.5_wp*0.56_wp, a, b, error)
      if (allocated(error)) return
      call check_close(error, b, 0.95_wp, 0.005_wp, 'thesis example: B = 0.95')
      if (allocated(error)) return
      ! no peak possible when the hyperbola alone exceeds 1 at gamma
      call ab_from_peak(4.0_wp, 1.2_wp, 0.3_wp, a, b, err)
      call check(error, allocated(err), 'alpha gamma/(s+gamma) >= 1 is refused')
      if (allocated(error)) return
      call check(error, index(err%message, 'III.20') > 0, 'the message names (III.20)')
   end subroutine test_ab

   !> (III.18) with c = 0: beta = alpha tan(phi) P_a / G0, the same at every sigma_n0:
   !> 0.7 tan41 100/40 = 1.52 (III.2), 0.84 tan37 100/35 = 1.81 (III.5),
   !> 0.75 tan37 100/45 = 1.26 (III.6, Dr 80 %) -- our reading of the printed metres.
   subroutine test_beta(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: SIGS(3) = [31.0_wp, 56.0_wp, 122.0_wp]
      real(wp) :: sig
      integer :: i
      do i = 1, 3
         sig = SIGS(i)
         call check_close(error, beta_from_slope(0.7_wp, tan(41*RAD), 40.0_wp, sig, 0.0_wp), &
            1.52_wp, 0.005_wp/1.52_wp, 'table III.2: beta = 1.52 mm')
         if (allocated(error)) return
      end do
      call check_close(error, beta_from_slope(0.84_wp, tan(37*RAD), 35.0_wp, 56.0_wp, 0.0_wp), &
         1.81_wp, 0.005_wp/1.81_wp, 'table III.5: beta = 1.81 mm')
      if (allocated(error)) return
      call check_close(error, beta_from_slope(0.75_wp, tan(37*RAD), 45.0_wp, 193.0_wp, 0.0_wp), &
         1.26_wp, 0.005_wp/1.26_wp, 'table III.6: beta = 1.26 mm')
      if (allocated(error)) return
      ! with cohesion the normalising stress is sigma_n0 + C: (56 + 10)/56 times larger
      call check_close(error, beta_from_slope(0.7_wp, 0.5_wp, 40.0_wp, 56.0_wp, 10.0_wp), &
         0.7_wp*0.5_wp*66.0_wp*100.0_wp/(40.0_wp*56.0_wp), 1.0e-15_wp, 'beta with C')
   end subroutine test_beta

   !> k0: (III.6) k0 = R0 s/(1 - R0) for the initial version; with A > 0 the bisection root
   !> gives R_m(k0) = R0 to 1e-12 and lies before the peak.
   subroutine test_k0(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: k0, a, b
      call k0_from_r0(0.3_wp, 1.0_wp, 9.0_wp*0.56_wp, 0.0_wp, 0.0_wp, k0, error)
      if (allocated(error)) return
      call check_close(error, k0, 0.3_wp*9.0_wp*0.56_wp/0.7_wp, 1.0e-14_wp, '(III.6)')
      if (allocated(error)) return
      call ab_from_peak(2.4_wp, 0.7_wp, 0.84_wp, a, b, error)
      if (allocated(error)) return
      call k0_from_r0(0.3_wp, 0.7_wp, 0.84_wp, a, b, k0, error, gamma=2.4_wp)
      if (allocated(error)) return
      call check_close(error, rm_value(k0, 0.7_wp, 0.84_wp, a, b), 0.3_wp, 1.0e-12_wp, &
         'R_m(k0) = R0')
      if (allocated(error)) return
      call check(error, k0 > 0.0_wp .and. k0 < 2.4_wp, 'k0 before the peak')
      if (allocated(error)) return
      call k0_from_r0(0.3_wp, 0.7_wp, 0.84_wp, a, b, k0, error)
      if (allocated(error)) return
      call check_close(error, rm_value(k0, 0.7_wp, 0.84_wp, a, b), 0.3_wp, 1.0e-12_wp, &
         'R_m(k0) = R0 without the peak given')
   end subroutine test_k0

   !> A line is fitted exactly; the secant of a straight start is its slope; the cubic
   !> extremum finds the maximum of y = 5 - (x - 1.234)^2 (1 + 0.3 (x - 1.234)) (an
   !> asymmetric peak, exactly a cubic) to 1e-10; the end value of a line is exact; the
   !> hyperbola 48.7 (x + 0.4)/(x + 1.3) is fitted to 1e-9.
   subroutine test_fits(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: x(401), y(401), slope, intercept, xm, ym, t, x0, sh
      integer :: i, imax
      logical :: ok
      x = [(0.01_wp*i, i=0, 400)]
      y = 3.0_wp*x - 2.0_wp
      call line_fit(x, y, slope, intercept)
      call check(error, abs(slope - 3.0_wp) < 1.0e-12_wp .and. abs(intercept + 2.0_wp) < &
         1.0e-12_wp, 'line fit exact')
      if (allocated(error)) return
      y = 7.0_wp*x
      call check_close(error, origin_slope_upto(x, y, 0.2_wp), 7.0_wp, 1.0e-13_wp, 'secant')
      if (allocated(error)) return
      call check_close(error, end_value(x, 3.0_wp*x - 2.0_wp, 0.1_wp), 10.0_wp, 1.0e-12_wp, &
         'end value of a line')
      if (allocated(error)) return
      y = 5.0_wp - (x - 1.234_wp)**2*(1.0_wp + 0.3_wp*(x - 1.234_wp))
      call smooth_max(x, y, 0.5_wp, xm, ym, imax)
      call check_close(error, xm, 1.234_wp, 1.0e-10_wp, 'cubic peak position')
      if (allocated(error)) return
      call check_close(error, ym, 5.0_wp, 1.0e-12_wp, 'cubic peak value')
      if (allocated(error)) return
      y = 48.7_wp*(x + 0.4_wp)/(x + 1.3_wp)
      call hyperbola_fit(x, y, t, x0, sh, ok)
      call check(error, ok .and. abs(t - 48.7_wp) < 1.0e-9_wp .and. abs(x0 - 0.4_wp) < &
         1.0e-10_wp .and. abs(sh - 1.3_wp) < 1.0e-10_wp, 'hyperbola fit exact')
   end subroutine test_fits

   !> The point driver's CSV (sigma_n0 from the first row's sigma_n, the text column `mode`
   !> ignored) and a minimal CSV with the columns in another order and a sigma_n0 comment.
   subroutine test_csv(error)
      type(error_t), allocatable, intent(out) :: error
      type(test_curve_t) :: cv
      integer :: u
      call make_directories(DIR)
      open (newunit=u, file=DIR//'/driver.csv', status='replace', action='write')
      write (u, '(a)') 'step,eps_t,eps_n,sigma_n,tau,mode,plastic_slip'
      write (u, '(a)') '0,0.0,0.0,56.0,0.0,stick,0.0'
      write (u, '(a)') '1,0.1,0.0,56.0,3.0,stick,0.0'
      write (u, '(a)') '2,0.2,0.01,56.0,6.0,stick,0.0'
      write (u, '(a)') '3,0.3,0.02,56.0,8.0,slip,0.05'
      write (u, '(a)') '4,0.4,0.01,56.0,9.0,slip,0.1'
      close (u)
      call read_test_curve(DIR//'/driver.csv', cv, error)
      if (allocated(error)) return
      call check(error, size(cv%eps_t) == 5 .and. cv%sigma_n0 == 56.0_wp .and. &
         cv%tau(4) == 8.0_wp .and. cv%eps_n(3) == 0.01_wp .and. cv%eps_t(5) == 0.4_wp, &
         "driver CSV: 5 rows, sigma_n0 = 56, columns by name")
      if (allocated(error)) return
      open (newunit=u, file=DIR//'/lab.csv', status='replace', action='write')
      write (u, '(a)') '# a laboratory test, sand on steel'
      write (u, '(a)') '# sigma_n0 = 31'
      write (u, '(a)') 'TAU, Eps_N, EPS_T'
      write (u, '(a)') '0, 0, 0'
      write (u, '(a)') '2, 0, 0.1'
      write (u, '(a)') '4, 0.01, 0.2'
      write (u, '(a)') ''
      write (u, '(a)') '5, 0.02, 0.3'
      write (u, '(a)') '6, 0.01, 0.4'
      close (u)
      call read_test_curve(DIR//'/lab.csv', cv, error)
      if (allocated(error)) return
      call check(error, size(cv%eps_t) == 5 .and. cv%sigma_n0 == 31.0_wp .and. &
         cv%tau(3) == 4.0_wp .and. cv%eps_t(2) == 0.1_wp .and. cv%eps_n(4) == 0.02_wp, &
         'lab CSV: columns in any order and case, sigma_n0 from the comment')
   end subroutine test_csv

   !> A missing column, a bad number (file:line) and an unknown sigma_n0 are reported.
   subroutine test_csv_errors(error)
      type(error_t), allocatable, intent(out) :: error
      type(test_curve_t) :: cv
      type(error_t), allocatable :: err
      integer :: u
      call make_directories(DIR)
      open (newunit=u, file=DIR//'/bad1.csv', status='replace', action='write')
      write (u, '(a)') 'eps_t,tau,sigma_n'
      write (u, '(a)') '0,0,56'
      close (u)
      call read_test_curve(DIR//'/bad1.csv', cv, err)
      call check(error, allocated(err), 'missing eps_n column refused')
      if (allocated(error)) return
      call check(error, index(err%message, 'eps_n') > 0 .and. index(err%message, ':1:') > 0, &
         'message names the columns and line 1: '//err%message)
      if (allocated(error)) return
      open (newunit=u, file=DIR//'/bad2.csv', status='replace', action='write')
      write (u, '(a)') 'eps_t,tau,eps_n,sigma_n'
      write (u, '(a)') '0,0,0,56'
      write (u, '(a)') '0.1,x3,0,56'
      close (u)
      call read_test_curve(DIR//'/bad2.csv', cv, err)
      call check(error, allocated(err), 'bad number refused')
      if (allocated(error)) return
      call check(error, index(err%message, 'bad2.csv:3:') > 0, 'file:line: '//err%message)
      if (allocated(error)) return
      open (newunit=u, file=DIR//'/bad3.csv', status='replace', action='write')
      write (u, '(a)') 'eps_t,tau,eps_n'
      write (u, '(a)') '0,0,0'
      close (u)
      call read_test_curve(DIR//'/bad3.csv', cv, err)
      call check(error, allocated(err), 'no sigma_n0 refused')
      if (allocated(error)) return
      call check(error, index(err%message, 'sigma_n0') > 0, 'message: '//err%message)
   end subroutine test_csv_errors

end module test_pecjoin_identify
