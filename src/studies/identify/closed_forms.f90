!> Closed forms of MODJOIN's hardening function and of its identification (thesis §III.3.1,
!> doc/theory.md §6.4), in kPa and mm:
!>
!>     R_m(k) = alpha k / (s + k) + A k^2 exp(-B k),      s = beta sigma_n0 / P_a   (III.16)
!>
!> (III.5, the initial version: alpha = 1, A = 0). Identification: beta from the initial slope
!> (III.18), A and B from R_m(gamma) = 1 and dR_m/dk(gamma) = 0 at the hardening variable
!> gamma of the peak (III.19 with the correction of doc/theory.md; closed form III.20), and the
!> starting value k0 of the hardening variable from R_m(k0) = R0 (III.6 generalised).
module pecplas_studies_identify_closed_forms
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error
   implicit none (type, external)
   private

   public :: PA, rm_value, rm_slope, beta_from_slope, ab_from_peak, k0_from_r0

   !> Atmospheric pressure P_a (kPa), the reference stress of (III.5), (III.15), (III.16).
   real(wp), parameter :: PA = 100.0_wp

contains

   !> R_m(k) of (III.16); s = beta sigma_n0 / P_a (mm).
   pure real(wp) function rm_value(k, alpha, s, a, b) result(r)
      real(wp), intent(in) :: k, alpha, s, a, b
      r = alpha*k/(s + k) + a*k*k*exp(-b*k)
   end function rm_value

   !> dR_m/dk of (III.16).
   pure real(wp) function rm_slope(k, alpha, s, a, b) result(d)
      real(wp), intent(in) :: k, alpha, s, a, b
      d = alpha*s/(s + k)**2 + a*exp(-b*k)*k*(2.0_wp - b*k)
   end function rm_slope

   !> beta from (III.18): the initial slope alpha / s of R_m equals that of the normalised
   !> shear curve, G0 / ((sigma_n0 + C) tan(phi)), so
   !> beta = alpha tan(phi) (sigma_n0 + C) P_a / (G0 sigma_n0)  (= alpha tan(phi) P_a / G0
   !> for c = 0, the thesis's form; C = c cot(phi)). As the thesis, G0 (not the improved
   !> version's G0 (sigma_n0/P_a)^0.5) is the slope: beta is then the same for every test.
   pure real(wp) function beta_from_slope(alpha, tan_phi, g0, sigma_n0, c_term) result(beta)
      real(wp), intent(in) :: alpha, tan_phi, g0, sigma_n0, c_term
      beta = alpha*tan_phi*(sigma_n0 + c_term)*PA/(g0*sigma_n0)
   end function beta_from_slope

   !> A and B of (III.20) from R_m(gamma) = 1 and dR_m/dk(gamma) = 0: with
   !> h = alpha gamma/(s + gamma) (the hyperbola at the peak), the second condition gives
   !> A exp(-B gamma) = alpha s / ((s + gamma)^2 gamma (B gamma - 2)); the first then
   !>     B = 2/gamma + alpha s / ((s + gamma)^2 (1 - h)),
   !>     A = alpha s exp(B gamma) / ((B gamma - 2) gamma (s + gamma)^2).
   !> A peak needs h < 1 (the hyperbola alone below 1 at gamma) and gamma > 0.
   subroutine ab_from_peak(gamma, alpha, s, a, b, error)
      real(wp), intent(in) :: gamma, alpha, s
      real(wp), intent(out) :: a, b
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: h
      character(len=80) :: buf
      a = 0.0_wp
      b = 0.0_wp
      h = alpha*gamma/(s + gamma)
      if (.not. (gamma > 0.0_wp .and. s > 0.0_wp .and. h < 1.0_wp)) then
         write (buf, '(3(a,g0.5))') 'gamma = ', gamma, ', s = ', s, ', alpha gamma/(s+gamma) = ', h
         call input_error(error, '(III.20) has no solution with A > 0 ('//trim(buf)// &
            '): the peak must lie where the hyperbola alone is below 1')
         return
      end if
      b = 2.0_wp/gamma + alpha*s/((s + gamma)**2*(1.0_wp - h))
      a = alpha*s*exp(b*gamma)/((b*gamma - 2.0_wp)*gamma*(s + gamma)**2)
   end subroutine ab_from_peak

   !> k0 with R_m(k0) = R0 (III.6: k0 = R0 s / (1 - R0) for alpha = 1, A = 0). With A = 0,
   !> k0 = R0 s / (alpha - R0); otherwise bisection on (0, k_top], where R_m rises from 0
   !> (k_top = the peak gamma when given, else the first k past which R_m exceeds R0).
   subroutine k0_from_r0(r0, alpha, s, a, b, k0, error, gamma)
      real(wp), intent(in) :: r0, alpha, s, a, b
      real(wp), intent(out) :: k0
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: gamma
      real(wp) :: lo, hi, mid
      integer :: i
      k0 = 0.0_wp
      if (.not. (r0 >= 0.0_wp)) then
         call input_error(error, 'R0 must be >= 0')
         return
      end if
      if (a == 0.0_wp) then
         if (.not. (alpha > r0)) then
            call input_error(error, 'R0 >= alpha: the hyperbola never reaches R0')
            return
         end if
         k0 = r0*s/(alpha - r0)
         return
      end if
      lo = 0.0_wp
      if (present(gamma)) then
         hi = gamma
      else
         hi = max(s, 1.0e-3_wp)
         do i = 1, 200
            if (rm_value(hi, alpha, s, a, b) >= r0) exit
            hi = 1.5_wp*hi
         end do
      end if
      if (rm_value(hi, alpha, s, a, b) < r0) then
         call input_error(error, 'R_m never reaches R0 before the peak')
         return
      end if
      do i = 1, 200
         mid = 0.5_wp*(lo + hi)
         if (rm_value(mid, alpha, s, a, b) < r0) then
            lo = mid
         else
            hi = mid
         end if
         if (hi - lo <= 1.0e-15_wp*hi) exit
      end do
      k0 = 0.5_wp*(lo + hi)
   end subroutine k0_from_r0

end module pecplas_studies_identify_closed_forms
