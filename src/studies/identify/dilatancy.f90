!> Fit of MODJOIN's a_g on a CNL curve (thesis §III.3.1: a_g "obtained by successive
!> approximations" after the other parameters). Under constant sigma_n the normal
!> displacement is plastic only and the flow rule (III.9–III.11) gives, with dp = d eps_t^p,
!>
!>     d eps_n / dp = (tan(psi) - |tau| / sigma_n) exp(-a_g p),
!>
!> where p = eps_t - tau/G is the plastic slip since the start of loading (= k - k0, the law's
!> damping variable, doc/theory.md §6.4), so the measured tau(eps_t) predicts eps_n for any
!> a_g by quadrature, without the law:
!> a_g minimises the squared misfit to the measured eps_n (a scan, then golden section).
module pecplas_studies_identify_dilatancy
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: predicted_eps_n, fit_a_g

   !> Range scanned for a_g (1/mm) and the scan step.
   real(wp), parameter :: AG_MAX = 10.0_wp, AG_STEP = 0.05_wp

contains

   !> eps_n(eps_t) predicted on a CNL curve by the flow rule (trapezoidal in k; the plastic
   !> displacement p = eps_t - tau/G is kept non-decreasing, so noise in the elastic range
   !> adds no spurious flow).
   pure subroutine predicted_eps_n(eps_t, tau, sigma_n0, g, tan_psi, a_g, eps_n)
      real(wp), intent(in) :: eps_t(:), tau(:), sigma_n0, g, tan_psi, a_g
      real(wp), intent(out) :: eps_n(:)
      real(wp) :: p_old, p, f_old, f
      integer :: i
      eps_n(1) = 0.0_wp
      p_old = max(0.0_wp, eps_t(1) - tau(1)/g)
      f_old = rate(tau(1), p_old)
      do i = 2, size(eps_t)
         p = max(p_old, eps_t(i) - tau(i)/g)
         f = rate(tau(i), p)
         eps_n(i) = eps_n(i - 1) + 0.5_wp*(f + f_old)*(p - p_old)
         p_old = p
         f_old = f
      end do
   contains
      pure real(wp) function rate(t, pl)
         real(wp), intent(in) :: t, pl
         rate = (tan_psi - abs(t)/sigma_n0)*exp(-a_g*pl)
      end function rate
   end subroutine predicted_eps_n

   !> a_g in [0, AG_MAX] minimising sum (predicted - measured eps_n)^2; `rms` = the root
   !> mean square misfit at the optimum (mm). eps_n is measured from the first point.
   pure subroutine fit_a_g(eps_t, tau, eps_n, sigma_n0, g, tan_psi, a_g, rms)
      real(wp), intent(in) :: eps_t(:), tau(:), eps_n(:), sigma_n0, g, tan_psi
      real(wp), intent(out) :: a_g, rms
      real(wp), parameter :: GOLD = 0.6180339887498949_wp
      real(wp) :: lo, hi, x1, x2, f1, f2, best, fbest, x
      integer :: i, n
      n = nint(AG_MAX/AG_STEP)
      best = 0.0_wp
      fbest = huge(1.0_wp)
      do i = 0, n
         x = i*AG_STEP
         f1 = misfit(x)
         if (f1 < fbest) then
            best = x
            fbest = f1
         end if
      end do
      lo = max(0.0_wp, best - AG_STEP)
      hi = min(AG_MAX, best + AG_STEP)
      x1 = hi - GOLD*(hi - lo)
      x2 = lo + GOLD*(hi - lo)
      f1 = misfit(x1)
      f2 = misfit(x2)
      do i = 1, 80
         if (f1 <= f2) then
            hi = x2
            x2 = x1
            f2 = f1
            x1 = hi - GOLD*(hi - lo)
            f1 = misfit(x1)
         else
            lo = x1
            x1 = x2
            f1 = f2
            x2 = lo + GOLD*(hi - lo)
            f2 = misfit(x2)
         end if
         if (hi - lo <= 1.0e-12_wp) exit
      end do
      a_g = 0.5_wp*(lo + hi)
      if (misfit(a_g) > fbest) a_g = best
      rms = sqrt(misfit(a_g)/size(eps_n))
   contains
      pure real(wp) function misfit(ag)
         real(wp), intent(in) :: ag
         real(wp) :: pred(size(eps_t))
         call predicted_eps_n(eps_t, tau, sigma_n0, g, tan_psi, ag, pred)
         misfit = sum((pred - (eps_n - eps_n(1)))**2)
      end function misfit
   end subroutine fit_a_g

end module pecplas_studies_identify_dilatancy
