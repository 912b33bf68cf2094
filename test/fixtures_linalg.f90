!> Test matrices for the linear-algebra suites, assembled the way the finite-element code
!> will assemble them (element blocks into a triplet builder): 2D Laplacians, an upwind
!> convection-diffusion operator and a Q4 plane-strain elastic square.
module fixtures_linalg
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_linalg_sparse, only: coo_t, csc_t, coo_to_csc
   implicit none (type, external)
   private

   public :: laplacian, convection_diffusion, elastic_square, det_vector
   public :: SUPPORT_NONE, SUPPORT_ROLLER, SUPPORT_FIXED

   !> Bottom edge of the elastic square: free, vertical rollers only, or clamped.
   integer, parameter :: SUPPORT_NONE = 0, SUPPORT_ROLLER = 1, SUPPORT_FIXED = 2

contains

   !> 5-point Laplacian on an m x m grid of nodes, assembled from 2x2 edge blocks. With
   !> `dirichlet`, every missing neighbour adds 1 to the diagonal (eliminated boundary: SPD);
   !> without, it is the graph Laplacian whose null vector is the constant.
   !> Edges in the right half (x > m/2) are `contrast` times stiffer (default 1).
   subroutine laplacian(m, dirichlet, a, error, upper_only, contrast)
      integer, intent(in) :: m
      logical, intent(in) :: dirichlet
      type(csc_t), intent(out) :: a
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: upper_only
      real(wp), intent(in), optional :: contrast
      type(coo_t) :: coo
      real(wp) :: c, w
      integer :: i, j, p
      c = 1.0_wp
      if (present(contrast)) c = contrast
      call coo%init(m*m, 4*m*m, upper_only)
      do j = 1, m
         do i = 1, m
            p = (j - 1)*m + i
            w = merge(c, 1.0_wp, 2*i > m)
            if (i < m) call coo%add_block([p, p + 1], w*reshape([1, -1, -1, 1]*1.0_wp, [2, 2]))
            if (j < m) call coo%add_block([p, p + m], w*reshape([1, -1, -1, 1]*1.0_wp, [2, 2]))
            if (dirichlet) then
               call coo%add(p, p, w*(merge(1, 0, i == 1) + merge(1, 0, i == m) + &
                  merge(1, 0, j == 1) + merge(1, 0, j == m)))
            end if
         end do
      end do
      call coo_to_csc(coo, a, error)
   end subroutine laplacian

   !> -laplace(u) + (bx, by).grad(u) with first-order upwinding and Dirichlet boundaries:
   !> a non-symmetric M-matrix (nonsingular).
   subroutine convection_diffusion(m, bx, by, a, error)
      integer, intent(in) :: m
      real(wp), intent(in) :: bx, by
      type(csc_t), intent(out) :: a
      type(error_t), allocatable, intent(out) :: error
      type(coo_t) :: coo
      integer :: i, j, p
      call coo%init(m*m, 5*m*m)
      do j = 1, m
         do i = 1, m
            p = (j - 1)*m + i
            call coo%add(p, p, 4.0_wp + bx + by)
            if (i > 1) call coo%add(p, p - 1, -1.0_wp - bx)
            if (i < m) call coo%add(p, p + 1, -1.0_wp)
            if (j > 1) call coo%add(p, p - m, -1.0_wp - by)
            if (j < m) call coo%add(p, p + m, -1.0_wp)
         end do
      end do
      call coo_to_csc(coo, a, error)
   end subroutine convection_diffusion

   !> Unit square of m x m Q4 plane-strain elements (nu = 0.3, E = 1, or `contrast` in the
   !> right half). `support` fixes the bottom edge; equations are numbered node by node,
   !> skipping fixed dofs. is_x(k) tells whether equation k is a horizontal displacement.
   subroutine elastic_square(m, support, a, is_x, error, contrast)
      integer, intent(in) :: m, support
      type(csc_t), intent(out) :: a
      logical, allocatable, intent(out) :: is_x(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: contrast
      type(coo_t) :: coo
      integer, allocatable :: eq(:, :)
      integer :: i, j, k, node(4), idx(8), neq
      real(wp) :: ke(8, 8), e_right
      e_right = 1.0_wp
      if (present(contrast)) e_right = contrast
      allocate (eq(2, (m + 1)**2))
      neq = 0
      do k = 1, (m + 1)**2
         do i = 1, 2
            eq(i, k) = 0
            if (k <= m + 1 .and. (support == SUPPORT_FIXED .or. (support == SUPPORT_ROLLER .and. i == 2))) cycle
            neq = neq + 1
            eq(i, k) = neq
         end do
      end do
      allocate (is_x(neq))
      do k = 1, (m + 1)**2
         if (eq(1, k) > 0) is_x(eq(1, k)) = .true.
         if (eq(2, k) > 0) is_x(eq(2, k)) = .false.
      end do
      call q4_stiffness(1.0_wp/m, ke)
      call coo%init(neq, 64*m*m)
      do j = 1, m
         do i = 1, m
            node = [(j - 1)*(m + 1) + i, (j - 1)*(m + 1) + i + 1, j*(m + 1) + i + 1, j*(m + 1) + i]
            idx = reshape(eq(:, node), [8])
            call coo%add_block(idx, merge(e_right, 1.0_wp, 2*i > m)*ke)
         end do
      end do
      call coo_to_csc(coo, a, error)
   end subroutine elastic_square

   !> Q4 plane-strain stiffness of a square of side h (E = 1, nu = 0.3), 2x2 Gauss.
   subroutine q4_stiffness(h, ke)
      real(wp), intent(in) :: h
      real(wp), intent(out) :: ke(8, 8)
      real(wp), parameter :: nu = 0.3_wp, xa(4) = [-1, 1, 1, -1], ya(4) = [-1, -1, 1, 1]
      real(wp) :: d(3, 3), b(3, 8), g, xi, eta, dndx, dndy
      integer :: ig, jg, a
      d = reshape([1 - nu, nu, 0.0_wp, nu, 1 - nu, 0.0_wp, 0.0_wp, 0.0_wp, (1 - 2*nu)/2], [3, 3]) &
          /((1 + nu)*(1 - 2*nu))
      g = 1.0_wp/sqrt(3.0_wp)
      ke = 0.0_wp
      do jg = -1, 1, 2
         do ig = -1, 1, 2
            xi = ig*g
            eta = jg*g
            b = 0.0_wp
            do a = 1, 4
               dndx = xa(a)*(1 + eta*ya(a))/4*(2/h)
               dndy = ya(a)*(1 + xi*xa(a))/4*(2/h)
               b(1, 2*a - 1) = dndx
               b(2, 2*a) = dndy
               b(3, 2*a - 1) = dndy
               b(3, 2*a) = dndx
            end do
            ke = ke + matmul(transpose(b), matmul(d, b))*(h*h/4)
         end do
      end do
   end subroutine q4_stiffness

   !> A fixed, non-trivial vector (entries in [-1, 2)) to build right-hand sides from.
   pure function det_vector(n, seed) result(x)
      integer, intent(in) :: n, seed
      real(wp) :: x(n)
      integer :: i
      do i = 1, n
         x(i) = -1.0_wp + 3.0_wp*modulo(0.7548776662466927_wp*i + 0.5698402909980532_wp*seed, 1.0_wp)
      end do
   end function det_vector

end module fixtures_linalg
