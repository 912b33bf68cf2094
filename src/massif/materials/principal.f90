!> Principal stresses of a 2D stress vector (xx, yy, zz, xy): zz is always a principal
!> stress (plane strain and axisymmetry), the in-plane part is a 2x2 symmetric tensor with
!> principal directions n_a = (c, s), n_b = (-s, c). Used by isotropic return maps that work
!> on principal values (Mohr–Coulomb): decompose the trial stress, return its principal
!> values, compose back in the same axes, and build the consistent tangent including the
!> rotation ("spin") of the axes.
module pecplas_massif_materials_principal
   use pecplas_base_kinds, only: wp
   use pecplas_massif_materials_type, only: NCOMP
   implicit none (type, external)
   private

   public :: principal_axes_t, principal_decompose, principal_compose, principal_tangent

   !> Principal axes of the in-plane part: cosine and sine of the angle of n_a to x.
   type :: principal_axes_t
      real(wp) :: c = 1.0_wp, s = 0.0_wp
   end type principal_axes_t

contains

   !> Principal values (a, b, z) of `stress`, a >= b; axes of the in-plane part. Equal
   !> in-plane values give the x, y axes.
   pure subroutine principal_decompose(stress, axes, values)
      real(wp), intent(in) :: stress(NCOMP)
      type(principal_axes_t), intent(out) :: axes
      real(wp), intent(out) :: values(3)
      real(wp) :: mean, half, radius, theta
      mean = 0.5_wp*(stress(1) + stress(2))
      half = 0.5_wp*(stress(1) - stress(2))
      radius = hypot(half, stress(4))
      values = [mean + radius, mean - radius, stress(3)]
      if (radius > 0.0_wp) then
         theta = 0.5_wp*atan2(stress(4), half)
         axes%c = cos(theta)
         axes%s = sin(theta)
      end if
   end subroutine principal_decompose

   !> Stress vector with principal values (a, b, z) along `axes`.
   pure function principal_compose(axes, values) result(stress)
      type(principal_axes_t), intent(in) :: axes
      real(wp), intent(in) :: values(3)
      real(wp) :: stress(NCOMP)
      associate (c => axes%c, s => axes%s)
         stress(1) = c*c*values(1) + s*s*values(2)
         stress(2) = s*s*values(1) + c*c*values(2)
         stress(3) = values(3)
         stress(4) = c*s*(values(1) - values(2))
      end associate
   end function principal_compose

   !> Derivative d stress / d trial (4x4, stress components) of an isotropic map
   !> trial -> stress that keeps the principal axes, given the trial and returned principal
   !> values (a, b, z) and `dvalues` = d values / d trial values (3x3). In the principal
   !> frame the normal components follow `dvalues` and the in-plane shear follows
   !> (sigma_a - sigma_b)/(trial_a - trial_b) (rotation of the axes); for equal trial values
   !> that ratio tends to the derivative of sigma_a - sigma_b along trial_a - trial_b.
   pure function principal_tangent(axes, trial, values, dvalues) result(dsig)
      type(principal_axes_t), intent(in) :: axes
      real(wp), intent(in) :: trial(3), values(3), dvalues(3, 3)
      real(wp) :: dsig(NCOMP, NCOMP)
      real(wp) :: q(NCOMP, NCOMP), qinv(NCOMP, NCOMP), m(NCOMP, NCOMP), gap, scale
      associate (c => axes%c, s => axes%s)
         ! q: (xx, yy, zz, xy) -> components (aa, bb, zz, ab) in the principal frame
         q = 0.0_wp
         q(1, :) = [c*c, s*s, 0.0_wp, 2.0_wp*c*s]
         q(2, :) = [s*s, c*c, 0.0_wp, -2.0_wp*c*s]
         q(3, 3) = 1.0_wp
         q(4, :) = [-c*s, c*s, 0.0_wp, c*c - s*s]
         qinv = 0.0_wp
         qinv(1, :) = [c*c, s*s, 0.0_wp, -2.0_wp*c*s]
         qinv(2, :) = [s*s, c*c, 0.0_wp, 2.0_wp*c*s]
         qinv(3, 3) = 1.0_wp
         qinv(4, :) = [c*s, -c*s, 0.0_wp, c*c - s*s]
      end associate
      m = 0.0_wp
      m(1:3, 1:3) = dvalues
      gap = trial(1) - trial(2)
      scale = maxval(abs(trial))
      if (gap > 1.0e-9_wp*scale) then
         m(4, 4) = (values(1) - values(2))/gap
      else
         m(4, 4) = 0.5_wp*(dvalues(1, 1) - dvalues(1, 2) - dvalues(2, 1) + dvalues(2, 2))
      end if
      dsig = matmul(qinv, matmul(m, q))
   end function principal_tangent

end module pecplas_massif_materials_principal
