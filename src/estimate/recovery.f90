!> Superconvergent patch recovery (Zienkiewicz–Zhu) of the massif stresses of one element
!> set: nodal stresses sigma*(NCOMP, nnode) fitted by least squares to the stresses at the
!> integration points of the elements around each interior vertex node.
!>
!> Basis of the element's own degree: T3 (1, x, y), Q4 (+ xy), T6 (complete quadratic),
!> Q8/Q8R (+ x^2 y, x y^2), in coordinates centred on the patch node and scaled by the patch
!> size. An interior vertex node takes its own patch's value; every other node of a patch
!> (mid-side, boundary) the mean of the patches that hold it (the standard remedy for
!> boundary nodes). A node reached by no interior patch (an element whose vertices all lie
!> on the set's boundary) takes the fit over its elements and their neighbours, at a lower
!> degree when the points do not determine the full basis. Recovery is per element set:
!> stresses jump across materials, so no patch spans two sets.
module pecplas_estimate_recovery
   use pecplas_base_kinds, only: wp
   use pecplas_massif_materials_type, only: NCOMP
   implicit none (type, external)
   private

   public :: recover_set_stresses, patch_basis_size, solve_small

   !> Relative pivot below which a patch fit counts as undetermined.
   real(wp), parameter :: PIVOT_TOL = 1.0e-10_wp

contains

   !> Number of terms of the recovery basis for an element of nnode nodes and nvert vertices.
   pure integer function patch_basis_size(nnode, nvert) result(nb)
      integer, intent(in) :: nnode, nvert
      if (nnode == nvert) then
         nb = merge(3, 4, nvert == 3)
      else
         nb = merge(6, 8, nvert == 3)
      end if
   end function patch_basis_size

   !> Recovered nodal stresses of one set. x(2, nnode_mesh) node coordinates, conn(nen, nel)
   !> connectivity, nvert vertices per element (the first nvert nodes), gx(2, ng, nel) and
   !> sig(NCOMP, ng, nel) positions and stresses of the integration points. Nodes outside the
   !> set keep sstar = 0; `have(i)` tells which nodes hold a value.
   subroutine recover_set_stresses(x, conn, nvert, gx, sig, sstar, have)
      real(wp), intent(in) :: x(:, :), gx(:, :, :), sig(:, :, :)
      integer, intent(in) :: conn(:, :), nvert
      real(wp), intent(out) :: sstar(:, :)
      logical, allocatable, intent(out) :: have(:)
      integer, allocatable :: start(:), adj(:), cnt(:), patch(:)
      logical, allocatable :: bnd(:), own(:)
      real(wp) :: coef(8, NCOMP), h, v(NCOMP)
      integer :: nnode, nen, nel, e, k, n, nb, nbfit
      logical :: ok

      nnode = size(x, 2); nen = size(conn, 1); nel = size(conn, 2)
      nb = patch_basis_size(nen, nvert)
      call node_elements(conn, nnode, start, adj)
      call boundary_nodes(conn, nvert, start, adj, bnd)
      sstar = 0.0_wp
      allocate (cnt(nnode), source=0)
      allocate (own(nnode), source=.false.)
      ! interior vertex patches
      do n = 1, nnode
         if (bnd(n) .or. start(n + 1) == start(n)) cycle
         if (.not. any(conn(1:nvert, adj(start(n))) == n)) cycle
         patch = adj(start(n):start(n + 1) - 1)
         call fit_patch(x(:, n), patch, gx, sig, nb, nvert, coef, h, nbfit, ok)
         if (.not. ok) cycle
         sstar(:, n) = evaluate(coef, nbfit, nvert, (x(:, n) - x(:, n))/h)
         own(n) = .true.
         do k = 1, size(patch)
            do e = 1, nen
               associate (m => conn(e, patch(k)))
                  if (own(m) .or. m == n) cycle
                  ! a node of several elements of the patch is counted once per patch
                  if (any(conn(:, patch(1:k - 1)) == m)) cycle
                  sstar(:, m) = sstar(:, m) + evaluate(coef, nbfit, nvert, (x(:, m) - x(:, n))/h)
                  cnt(m) = cnt(m) + 1
               end associate
            end do
         end do
      end do
      allocate (have(nnode), source=.false.)
      do n = 1, nnode
         if (start(n + 1) == start(n)) cycle
         have(n) = .true.
         if (own(n)) cycle
         if (cnt(n) > 0) then
            sstar(:, n) = sstar(:, n)/cnt(n)
            cycle
         end if
         ! no interior patch reaches n: fit over its elements and their neighbours
         call second_ring(n, conn, start, adj, patch)
         call fit_patch(x(:, n), patch, gx, sig, nb, nvert, coef, h, nbfit, ok)
         if (ok) then
            v = evaluate(coef, nbfit, nvert, [0.0_wp, 0.0_wp])
         else
            v = sum(sum(sig(:, :, patch), dim=3), dim=2)/real(size(sig, 2)*size(patch), wp)
         end if
         sstar(:, n) = v
      end do
   end subroutine recover_set_stresses

   !> Elements around each node: adj(start(i):start(i+1)-1).
   subroutine node_elements(conn, nnode, start, adj)
      integer, intent(in) :: conn(:, :), nnode
      integer, allocatable, intent(out) :: start(:), adj(:)
      integer, allocatable :: fill(:)
      integer :: e, k, m
      allocate (start(nnode + 1), source=0)
      do e = 1, size(conn, 2)
         do k = 1, size(conn, 1)
            m = conn(k, e)
            if (any(conn(1:k - 1, e) == m)) cycle
            start(m + 1) = start(m + 1) + 1
         end do
      end do
      start(1) = 1
      do m = 1, nnode
         start(m + 1) = start(m) + start(m + 1)
      end do
      allocate (adj(start(nnode + 1) - 1))
      fill = start(1:nnode)
      do e = 1, size(conn, 2)
         do k = 1, size(conn, 1)
            m = conn(k, e)
            if (any(conn(1:k - 1, e) == m)) cycle
            adj(fill(m)) = e
            fill(m) = fill(m) + 1
         end do
      end do
   end subroutine node_elements

   !> Nodes on the boundary of the set: the nodes of every element edge (between
   !> consecutive vertices) that no other element of the set shares.
   subroutine boundary_nodes(conn, nvert, start, adj, bnd)
      integer, intent(in) :: conn(:, :), nvert, start(:), adj(:)
      logical, allocatable, intent(out) :: bnd(:)
      integer :: e, k, a, b, j, f
      logical :: shared
      allocate (bnd(size(start) - 1), source=.false.)
      do e = 1, size(conn, 2)
         do k = 1, nvert
            a = conn(k, e); b = conn(mod(k, nvert) + 1, e)
            shared = .false.
            do j = start(a), start(a + 1) - 1
               f = adj(j)
               if (f /= e .and. any(conn(1:nvert, f) == b)) shared = .true.
            end do
            if (shared) cycle
            bnd(a) = .true.; bnd(b) = .true.
            ! mid-side node of a quadratic edge: numbered nvert + k (Gmsh order)
            if (size(conn, 1) > nvert) bnd(conn(nvert + k, e)) = .true.
         end do
      end do
   end subroutine boundary_nodes

   !> Elements around node n and every element sharing a node with them.
   subroutine second_ring(n, conn, start, adj, patch)
      integer, intent(in) :: n, conn(:, :), start(:), adj(:)
      integer, allocatable, intent(out) :: patch(:)
      integer :: j, k, i, f
      patch = adj(start(n):start(n + 1) - 1)
      do j = start(n), start(n + 1) - 1
         do k = 1, size(conn, 1)
            associate (m => conn(k, adj(j)))
               do i = start(m), start(m + 1) - 1
                  f = adj(i)
                  if (.not. any(patch == f)) patch = [patch, f]
               end do
            end associate
         end do
      end do
   end subroutine second_ring

   !> Least-squares fit of the basis to the point stresses of the patch elements, centred on
   !> xc and scaled by the largest distance h; drops to the linear, then constant basis when
   !> the points do not determine the full one (ok = .false. only for an empty patch).
   subroutine fit_patch(xc, patch, gx, sig, nb, nvert, coef, h, nbfit, ok)
      real(wp), intent(in) :: xc(2), gx(:, :, :), sig(:, :, :)
      integer, intent(in) :: patch(:), nb, nvert
      real(wp), intent(out) :: coef(8, NCOMP), h
      integer, intent(out) :: nbfit
      logical, intent(out) :: ok
      real(wp) :: ata(8, 8), atb(8, NCOMP), p(8)
      integer :: k, g, try, tries(3)
      h = 0.0_wp
      do k = 1, size(patch)
         do g = 1, size(gx, 2)
            h = max(h, norm2(gx(:, g, patch(k)) - xc))
         end do
      end do
      ok = h > 0.0_wp
      coef = 0.0_wp
      nbfit = 0
      if (.not. ok) return
      tries = [nb, 3, 1] ! full, linear, constant
      do try = 1, 3
         nbfit = tries(try)
         if (try > 1 .and. nbfit >= nb) cycle
         ata = 0.0_wp; atb = 0.0_wp
         do k = 1, size(patch)
            do g = 1, size(gx, 2)
               p = basis((gx(:, g, patch(k)) - xc)/h, nvert)
               ata(1:nbfit, 1:nbfit) = ata(1:nbfit, 1:nbfit) + &
                  spread(p(1:nbfit), 2, nbfit)*spread(p(1:nbfit), 1, nbfit)
               atb(1:nbfit, :) = atb(1:nbfit, :) + spread(p(1:nbfit), 2, NCOMP)* &
                  spread(sig(:, g, patch(k)), 1, nbfit)
            end do
         end do
         call solve_small(ata(1:nbfit, 1:nbfit), atb(1:nbfit, :), ok)
         if (ok) then
            coef(1:nbfit, :) = atb(1:nbfit, :)
            return
         end if
      end do
   end subroutine fit_patch

   !> Value of the fitted polynomial at scaled local coordinates s.
   pure function evaluate(coef, nbfit, nvert, s) result(v)
      real(wp), intent(in) :: coef(8, NCOMP), s(2)
      integer, intent(in) :: nbfit, nvert
      real(wp) :: v(NCOMP), p(8)
      p = basis(s, nvert)
      v = matmul(p(1:nbfit), coef(1:nbfit, :))
   end function evaluate

   !> Basis terms, the first 3 linear: (1, x, y, xy, x^2, y^2, x^2 y, x y^2) for
   !> quadrilaterals (Q4 uses the first 4, Q8 all 8), (1, x, y, x^2, xy, y^2) for triangles.
   pure function basis(s, nvert) result(p)
      real(wp), intent(in) :: s(2)
      integer, intent(in) :: nvert
      real(wp) :: p(8)
      if (nvert == 3) then
         p = [1.0_wp, s(1), s(2), s(1)**2, s(1)*s(2), s(2)**2, 0.0_wp, 0.0_wp]
      else
         p = [1.0_wp, s(1), s(2), s(1)*s(2), s(1)**2, s(2)**2, s(1)**2*s(2), s(1)*s(2)**2]
      end if
   end function basis

   !> Solves a x = b in place (b holds x) by Gaussian elimination with partial pivoting;
   !> ok = .false. when a pivot falls below PIVOT_TOL times the largest diagonal entry.
   pure subroutine solve_small(a, b, ok)
      real(wp), intent(inout) :: a(:, :), b(:, :)
      logical, intent(out) :: ok
      real(wp) :: scale, f
      real(wp), allocatable :: row(:), rowb(:)
      integer :: n, k, i, piv
      n = size(a, 1)
      scale = 0.0_wp
      do k = 1, n
         scale = max(scale, abs(a(k, k)))
      end do
      ok = scale > 0.0_wp
      if (.not. ok) return
      do k = 1, n
         piv = k - 1 + maxloc(abs(a(k:n, k)), dim=1)
         if (abs(a(piv, k)) <= PIVOT_TOL*scale) then
            ok = .false.
            return
         end if
         if (piv /= k) then
            row = a(k, :); a(k, :) = a(piv, :); a(piv, :) = row
            rowb = b(k, :); b(k, :) = b(piv, :); b(piv, :) = rowb
         end if
         do i = k + 1, n
            f = a(i, k)/a(k, k)
            a(i, k:n) = a(i, k:n) - f*a(k, k:n)
            b(i, :) = b(i, :) - f*b(k, :)
         end do
      end do
      do k = n, 1, -1
         b(k, :) = (b(k, :) - matmul(a(k, k + 1:n), b(k + 1:n, :)))/a(k, k)
      end do
   end subroutine solve_small

end module pecplas_estimate_recovery
