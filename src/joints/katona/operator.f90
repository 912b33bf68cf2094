!> The constraint operator D of the Katona doublets (one 2 x 4 block per doublet k):
!>     z_k = (eps_n, eps_t) = ( n.(u_1 - u_2), t.(u_2 - u_1) )
!> (eps_n = -g_n closure positive, faces 1 and 2), its transpose (the nodal forces D^T f of
!> the contact forces f_k = (N, T), as a joint's internal force), the augmentation
!> alpha D^T D of a singular stiffness, and the flexibility G = D R^-1 D^T built with
!> multi-right-hand-side solves on the factorised R.
module pecplas_joints_katona_operator
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_fe_dofs, only: dofs_t
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_linalg_solver_type, only: linear_solver_t
   use pecplas_joints_katona_type, only: katona_t
   implicit none (type, external)
   private

   public :: doublet_rows, relative_displacements, add_contact_forces, apply_d_free, &
      add_dt_free, add_augmentation, build_flexibility

   !> Columns of the right-hand-side blocks of the flexibility solves.
   integer, parameter :: BLOCK_COLUMNS = 64

contains

   !> c(row, node, dir): row 1 = eps_n, 2 = eps_t; node 1 = face 1, 2 = face 2.
   pure function doublet_rows(kt, k) result(c)
      type(katona_t), intent(in) :: kt
      integer, intent(in) :: k
      real(wp) :: c(2, 2, 2)
      real(wp) :: n(2), t(2)
      t = kt%t(:, k)
      n = [-t(2), t(1)]
      c(1, 1, :) = n
      c(1, 2, :) = -n
      c(2, 1, :) = -t
      c(2, 2, :) = t
   end function doublet_rows

   !> z(2, nd) = D u for nodal displacements u(2, nnode).
   pure subroutine relative_displacements(kt, u, z)
      type(katona_t), intent(in) :: kt
      real(wp), intent(in) :: u(:, :)
      real(wp), intent(out) :: z(:, :)
      real(wp) :: c(2, 2, 2)
      integer :: k, r
      do k = 1, kt%nd
         c = doublet_rows(kt, k)
         do r = 1, 2
            z(r, k) = dot_product(c(r, 1, :), u(:, kt%node(1, k))) + &
               dot_product(c(r, 2, :), u(:, kt%node(2, k)))
         end do
      end do
   end subroutine relative_displacements

   !> fnodal(2, nnode) += D^T f for doublet forces f(2, nd).
   pure subroutine add_contact_forces(kt, f, fnodal)
      type(katona_t), intent(in) :: kt
      real(wp), intent(in) :: f(:, :)
      real(wp), intent(inout) :: fnodal(:, :)
      real(wp) :: c(2, 2, 2)
      integer :: k, a
      do k = 1, kt%nd
         c = doublet_rows(kt, k)
         do a = 1, 2
            fnodal(:, kt%node(a, k)) = fnodal(:, kt%node(a, k)) + c(1, a, :)*f(1, k) + &
               c(2, a, :)*f(2, k)
         end do
      end do
   end subroutine add_contact_forces

   !> z(2 nd) = D x for a vector x(neq) of the free equations (constrained dofs count 0).
   pure subroutine apply_d_free(kt, dofs, x, z)
      type(katona_t), intent(in) :: kt
      type(dofs_t), intent(in) :: dofs
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: z(:)
      real(wp) :: c(2, 2, 2)
      integer :: k, r, a, d, q
      z = 0.0_wp
      do k = 1, kt%nd
         c = doublet_rows(kt, k)
         do a = 1, 2
            do d = 1, 2
               q = dofs%eq(d, kt%node(a, k))
               if (q == 0) cycle
               do r = 1, 2
                  z(2*k - 2 + r) = z(2*k - 2 + r) + c(r, a, d)*x(q)
               end do
            end do
         end do
      end do
   end subroutine apply_d_free

   !> y(neq) += D^T h for h(2 nd) (free equations only).
   pure subroutine add_dt_free(kt, dofs, h, y)
      type(katona_t), intent(in) :: kt
      type(dofs_t), intent(in) :: dofs
      real(wp), intent(in) :: h(:)
      real(wp), intent(inout) :: y(:)
      real(wp) :: c(2, 2, 2)
      integer :: k, a, d, q
      do k = 1, kt%nd
         c = doublet_rows(kt, k)
         do a = 1, 2
            do d = 1, 2
               q = dofs%eq(d, kt%node(a, k))
               if (q == 0) cycle
               y(q) = y(q) + c(1, a, d)*h(2*k - 1) + c(2, a, d)*h(2*k)
            end do
         end do
      end do
   end subroutine add_dt_free

   !> k += alpha D^T D on the stored pattern. Per doublet D_k^T D_k = [I, -I; -I, I] (n and t
   !> orthonormal), so this ties the two nodes of every doublet like a stiff bonded spring.
   subroutine add_augmentation(kt, dofs, k, error)
      type(katona_t), intent(in) :: kt
      type(dofs_t), intent(in) :: dofs
      type(csc_t), intent(inout) :: k
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: block(4, 4)
      integer :: idx(4), j, i
      block = 0.0_wp
      do i = 1, 4
         block(i, i) = kt%alpha
      end do
      block(1, 3) = -kt%alpha; block(3, 1) = -kt%alpha
      block(2, 4) = -kt%alpha; block(4, 2) = -kt%alpha
      do j = 1, kt%nd
         idx = [dofs%eq(:, kt%node(1, j)), dofs%eq(:, kt%node(2, j))]
         call k%add_block(idx, block, error)
         if (allocated(error)) return
      end do
   end subroutine add_augmentation

   !> G = D R^-1 D^T (2 nd, 2 nd) with the factorised `solver` (R, or R_a when augmented),
   !> by blocks of BLOCK_COLUMNS right-hand sides.
   subroutine build_flexibility(kt, dofs, solver, g, error)
      type(katona_t), intent(in) :: kt
      type(dofs_t), intent(in) :: dofs
      class(linear_solver_t), intent(inout) :: solver
      real(wp), allocatable, intent(inout) :: g(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: b(:, :), x(:, :)
      real(wp) :: c(2, 2, 2)
      integer :: n2, first, nb, j, col, k, r, a, d, q
      n2 = 2*kt%nd
      if (allocated(g)) then
         if (size(g, 1) /= n2) deallocate (g)
      end if
      if (.not. allocated(g)) allocate (g(n2, n2))
      allocate (b(dofs%neq, min(BLOCK_COLUMNS, n2)), x(dofs%neq, min(BLOCK_COLUMNS, n2)))
      do first = 1, n2, BLOCK_COLUMNS
         nb = min(BLOCK_COLUMNS, n2 - first + 1)
         b(:, 1:nb) = 0.0_wp
         do j = 1, nb
            col = first + j - 1
            k = (col + 1)/2
            r = col - 2*(k - 1)
            c = doublet_rows(kt, k)
            do a = 1, 2
               do d = 1, 2
                  q = dofs%eq(d, kt%node(a, k))
                  if (q > 0) b(q, j) = b(q, j) + c(r, a, d)
               end do
            end do
         end do
         call solver%solve(b(:, 1:nb), x(:, 1:nb), error)
         if (allocated(error)) return
         do j = 1, nb
            call apply_d_free(kt, dofs, x(:, j), g(:, first + j - 1))
         end do
      end do
   end subroutine build_flexibility

end module pecplas_joints_katona_operator
