!> Consistent edge loads: nodal distributions and resultants against closed-form
!> integrals (tolerance 1e-13 relative: Gauss rules are exact, only rounding remains).
module test_massif_edge_load
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC
   use pecplas_massif_edge_load, only: edge_pressure_forces, edge_traction_forces, &
      edge_linear_pressure_forces
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_massif_edge_load

   real(wp), parameter :: PI = acos(-1.0_wp), TOL = 1.0e-13_wp

contains

   subroutine collect_massif_edge_load(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('plane_pressure_nodes', test_plane_pressure), &
               new_unittest('plane_curved_resultant', test_plane_curved), &
               new_unittest('plane_linear_pressure', test_plane_linear), &
               new_unittest('axi_vertical_edge', test_axi_vertical), &
               new_unittest('axi_horizontal_edge', test_axi_horizontal), &
               new_unittest('axi_curved_resultant', test_axi_curved), &
               new_unittest('axi_quadratic_pressure', test_axi_quadratic), &
               new_unittest('traction_resultants', test_traction), &
               new_unittest('bad_edges', test_bad_edges), &
               new_unittest('depth_pressure_plane', test_depth_plane), &
               new_unittest('depth_pressure_axi', test_depth_axi), &
               new_unittest('depth_pressure_cut', test_depth_cut), &
               new_unittest('depth_pressure_cut_axi', test_depth_cut_axi)]
   end subroutine collect_massif_edge_load

   !> All components of a against b within TOL times the largest |b|.
   logical function close(a, b)
      real(wp), intent(in) :: a(:), b(:)
      close = all(abs(a - b) <= TOL*maxval(abs(b)))
   end function close

   !> Straight plane edge (1,2) -> (4,6), L = 5, inward normal (-0.8, 0.6): a uniform
   !> pressure gives p L t / 2 per end node, and (1/6, 1/6, 2/3) p L t with a mid node.
   subroutine test_plane_pressure(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: P = 3.0_wp, T = 0.5_wp, NIN(2) = [-0.8_wp, 0.6_wp]
      real(wp) :: fe2(4), fe3(6), x2(2, 2)
      x2 = reshape([1.0_wp, 2.0_wp, 4.0_wp, 6.0_wp], [2, 2])
      call edge_pressure_forces(PLANE_STRAIN, T, x2, P, fe2, error)
      if (allocated(error)) return
      call check(error, close(fe2, P*5.0_wp*T*[NIN, NIN]/2.0_wp), '2-node: half to each end')
      if (allocated(error)) return
      call edge_pressure_forces(PLANE_STRAIN, T, reshape([x2, 2.5_wp, 4.0_wp], [2, 3]), P, fe3, &
         error)
      if (allocated(error)) return
      call check(error, close(fe3, P*5.0_wp*T*[NIN/6.0_wp, NIN/6.0_wp, 2.0_wp*NIN/3.0_wp]), &
         '3-node: 1/6, 1/6, 2/3')
   end subroutine test_plane_pressure

   !> On a curved 3-node edge the resultant of a uniform pressure is p t times the chord
   !> turned inwards, (-(y2 - y1), x2 - x1), whatever the curve.
   subroutine test_plane_curved(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: P = 2.0_wp, T = 1.5_wp
      real(wp) :: fe(6), x(2, 3)
      x = reshape([0.0_wp, 0.0_wp, 3.0_wp, 1.0_wp, 1.2_wp, 1.1_wp], [2, 3])
      call edge_pressure_forces(PLANE_STRAIN, T, x, P, fe, error)
      if (allocated(error)) return
      call check(error, close([sum(fe(1::2)), sum(fe(2::2))], P*T*[-1.0_wp, 3.0_wp]), &
         'resultant = p t x (inward-turned chord)')
   end subroutine test_plane_curved

   !> Linearly varying pressure on a horizontal edge of length L (body above):
   !> F1 = L (2 p1 + p2)/6, F2 = L (p1 + 2 p2)/6 upwards; with a mid node carrying the
   !> mean value the resultant and moment are unchanged.
   subroutine test_plane_linear(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: P1 = 1.0_wp, P2 = 4.0_wp, L = 2.0_wp
      real(wp) :: fe2(4), fe3(6), x(2, 3)
      x = reshape([0.0_wp, 0.0_wp, L, 0.0_wp, 0.5_wp*L, 0.0_wp], [2, 3])
      call edge_pressure_forces(PLANE_STRAIN, 1.0_wp, x(:, 1:2), [P1, P2], fe2, error)
      if (allocated(error)) return
      call check(error, close(fe2, [0.0_wp, L*(2*P1 + P2)/6, 0.0_wp, L*(P1 + 2*P2)/6]), &
         '2-node linear pressure')
      if (allocated(error)) return
      call edge_pressure_forces(PLANE_STRAIN, 1.0_wp, x, [P1, P2, 0.5_wp*(P1 + P2)], fe3, error)
      if (allocated(error)) return
      call check(error, close([sum(fe3(2::2)), dot_product(fe3(2::2), x(1, :))], &
         [L*(P1 + P2)/2, L*L*(P1 + 2*P2)/6]), '3-node resultant and moment')
   end subroutine test_plane_linear

   !> Outer face r = R, z in [0.2, 1.4] (walked upwards, body inside): total radial force
   !> -p 2 pi R L; 1/2, 1/2 and 1/6, 1/6, 2/3 of it at the nodes (r constant).
   subroutine test_axi_vertical(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: P = 3.0_wp, R = 1.5_wp, L = 1.2_wp
      real(wp) :: fe2(4), fe3(6), x(2, 3), ftot
      x = reshape([R, 0.2_wp, R, 1.4_wp, R, 0.8_wp], [2, 3])
      ftot = -P*2.0_wp*PI*R*L
      call edge_pressure_forces(AXISYMMETRIC, 1.0_wp, x(:, 1:2), P, fe2, error)
      if (allocated(error)) return
      call check(error, close(fe2, [ftot/2, 0.0_wp, ftot/2, 0.0_wp]), '2-node ring forces')
      if (allocated(error)) return
      call edge_pressure_forces(AXISYMMETRIC, 1.0_wp, x, P, fe3, error)
      if (allocated(error)) return
      call check(error, close(fe3, [ftot/6, 0.0_wp, ftot/6, 0.0_wp, 2*ftot/3, 0.0_wp]), &
         '3-node ring forces')
   end subroutine test_axi_vertical

   !> Top face z = 1 from r2 = 2 to r1 = 0.5 (walked towards the axis, body below): total
   !> -p pi (r2^2 - r1^2) along z; 2-node shares 2 pi p L (2 r_i + r_j)/6; a 3-node edge
   !> with its mid node off-centre on the line gives the same total.
   subroutine test_axi_horizontal(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: P = 3.0_wp, R1 = 0.5_wp, R2 = 2.0_wp, L = R2 - R1
      real(wp) :: fe2(4), fe3(6), x(2, 3)
      x = reshape([R2, 1.0_wp, R1, 1.0_wp, 1.1_wp, 1.0_wp], [2, 3])
      call edge_pressure_forces(AXISYMMETRIC, 1.0_wp, x(:, 1:2), P, fe2, error)
      if (allocated(error)) return
      call check(error, close(fe2, -2*PI*P*L*[0.0_wp, (2*R2 + R1)/6, 0.0_wp, (R2 + 2*R1)/6]), &
         '2-node ring forces')
      if (allocated(error)) return
      call edge_pressure_forces(AXISYMMETRIC, 1.0_wp, x, P, fe3, error)
      if (allocated(error)) return
      call check(error, close([sum(fe3(1::2)), sum(fe3(2::2))], [0.0_wp, -P*PI*(R2**2 - R1**2)]), &
         '3-node total ring force')
   end subroutine test_axi_horizontal

   !> A curved 3-node edge from r = 2 to r = 0.5: the axial resultant of a uniform
   !> pressure is p pi (r_end^2 - r_start^2) for any curve (needs the full degree-5 rule).
   subroutine test_axi_curved(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: P = 3.0_wp
      real(wp) :: fe(6), x(2, 3)
      x = reshape([2.0_wp, 1.0_wp, 0.5_wp, 1.3_wp, 1.2_wp, 1.5_wp], [2, 3])
      call edge_pressure_forces(AXISYMMETRIC, 1.0_wp, x, P, fe, error)
      if (allocated(error)) return
      call check(error, close([sum(fe(2::2))], [P*PI*(0.25_wp - 4.0_wp)]), &
         'axial resultant on a curved edge')
   end subroutine test_axi_curved

   !> Nodal pressure p = r^2 on a 3-node top face from r = 2 to 0.5 (interpolated
   !> exactly). Weak form with q = 1 and q = r^2 (also exact at the nodes):
   !> sum F_z = -2 pi int r^3 dr and sum F_z r_i^2 = -2 pi int r^5 dr.
   subroutine test_axi_quadratic(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: fe(6), x(2, 3), r(3)
      x = reshape([2.0_wp, 1.0_wp, 0.5_wp, 1.0_wp, 1.25_wp, 1.0_wp], [2, 3])
      r = x(1, :)
      call edge_pressure_forces(AXISYMMETRIC, 1.0_wp, x, r**2, fe, error)
      if (allocated(error)) return
      call check(error, close([sum(fe(2::2)), dot_product(fe(2::2), r**2)], &
         -2*PI*[(2.0_wp**4 - 0.5_wp**4)/4, (2.0_wp**6 - 0.5_wp**6)/6]) .and. &
         all(abs(fe(1::2)) <= TOL*maxval(abs(fe))), 'weak-form moments, no radial force')
   end subroutine test_axi_quadratic

   !> Uniform traction: resultant t L thickness (plane), t pi (r2^2 - r1^2) on a
   !> horizontal ring face; linear nodal traction on 2 nodes: L (2 t1 + t2)/6 at node 1.
   subroutine test_traction(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: TR(2) = [2.0_wp, -5.0_wp], T2(2) = [1.0_wp, 3.0_wp]
      real(wp) :: fe2(4), fe3(6), x(2, 3)
      x = reshape([1.0_wp, 2.0_wp, 4.0_wp, 6.0_wp, 2.5_wp, 4.0_wp], [2, 3])
      call edge_traction_forces(PLANE_STRAIN, 0.5_wp, x, TR, fe3, error)
      if (allocated(error)) return
      call check(error, close([sum(fe3(1::2)), sum(fe3(2::2))], TR*5.0_wp*0.5_wp), &
         'plane 3-node resultant')
      if (allocated(error)) return
      call edge_traction_forces(PLANE_STRAIN, 1.0_wp, x(:, 1:2), reshape([TR, T2], [2, 2]), &
         fe2, error)
      if (allocated(error)) return
      call check(error, close(fe2, 5.0_wp*[(2*TR + T2)/6, (TR + 2*T2)/6]), 'linear traction')
      if (allocated(error)) return
      x = reshape([2.0_wp, 1.0_wp, 0.5_wp, 1.0_wp, 1.25_wp, 1.0_wp], [2, 3])
      call edge_traction_forces(AXISYMMETRIC, 1.0_wp, x, TR, fe3, error)
      if (allocated(error)) return
      call check(error, close([sum(fe3(1::2)), sum(fe3(2::2))], TR*PI*(4.0_wp - 0.25_wp)), &
         'axisymmetric ring resultant')
   end subroutine test_traction

   !> An edge on the axis carries nothing (no error); r < 0 and 4 nodes are errors.
   subroutine test_bad_edges(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      real(wp) :: fe2(4), fe4(8)
      call edge_pressure_forces(AXISYMMETRIC, 1.0_wp, reshape([0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp], &
         [2, 2]), 5.0_wp, fe2, error)
      if (allocated(error)) return
      call check(error, maxval(abs(fe2)) <= tiny(1.0_wp), 'edge on the axis: zero ring force')
      if (allocated(error)) return
      call edge_pressure_forces(AXISYMMETRIC, 1.0_wp, reshape([-1.0_wp, 1.0_wp, -1.0_wp, &
         0.0_wp], [2, 2]), 5.0_wp, fe2, e)
      call check(error, allocated(e), 'r < 0 must be an error')
      if (allocated(error)) return
      deallocate (e)
      call edge_pressure_forces(PLANE_STRAIN, 1.0_wp, reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, &
         2.0_wp, 0.0_wp, 3.0_wp, 0.0_wp], [2, 4]), 5.0_wp, fe4, e)
      call check(error, allocated(e), '4-node edge must be an error')
   end subroutine test_bad_edges

   !> p(y) = 10 + 3 (7 - y) on the straight edge (1,2) -> (4,6) of test_plane_pressure: 25
   !> and 13 at its ends. 2 nodes: L t (2 p1 + p2)/6 and L t (p1 + 2 p2)/6 along the inward
   !> normal (the trapezoid, resultant L t (p1 + p2)/2); 3 nodes: L t p1/6, L t p2/6,
   !> L t (p1 + p2)/3 (the integrals of the quadratic shape functions times a linear p).
   subroutine test_depth_plane(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: T = 0.5_wp, L = 5.0_wp, NIN(2) = [-0.8_wp, 0.6_wp], &
         P1 = 25.0_wp, P2 = 13.0_wp
      real(wp) :: fe2(4), fe3(6), x2(2, 2)
      x2 = reshape([1.0_wp, 2.0_wp, 4.0_wp, 6.0_wp], [2, 2])
      call edge_linear_pressure_forces(PLANE_STRAIN, T, x2, 10.0_wp, 3.0_wp, 7.0_wp, fe2, error)
      if (allocated(error)) return
      call check(error, close(fe2, L*T*[(2*P1 + P2)/6*NIN, (P1 + 2*P2)/6*NIN]), &
         '2-node: trapezoid (2 p1 + p2)/6, (p1 + 2 p2)/6')
      if (allocated(error)) return
      call check(error, close(fe2(1:2) + fe2(3:4), L*T*(P1 + P2)/2*NIN), &
         'resultant: trapezoid area along the inward normal')
      if (allocated(error)) return
      call edge_linear_pressure_forces(PLANE_STRAIN, T, reshape([x2, 2.5_wp, 4.0_wp], [2, 3]), &
         10.0_wp, 3.0_wp, 7.0_wp, fe3, error)
      if (allocated(error)) return
      call check(error, close(fe3, L*T*[P1/6*NIN, P2/6*NIN, (P1 + P2)/3*NIN]), &
         '3-node: p1/6, p2/6, (p1 + p2)/3')
   end subroutine test_depth_plane

   !> The same pressure in axisymmetry (r = x from 1 to 4): with t = s/L, N1 = 1 - t, N2 = t,
   !> p and r linear, F_i = 2 pi L int N_i p r dt = 2 pi L [p1 r1/4 + (p1 r2 + p2 r1)/12 +
   !> p2 r2/12] = 200 pi and 245 pi; 3 nodes: 143/3, 278/3, 914/3 times pi (the quadratic
   !> shape functions times p r, integrated exactly), the same resultant 445 pi.
   subroutine test_depth_axi(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: NIN(2) = [-0.8_wp, 0.6_wp]
      real(wp) :: fe2(4), fe3(6), x2(2, 2)
      x2 = reshape([1.0_wp, 2.0_wp, 4.0_wp, 6.0_wp], [2, 2])
      call edge_linear_pressure_forces(AXISYMMETRIC, 1.0_wp, x2, 10.0_wp, 3.0_wp, 7.0_wp, fe2, &
         error)
      if (allocated(error)) return
      call check(error, close(fe2, PI*[200.0_wp*NIN, 245.0_wp*NIN]), '2-node: 200 pi, 245 pi')
      if (allocated(error)) return
      call edge_linear_pressure_forces(AXISYMMETRIC, 1.0_wp, reshape([x2, 2.5_wp, 4.0_wp], &
         [2, 3]), 10.0_wp, 3.0_wp, 7.0_wp, fe3, error)
      if (allocated(error)) return
      call check(error, close(fe3, PI*[143.0_wp/3*NIN, 278.0_wp/3*NIN, 914.0_wp/3*NIN]), &
         '3-node: 143/3, 278/3, 914/3 pi')
   end subroutine test_depth_axi

   !> Water against a wall: the edge (0,4) -> (0,0) (body at x > 0, inward normal +x), table
   !> at y = 3, p = max(0, 10 (3 - y)). The resultant is the triangle 10 3**2/2 = 45; 2 nodes,
   !> with t from the top and p = 40 (t - 1/4) below the cut: F1 = 160 int (1 - t)(t - 1/4)
   !> = 11.25, F2 = 160 int t (t - 1/4) = 33.75 (t from 1/4 to 1); 3 nodes (mid (0,2)):
   !> -45/16, 315/16, 225/8. Without the floor the part above the table pulls: the forces
   !> are those of the nodal values -10 and 30. A pressure below the floor everywhere gives
   !> the floor alone.
   subroutine test_depth_cut(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: fe2(4), fe3(6), ref(4), x2(2, 2)
      x2 = reshape([0.0_wp, 4.0_wp, 0.0_wp, 0.0_wp], [2, 2])
      call edge_linear_pressure_forces(PLANE_STRAIN, 1.0_wp, x2, 0.0_wp, 10.0_wp, 3.0_wp, fe2, &
         error, p_min=0.0_wp)
      if (allocated(error)) return
      call check(error, close(fe2, [11.25_wp, 0.0_wp, 33.75_wp, 0.0_wp]), &
         '2-node cut: 11.25, 33.75 (total 45)')
      if (allocated(error)) return
      call edge_linear_pressure_forces(PLANE_STRAIN, 1.0_wp, reshape([x2, 0.0_wp, 2.0_wp], &
         [2, 3]), 0.0_wp, 10.0_wp, 3.0_wp, fe3, error, p_min=0.0_wp)
      if (allocated(error)) return
      call check(error, close(fe3, [-45.0_wp/16, 0.0_wp, 315.0_wp/16, 0.0_wp, 225.0_wp/8, &
         0.0_wp]), '3-node cut: -45/16, 315/16, 225/8')
      if (allocated(error)) return
      ! the mid node off the middle, (0, 2.6): y(s), and p(s), are quadratic in s, the cut a
      ! root of a quadratic; on the same straight line the resultant is 45 and the moment
      ! about the top sum F_i (4 - y_i) = int p (4 - y) dy = 10 int_0^3 (3 - y)(4 - y) = 135
      call edge_linear_pressure_forces(PLANE_STRAIN, 1.0_wp, reshape([x2, 0.0_wp, 2.6_wp], &
         [2, 3]), 0.0_wp, 10.0_wp, 3.0_wp, fe3, error, p_min=0.0_wp)
      if (allocated(error)) return
      call check(error, abs(fe3(1) + fe3(3) + fe3(5) - 45.0_wp) <= TOL*45.0_wp .and. &
         abs(4*fe3(3) + (4 - 2.6_wp)*fe3(5) - 135.0_wp) <= TOL*135.0_wp .and. &
         all(fe3(2:6:2) == 0.0_wp), 'off-centre mid node: resultant 45, moment 135')
      if (allocated(error)) return
      call edge_linear_pressure_forces(PLANE_STRAIN, 1.0_wp, x2, 0.0_wp, 10.0_wp, 3.0_wp, fe2, &
         error)
      if (allocated(error)) return
      call edge_pressure_forces(PLANE_STRAIN, 1.0_wp, x2, [-10.0_wp, 30.0_wp], ref, error)
      if (allocated(error)) return
      call check(error, close(fe2, ref), 'no floor: the nodal values -10, 30')
      if (allocated(error)) return
      call edge_linear_pressure_forces(PLANE_STRAIN, 1.0_wp, x2, 0.0_wp, 10.0_wp, -1.0_wp, &
         fe2, error, p_min=2.0_wp)
      if (allocated(error)) return
      call edge_pressure_forces(PLANE_STRAIN, 1.0_wp, x2, 2.0_wp, ref, error)
      if (allocated(error)) return
      call check(error, close(fe2, ref), 'all below the floor: the floor alone')
   end subroutine test_depth_cut

   !> p = max(0, 3 (5 - y)) on the inclined axisymmetric edge (1,2) -> (4,6), cut at y = 5
   !> (three quarters along): with x = 5/2 + 3/2 s, y = 4 + 2 s, int N_i p 2 pi x (5/2) ds
   !> over -1 <= s <= 1/2 is 5265/128, 2295/128 pi (2 nodes) and 5157/256, -783/256, 5373/128
   !> pi (3 nodes), both 945/16 pi in all.
   subroutine test_depth_cut_axi(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: NIN(2) = [-0.8_wp, 0.6_wp]
      real(wp) :: fe2(4), fe3(6), x2(2, 2)
      x2 = reshape([1.0_wp, 2.0_wp, 4.0_wp, 6.0_wp], [2, 2])
      call edge_linear_pressure_forces(AXISYMMETRIC, 1.0_wp, x2, 0.0_wp, 3.0_wp, 5.0_wp, fe2, &
         error, p_min=0.0_wp)
      if (allocated(error)) return
      call check(error, close(fe2, PI*[5265.0_wp/128*NIN, 2295.0_wp/128*NIN]), &
         '2-node: 5265/128, 2295/128 pi')
      if (allocated(error)) return
      call edge_linear_pressure_forces(AXISYMMETRIC, 1.0_wp, reshape([x2, 2.5_wp, 4.0_wp], &
         [2, 3]), 0.0_wp, 3.0_wp, 5.0_wp, fe3, error, p_min=0.0_wp)
      if (allocated(error)) return
      call check(error, close(fe3, PI*[5157.0_wp/256*NIN, -783.0_wp/256*NIN, &
         5373.0_wp/128*NIN]), '3-node: 5157/256, -783/256, 5373/128 pi')
   end subroutine test_depth_cut_axi

end module test_massif_edge_load
