!> Identification of MODJOIN's parameters from CNL tests (thesis §III.3.1, III.17–III.20,
!> doc/theory.md §6.4 with its correction dR_m/dk = 0 at the peak), test by test and averaged as
!> the thesis did. On each curve (kPa, mm):
!>
!> - G0: secant modulus at 0.2 mm (least squares through the origin over [0, 0.2] mm),
!>   divided by (sigma_n0/P_a)^0.5 for the improved version (III.15); K0 = 2 G0 (the
!>   thesis's own choice: no compression test);
!> - peak (eps_peak, tau_peak): vertex of a parabola fitted around the largest tau;
!>   phi, c: least-squares line tau_peak = c + sigma_n0 tan(phi) over the tests (or through
!>   the origin with `zero_cohesion`, or with one test);
!>   (initial version, no peak: tau_peak = the asymptote of a hyperbola fitted to the curve,
!>   which also gives beta);
!> - alpha = tau_lim / tau_peak (III.17), tau_lim from a line over the last 10 % of the curve;
!> - beta from (III.18); R0 = tau_y / ((sigma_n0 + C) tan(phi)), tau_y the end of the
!>   straight start (deviation from the secant line <= r0_tol), unless given;
!> - A, B from (III.20) at gamma = k0 + eps_peak - tau_peak/G (the hardening variable at
!>   the peak: its start k0 plus the plastic part of eps_peak), iterated with k0 from
!>   R_m(k0) = R0; `total_gamma` takes the thesis's literal gamma = eps_peak (elastic part
!>   neglected); `refine_alpha` corrects (III.17) for the hyperbola not yet at alpha at the end;
!> - psi: tau/sigma_n at the turn of eps_n (contraction -> dilation, the characteristic
!>   state), regression through the origin over the tests where eps_n turns;
!> - a_g: least-squares fit of eps_n (pecplas_studies_identify_dilatancy).
module pecplas_studies_identify_method
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error
   use pecplas_studies_identify_closed_forms, only: PA, beta_from_slope, ab_from_peak, k0_from_r0
   use pecplas_studies_identify_curves, only: test_curve_t
   use pecplas_studies_identify_fits, only: line_fit, origin_fit, smooth_max, interpolate, end_value, &
      origin_slope_upto, hyperbola_fit
   use pecplas_studies_identify_dilatancy, only: fit_a_g
   implicit none (type, external)
   private

   public :: identify_options_t, test_values_t, identification_t, identify
   public :: VERSION_INITIAL, VERSION_IMPROVED, VERSION_NAMES

   integer, parameter :: VERSION_INITIAL = 1, VERSION_IMPROVED = 2
   character(len=*), parameter :: VERSION_NAMES(2) = [character(len=8) :: 'initial', 'improved']
   real(wp), parameter :: DEG = 180.0_wp/acos(-1.0_wp)

   !> Choices of the method (defaults: the thesis's, with gamma plastic).
   type :: identify_options_t
      integer :: version = VERSION_IMPROVED
      !> Displacement of the secant modulus (mm), window of the peak/turn parabolas (mm),
      !> last fraction of the curve giving tau_lim, straightness tolerance for R0.
      real(wp) :: secant_at = 0.2_wp, window = 0.5_wp, lim_fraction = 0.1_wp
      real(wp) :: r0_tol = 0.02_wp
      !> R0 given (>= 0) instead of detected.
      real(wp) :: r0 = -1.0_wp
      logical :: zero_cohesion = .false., total_gamma = .false., refine_alpha = .false.
   end type identify_options_t

   !> What one test gives (angles in degrees).
   type :: test_values_t
      character(len=:), allocatable :: file
      real(wp) :: sigma_n0 = 0, g_secant = 0, g0 = 0, eps_peak = 0, tau_peak = 0, phi = 0
      real(wp) :: tau_lim = 0, alpha = 1, beta = 0, r0 = 0, k0 = 0, gamma = 0, a = 0, b = 0
      real(wp) :: eps_turn = 0, tau_turn = 0, psi = 0, a_g = 0, ag_rms = 0
      !> eps_n turns (contraction -> dilation) on this curve: it then enters psi's regression.
      logical :: turns = .false.
      !> Initial version, tau still rising at the end: tau_peak is the asymptote of the
      !> hyperbola fitted to the plastic part, and beta that hyperbola's.
      logical :: asymptote = .false.
      real(wp) :: beta_fit = 0
   end type test_values_t

   !> Per-test values and the averaged/regressed parameter set.
   type :: identification_t
      integer :: version = VERSION_IMPROVED
      type(test_values_t), allocatable :: tests(:)
      real(wp) :: k0_modulus = 0, g0 = 0, phi = 0, c = 0, r0 = 0, alpha = 1, beta = 0
      real(wp) :: a = 0, b = 0, psi = 0, a_g = 0
   end type identification_t

contains

   !> Identifies the parameters from the CNL `curves`.
   subroutine identify(curves, opt, res, error)
      type(test_curve_t), intent(in) :: curves(:)
      type(identify_options_t), intent(in) :: opt
      type(identification_t), intent(out) :: res
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: sig(:), tpk(:)
      real(wp) :: tan_phi, c_term, tan_psi, en_turn
      integer :: i, n, imax

      n = size(curves)
      if (n == 0) then
         call input_error(error, 'no test curve given')
         return
      end if
      res%version = opt%version
      allocate (res%tests(n))
      do i = 1, n
         associate (t => res%tests(i), cv => curves(i))
            t%file = cv%file
            t%sigma_n0 = cv%sigma_n0
            t%g_secant = origin_slope_upto(cv%eps_t, cv%tau, opt%secant_at)
            t%g0 = t%g_secant
            if (opt%version == VERSION_IMPROVED) t%g0 = t%g_secant/sqrt(cv%sigma_n0/PA)
            call smooth_max(cv%eps_t, cv%tau, opt%window, t%eps_peak, t%tau_peak, imax)
            if (imax == 1) then
               call input_error(error, cv%file//': tau is largest at the first point: '// &
                  'not a shear curve from rest')
               return
            end if
            if (opt%version == VERSION_IMPROVED .and. imax == size(cv%tau)) then
               call input_error(error, cv%file//': tau has no peak before the end of the '// &
                  'curve; identify it with the initial version (--version initial)')
               return
            end if
            t%tau_lim = end_value(cv%eps_t, cv%tau, opt%lim_fraction)
            if (opt%version == VERSION_INITIAL .and. imax == size(cv%tau)) then
               call asymptote(cv, t, error)
               if (allocated(error)) return
            end if
            call smooth_max(cv%eps_t, cv%eps_n, opt%window, t%eps_turn, en_turn, imax)
            t%turns = imax > 1 .and. imax < size(cv%eps_n)
            if (t%turns) then
               t%tau_turn = interpolate(cv%eps_t, cv%tau, t%eps_turn)
               t%psi = atan(t%tau_turn/cv%sigma_n0)*DEG
            end if
         end associate
      end do

      ! explicit constructors: a component array of a derived type would be copied anyway
      sig = [(res%tests(i)%sigma_n0, i=1, n)]
      tpk = [(res%tests(i)%tau_peak, i=1, n)]
      if (n >= 2 .and. .not. opt%zero_cohesion .and. maxval(sig) > minval(sig)) then
         call line_fit(sig, tpk, tan_phi, res%c)
      else
         tan_phi = origin_fit(sig, tpk)
         res%c = 0.0_wp
      end if
      if (.not. tan_phi > 0.0_wp) then
         call input_error(error, 'the peaks give a friction angle <= 0 (tau_peak falls with '// &
            'sigma_n0): check the curves')
         return
      end if
      res%phi = atan(tan_phi)*DEG
      c_term = res%c/tan_phi
      if (.not. any([(res%tests(i)%turns, i=1, n)])) then
         call input_error(error, 'eps_n turns from contraction to dilation on none of the '// &
            'curves (closure-positive eps_n has no interior maximum): psi needs one')
         return
      end if
      tan_psi = origin_fit(pack(sig, [(res%tests(i)%turns, i=1, n)]), &
         pack([(res%tests(i)%tau_turn, i=1, n)], [(res%tests(i)%turns, i=1, n)]))
      res%psi = atan(tan_psi)*DEG

      do i = 1, n
         res%tests(i)%phi = atan(res%tests(i)%tau_peak/sig(i))*DEG
         call hardening(curves(i), opt, tan_phi, c_term, res%tests(i), error)
         if (allocated(error)) return
         associate (t => res%tests(i))
            call fit_a_g(curves(i)%eps_t, curves(i)%tau, curves(i)%eps_n, t%sigma_n0, &
               t%g_secant, tan_psi, t%a_g, t%ag_rms)
         end associate
      end do

      res%g0 = mean([(res%tests(i)%g0, i=1, n)])
      res%k0_modulus = 2.0_wp*res%g0
      res%alpha = mean([(res%tests(i)%alpha, i=1, n)])
      res%beta = mean([(res%tests(i)%beta, i=1, n)])
      res%r0 = mean([(res%tests(i)%r0, i=1, n)])
      res%a = mean([(res%tests(i)%a, i=1, n)])
      res%b = mean([(res%tests(i)%b, i=1, n)])
      res%a_g = mean([(res%tests(i)%a_g, i=1, n)])
   end subroutine identify

   !> alpha, beta, R0, k0, gamma, A, B of one test (see the module header).
   subroutine hardening(cv, opt, tan_phi, c_term, t, error)
      type(test_curve_t), intent(in) :: cv
      type(identify_options_t), intent(in) :: opt
      real(wp), intent(in) :: tan_phi, c_term
      type(test_values_t), intent(inout) :: t
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: s, ratio, k_end, k0_new, e_end, h
      integer :: it

      t%r0 = opt%r0
      if (t%r0 < 0.0_wp) t%r0 = yield_stress(cv, t%g_secant, opt%r0_tol)/ &
         ((t%sigma_n0 + c_term)*tan_phi)
      ratio = t%tau_lim/t%tau_peak
      t%alpha = 1.0_wp
      if (opt%version == VERSION_IMPROVED) t%alpha = ratio
      t%beta = beta_from_slope(t%alpha, tan_phi, t%g0, t%sigma_n0, c_term)
      if (t%asymptote) t%beta = t%beta_fit
      s = t%beta*t%sigma_n0/PA
      t%a = 0.0_wp
      t%b = 0.0_wp
      if (opt%version == VERSION_INITIAL) then
         call k0_from_r0(t%r0, 1.0_wp, s, 0.0_wp, 0.0_wp, t%k0, error)
         if (allocated(error)) error%message = cv%file//': '//error%message
         t%gamma = t%k0 + t%eps_peak - t%tau_peak/t%g_secant
         return
      end if
      e_end = cv%eps_t(size(cv%eps_t))
      t%k0 = 0.0_wp
      if (t%alpha > t%r0) t%k0 = t%r0*s/(t%alpha - t%r0)
      do it = 1, 200
         if (opt%total_gamma) then
            t%gamma = t%eps_peak
         else
            t%gamma = t%k0 + t%eps_peak - t%tau_peak/t%g_secant
         end if
         call ab_from_peak(t%gamma, t%alpha, s, t%a, t%b, error)
         if (allocated(error)) exit
         if (opt%refine_alpha) then
            ! R_m(k_end)/R_m(gamma) = tau_lim/tau_peak with R_m(gamma) = 1, solved for alpha
            k_end = t%k0 + e_end - t%tau_lim/t%g_secant
            h = k_end/(s + k_end)
            t%alpha = (ratio - t%a*k_end**2*exp(-t%b*k_end))/h
            t%beta = beta_from_slope(t%alpha, tan_phi, t%g0, t%sigma_n0, c_term)
            s = t%beta*t%sigma_n0/PA
         end if
         call k0_from_r0(t%r0, t%alpha, s, t%a, t%b, k0_new, error, gamma=t%gamma)
         if (allocated(error)) exit
         if (abs(k0_new - t%k0) <= 1.0e-13_wp*t%gamma .and. it > 2) exit
         t%k0 = k0_new
      end do
      if (allocated(error)) error%message = cv%file//': '//error%message
   end subroutine hardening

   !> Initial version without a peak: on CNL, tau = T k/(s + k) with k = k0 + p and
   !> p = eps_t - tau/G the plastic displacement, i.e. the hyperbola tau = T (p + k0)/(p + s +
   !> k0), fitted on the clearly plastic points (p > 5 % of its largest value). Its asymptote
   !> T = tan(phi)(sigma_n0 + C) stands for tau_peak (the curve has not reached it) and
   !> s = beta sigma_n0/P_a gives beta: the thesis's own beta of table III.1 (9 mm) is not the
   !> (III.18) value (2.2 mm), so it was fitted too.
   subroutine asymptote(cv, t, error)
      type(test_curve_t), intent(in) :: cv
      type(test_values_t), intent(inout) :: t
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: p(size(cv%eps_t)), tt, k0, s1
      logical :: use(size(cv%eps_t)), ok
      p = cv%eps_t - cv%tau/t%g_secant
      use = p > 0.05_wp*maxval(p) .and. cv%tau > 0.0_wp
      ok = count(use) >= 5
      if (ok) call hyperbola_fit(pack(p, use), pack(cv%tau, use), tt, k0, s1, ok)
      if (ok) ok = s1 > k0 .and. k0 >= 0.0_wp .and. tt > t%tau_peak
      if (.not. ok) then
         call input_error(error, cv%file//': tau still rises at the end of the curve and '// &
            'no hyperbola tau = T k/(s + k) fits it: cannot place the strength')
         return
      end if
      t%asymptote = .true.
      t%tau_peak = tt
      t%beta_fit = (s1 - k0)*PA/t%sigma_n0
   end subroutine asymptote

   !> tau at the end of the straight start of the curve (the yield point of R0). The
   !> relative deviation from the secant line, d = 1 - tau/(G eps_t) = eps_p/eps_t, is 0 on
   !> the straight part; past the kink the plastic part eps_p = eps_t - tau/G grows about
   !> linearly: a line fitted to eps_p over the first points with tol < d <= 4 tol (the
   !> first past the kink that noise of size < tol cannot fake) is extrapolated to
   !> eps_p = 0. Fallback: the last point with d <= tol.
   pure real(wp) function yield_stress(cv, g, tol) result(ty)
      type(test_curve_t), intent(in) :: cv
      real(wp), intent(in) :: g, tol
      real(wp) :: d(size(cv%eps_t)), slope, intercept, ey
      logical :: band(size(cv%eps_t))
      integer :: i, first
      ty = 0.0_wp
      d = 0.0_wp
      first = 0
      do i = 1, size(cv%eps_t)
         if (.not. cv%eps_t(i) > 0.0_wp) cycle
         d(i) = 1.0_wp - cv%tau(i)/(g*cv%eps_t(i))
         if (d(i) > tol .and. ty > 0.0_wp) then
            first = i
            exit
         end if
         ty = cv%tau(i)
      end do
      if (first == 0) return
      band = .false.
      do i = first, size(cv%eps_t)
         d(i) = 1.0_wp - cv%tau(i)/(g*cv%eps_t(i))
         if (d(i) > 4.0_wp*tol) exit
         band(i) = d(i) > tol
      end do
      if (count(band) < 2) return
      call line_fit(pack(cv%eps_t, band), pack(d*cv%eps_t, band), slope, intercept)
      if (.not. slope > 0.0_wp) return
      ey = -intercept/slope
      if (ey > 0.0_wp .and. ey <= cv%eps_t(first)) ty = g*ey
   end function yield_stress

   pure real(wp) function mean(x)
      real(wp), intent(in) :: x(:)
      mean = sum(x)/size(x)
   end function mean

end module pecplas_studies_identify_method
