!> MODJOIN's monotonic CNL response in closed form (up to one quadrature), an oracle
!> independent of the law's return mapping. Under constant sigma_n (kPa, mm):
!> G = G0 (initial) or G0 (sigma_n0/P_a)^0.5 (improved) is constant; the response is elastic
!> up to tau_y = tan(phi) (sigma_n0 + C) R0; then the consistency condition keeps
!> tau = tan(phi) (sigma_n0 + C) R_m(k), with dk = d eps_t^p, so that
!>
!>     eps_t(k) = tau(k)/G + k - k0,
!>     eps_n(k) = int_k0^k (tan(psi) - tau(k')/sigma_n0) exp(-a_g (k' - k0)) dk'   (III.9–III.11),
!>
!> eps_n closure positive (dilation < 0). Each eps_t is inverted for k by bisection (the path
!> is monotonic in k while 1 + tan(phi)(sigma_n0 + C) R_m'(k)/G > 0: no snap-back), and
!> eps_n integrated with 5-point Gauss–Legendre on each step.
module pecplas_studies_identify_analytic_cnl
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error
   use pecplas_studies_identify_closed_forms, only: PA, rm_value, rm_slope, k0_from_r0
   implicit none (type, external)
   private

   public :: modjoin_set_t, analytic_cnl

   real(wp), parameter :: RAD = acos(-1.0_wp)/180.0_wp

   !> A MODJOIN parameter set (kPa, mm, degrees); `improved` selects (III.15)'s elasticity.
   type :: modjoin_set_t
      real(wp) :: k0_modulus = 80, g0 = 40, phi = 41, c = 0, r0 = 0.3, beta = 1.5
      real(wp) :: alpha = 0.7, a = 0.6, b = 0.96, psi = 27, a_g = 0.4
      logical :: improved = .true.
   end type modjoin_set_t

contains

   !> tau and eps_n at the given eps_t (increasing, from 0) of a CNL test at sigma_n0.
   subroutine analytic_cnl(p, sigma_n0, eps_t, tau, eps_n, error)
      type(modjoin_set_t), intent(in) :: p
      real(wp), intent(in) :: sigma_n0, eps_t(:)
      real(wp), intent(out) :: tau(:), eps_n(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: XG(5) = [-0.9061798459386640_wp, -0.5384693101056831_wp, 0.0_wp, &
         0.5384693101056831_wp, 0.9061798459386640_wp]
      real(wp), parameter :: WG(5) = [0.2369268850561891_wp, 0.4786286704993665_wp, &
         0.5688888888888889_wp, 0.4786286704993665_wp, 0.2369268850561891_wp]
      real(wp) :: g, s, k0, tmf, ey, k, k_old, lo, hi, mid, kk, h
      integer :: i, j, it

      g = p%g0
      if (p%improved) g = p%g0*sqrt(sigma_n0/PA)
      s = p%beta*sigma_n0/PA
      tmf = tan(p%phi*RAD)*(sigma_n0 + p%c/tan(p%phi*RAD))
      call k0_from_r0(p%r0, p%alpha, s, p%a, p%b, k0, error)
      if (allocated(error)) return
      ey = tmf*p%r0/g
      k_old = k0
      do i = 1, size(eps_t)
         if (eps_t(i) <= ey) then
            tau(i) = g*eps_t(i)
            eps_n(i) = 0.0_wp
            cycle
         end if
         ! eps_t(k) = tmf R_m(k)/G + k - k0 increases from ey at k0: bracket, then bisect
         lo = k_old
         hi = max(k_old, k0) + (eps_t(i) - ey) + 1.0e-3_wp
         do while (branch(hi) < eps_t(i))
            hi = hi + (eps_t(i) - ey) + 1.0e-3_wp
         end do
         do it = 1, 200
            mid = 0.5_wp*(lo + hi)
            if (branch(mid) < eps_t(i)) then
               lo = mid
            else
               hi = mid
            end if
            if (hi - lo <= 1.0e-15_wp*hi) exit
         end do
         k = 0.5_wp*(lo + hi)
         if (1.0_wp + tmf*rm_slope(k, p%alpha, s, p%a, p%b)/g <= 0.0_wp) then
            call input_error(error, 'analytic CNL: the softening is steeper than the '// &
               'elasticity (snap-back): no strain-driven path')
            return
         end if
         tau(i) = tmf*rm_value(k, p%alpha, s, p%a, p%b)
         h = 0.5_wp*(k - k_old)
         eps_n(i) = 0.0_wp
         if (i > 1) eps_n(i) = eps_n(i - 1)
         do j = 1, 5
            kk = 0.5_wp*(k + k_old) + h*XG(j)
            eps_n(i) = eps_n(i) + h*WG(j)*(tan(p%psi*RAD) - &
               tmf*rm_value(kk, p%alpha, s, p%a, p%b)/sigma_n0)*exp(-p%a_g*(kk - k0))
         end do
         k_old = k
      end do
   contains
      real(wp) function branch(kv)
         real(wp), intent(in) :: kv
         branch = tmf*rm_value(kv, p%alpha, s, p%a, p%b)/g + kv - k0
      end function branch
   end subroutine analytic_cnl

end module pecplas_studies_identify_analytic_cnl
