!> The spurious zero-energy mode of Q8R (8 nodes, 2 x 2 points) and the condition under
!> which a mesh is free of it. Zero eigenvalues (< 1e-10 lambda_max) of the assembled plane
!> strain stiffness of small distorted meshes, LAPACK dsyev:
!> - one free element: 3 rigid modes + 1 spurious mode;
!> - meshes where every element shares a side (3 nodes) with another one: only the 3 rigid
!>   modes (the mode is not communicable: two neighbours cannot both deform in it);
!> - one element with minimal supports (3 dofs): the spurious mode is left (singular);
!>   with one side held (its 3 nodes fixed): none.
module test_massif_q8r
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_options, only: PLANE_STRAIN
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_factory, only: new_massif_element
   use pecplas_massif_kinematics, only: massif_rule_t, new_massif_rule
   use pecplas_testing, only: unittest_t, new_unittest, check
   use fixtures_massif, only: patch_t, assemble_stiffness, hooke, sym_eigenvalues
   implicit none (type, external)
   private
   public :: collect_massif_q8r

contains

   subroutine collect_massif_q8r(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('one_element_one_spurious_mode', test_one_element), &
               new_unittest('strip_2x1_rigid_only', test_strip), &
               new_unittest('patch_2x2_rigid_only', test_patch), &
               new_unittest('supports', test_supports)]
   end subroutine collect_massif_q8r

   !> nx x ny Q8R elements over [0, nx] x [0, ny] with interior corner nodes moved off the
   !> grid (a generic, non-rectangular geometry); mid-side nodes at the side midpoints. Only
   !> nodes used by an element are created.
   subroutine q8_grid(nx, ny, patch)
      integer, intent(in) :: nx, ny
      type(patch_t), intent(out) :: patch
      integer :: id(0:2*nx, 0:2*ny), i, j, e, n
      real(wp) :: x(2)
      id = 0
      n = 0
      do j = 0, 2*ny
         do i = 0, 2*nx
            if (mod(i, 2) == 1 .and. mod(j, 2) == 1) cycle ! element centre: not a Q8 node
            n = n + 1
            id(i, j) = n
         end do
      end do
      allocate (patch%x(2, n), patch%conn(8, nx*ny), patch%boundary(n))
      patch%boundary = .false.
      do j = 0, 2*ny, 2
         do i = 0, 2*nx, 2
            x = [real(i, wp), real(j, wp)]/2.0_wp
            ! smooth distortion that vanishes on the outer boundary
            x = x + 0.15_wp*[sin(real(i*j + 1, wp)), cos(real(3*i + j, wp))]* &
                merge(1.0_wp, 0.0_wp, i > 0 .and. i < 2*nx .and. j > 0 .and. j < 2*ny)
            patch%x(:, id(i, j)) = x
         end do
      end do
      do j = 0, 2*ny
         do i = 0, 2*nx
            if (id(i, j) == 0 .or. (mod(i, 2) == 0 .and. mod(j, 2) == 0)) cycle
            if (mod(i, 2) == 1) then
               patch%x(:, id(i, j)) = 0.5_wp*(patch%x(:, id(i - 1, j)) + patch%x(:, id(i + 1, j)))
            else
               patch%x(:, id(i, j)) = 0.5_wp*(patch%x(:, id(i, j - 1)) + patch%x(:, id(i, j + 1)))
            end if
         end do
      end do
      e = 0
      do j = 0, 2*ny - 2, 2
         do i = 0, 2*nx - 2, 2
            e = e + 1
            patch%conn(:, e) = [id(i, j), id(i + 2, j), id(i + 2, j + 2), id(i, j + 2), &
                                id(i + 1, j), id(i + 2, j + 1), id(i + 1, j + 2), id(i, j + 1)]
         end do
      end do
   end subroutine q8_grid

   !> Number of zero eigenvalues (< 1e-10 lambda_max) of the Q8R plane strain stiffness of
   !> `patch` (E = 1, nu = 0.3) with the dofs `fixed` removed; `gap` = smallest nonzero
   !> eigenvalue / lambda_max (separation from the zero ones).
   subroutine count_zero_modes(patch, fixed, nzero, gap, error)
      type(patch_t), intent(in) :: patch
      integer, intent(in) :: fixed(:)
      integer, intent(out) :: nzero
      real(wp), intent(out) :: gap
      type(error_t), allocatable, intent(out) :: error
      class(massif_element_t), allocatable :: elem
      type(massif_rule_t) :: rule
      real(wp), allocatable :: k(:, :), lam(:)
      logical, allocatable :: free(:)
      integer, allocatable :: dofs(:)
      integer :: info, i
      call new_massif_element('Q8R', elem, error)
      if (allocated(error)) return
      call new_massif_rule(rule, elem)
      call assemble_stiffness(elem, rule, PLANE_STRAIN, 1.0_wp, patch, hooke(1.0_wp, 0.3_wp), &
         k, error)
      if (allocated(error)) return
      allocate (free(size(k, 1)), source=.true.)
      free(fixed) = .false.
      dofs = pack([(i, i=1, size(k, 1))], free)
      allocate (lam(size(dofs)))
      call sym_eigenvalues(k(dofs, dofs), lam, info)
      call check(error, info == 0, 'dsyev failed')
      if (allocated(error)) return
      nzero = count(abs(lam) < 1.0e-10_wp*lam(size(lam)))
      gap = lam(min(nzero + 1, size(lam)))/lam(size(lam))
      write (*, '(a,i0,a,es9.2)') '        zero modes ', nzero, ', next eigenvalue / max ', gap
   end subroutine count_zero_modes

   subroutine expect_modes(nx, ny, fixed, expected, what, error)
      integer, intent(in) :: nx, ny, fixed(:), expected
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      type(patch_t) :: patch
      integer :: nzero
      real(wp) :: gap
      call q8_grid(nx, ny, patch)
      call count_zero_modes(patch, fixed, nzero, gap, error)
      if (allocated(error)) return
      ! separation: the stiffest deformation modes are ~1e3 times the softest here
      call check(error, nzero == expected .and. gap > 1.0e-5_wp, what)
   end subroutine expect_modes

   subroutine test_one_element(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_modes(1, 1, [integer ::], 4, 'one free Q8R: 3 rigid + 1 spurious mode', error)
   end subroutine test_one_element

   subroutine test_strip(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_modes(2, 1, [integer ::], 3, 'two Q8R sharing a side: rigid modes only', error)
   end subroutine test_strip

   subroutine test_patch(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_modes(2, 2, [integer ::], 3, '2 x 2 Q8R patch: rigid modes only', error)
   end subroutine test_patch

   !> Node numbering of q8_grid(1, 1): 1, 2, 3 bottom (corner, mid, corner), 4 and 5 the
   !> side mid-nodes, 6, 7, 8 top. Minimal supports: node 1 in x and y, node 3 in y.
   subroutine test_supports(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_modes(1, 1, [1, 2, 6], 1, 'one Q8R on minimal supports keeps its spurious mode', &
         error)
      if (allocated(error)) return
      call expect_modes(1, 1, [1, 2, 3, 4, 5, 6], 0, 'one Q8R with a side held: no zero mode', &
         error)
   end subroutine test_supports

end module test_massif_q8r
