!> Patch tests of T3, T6, Q4, Q8 in plane strain and axisymmetry (r in [1, 2]) on a
!> distorted patch with interior nodes, assembled densely and solved with LAPACK.
!> Displacement-driven: boundary nodes take an exact linear field, the interior nodes
!> must follow it. Force-driven: edge loads on the faces with minimal supports, the
!> Gauss-point stresses must equal the exact uniform state. Tolerance 1e-10 relative:
!> the discrete solution is exact, so only rounding (condition ~1e3) remains.
module test_massif_patch
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_factory, only: new_massif_element, KNOWN_MASSIF_ELEMENTS
   use pecplas_massif_kinematics, only: massif_rule_t, new_massif_rule
   use pecplas_massif_element_matrices, only: massif_strains, massif_body_force
   use pecplas_massif_edge_load, only: edge_pressure_forces, edge_traction_forces
   use pecplas_testing, only: unittest_t, new_unittest, check
   use fixtures_massif, only: patch_t, build_patch, assemble_stiffness, element_dofs, &
      linear_field, hooke, dense_solve
   implicit none (type, external)
   private
   public :: collect_massif_patch

   character(len=*), parameter :: NAMES(*) = KNOWN_MASSIF_ELEMENTS
   real(wp), parameter :: YOUNG = 2.0e4_wp, NU = 0.3_wp, THICK = 0.5_wp, TOL = 1.0e-10_wp
   real(wp), parameter :: TWO_PI = 2.0_wp*acos(-1.0_wp)
   !> Faces of the patch [x0, x0+1] x [0, 1]: left, right, bottom, top, outward normals.
   real(wp), parameter :: NORMALS(2, 4) = reshape([-1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, &
                                                   0.0_wp, -1.0_wp, 0.0_wp, 1.0_wp], [2, 4])

contains

   subroutine collect_massif_patch(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('displacement_plane', test_disp_plane), &
               new_unittest('displacement_axi', test_disp_axi), &
               new_unittest('displacement_axi_shear', test_disp_axi_shear), &
               new_unittest('force_plane_uniaxial', test_force_plane_uniaxial), &
               new_unittest('force_plane_traction', test_force_plane_traction), &
               new_unittest('force_axi_hydrostatic', test_force_axi_hydrostatic), &
               new_unittest('force_axi_uniaxial', test_force_axi_uniaxial)]
   end subroutine collect_massif_patch

   !> General linear field u = A x + c with all three plane strain components and a rotation.
   subroutine test_disp_plane(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: A(2, 2) = reshape([1.0e-3_wp, -4.0e-4_wp, 2.5e-3_wp, &
                                                -1.5e-3_wp], [2, 2])
      integer :: ie
      do ie = 1, size(NAMES)
         call displacement_patch(NAMES(ie), PLANE_STRAIN, 0.0_wp, A, [2.0e-4_wp, -1.0e-4_wp], &
            [A(1, 1), A(2, 2), 0.0_wp, A(1, 2) + A(2, 1)], error)
         if (allocated(error)) return
      end do
   end subroutine test_disp_plane

   !> u_r = a r, u_z = b z + d: eps = (a, b, a, 0); sigma_rr = sigma_tt, so equilibrium
   !> holds without body force.
   subroutine test_disp_axi(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: AR = 2.0e-3_wp, BZ = -1.0e-3_wp
      integer :: ie
      do ie = 1, size(NAMES)
         call displacement_patch(NAMES(ie), AXISYMMETRIC, 1.0_wp, &
            reshape([AR, 0.0_wp, 0.0_wp, BZ], [2, 2]), [0.0_wp, 3.0e-4_wp], &
            [AR, BZ, AR, 0.0_wp], error)
         if (allocated(error)) return
      end do
   end subroutine test_disp_axi

   !> u_z = b z + c r adds a uniform shear tau = mu c, which in axisymmetry is balanced
   !> only by the body force b_z = -tau / r (d tau/dr + tau/r = 0 fails otherwise). Its
   !> nodal forces -2 pi tau int N dA are a plane-strain body force of thickness 2 pi.
   subroutine test_disp_axi_shear(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: AR = 2.0e-3_wp, BZ = -1.0e-3_wp, CR = 1.5e-3_wp
      integer :: ie
      do ie = 1, size(NAMES)
         call displacement_patch(NAMES(ie), AXISYMMETRIC, 1.0_wp, &
            reshape([AR, CR, 0.0_wp, BZ], [2, 2]), [0.0_wp, 3.0e-4_wp], [AR, BZ, AR, CR], error)
         if (allocated(error)) return
      end do
   end subroutine test_disp_axi_shear

   subroutine displacement_patch(name, kind, x0, a, c, eps_exact, error)
      character(len=*), intent(in) :: name
      integer, intent(in) :: kind
      real(wp), intent(in) :: x0, a(2, 2), c(2), eps_exact(4)
      type(error_t), allocatable, intent(out) :: error
      class(massif_element_t), allocatable :: elem
      type(massif_rule_t) :: rule
      type(patch_t) :: patch
      real(wp), allocatable :: k(:, :), f(:), u(:), ue(:), fe(:)
      logical, allocatable :: fixed(:)
      real(wp) :: tau, d(4, 4)
      integer :: e
      call setup(name, x0, elem, rule, patch)
      call assemble_stiffness(elem, rule, kind, THICK, patch, hooke(YOUNG, NU), k, error)
      if (allocated(error)) return
      ue = linear_field(patch%x, a, c)
      allocate (f(size(ue)), source=0.0_wp)
      d = hooke(YOUNG, NU)
      tau = d(4, 4)*eps_exact(4)
      if (kind == AXISYMMETRIC .and. abs(tau) > 0.0_wp) then
         allocate (fe(2*rule%nnode))
         do e = 1, size(patch%conn, 2)
            call massif_body_force(rule, PLANE_STRAIN, TWO_PI, patch%x(:, patch%conn(:, e)), &
               [0.0_wp, -tau], fe, error)
            if (allocated(error)) return
            f(element_dofs(patch%conn(:, e))) = f(element_dofs(patch%conn(:, e))) + fe
         end do
      end if
      fixed = [(patch%boundary((e + 1)/2), e=1, size(ue))]
      u = merge(ue, 0.0_wp, fixed)
      call solve_free(k, f, fixed, u, error)
      if (allocated(error)) return
      call check(error, all(abs(u - ue) <= TOL*maxval(abs(ue))), &
         name//' interior displacements follow the linear field')
      if (allocated(error)) return
      call check_points(rule, kind, patch, u, eps_exact, matmul(d, eps_exact), name, error)
   end subroutine displacement_patch

   !> Uniaxial tension s on the right face as a negative pressure; left face on rollers,
   !> one point fixed vertically. sigma = (s, 0, nu s, 0) in plane strain.
   subroutine test_force_plane_uniaxial(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: S = 15.0_wp
      real(wp) :: pres(4)
      integer :: ie
      pres = [0.0_wp, -S, 0.0_wp, 0.0_wp]
      do ie = 1, size(NAMES)
         call force_patch(NAMES(ie), PLANE_STRAIN, 0.0_wp, pres, spread([0.0_wp, 0.0_wp], 2, 4), &
            [S, 0.0_wp, NU*S, 0.0_wp], 1, error)
         if (allocated(error)) return
      end do
   end subroutine test_force_plane_uniaxial

   !> A general uniform stress as tractions sigma n on all four faces, three supports.
   subroutine test_force_plane_traction(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: SXX = 12.0_wp, SYY = -7.0_wp, SXY = 4.0_wp
      real(wp) :: sig(2, 2), trac(2, 4)
      integer :: ie
      sig = reshape([SXX, SXY, SXY, SYY], [2, 2])
      trac = matmul(sig, NORMALS)
      do ie = 1, size(NAMES)
         call force_patch(NAMES(ie), PLANE_STRAIN, 0.0_wp, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], &
            trac, [SXX, SYY, NU*(SXX + SYY), SXY], 2, error)
         if (allocated(error)) return
      end do
   end subroutine test_force_plane_traction

   !> Pressure p on all faces of the ring (inner, outer, bottom, top): sigma = -p I.
   subroutine test_force_axi_hydrostatic(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: P = 20.0_wp
      integer :: ie
      do ie = 1, size(NAMES)
         call force_patch(NAMES(ie), AXISYMMETRIC, 1.0_wp, [P, P, P, P], &
            spread([0.0_wp, 0.0_wp], 2, 4), [-P, -P, -P, 0.0_wp], 3, error)
         if (allocated(error)) return
      end do
   end subroutine test_force_axi_hydrostatic

   !> Axial tension s on the top and bottom of a free-sided ring (negative pressures),
   !> held by one vertical support: sigma_zz = s.
   subroutine test_force_axi_uniaxial(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: S = 9.0_wp
      integer :: ie
      do ie = 1, size(NAMES)
         call force_patch(NAMES(ie), AXISYMMETRIC, 1.0_wp, [0.0_wp, 0.0_wp, -S, -S], &
            spread([0.0_wp, 0.0_wp], 2, 4), [0.0_wp, S, 0.0_wp, 0.0_wp], 3, error)
         if (allocated(error)) return
      end do
   end subroutine test_force_axi_uniaxial

   !> Loads face f with pressure pres(f) and traction trac(:, f); supports by `support`:
   !> 1 = rollers (u = 0) on the left face + v = 0 at node 1 (corner (x0, 0)),
   !> 2 = u = v = 0 at node 1 and v = 0 at node 2 (corner (x0+1, 0)), 3 = v = 0 at node 1.
   subroutine force_patch(name, kind, x0, pres, trac, sig_exact, support, error)
      character(len=*), intent(in) :: name
      integer, intent(in) :: kind, support
      real(wp), intent(in) :: x0, pres(4), trac(2, 4), sig_exact(4)
      type(error_t), allocatable, intent(out) :: error
      class(massif_element_t), allocatable :: elem
      type(massif_rule_t) :: rule
      type(patch_t) :: patch
      real(wp), allocatable :: k(:, :), f(:), u(:), fe(:), xed(:, :), d(:, :)
      integer, allocatable :: ed(:, :), nodes(:)
      logical, allocatable :: fixed(:)
      integer :: e, j, face
      call setup(name, x0, elem, rule, patch)
      call assemble_stiffness(elem, rule, kind, THICK, patch, hooke(YOUNG, NU), k, error)
      if (allocated(error)) return
      allocate (f(size(k, 1)), source=0.0_wp)
      allocate (fixed(size(f)), source=.false.)
      allocate (ed, source=elem%edges())
      do e = 1, size(patch%conn, 2)
         do j = 1, size(ed, 2)
            nodes = patch%conn(ed(:, j), e)
            xed = patch%x(:, nodes)
            do face = 1, 4
               if (.not. all(on_face(xed, face, x0))) cycle
               allocate (fe(2*size(nodes)))
               call edge_pressure_forces(kind, THICK, xed, pres(face), fe, error)
               if (allocated(error)) return
               f(element_dofs(nodes)) = f(element_dofs(nodes)) + fe
               call edge_traction_forces(kind, THICK, xed, trac(:, face), fe, error)
               if (allocated(error)) return
               f(element_dofs(nodes)) = f(element_dofs(nodes)) + fe
               deallocate (fe)
            end do
         end do
      end do
      select case (support)
      case (1)
         fixed(1::2) = on_face(patch%x, 1, x0)
         fixed(2) = .true.
      case (2)
         fixed([1, 2, 4]) = .true.
      case default
         fixed(2) = .true.
      end select
      allocate (u(size(f)), source=0.0_wp)
      call solve_free(k, f, fixed, u, error)
      if (allocated(error)) return
      d = hooke(YOUNG, NU)
      call check_points(rule, kind, patch, u, solve4(d, sig_exact), sig_exact, name, error)
   end subroutine force_patch

   subroutine setup(name, x0, elem, rule, patch)
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: x0
      class(massif_element_t), allocatable, intent(out) :: elem
      type(massif_rule_t), intent(out) :: rule
      type(patch_t), intent(out) :: patch
      type(error_t), allocatable :: error
      call new_massif_element(name, elem, error)
      if (allocated(error)) error stop 'known element name refused'
      call new_massif_rule(rule, elem)
      call build_patch(name, x0, patch)
   end subroutine setup

   !> Solves K(free, free) u(free) = f(free) - K(free, fixed) u(fixed) with dgesv.
   subroutine solve_free(k, f, fixed, u, error)
      real(wp), intent(in) :: k(:, :), f(:)
      logical, intent(in) :: fixed(:)
      real(wp), intent(inout) :: u(:)
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: fr(:), fx(:)
      real(wp), allocatable :: a(:, :), rhs(:)
      integer :: i, info
      fr = pack([(i, i=1, size(f))], .not. fixed)
      fx = pack([(i, i=1, size(f))], fixed)
      a = k(fr, fr)
      rhs = f(fr) - matmul(k(fr, fx), u(fx))
      call dense_solve(a, rhs, info)
      call check(error, info == 0, 'patch system singular (dgesv)')
      if (allocated(error)) return
      u(fr) = rhs
   end subroutine solve_free

   !> Strains and stresses at every Gauss point of every element equal the exact ones.
   subroutine check_points(rule, kind, patch, u, eps_exact, sig_exact, name, error)
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: kind
      type(patch_t), intent(in) :: patch
      real(wp), intent(in) :: u(:), eps_exact(4), sig_exact(4)
      character(len=*), intent(in) :: name
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: eps(4, rule%ngauss), d(4, 4)
      integer :: e, ig
      d = hooke(YOUNG, NU)
      do e = 1, size(patch%conn, 2)
         call massif_strains(rule, kind, THICK, patch%x(:, patch%conn(:, e)), &
            u(element_dofs(patch%conn(:, e))), eps, error)
         if (allocated(error)) return
         do ig = 1, rule%ngauss
            call check(error, all(abs(eps(:, ig) - eps_exact) <= TOL*maxval(abs(eps_exact))) &
               .and. all(abs(matmul(d, eps(:, ig)) - sig_exact) <= TOL*maxval(abs(sig_exact))), &
               name//' Gauss-point strain and stress exact')
            if (allocated(error)) return
         end do
      end do
   end subroutine check_points

   !> Which points x(2, :) lie on face `face` of the patch [x0, x0+1] x [0, 1].
   pure function on_face(x, face, x0) result(on)
      real(wp), intent(in) :: x(:, :), x0
      integer, intent(in) :: face
      logical :: on(size(x, 2))
      real(wp), parameter :: EPS = 1.0e-12_wp
      select case (face)
      case (1)
         on = abs(x(1, :) - x0) < EPS
      case (2)
         on = abs(x(1, :) - x0 - 1.0_wp) < EPS
      case (3)
         on = abs(x(2, :)) < EPS
      case default
         on = abs(x(2, :) - 1.0_wp) < EPS
      end select
   end function on_face

   !> Strain of a given stress: solves d eps = sig (4 x 4, with dgesv).
   function solve4(d, sig) result(eps)
      real(wp), intent(in) :: d(4, 4), sig(4)
      real(wp) :: eps(4), a(4, 4)
      integer :: info
      a = d
      eps = sig
      call dense_solve(a, eps, info)
      if (info /= 0) error stop 'Hooke matrix singular'
   end function solve4

end module test_massif_patch
