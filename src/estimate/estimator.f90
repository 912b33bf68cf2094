!> A posteriori error estimate of the converged state (Zienkiewicz–Zhu): per massif element
!> eta_e^2 = int_e (sigma* - sigma_h) : C^-1 : (sigma* - sigma_h) dV, with sigma* the
!> patch-recovered stress (pecplas_estimate_recovery) and C^-1 the elastic compliance of the
!> set's material; dV carries the thickness (plane strain) or 2 pi r (axisymmetric), and
!> the four components (xx, yy, zz or hoop, xy) enter. The global estimate is
!> sqrt(sum eta_e^2) and `energy` the same norm of the FE stresses, sqrt(int sigma_h :
!> C^-1 : sigma_h dV). After plastic flow eta measures the discretisation error of the
!> stress field in the complementary-energy norm of the elastic compliance (doc/theory.md),
!> not a bound on the error of the plastic solution. An undrained set is measured as the
!> material it is assembled as: C^-1 of D' + (K_w/n) m m^T (pecplas_fe_water_stiffness) and
!> the stress that stiffness makes, sigma' - p_excess m (the steady pore pressure is a
!> prescribed field, no error of the displacements). The material is the set's in the
!> state's phase. Joint sets get the traction indicator of pecplas_estimate_joints.
module pecplas_estimate_estimator
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_problem_type, only: problem_t
   use pecplas_massif_materials_type, only: NCOMP
   use pecplas_massif_kinematics, only: massif_point_t, massif_gauss_point
   use pecplas_estimate_recovery, only: recover_set_stresses, solve_small
   use pecplas_estimate_type, only: eta_set_t, error_estimate_t
   use pecplas_estimate_joints, only: joint_indicators
   use pecplas_fe_state, only: set_material
   use pecplas_fe_water_stiffness, only: set_elastic_tangent
   implicit none (type, external)
   private

   public :: eta_set_t, error_estimate_t, estimate_error, set_compliance


contains

   !> Estimate of the converged state held in problem%state.
   subroutine estimate_error(model, problem, est, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      type(error_estimate_t), intent(out) :: est
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: gx(:, :, :), dvol(:, :), sstar(:, :), sig(:, :, :)
      logical, allocatable :: have(:)
      real(wp) :: cinv(NCOMP, NCOMP), d(NCOMP), eta2, en2, s(NCOMP)
      type(massif_point_t) :: pt
      integer :: is, e, g, nen, nel, ng, nvert, m, k

      allocate (est%sets(size(model%mesh%esets)))
      eta2 = 0.0_wp; en2 = 0.0_wp
      do is = 1, size(model%mesh%esets)
         associate (set => model%mesh%esets(is), st => problem%state%sets(is), &
                    rule => problem%system%rules(is))
            nen = size(set%conn, 1); nel = size(set%conn, 2); ng = st%ngauss
            nvert = merge(3, 4, set%etype(1:1) == 'T')
            m = set_material(model, is, st)
            call set_compliance(model, is, m, cinv, error)
            if (allocated(error)) return
            ! the stress of the assembled stiffness: an undrained set's less its excess pore
            ! pressure (sigma' - p_excess m, p positive in compression)
            sig = st%stress
            if (model%water%kwn(is, m) > 0.0_wp .and. st%pore%on()) then
               do k = 1, 3
                  sig(k, :, :) = sig(k, :, :) - st%pore%excess
               end do
            end if
            allocate (gx(2, ng, nel), dvol(ng, nel))
            do e = 1, nel
               do g = 1, ng
                  call massif_gauss_point(rule, g, model%analysis%kind, &
                     model%analysis%thickness, model%mesh%x(:, set%conn(:, e)), pt, error)
                  if (allocated(error)) return
                  gx(:, g, e) = pt%x
                  dvol(g, e) = pt%dvol
               end do
            end do
            allocate (sstar(NCOMP, model%mesh%nnode()))
            call recover_set_stresses(model%mesh%x, set%conn, nvert, gx, sig, sstar, have)
            allocate (est%sets(is)%eta(nel), source=0.0_wp)
            do e = 1, nel
               do g = 1, ng
                  s = sig(:, g, e)
                  d = matmul(sstar(:, set%conn(:, e)), rule%n(:, g)) - s
                  est%sets(is)%eta(e) = est%sets(is)%eta(e) + dot_product(d, matmul(cinv, d))*dvol(g, e)
                  en2 = en2 + dot_product(s, matmul(cinv, s))*dvol(g, e)
               end do
            end do
            eta2 = eta2 + sum(est%sets(is)%eta)
            est%sets(is)%eta = sqrt(max(est%sets(is)%eta, 0.0_wp))
            deallocate (gx, dvol, sstar)
         end associate
      end do
      est%eta = sqrt(max(eta2, 0.0_wp))
      est%energy = sqrt(max(en2, 0.0_wp))
      call joint_indicators(model, problem%state%joints, est%joints, error)
      if (allocated(error)) return
      if (.not. (ieee_finite(est%eta) .and. ieee_finite(est%energy))) &
         call fatal_error(error, 'error estimate: non-finite value (stresses not finite)')
   contains
      pure logical function ieee_finite(v)
         real(wp), intent(in) :: v
         ieee_finite = v == v .and. abs(v) <= huge(v)
      end function ieee_finite
   end subroutine estimate_error

   !> Elastic compliance C^-1 (NCOMP x NCOMP, engineering shear) of element set is made of
   !> material m: the inverse of its assembled elastic stiffness (with the pore water's in an
   !> undrained set).
   subroutine set_compliance(model, is, m, cinv, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: is, m
      real(wp), intent(out) :: cinv(NCOMP, NCOMP)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: dmat(NCOMP, NCOMP)
      logical :: ok
      integer :: k
      call set_elastic_tangent(model, is, m, dmat)
      cinv = 0.0_wp
      do k = 1, NCOMP
         cinv(k, k) = 1.0_wp
      end do
      call solve_small(dmat, cinv, ok)
      if (.not. ok) call fatal_error(error, 'error estimate: elastic tangent of set '// &
         model%mesh%esets(is)%name//' is singular')
   end subroutine set_compliance

end module pecplas_estimate_estimator
