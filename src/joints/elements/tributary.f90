!> Tributary measure and orientation of spring doublets from the joint edges around them.
!> A spring carries the force of the interface stress over its share of the adjacent
!> edges: share_a = integral of N_a dA over each adjacent edge (N_a the edge shape function
!> of its node, dA = thickness ds in plane strain, 2 pi r ds in axisymmetry). On straight
!> linear edges in plane strain that is half of each adjacent segment; in general it is the
!> consistent nodal measure, so that a uniform interface stress gives the same nodal forces
!> as the Goodman elements on those edges (exact joint patch test, also axisymmetric and on
!> quadratic edges: 1/6, 2/3, 1/6 of the length). The spring tangent is the normalised sum
!> of the unit tangents of the adjacent edges at the node.
module pecplas_joints_elements_tributary
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error
   use pecplas_model_options, only: AXISYMMETRIC
   use pecplas_joints_elements_line, only: line_shape, line_rule
   implicit none (type, external)
   private

   public :: spring_tributaries

   real(wp), parameter :: TWO_PI = 2.0_wp*acos(-1.0_wp)

contains

   !> For springs whose face-1 nodes are face1(k), and joint edges edges(2 or 3, m) (face-1
   !> nodes: end, end[, mid], a 0 mid for a linear edge; oriented with face 2 on the left):
   !> tributary(k) and unit tangent(2, k). bad = a spring with no adjacent edge (error).
   subroutine spring_tributaries(x, analysis_kind, thickness, face1, edges, tributary, &
         tangent, bad, error)
      real(wp), intent(in) :: x(:, :), thickness
      integer, intent(in) :: analysis_kind, face1(:), edges(:, :)
      real(wp), intent(out) :: tributary(:), tangent(:, :)
      integer, intent(out) :: bad
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: spring_of(:)
      real(wp) :: xi(3), w(3), sh(3), dsh(3), xe(2, 3), dx(2), jac, r, share(3), xn(3)
      integer :: nen, f, a, ip, k
      logical, allocatable :: touched(:)

      bad = 0
      tributary = 0.0_wp
      tangent = 0.0_wp
      allocate (spring_of(size(x, 2)), source=0)
      allocate (touched(size(face1)), source=.false.)
      do k = 1, size(face1)
         spring_of(face1(k)) = k
      end do
      call line_rule(3, .false., xi, w)
      xn = [-1.0_wp, 1.0_wp, 0.0_wp]
      do f = 1, size(edges, 2)
         nen = 2
         if (size(edges, 1) == 3) then
            if (edges(3, f) > 0) nen = 3
         end if
         if (any(spring_of(edges(1:nen, f)) == 0)) cycle
         xe(:, 1:nen) = x(:, edges(1:nen, f))
         share = 0.0_wp
         do ip = 1, 3
            call line_shape(nen, xi(ip), sh(1:nen), dsh(1:nen))
            jac = norm2(matmul(xe(:, 1:nen), dsh(1:nen)))
            r = dot_product(xe(1, 1:nen), sh(1:nen))
            if (analysis_kind == AXISYMMETRIC) then
               share(1:nen) = share(1:nen) + w(ip)*jac*TWO_PI*max(r, 0.0_wp)*sh(1:nen)
            else
               share(1:nen) = share(1:nen) + w(ip)*jac*thickness*sh(1:nen)
            end if
         end do
         do a = 1, nen
            k = spring_of(edges(a, f))
            tributary(k) = tributary(k) + share(a)
            call line_shape(nen, xn(a), sh(1:nen), dsh(1:nen))
            dx = matmul(xe(:, 1:nen), dsh(1:nen))
            if (norm2(dx) > 0.0_wp) tangent(:, k) = tangent(:, k) + dx/norm2(dx)
            touched(k) = .true.
         end do
      end do
      do k = 1, size(face1)
         if (.not. touched(k) .or. .not. (norm2(tangent(:, k)) > 0.0_wp)) then
            bad = k
            call input_error(error, 'a spring has no adjacent joint edge (or its edges '// &
               'turn back on each other): its tributary measure and orientation are unknown')
            return
         end if
         tangent(:, k) = tangent(:, k)/norm2(tangent(:, k))
      end do
   end subroutine spring_tributaries

end module pecplas_joints_elements_tributary
