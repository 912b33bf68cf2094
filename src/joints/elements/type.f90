!> Abstract joint (interface) element of PECJOIN (Annex B). An element evaluates, at each of
!> its integration points, the matrix D of (B.6) that maps the element displacements
!> U^e = (u1, v1, u2, v2, ...) to the relative displacements (g_n, eps_t) — row 1 the
!> normal gap (opening positive), row 2 the tangential slip eps_t = U_t(2) - U_t(1) — and
!> the measure of the point (length x thickness, 2 pi r x length, or a spring's tributary).
!>
!> The interface laws work with eps = (eps_n, eps_t), eps_n = -g_n (closure positive) and
!> sigma = (sigma_n, tau), sigma_n compression positive. With S = diag(-1, 1):
!>   eps = S D U,   f = sum D^T (S sigma) dA,   K = sum D^T S C S D dA.
!> Node order (B.7–B.10): face 1 nodes 1-2 (mid 5), face 2 nodes 3 facing 2, 4 facing 1
!> (mid 6); springs: face-1 node, face-2 node. The normal n = (-t_y, t_x) of the tangent
!> t = dX/dxi / J points from face 1 into face 2.
module pecplas_joints_elements_type
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   implicit none (type, external)
   private

   public :: joint_element_t, joint_element_box_t, joint_point_t
   public :: MAX_JOINT_NODES, MAX_JOINT_POINTS
   public :: joint_strain, joint_force, joint_stiffness

   !> Largest joint element (6-node Goodman) and largest number of points per element.
   integer, parameter :: MAX_JOINT_NODES = 6, MAX_JOINT_POINTS = 3

   !> One integration point. Fixed-size arrays (no allocation per point); only the first
   !> 2*nnode columns of d are meaningful.
   type :: joint_point_t
      !> (g_n, eps_t) = d U^e (divided by the thickness for a thin layer).
      real(wp) :: d(2, 2*MAX_JOINT_NODES) = 0.0_wp
      !> Physical position and unit tangent t (n = (-t_y, t_x)).
      real(wp) :: x(2) = 0.0_wp, t(2) = [1.0_wp, 0.0_wp]
      !> Measure of the point: w J thickness (plane strain), w J 2 pi r (axisymmetric),
      !> times e for a thin layer; a spring's tributary length or area.
      real(wp) :: da = 0.0_wp
   end type joint_point_t

   type, abstract :: joint_element_t
   contains
      !> Deck name (SPRING, GOODMAN4, GOODMAN6, THIN_LAYER).
      procedure(name_ifc), deferred :: name
      procedure(count_ifc), deferred :: nnode
      procedure(count_ifc), deferred :: npoint
      !> Integration points of one element of nodal coordinates xe(2, nnode).
      procedure(points_ifc), deferred :: points
   end type joint_element_t

   type :: joint_element_box_t
      class(joint_element_t), allocatable :: e
   end type joint_element_box_t

   abstract interface
      pure function name_ifc(this) result(name)
         import :: joint_element_t
         class(joint_element_t), intent(in) :: this
         character(len=:), allocatable :: name
      end function name_ifc

      pure integer function count_ifc(this)
         import :: joint_element_t
         class(joint_element_t), intent(in) :: this
      end function count_ifc

      subroutine points_ifc(this, xe, analysis_kind, thickness, pts, error, tangent, tributary)
         import :: joint_element_t, joint_point_t, wp, error_t
         class(joint_element_t), intent(in) :: this
         !> Nodal coordinates (2, nnode) in the node order of (B.7)/(B.9).
         real(wp), intent(in) :: xe(:, :)
         !> PLANE_STRAIN or AXISYMMETRIC, and the plane-strain out-of-plane thickness.
         integer, intent(in) :: analysis_kind
         real(wp), intent(in) :: thickness
         !> One entry per integration point (size npoint).
         type(joint_point_t), intent(out) :: pts(:)
         type(error_t), allocatable, intent(out) :: error
         !> Springs only: unit tangent of the doublet and its tributary measure.
         real(wp), intent(in), optional :: tangent(2), tributary
      end subroutine points_ifc
   end interface

contains

   !> Law strain eps = (eps_n, eps_t) = S D U^e at a point (eps_n = -g_n).
   pure function joint_strain(pt, ue) result(eps)
      type(joint_point_t), intent(in) :: pt
      real(wp), intent(in) :: ue(:)
      real(wp) :: eps(2)
      eps = matmul(pt%d(:, 1:size(ue)), ue)
      eps(1) = -eps(1)
   end function joint_strain

   !> Adds the point's internal force D^T (S sigma) dA to fe.
   pure subroutine joint_force(pt, sigma, fe)
      type(joint_point_t), intent(in) :: pt
      real(wp), intent(in) :: sigma(2)
      real(wp), intent(inout) :: fe(:)
      fe = fe + matmul([-sigma(1), sigma(2)], pt%d(:, 1:size(fe)))*pt%da
   end subroutine joint_force

   !> Adds the point's stiffness D^T S C S D dA to ke (C may be non-symmetric).
   pure subroutine joint_stiffness(pt, c, ke)
      type(joint_point_t), intent(in) :: pt
      real(wp), intent(in) :: c(2, 2)
      real(wp), intent(inout) :: ke(:, :)
      real(wp) :: scs(2, 2)
      integer :: nd
      nd = size(ke, 1)
      scs = c
      scs(1, 2) = -c(1, 2)
      scs(2, 1) = -c(2, 1)
      ke = ke + matmul(transpose(pt%d(:, 1:nd)), matmul(scs, pt%d(:, 1:nd)))*pt%da
   end subroutine joint_stiffness

end module pecplas_joints_elements_type
