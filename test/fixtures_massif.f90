!> Shared fixtures of the massif element tests: distorted sample elements, a distorted
!> patch mesh, dense assembly, Hooke matrix, and LAPACK (dgesv, dsyev) wrappers with
!> locally declared interfaces.
module fixtures_massif
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_massif_materials_elastic, only: elastic_t
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_kinematics, only: massif_rule_t
   use pecplas_massif_element_matrices, only: massif_stiffness
   implicit none (type, external)
   private

   public :: sample_xe, sample_points, hooke, dense_solve, sym_eigenvalues
   public :: patch_t, build_patch, assemble_stiffness, element_dofs, linear_field

   !> Patch of elements covering [x0, x0+1] x [0, 1].
   type :: patch_t
      real(wp), allocatable :: x(:, :)
      integer, allocatable :: conn(:, :)
      logical, allocatable :: boundary(:)
   end type patch_t

   interface
      subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: wp
         integer, intent(in) :: n, nrhs, lda, ldb
         real(wp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgesv
      subroutine dsyev(jobz, uplo, n, a, lda, w, work, lwork, info)
         import :: wp
         character(len=1), intent(in) :: jobz, uplo
         integer, intent(in) :: n, lda, lwork
         real(wp), intent(inout) :: a(lda, *)
         real(wp), intent(out) :: w(*), work(*)
         integer, intent(out) :: info
      end subroutine dsyev
   end interface

contains

   !> A distorted element of type `name` with r in [1, 2.3] (valid for axisymmetry).
   !> Quadratic elements get mid-side nodes moved off the chords (curved edges).
   function sample_xe(name) result(xe)
      character(len=*), intent(in) :: name
      real(wp), allocatable :: xe(:, :)
      real(wp), parameter :: TRI(2, 3) = reshape([1.1_wp, 0.2_wp, 2.3_wp, 0.5_wp, &
                                                  1.4_wp, 1.7_wp], [2, 3])
      real(wp), parameter :: QUAD(2, 4) = reshape([1.0_wp, 0.1_wp, 2.2_wp, 0.3_wp, &
                                                   2.0_wp, 1.4_wp, 1.2_wp, 1.1_wp], [2, 4])
      select case (name)
      case ('T3')
         xe = TRI
      case ('Q4')
         xe = QUAD
      case ('T6')
         xe = reshape([TRI, mid(TRI, 1, 2), mid(TRI, 2, 3), mid(TRI, 3, 1)], [2, 6])
         xe(:, 4) = xe(:, 4) + [0.03_wp, -0.05_wp]
         xe(:, 5) = xe(:, 5) + [0.04_wp, 0.02_wp]
      case ('Q8', 'Q8R')
         xe = reshape([QUAD, mid(QUAD, 1, 2), mid(QUAD, 2, 3), mid(QUAD, 3, 4), &
                       mid(QUAD, 4, 1)], [2, 8])
         xe(:, 5) = xe(:, 5) + [0.02_wp, -0.06_wp]
         xe(:, 7) = xe(:, 7) + [-0.03_wp, 0.04_wp]
      end select
   contains
      pure function mid(c, i, j) result(m)
         real(wp), intent(in) :: c(:, :)
         integer, intent(in) :: i, j
         real(wp) :: m(2)
         m = 0.5_wp*(c(:, i) + c(:, j))
      end function mid
   end function sample_xe

   !> Sample points inside the reference element (not Gauss points).
   function sample_points(name) result(p)
      character(len=*), intent(in) :: name
      real(wp) :: p(2, 3)
      if (name(1:1) == 'T') then
         p = reshape([0.2_wp, 0.3_wp, 0.6_wp, 0.1_wp, 0.05_wp, 0.85_wp], [2, 3])
      else
         p = reshape([0.3_wp, -0.7_wp, -0.5_wp, 0.2_wp, 0.9_wp, 0.95_wp], [2, 3])
      end if
   end function sample_points


   !> Isotropic Hooke matrix from the project's elastic material.
   function hooke(young, poisson) result(d)
      real(wp), intent(in) :: young, poisson
      real(wp) :: d(4, 4)
      type(elastic_t) :: mat
      mat%young = young
      mat%poisson = poisson
      call mat%elastic_tangent(d)
   end function hooke

   !> Solves a x = b in place (b becomes x) with LAPACK dgesv; info /= 0 on failure.
   subroutine dense_solve(a, b, info)
      real(wp), intent(inout) :: a(:, :), b(:)
      integer, intent(out) :: info
      integer :: ipiv(size(b))
      call dgesv(size(b), 1, a, size(a, 1), ipiv, b, size(b), info)
   end subroutine dense_solve

   !> Eigenvalues (ascending) of a symmetric matrix with LAPACK dsyev.
   subroutine sym_eigenvalues(a, lam, info)
      real(wp), intent(in) :: a(:, :)
      real(wp), intent(out) :: lam(:)
      integer, intent(out) :: info
      real(wp) :: work(64*size(a, 1)), c(size(a, 1), size(a, 2))
      c = a
      call dsyev('N', 'U', size(a, 1), c, size(a, 1), lam, work, size(work), info)
   end subroutine sym_eigenvalues

   !> Patch over [x0, x0+1] x [0, 1]: four distorted interior corner nodes; five
   !> quadrilaterals (Q4, Q8) or ten triangles (T3, T6, each quadrilateral cut along a
   !> diagonal); quadratic elements get mid-side nodes at edge midpoints.
   subroutine build_patch(name, x0, patch)
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: x0
      type(patch_t), intent(out) :: patch
      real(wp), parameter :: CORNERS(2, 8) = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, &
         1.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 0.2_wp, 0.15_wp, 0.75_wp, 0.25_wp, 0.7_wp, 0.7_wp, &
         0.3_wp, 0.8_wp], [2, 8])
      integer, parameter :: QUADS(4, 5) = reshape([5, 6, 7, 8, 1, 2, 6, 5, 2, 3, 7, 6, &
                                                   3, 4, 8, 7, 4, 1, 5, 8], [4, 5])
      integer, allocatable :: lin(:, :)
      integer :: e, k, nc, i, j
      real(wp) :: x(2, 64), tol
      if (name(1:1) == 'Q') then
         allocate (lin, source=QUADS)
      else
         allocate (lin(3, 10))
         do e = 1, 5
            lin(:, 2*e - 1) = QUADS([1, 2, 3], e)
            lin(:, 2*e) = QUADS([1, 3, 4], e)
         end do
      end if
      nc = size(lin, 1)
      x(:, 1:8) = CORNERS
      k = 8
      if (name == 'T6' .or. name(1:2) == 'Q8') then
         allocate (patch%conn(2*nc, size(lin, 2)))
         patch%conn(1:nc, :) = lin
         do e = 1, size(lin, 2)
            do i = 1, nc
               j = lin(mod(i, nc) + 1, e)
               call midside(0.5_wp*(x(:, lin(i, e)) + x(:, j)), patch%conn(nc + i, e))
            end do
         end do
      else
         patch%conn = lin
      end if
      patch%x = x(:, 1:k)
      tol = 1.0e-12_wp
      patch%boundary = abs(patch%x(1, :)) < tol .or. abs(patch%x(1, :) - 1.0_wp) < tol &
                       .or. abs(patch%x(2, :)) < tol .or. abs(patch%x(2, :) - 1.0_wp) < tol
      patch%x(1, :) = patch%x(1, :) + x0
   contains
      !> Node at point p: the existing one (shared edge) or a new one.
      subroutine midside(p, node)
         real(wp), intent(in) :: p(2)
         integer, intent(out) :: node
         do node = 9, k
            if (norm2(x(:, node) - p) < 1.0e-12_wp) return
         end do
         k = k + 1
         x(:, k) = p
         node = k
      end subroutine midside
   end subroutine build_patch

   !> Nodal values of the linear field u = A x + c (DOF order u1, v1, ...).
   pure function linear_field(xe, a, c) result(ue)
      real(wp), intent(in) :: xe(:, :), a(2, 2), c(2)
      real(wp) :: ue(2*size(xe, 2))
      integer :: k
      do k = 1, size(xe, 2)
         ue(2*k - 1:2*k) = matmul(a, xe(:, k)) + c
      end do
   end function linear_field

   !> DOF numbers (u1, v1, u2, v2, ...) of element nodes `nodes`.
   pure function element_dofs(nodes) result(dofs)
      integer, intent(in) :: nodes(:)
      integer :: dofs(2*size(nodes))
      dofs(1::2) = 2*nodes - 1
      dofs(2::2) = 2*nodes
   end function element_dofs

   !> Dense global stiffness of a patch with one Hooke matrix d at every point.
   subroutine assemble_stiffness(elem, rule, analysis_kind, thickness, patch, d, k, error)
      class(massif_element_t), intent(in) :: elem
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness
      type(patch_t), intent(in) :: patch
      real(wp), intent(in) :: d(4, 4)
      real(wp), allocatable, intent(out) :: k(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: ke(:, :), dg(:, :, :)
      integer :: e, ig
      integer, allocatable :: dofs(:)
      allocate (k(2*size(patch%x, 2), 2*size(patch%x, 2)), source=0.0_wp)
      allocate (ke(2*elem%nnode(), 2*elem%nnode()), dg(4, 4, rule%ngauss))
      do ig = 1, rule%ngauss
         dg(:, :, ig) = d
      end do
      do e = 1, size(patch%conn, 2)
         call massif_stiffness(rule, analysis_kind, thickness, patch%x(:, patch%conn(:, e)), dg, &
            ke, error)
         if (allocated(error)) return
         dofs = element_dofs(patch%conn(:, e))
         k(dofs, dofs) = k(dofs, dofs) + ke
      end do
   end subroutine assemble_stiffness

end module fixtures_massif
