!> Drucker–Prager return map at one point (c = 10, phi = 30 deg, psi = 10 or 30 deg,
!> E = 1e4, NU = 0.3): elastic range, returned stress on the cone, plastic strain along
!> dg/dsigma, apex, consistent tangent against central differences for the three matchings,
!> symmetry for psi = phi, and the matched cones through Mohr–Coulomb's meridians.
module test_massif_plasticity_dp
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_massif_materials_type, only: NCOMP
   use pecplas_massif_materials_drucker_prager, only: drucker_prager_t
   use pecplas_massif_materials_soil, only: RETURN_ELASTIC, RETURN_SMOOTH, RETURN_APEX
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_plasticity, only: E, NU, COH, dp, rotated_stress, compliance, fd_tangent, &
      rel_diff, mc_strength
   implicit none (type, external)
   private
   public :: collect_massif_plasticity_dp

   real(wp), parameter :: THETA = 0.3_wp
   real(wp), parameter :: SIG0(NCOMP) = [-50.0_wp, -50.0_wp, -50.0_wp, 0.0_wp]
   !> Trial principal values (a, b, z) beyond the cone: compression-like, extension-like,
   !> plane shear.
   real(wp), parameter :: TRIALS(3, 3) = reshape([0.0_wp, -150.0_wp, -70.0_wp, &
      -30.0_wp, -200.0_wp, -32.0_wp, 20.0_wp, -120.0_wp, -50.0_wp], [3, 3])

contains

   subroutine collect_massif_plasticity_dp(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('elastic_range', test_elastic), &
               new_unittest('cone_return_and_flow', test_cone), &
               new_unittest('apex_return', test_apex), &
               new_unittest('tangent_central_differences', test_tangent), &
               new_unittest('tangent_symmetric_iff_associated', test_symmetry), &
               new_unittest('cones_through_meridians', test_meridians)]
   end subroutine collect_massif_plasticity_dp

   pure function increment_to(v) result(deps)
      real(wp), intent(in) :: v(3)
      real(wp) :: deps(NCOMP)
      deps = compliance(rotated_stress(v, THETA) - SIG0)
   end function increment_to

   !> Inside the cone: stress SIG0 + De deps with De from E, NU (Lame form), no history.
   subroutine test_elastic(error)
      type(error_t), allocatable, intent(out) :: error
      type(drucker_prager_t) :: mat
      real(wp) :: deps(NCOMP), s(NCOMP), d(NCOMP, NCOMP), st(6), expected(NCOMP)
      mat = dp(30.0_wp, 10.0_wp, 3)
      deps = increment_to([-40.0_wp, -70.0_wp, -55.0_wp])
      st = 0.0_wp
      call mat%update(SIG0, deps, st, s, d, error)
      if (allocated(error)) return
      ! the increment was built with the compliance: the stress is the chosen trial
      expected = rotated_stress([-40.0_wp, -70.0_wp, -55.0_wp], THETA)
      call check(error, maxval(abs(s - expected)) <= 1.0e-12_wp*70.0_wp .and. &
         nint(st(6)) == RETURN_ELASTIC .and. all(st(1:5) == 0.0_wp) .and. &
         abs(d(1, 1) - E*(1.0_wp - NU)/((1.0_wp + NU)*(1.0_wp - 2.0_wp*NU))) <= 1.0e-12_wp*E &
         .and. abs(d(4, 4) - E/(2.0_wp*(1.0_wp + NU))) <= 1.0e-12_wp*E, &
         'elastic range: Hooke, no plastic strain')
   end subroutine test_elastic

   !> f = 0 after the return (1e-10 of the stress), and the plastic strain increment is
   !> parallel to dg/dsigma = s/(2 sqrt(J2)) + etabar/3 I at the returned stress.
   subroutine test_cone(error)
      type(error_t), allocatable, intent(out) :: error
      type(drucker_prager_t) :: mat
      real(wp) :: s(NCOMP), d(NCOMP, NCOMP), st(6), dev(NCOMP), flow(NCOMP), j2
      integer :: i, match
      do match = 1, 3
         mat = dp(30.0_wp, 10.0_wp, match)
         do i = 1, size(TRIALS, 2)
            st = 0.0_wp
            call mat%update(SIG0, increment_to(TRIALS(:, i)), st, s, d, error)
            if (allocated(error)) return
            call check(error, nint(st(6)) == RETURN_SMOOTH, 'cone return expected')
            if (allocated(error)) return
            call check_close(error, mat%yield(s), 0.0_wp, 0.0_wp, 'f = 0 on the cone', &
               atol=1.0e-10_wp*maxval(abs(s)))
            if (allocated(error)) return
            dev = s - sum(s(1:3))/3.0_wp*[1.0_wp, 1.0_wp, 1.0_wp, 0.0_wp]
            j2 = sqrt(0.5_wp*(sum(dev(1:3)**2) + 2.0_wp*dev(4)**2))
            flow = dev/(2.0_wp*j2) + mat%etabar/3.0_wp*[1.0_wp, 1.0_wp, 1.0_wp, 0.0_wp]
            flow(4) = 2.0_wp*flow(4) ! engineering shear strain
            call check(error, norm2(st(1:4) - dot_product(st(1:4), flow)/ &
               dot_product(flow, flow)*flow) <= 1.0e-10_wp*norm2(st(1:4)) .and. &
               dot_product(st(1:4), flow) > 0.0_wp, 'plastic strain along dg/dsigma')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_cone

   !> Beyond the apex p = xi c / eta: stress at the apex, tangent 0 like its differences.
   subroutine test_apex(error)
      type(error_t), allocatable, intent(out) :: error
      type(drucker_prager_t) :: mat
      real(wp) :: s(NCOMP), d(NCOMP, NCOMP), st(6), deps(NCOMP), apex
      integer :: k
      deps = increment_to([30.0_wp, 25.0_wp, 28.0_wp])
      do k = 1, 2
         mat = dp(30.0_wp, merge(10.0_wp, 30.0_wp, k == 1), 3)
         apex = mat%xi*COH/mat%eta
         st = 0.0_wp
         call mat%update(SIG0, deps, st, s, d, error)
         if (allocated(error)) return
         call check(error, maxval(abs(s - [apex, apex, apex, 0.0_wp])) <= 1.0e-12_wp*apex &
            .and. nint(st(6)) == RETURN_APEX .and. all(d == 0.0_wp) .and. &
            maxval(abs(fd_tangent(mat, SIG0, deps, 1.0e-6_wp))) <= 1.0e-6_wp, &
            'apex: stress xi c/eta, tangent and its differences 0')
         if (allocated(error)) return
      end do
   end subroutine test_apex

   !> Tangent = central differences (step 1e-6, relative error < 1e-6): every matching,
   !> psi = 10 and 30 degrees, every trial.
   subroutine test_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      type(drucker_prager_t) :: mat
      real(wp) :: s(NCOMP), d(NCOMP, NCOMP), st(6), deps(NCOMP), err
      integer :: i, k, match
      character(len=80) :: buf
      do match = 1, 3
         do k = 1, 2
            mat = dp(30.0_wp, merge(10.0_wp, 30.0_wp, k == 1), match)
            do i = 1, size(TRIALS, 2)
               deps = increment_to(TRIALS(:, i))
               st = 0.0_wp
               call mat%update(SIG0, deps, st, s, d, error)
               if (allocated(error)) return
               err = rel_diff(d, fd_tangent(mat, SIG0, deps, 1.0e-6_wp))
               write (buf, '(a,i0,a,i0,a,i0,a,es9.2)') 'match ', match, ' psi set ', k, &
                  ' trial ', i, ': error ', err
               call check(error, err < 1.0e-6_wp, trim(buf))
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_tangent

   !> psi = phi: symmetric tangent (1e-12); psi < phi: not (> 1e-3); symmetric_tangent().
   subroutine test_symmetry(error)
      type(error_t), allocatable, intent(out) :: error
      type(drucker_prager_t) :: mat
      real(wp) :: s(NCOMP), d(NCOMP, NCOMP), st(6), asym
      integer :: k
      do k = 1, 2
         mat = dp(30.0_wp, merge(30.0_wp, 10.0_wp, k == 1), 3)
         st = 0.0_wp
         call mat%update(SIG0, increment_to(TRIALS(:, 1)), st, s, d, error)
         if (allocated(error)) return
         asym = rel_diff(d, transpose(d))
         if ((k == 1 .and. .not. asym < 1.0e-12_wp) .or. (k == 2 .and. .not. asym > 1.0e-3_wp) &
            .or. (mat%symmetric_tangent() .neqv. (k == 1))) then
            call fatal_error(error, 'tangent symmetric exactly when psi = phi')
            return
         end if
      end do
   end subroutine test_symmetry

   !> MATCH = 1 passes through Mohr–Coulomb's triaxial compression failure states
   !> (sigma_2 = sigma_3 = -p, sigma_1 = -(p N + 2 c sqrt N)), MATCH = 2 through its
   !> triaxial extension ones (sigma_1 = sigma_2 = -p, sigma_3 = -(p - 2 c sqrt N)/N):
   !> f = 0 to 1e-12 at p = 0, 50, 200.
   subroutine test_meridians(error)
      type(error_t), allocatable, intent(out) :: error
      type(drucker_prager_t) :: outer, inner
      real(wp), parameter :: pressures(3) = [0.0_wp, 50.0_wp, 200.0_wp]
      real(wp) :: p, sc(NCOMP), se(NCOMP), n
      integer :: i
      outer = dp(30.0_wp, 10.0_wp, 1)
      inner = dp(30.0_wp, 10.0_wp, 2)
      n = 3.0_wp ! N_phi for 30 degrees
      do i = 1, 3
         p = pressures(i)
         sc = [-p, -mc_strength(p, COH, 30.0_wp), -p, 0.0_wp]
         se = [-p, -(p - 2.0_wp*COH*sqrt(n))/n, -p, 0.0_wp]
         call check(error, abs(outer%yield(sc)) <= 1.0e-12_wp*(p + COH) .and. &
            abs(inner%yield(se)) <= 1.0e-12_wp*(p + COH), &
            'matched cones through the Mohr-Coulomb meridians')
         if (allocated(error)) return
      end do
   end subroutine test_meridians

end module test_massif_plasticity_dp
