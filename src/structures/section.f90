!> Section law of a plate: resultants s = (N_s, Q, M_s, N_theta, M_theta) per unit width (or
!> per unit length of circumference) from the generalized strains of pecplas_structures_beam.
!> Elastic: A = EA/(1-nu^2), D = EI/(1-nu^2), shear 5 EA/(12 (1+nu)); in plane strain
!> N = A eps, Q = GAs gamma, M = D kappa; in axisymmetry the meridional and hoop resultants
!> couple through nu (N_s = A (eps_s + nu eps_theta), M_s = D (kappa_s + nu kappa_theta), ...).
!> Elastoplastic (plane strain, Np or Mp given): the interaction f = (N/Np)^2 + (M/Mp)^2 - 1
!> <= 0 (an absent limit drops its term), associated flow on the plastic axial strain and
!> curvature, perfectly plastic, closest-point return and its consistent tangent; the shear
!> force stays elastic.
module pecplas_structures_section
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_plates, only: plate_section_t
   use pecplas_structures_beam, only: NGEN, shear_stiffness
   implicit none (type, external)
   private

   public :: NHIST, section_elastic, section_update

   !> History per point: plastic axial strain, plastic curvature, accumulated multiplier.
   integer, parameter :: NHIST = 3

contains

   !> Elastic section matrix C (NGEN, NGEN).
   pure subroutine section_elastic(section, axisym, c)
      type(plate_section_t), intent(in) :: section
      logical, intent(in) :: axisym
      real(wp), intent(out) :: c(NGEN, NGEN)
      real(wp) :: a, d, nu
      nu = section%nu
      a = section%ea/(1.0_wp - nu**2)
      d = section%ei/(1.0_wp - nu**2)
      c = 0.0_wp
      c(1, 1) = a
      c(2, 2) = shear_stiffness(section)
      c(3, 3) = d
      if (axisym) then
         c(1, 4) = nu*a
         c(4, 1) = nu*a
         c(4, 4) = a
         c(3, 5) = nu*d
         c(5, 3) = nu*d
         c(5, 5) = d
      end if
   end subroutine section_elastic

   !> Resultants s from the converged s0 and the strain increment de, history from hist0,
   !> and the consistent tangent c.
   subroutine section_update(section, axisym, s0, de, hist0, s, hist, c, error)
      type(plate_section_t), intent(in) :: section
      logical, intent(in) :: axisym
      real(wp), intent(in) :: s0(NGEN), de(NGEN), hist0(NHIST)
      real(wp), intent(out) :: s(NGEN), hist(NHIST), c(NGEN, NGEN)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: ce(NGEN, NGEN), ia, id, a, d, nt, mt, dl, g, dg, fn, fm, xi(2), v(2)
      integer :: it
      call section_elastic(section, axisym, ce)
      s = s0 + matmul(ce, de)
      hist = hist0
      c = ce
      if (axisym .or. .not. section%plastic()) return
      ia = 0.0_wp
      id = 0.0_wp
      if (section%np > 0.0_wp) ia = 1.0_wp/section%np**2
      if (section%mp > 0.0_wp) id = 1.0_wp/section%mp**2
      nt = s(1)
      mt = s(3)
      if (ia*nt**2 + id*mt**2 <= 1.0_wp) return
      a = ce(1, 1)
      d = ce(3, 3)
      ! N = nt / (1 + 2 dl a ia), M = mt / (1 + 2 dl d id); f(dl) = 0 by Newton (f convex
      ! and decreasing in dl: the iterates rise monotonically to the root)
      dl = 0.0_wp
      do it = 1, 100
         fn = nt/(1.0_wp + 2.0_wp*dl*a*ia)
         fm = mt/(1.0_wp + 2.0_wp*dl*d*id)
         g = ia*fn**2 + id*fm**2 - 1.0_wp
         if (abs(g) <= 1.0e-14_wp) exit
         dg = -4.0_wp*(ia**2*a*fn**2/(1.0_wp + 2.0_wp*dl*a*ia) + &
            id**2*d*fm**2/(1.0_wp + 2.0_wp*dl*d*id))
         dl = dl - g/dg
      end do
      if (abs(g) > 1.0e-10_wp) then
         call fatal_error(error, 'plate section return did not converge')
         return
      end if
      s(1) = fn
      s(3) = fm
      hist(1) = hist0(1) + 2.0_wp*dl*ia*fn
      hist(2) = hist0(2) + 2.0_wp*dl*id*fm
      hist(3) = hist0(3) + dl
      ! consistent tangent on (N, M): Xi - (Xi n)(Xi n)^T / (n^T Xi n), Xi = (C^-1 + dl f'')^-1
      xi = [1.0_wp/(1.0_wp/a + 2.0_wp*dl*ia), 1.0_wp/(1.0_wp/d + 2.0_wp*dl*id)]
      v = xi*[2.0_wp*ia*fn, 2.0_wp*id*fm]
      c(1, 1) = xi(1) - v(1)*v(1)/dot_product(v, [2.0_wp*ia*fn, 2.0_wp*id*fm])
      c(3, 3) = xi(2) - v(2)*v(2)/dot_product(v, [2.0_wp*ia*fn, 2.0_wp*id*fm])
      c(1, 3) = -v(1)*v(2)/dot_product(v, [2.0_wp*ia*fn, 2.0_wp*id*fm])
      c(3, 1) = c(1, 3)
   end subroutine section_update

end module pecplas_structures_section
