!> Children of a refined massif element in its reference coordinates (pecplas_model_refine_local),
!> counter-clockwise like the parent, and the parent's isoparametric map that places their nodes.
!> Quadrilaterals (reference square [-1, 1]^2): four marked sides give four quadrilaterals,
!> two opposite ones two. Triangles (reference corners (0,0), (1,0), (0,1)): bisection of
!> the longest side from the opposite corner, then of each child on its marked parent side
!> (newest-vertex bisection: 2, 3 or 4 children, angles bounded under repetition).
module pecplas_model_refine_local_children
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: quad_children, quad_transition, triangle_children, parent_map, REF_QUAD, REF_TRI

   real(wp), parameter :: REF_QUAD(2, 4) = reshape([-1.0_wp, -1.0_wp, 1.0_wp, -1.0_wp, &
      1.0_wp, 1.0_wp, -1.0_wp, 1.0_wp], [2, 4])
   real(wp), parameter :: REF_TRI(2, 3) = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, &
      0.0_wp, 1.0_wp], [2, 3])

contains

   !> Children corners ref(2, 4, n) of a quadrilateral with marked sides `mk` (all, or 1 and 3,
   !> or 2 and 4: the closure guarantees one of these).
   subroutine quad_children(mk, ref)
      logical, intent(in) :: mk(4)
      real(wp), allocatable, intent(out) :: ref(:, :, :)
      real(wp) :: p(2, 4), m(2, 4), c(2)
      integer :: i
      p = REF_QUAD
      do i = 1, 4
         m(:, i) = 0.5_wp*(p(:, i) + p(:, mod(i, 4) + 1))
      end do
      c = 0.0_wp
      if (all(mk)) then
         allocate (ref(2, 4, 4))
         ref(:, :, 1) = reshape([p(:, 1), m(:, 1), c, m(:, 4)], [2, 4])
         ref(:, :, 2) = reshape([m(:, 1), p(:, 2), m(:, 2), c], [2, 4])
         ref(:, :, 3) = reshape([c, m(:, 2), p(:, 3), m(:, 3)], [2, 4])
         ref(:, :, 4) = reshape([m(:, 4), c, m(:, 3), p(:, 4)], [2, 4])
      else if (mk(1)) then
         allocate (ref(2, 4, 2))
         ref(:, :, 1) = reshape([p(:, 1), m(:, 1), m(:, 3), p(:, 4)], [2, 4])
         ref(:, :, 2) = reshape([m(:, 1), p(:, 2), p(:, 3), m(:, 3)], [2, 4])
      else
         allocate (ref(2, 4, 2))
         ref(:, :, 1) = reshape([p(:, 1), p(:, 2), m(:, 2), m(:, 4)], [2, 4])
         ref(:, :, 2) = reshape([m(:, 4), m(:, 2), p(:, 3), p(:, 4)], [2, 4])
      end if
   end subroutine quad_children

   !> Transition of a quadrilateral with only side i marked: three triangles ref(2, 3, 3)
   !> fanned from the side's midpoint M: (M, P_i+1, P_i+2), (M, P_i+2, P_i+3), (M, P_i+3, P_i).
   subroutine quad_transition(i, ref)
      integer, intent(in) :: i
      real(wp), allocatable, intent(out) :: ref(:, :, :)
      real(wp) :: m(2)
      integer :: k, c(4)
      c = [(mod(i + k - 1, 4) + 1, k=0, 3)]
      m = 0.5_wp*(REF_QUAD(:, c(1)) + REF_QUAD(:, c(2)))
      allocate (ref(2, 3, 3))
      do k = 1, 3
         ref(:, :, k) = reshape([m, REF_QUAD(:, c(k + 1)), REF_QUAD(:, c(mod(k + 1, 4) + 1))], &
            [2, 3])
      end do
   end subroutine quad_transition

   !> Children corners ref(2, 3, n) of a triangle with marked sides `mk`, bisected first on
   !> side `k` (its longest, marked), then each child on its marked parent side.
   subroutine triangle_children(mk, k, ref)
      logical, intent(in) :: mk(3)
      integer, intent(in) :: k
      real(wp), allocatable, intent(out) :: ref(:, :, :)
      real(wp) :: a(2, 3), b(2, 3), t(2, 3, 2)
      integer :: k1, k2
      k1 = mod(k, 3) + 1
      k2 = mod(k + 1, 3) + 1
      call bisect(REF_TRI, k, a, b)
      ! a = (P_k, M, P_k2): its side 3 is parent side k2; b = (M, P_k1, P_k2): side 2 is k1
      allocate (ref(2, 3, 0))
      if (mk(k2)) then
         call bisect(a, 3, t(:, :, 1), t(:, :, 2))
         ref = reshape([reshape(ref, [size(ref)]), reshape(t, [12])], [2, 3, size(ref, 3) + 2])
      else
         ref = reshape([reshape(ref, [size(ref)]), reshape(a, [6])], [2, 3, size(ref, 3) + 1])
      end if
      if (mk(k1)) then
         call bisect(b, 2, t(:, :, 1), t(:, :, 2))
         ref = reshape([reshape(ref, [size(ref)]), reshape(t, [12])], [2, 3, size(ref, 3) + 2])
      else
         ref = reshape([reshape(ref, [size(ref)]), reshape(b, [6])], [2, 3, size(ref, 3) + 1])
      end if
   end subroutine triangle_children

   !> Triangle tri cut at the midpoint M of its side i (corner i to i + 1) from the opposite
   !> corner: (P_i, M, P_opp) and (M, P_i+1, P_opp).
   pure subroutine bisect(tri, i, a, b)
      real(wp), intent(in) :: tri(2, 3)
      integer, intent(in) :: i
      real(wp), intent(out) :: a(2, 3), b(2, 3)
      real(wp) :: m(2)
      integer :: i1, i2
      i1 = mod(i, 3) + 1
      i2 = mod(i + 1, 3) + 1
      m = 0.5_wp*(tri(:, i) + tri(:, i1))
      a = reshape([tri(:, i), m, tri(:, i2)], [2, 3])
      b = reshape([m, tri(:, i1), tri(:, i2)], [2, 3])
   end subroutine bisect

   !> Point of the parent element (nodes xe(2, npe), T3/T6/Q4/Q8 node order) at reference
   !> coordinates r.
   pure function parent_map(xe, r) result(x)
      real(wp), intent(in) :: xe(:, :), r(2)
      real(wp) :: x(2)
      real(wp) :: n(8), l(3), s, t
      integer :: npe
      npe = size(xe, 2)
      s = r(1)
      t = r(2)
      select case (npe)
      case (3, 6)
         l = [1.0_wp - s - t, s, t]
         if (npe == 3) then
            n(1:3) = l
         else
            n(1:6) = [l(1)*(2*l(1) - 1), l(2)*(2*l(2) - 1), l(3)*(2*l(3) - 1), &
               4*l(1)*l(2), 4*l(2)*l(3), 4*l(3)*l(1)]
         end if
      case (4)
         n(1:4) = 0.25_wp*[(1 - s)*(1 - t), (1 + s)*(1 - t), (1 + s)*(1 + t), (1 - s)*(1 + t)]
      case default
         n(1:4) = 0.25_wp*[(1 - s)*(1 - t)*(-s - t - 1), (1 + s)*(1 - t)*(s - t - 1), &
            (1 + s)*(1 + t)*(s + t - 1), (1 - s)*(1 + t)*(-s + t - 1)]
         n(5:8) = 0.5_wp*[(1 - s*s)*(1 - t), (1 + s)*(1 - t*t), (1 - s*s)*(1 + t), &
            (1 - s)*(1 - t*t)]
      end select
      x = matmul(xe, n(1:npe))
   end function parent_map

end module pecplas_model_refine_local_children
