!> Integration-point kernels of the massif elements that use the structure of the strain
!> matrix instead of a dense B(4, 2*nnode). Node a contributes only in fixed places:
!>
!>     column u_a: (dN_a/dx, 0, N_a/r, dN_a/dy),   column v_a: (0, dN_a/dy, 0, dN_a/dx)
!>
!> (strain order xx, yy, zz, xy; N_a/r = 0 in plane strain), so D B, B^T (D B), B u and
!> B^T sigma take two or three products per entry instead of four, and B is never formed.
!> Inputs are those of massif_gauss_derivs: dndx(2, nn), hr(nn) = N/r, dvol. Explicit
!> shapes: called per point, they take no array descriptors.
!> The results equal the dense products up to round-off (test_massif_kernels).
module pecplas_massif_point_kernels
   use pecplas_base_kinds, only: wp
   use pecplas_massif_kinematics, only: MAX_NODES
   implicit none (type, external)
   private

   public :: point_stiffness_add, point_strain, point_force_add

contains

   !> ke(1:2nn, 1:2nn) += B^T d B dvol at one point; `axi`: the hoop row is present.
   !> With `upper` only the node blocks (a, b) with a <= b are written (the caller mirrors
   !> them); d may be non-symmetric.
   pure subroutine point_stiffness_add(nn, dndx, hr, dvol, d, axi, upper, ke)
      integer, intent(in) :: nn
      real(wp), intent(in) :: dndx(2, nn), hr(nn), dvol, d(4, 4)
      logical, intent(in) :: axi, upper
      real(wp), intent(inout) :: ke(2*nn, 2*nn)
      real(wp) :: db(4, 2*MAX_NODES), bx, by, c1, c2, c3, c4
      integer :: a, b, j, amax
      ! db = D B dvol, column by column
      do b = 1, nn
         bx = dndx(1, b)*dvol
         by = dndx(2, b)*dvol
         if (axi) then
            db(:, 2*b - 1) = d(:, 1)*bx + d(:, 3)*(hr(b)*dvol) + d(:, 4)*by
         else
            db(:, 2*b - 1) = d(:, 1)*bx + d(:, 4)*by
         end if
         db(:, 2*b) = d(:, 2)*by + d(:, 4)*bx
      end do
      ! ke(:, j) += B^T db(:, j): rows u_a and v_a of node a
      do j = 1, 2*nn
         amax = nn
         if (upper) amax = (j + 1)/2
         c1 = db(1, j); c2 = db(2, j); c3 = db(3, j); c4 = db(4, j)
         if (axi) then
            do a = 1, amax
               ke(2*a - 1, j) = ke(2*a - 1, j) + (dndx(1, a)*c1 + hr(a)*c3 + dndx(2, a)*c4)
               ke(2*a, j) = ke(2*a, j) + (dndx(2, a)*c2 + dndx(1, a)*c4)
            end do
         else
            do a = 1, amax
               ke(2*a - 1, j) = ke(2*a - 1, j) + (dndx(1, a)*c1 + dndx(2, a)*c4)
               ke(2*a, j) = ke(2*a, j) + (dndx(2, a)*c2 + dndx(1, a)*c4)
            end do
         end if
      end do
   end subroutine point_stiffness_add

   !> eps(4) = B ue for nodal displacements ue(2*nn) (u1, v1, u2, v2, ...).
   pure subroutine point_strain(nn, dndx, hr, ue, eps)
      integer, intent(in) :: nn
      real(wp), intent(in) :: dndx(2, nn), hr(nn), ue(2*nn)
      real(wp), intent(out) :: eps(4)
      integer :: a
      eps = 0.0_wp
      do a = 1, nn
         eps(1) = eps(1) + dndx(1, a)*ue(2*a - 1)
         eps(2) = eps(2) + dndx(2, a)*ue(2*a)
         eps(3) = eps(3) + hr(a)*ue(2*a - 1)
         eps(4) = eps(4) + (dndx(2, a)*ue(2*a - 1) + dndx(1, a)*ue(2*a))
      end do
   end subroutine point_strain

   !> fe(2*nn) += B^T sigma dvol for the point stress sigma(4).
   pure subroutine point_force_add(nn, dndx, hr, dvol, sigma, fe)
      integer, intent(in) :: nn
      real(wp), intent(in) :: dndx(2, nn), hr(nn), dvol, sigma(4)
      real(wp), intent(inout) :: fe(2*nn)
      real(wp) :: s(4)
      integer :: a
      s = sigma*dvol
      do a = 1, nn
         fe(2*a - 1) = fe(2*a - 1) + (dndx(1, a)*s(1) + hr(a)*s(3) + dndx(2, a)*s(4))
         fe(2*a) = fe(2*a) + (dndx(2, a)*s(2) + dndx(1, a)*s(4))
      end do
   end subroutine point_force_add

end module pecplas_massif_point_kernels
