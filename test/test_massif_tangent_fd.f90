!> Whole-element consistent tangents against central differences: for each massif element
!> (T3, T6, Q4, Q8, Q8R, a distorted shape; plane strain, and axisymmetric at radius 10 to 11
!> where the hoop strain u_r/r joins the in-plane ones) and each soil in a plastic state,
!> the element stiffness sum B^T D B dV of the points' consistent tangents D equals the
!> derivative of the element's internal forces sum B^T sigma(u) dV with respect to its nodal
!> displacements, every point integrated from the same converged stress with its strain of
!> u. States: Mohr–Coulomb (c = 10, phi = 30, psi = 10: non-associated, and psi = 30) on its
!> main plane, on an edge (two planes: a corner of the hexagon) and at the apex; Drucker–
!> Prager (plane-strain match, psi = 10 and 30) on the cone and at the apex. The displacement
!> is a homogeneous in-plane strain plus a small quadratic field (the points differ), and the
!> test first checks that every point of the element returned in the intended way.
!>
!> Tolerance: ||K - K_fd|| <= 1e-6 ||K_e|| (Frobenius norms, K_e the element's elastic
!> stiffness: the scale of the entries, also at the apex where K = 0). The central
!> difference with a step of 1e-6 on strains of ~1e-2 errs by (h/eps)^2 ~ 1e-8 in a smooth
!> regime, and round-off adds ~1e-16 |sigma|/(h E) ~ 1e-12; a wrong or missing term of a
!> tangent (the spin of the principal axes, a corner's second multiplier) is 1e-3 or more.
module test_massif_tangent_fd
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_factory, only: new_massif_element
   use pecplas_massif_kinematics, only: massif_rule_t, new_massif_rule
   use pecplas_massif_element_matrices, only: massif_stiffness, massif_internal_force, &
      massif_strains
   use pecplas_massif_materials_type, only: material_t, NCOMP
   use pecplas_massif_materials_soil, only: RETURN_SMOOTH, RETURN_EDGE, RETURN_APEX
   use pecplas_testing, only: unittest_t, new_unittest, check
   use fixtures_plasticity, only: mc, dp
   implicit none (type, external)
   private
   public :: collect_massif_tangent_fd

   !> Converged stress of every point (hydrostatic, inside both cones) and principal in-plane
   !> strains (a, b) of each state, axes at THETA from x: main plane or cone; edge (two planes,
   !> a corner of the hexagon: triaxial extension, sigma_b and sigma_zz returned together);
   !> apex (in-plane tension beyond c cot(phi)).
   real(wp), parameter :: SIG0(3) = [-50.0_wp, -200.0_wp, -50.0_wp]
   real(wp), parameter :: STRAINS(2, 3) = reshape([0.01_wp, -0.01_wp, &
      0.02_wp, 0.0002_wp, 0.012_wp, 0.01_wp], [2, 3])
   real(wp), parameter :: THETA = 0.3_wp, H = 1.0e-6_wp, TOL = 1.0e-6_wp
   !> Amplitude of the quadratic part of the displacement (relative to the strains).
   real(wp), parameter :: BEND = 0.02_wp
   !> Axisymmetric cases: radius of the element's origin.
   real(wp), parameter :: R_AXI = 10.0_wp

contains

   subroutine collect_massif_tangent_fd(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('t3', test_t3), new_unittest('t6', test_t6), &
               new_unittest('q4', test_q4), new_unittest('q8', test_q8), &
               new_unittest('q8r', test_q8r), new_unittest('t3_axi', test_t3_axi), &
               new_unittest('t6_axi', test_t6_axi), new_unittest('q4_axi', test_q4_axi), &
               new_unittest('q8_axi', test_q8_axi), new_unittest('q8r_axi', test_q8r_axi)]
   end subroutine collect_massif_tangent_fd

   subroutine test_t3_axi(error)
      type(error_t), allocatable, intent(out) :: error
      call every_state('T3', error, AXISYMMETRIC)
   end subroutine test_t3_axi

   subroutine test_t6_axi(error)
      type(error_t), allocatable, intent(out) :: error
      call every_state('T6', error, AXISYMMETRIC)
   end subroutine test_t6_axi

   subroutine test_q4_axi(error)
      type(error_t), allocatable, intent(out) :: error
      call every_state('Q4', error, AXISYMMETRIC)
   end subroutine test_q4_axi

   subroutine test_q8_axi(error)
      type(error_t), allocatable, intent(out) :: error
      call every_state('Q8', error, AXISYMMETRIC)
   end subroutine test_q8_axi

   subroutine test_q8r_axi(error)
      type(error_t), allocatable, intent(out) :: error
      call every_state('Q8R', error, AXISYMMETRIC)
   end subroutine test_q8r_axi

   subroutine test_t3(error)
      type(error_t), allocatable, intent(out) :: error
      call every_state('T3', error)
   end subroutine test_t3

   subroutine test_t6(error)
      type(error_t), allocatable, intent(out) :: error
      call every_state('T6', error)
   end subroutine test_t6

   subroutine test_q4(error)
      type(error_t), allocatable, intent(out) :: error
      call every_state('Q4', error)
   end subroutine test_q4

   subroutine test_q8(error)
      type(error_t), allocatable, intent(out) :: error
      call every_state('Q8', error)
   end subroutine test_q8

   subroutine test_q8r(error)
      type(error_t), allocatable, intent(out) :: error
      call every_state('Q8R', error)
   end subroutine test_q8r

   !> Mohr–Coulomb in its three states and Drucker–Prager in its two, psi = 10 and 30;
   !> `analysis` PLANE_STRAIN (default) or AXISYMMETRIC.
   subroutine every_state(name, error, analysis)
      character(len=*), intent(in) :: name
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: analysis
      real(wp) :: psi
      integer :: k, an
      an = PLANE_STRAIN
      if (present(analysis)) an = analysis
      do k = 1, 2
         psi = merge(10.0_wp, 30.0_wp, k == 1)
         call one_case(name, mc(30.0_wp, psi), 'Mohr-Coulomb', 1, RETURN_SMOOTH, an, error)
         if (allocated(error)) return
         call one_case(name, mc(30.0_wp, psi), 'Mohr-Coulomb', 2, RETURN_EDGE, an, error)
         if (allocated(error)) return
         call one_case(name, mc(30.0_wp, psi), 'Mohr-Coulomb', 3, RETURN_APEX, an, error)
         if (allocated(error)) return
         call one_case(name, dp(30.0_wp, psi, 3), 'Drucker-Prager', 1, RETURN_SMOOTH, an, error)
         if (allocated(error)) return
         call one_case(name, dp(30.0_wp, psi, 3), 'Drucker-Prager', 3, RETURN_APEX, an, error)
         if (allocated(error)) return
      end do
   end subroutine every_state

   !> Element `name` of material `mat` strained by state `state` of STRAINS: every point
   !> returns with `kind`, and the tangent stiffness matches central differences.
   subroutine one_case(name, mat, label, state, kind, analysis, error)
      character(len=*), intent(in) :: name, label
      class(material_t), intent(in) :: mat
      integer, intent(in) :: state, kind, analysis
      type(error_t), allocatable, intent(out) :: error
      class(massif_element_t), allocatable :: elem
      type(massif_rule_t) :: rule
      real(wp), allocatable :: xe(:, :), ue(:), ke(:, :), kfd(:, :), kel(:, :), fp(:), fm(:), &
         d(:, :, :), de(:, :, :)
      integer, allocatable :: kinds(:)
      real(wp) :: err, sig_conv(NCOMP)
      integer :: j, nd
      character(len=160) :: msg
      call new_massif_element(name, elem, error)
      if (allocated(error)) return
      call new_massif_rule(rule, elem)
      xe = shape_of(name)
      nd = 2*rule%nnode
      ue = displacement(xe, STRAINS(:, state))
      ! axisymmetric: the same element and displacements at radius R_AXI (hoop strains
      ! u_r/r about 1/R_AXI of the in-plane ones)
      if (analysis == AXISYMMETRIC) xe(1, :) = xe(1, :) + R_AXI
      allocate (ke(nd, nd), kfd(nd, nd), kel(nd, nd), fp(nd), fm(nd))
      sig_conv = SIG0(state)*[1.0_wp, 1.0_wp, 1.0_wp, 0.0_wp]
      call forces(mat, sig_conv, rule, analysis, xe, ue, fp, d, kinds, error)
      if (allocated(error)) return
      write (msg, '(a,1x,a,a,f4.0,a,i0,a,*(i2))') name, label, ' psi ', psi_of(mat), &
         ' state ', state, ': return kinds of the points', kinds
      call check(error, all(kinds == kind), trim(msg))
      if (allocated(error)) return
      call massif_stiffness(rule, analysis, 1.0_wp, xe, d, ke, error)
      if (allocated(error)) return
      allocate (de, mold=d)
      call mat%elastic_tangent(de(:, :, 1))
      de = spread(de(:, :, 1), 3, rule%ngauss)
      call massif_stiffness(rule, analysis, 1.0_wp, xe, de, kel, error)
      if (allocated(error)) return
      do j = 1, nd
         ue(j) = ue(j) + H
         call forces(mat, sig_conv, rule, analysis, xe, ue, fp, d, kinds, error)
         if (allocated(error)) return
         ue(j) = ue(j) - 2.0_wp*H
         call forces(mat, sig_conv, rule, analysis, xe, ue, fm, d, kinds, error)
         if (allocated(error)) return
         ue(j) = ue(j) + H
         kfd(:, j) = (fp - fm)/(2.0_wp*H)
      end do
      err = norm2(ke - kfd)/norm2(kel)
      write (msg, '(a,1x,a,a,f4.0,a,i0,a,es9.2,a,es9.2)') name, label, ' psi ', psi_of(mat), &
         ' state ', state, ': ||K - K_fd||/||K_e|| = ', err, ', ||K||/||K_e|| = ', &
         norm2(ke)/norm2(kel)
      call check(error, err <= TOL, trim(msg))
   end subroutine one_case

   !> Internal forces of the element at nodal displacements ue, each point updated from the
   !> converged stress sig_conv with its strain; the points' tangents and return kinds.
   subroutine forces(mat, sig_conv, rule, analysis, xe, ue, fe, d, kinds, error)
      class(material_t), intent(in) :: mat
      real(wp), intent(in) :: sig_conv(NCOMP)
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: analysis
      real(wp), intent(in) :: xe(:, :), ue(:)
      real(wp), intent(out) :: fe(:)
      real(wp), allocatable, intent(out) :: d(:, :, :)
      integer, allocatable, intent(out) :: kinds(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: eps(NCOMP, rule%ngauss), sig(NCOMP, rule%ngauss)
      real(wp), allocatable :: st(:)
      integer :: g
      allocate (d(NCOMP, NCOMP, rule%ngauss), kinds(rule%ngauss))
      call massif_strains(rule, analysis, 1.0_wp, xe, ue, eps, error)
      if (allocated(error)) return
      do g = 1, rule%ngauss
         allocate (st(mat%nstate()), source=0.0_wp)
         call mat%update(sig_conv, eps(:, g), st, sig(:, g), d(:, :, g), error)
         if (allocated(error)) return
         kinds(g) = nint(st(6))
         deallocate (st)
      end do
      call massif_internal_force(rule, analysis, 1.0_wp, xe, sig, fe, error)
   end subroutine forces

   !> Nodal displacements of the in-plane strain with principal values e (axes at THETA),
   !> plus BEND |e| times a quadratic field, at nodes xe.
   pure function displacement(xe, e) result(ue)
      real(wp), intent(in) :: xe(:, :), e(2)
      real(wp) :: ue(2*size(xe, 2))
      real(wp) :: c, s, exx, eyy, exy, x, y
      integer :: k
      c = cos(THETA); s = sin(THETA)
      exx = c*c*e(1) + s*s*e(2)
      eyy = s*s*e(1) + c*c*e(2)
      exy = c*s*(e(1) - e(2))
      do k = 1, size(xe, 2)
         x = xe(1, k); y = xe(2, k)
         ue(2*k - 1) = exx*x + exy*y + BEND*maxval(abs(e))*(0.5_wp*x*x - 0.3_wp*x*y)
         ue(2*k) = exy*x + eyy*y + BEND*maxval(abs(e))*(0.4_wp*y*y + 0.2_wp*x*y)
      end do
   end function displacement

   !> A distorted element of type `name`: corners off a square (or a scalene triangle),
   !> mid-side nodes off the side midpoints.
   pure function shape_of(name) result(xe)
      character(len=*), intent(in) :: name
      real(wp), allocatable :: xe(:, :)
      real(wp), parameter :: quad(2, 4) = reshape([0.0_wp, 0.0_wp, 1.1_wp, 0.1_wp, &
         1.2_wp, 1.0_wp, -0.1_wp, 0.9_wp], [2, 4])
      real(wp), parameter :: tri(2, 3) = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.1_wp, &
         0.2_wp, 0.9_wp], [2, 3])
      real(wp), parameter :: shift(2) = [0.02_wp, -0.03_wp]
      integer :: k
      select case (name)
      case ('T3')
         xe = tri
      case ('T6')
         allocate (xe(2, 6))
         xe(:, 1:3) = tri
         do k = 1, 3
            xe(:, 3 + k) = 0.5_wp*(tri(:, k) + tri(:, mod(k, 3) + 1)) + shift
         end do
      case ('Q4')
         xe = quad
      case default
         allocate (xe(2, 8))
         xe(:, 1:4) = quad
         do k = 1, 4
            xe(:, 4 + k) = 0.5_wp*(quad(:, k) + quad(:, mod(k, 4) + 1)) + shift
         end do
      end select
   end function shape_of

   !> The dilatancy angle of a fixture material, for messages (degrees; -1 if unknown).
   real(wp) function psi_of(mat)
      use pecplas_massif_materials_mohr_coulomb, only: mohr_coulomb_t
      use pecplas_massif_materials_drucker_prager, only: drucker_prager_t
      class(material_t), intent(in) :: mat
      psi_of = -1.0_wp
      select type (mat)
      type is (mohr_coulomb_t)
         psi_of = mat%soil%psi*180.0_wp/acos(-1.0_wp)
      type is (drucker_prager_t)
         psi_of = mat%soil%psi*180.0_wp/acos(-1.0_wp)
      end select
   end function psi_of

end module test_massif_tangent_fd
