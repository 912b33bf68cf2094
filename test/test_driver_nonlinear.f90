!> The pieces of the nonlinear solution: BFGS two-loop against the dense update formula,
!> the line search on 1-D slopes with known roots, the arc-length root choice and the
!> length adaptation, the chain of methods with a remembered (lead) method.
module test_driver_nonlinear
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_solve_bfgs, only: bfgs_t
   use pecplas_solve_line_search, only: line_search_t
   use pecplas_solve_arc_length, only: arc_root, adapt_length, arc_predictor_sign
   use pecplas_solve_attempts, only: method_chain
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: METHOD_MODIFIED, METHOD_QUASI, METHOD_NEWTON
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_driver_nonlinear

   integer, parameter :: N = 5

contains

   subroutine collect_driver_nonlinear(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('bfgs_equals_dense_update', test_bfgs), &
               new_unittest('bfgs_skips_negative_curvature', test_bfgs_skip), &
               new_unittest('line_search_linear_slope', test_ls_linear), &
               new_unittest('line_search_nonlinear_slope', test_ls_tanh), &
               new_unittest('line_search_extrapolates', test_ls_extrapolate), &
               new_unittest('arc_root_does_not_turn_back', test_arc_root), &
               new_unittest('arc_length_adaptation', test_adapt), &
               new_unittest('chain_starts_with_its_lead', test_chain_lead)]
   end subroutine collect_driver_nonlinear

   !> K = Q diag(d) Q with Q = I - 2 v v^T / v.v (symmetric orthogonal): K^-1 = Q diag(1/d) Q.
   function kinv_apply(b) result(x)
      real(wp), intent(in) :: b(:)
      real(wp) :: x(size(b)), v(N), d(N)
      d = [1.0_wp, 2.0_wp, 5.0_wp, 10.0_wp, 50.0_wp]
      v = [1.0_wp, -2.0_wp, 0.5_wp, 3.0_wp, 1.0_wp]
      x = b - 2.0_wp*v*dot_product(v, b)/dot_product(v, v)
      x = x/d
      x = x - 2.0_wp*v*dot_product(v, x)/dot_product(v, v)
   end function kinv_apply

   !> H r by two loops with H0 = K^-1 equals the dense product after three updates
   !> H <- (I - rho s y^T) H (I - rho y s^T) + rho s s^T (pairs y = A s, A SPD: y.s > 0).
   subroutine test_bfgs(error)
      type(error_t), allocatable, intent(out) :: error
      type(bfgs_t) :: b
      real(wp) :: h(N, N), e(N, N), s(N, 3), y(N, 3), a(N, N), r(N), q(N), z(N), alpha(3), rho
      integer :: i, k
      logical :: kept
      e = 0.0_wp
      do i = 1, N
         e(i, i) = 1.0_wp
         h(:, i) = kinv_apply(e(:, i))
      end do
      a = reshape([(real(mod(7*i, 11), wp)/11.0_wp, i=1, N*N)], [N, N])
      a = matmul(transpose(a), a) + 3.0_wp*e
      s = reshape([(sin(real(i, wp)), i=1, 3*N)], [N, 3])
      y = matmul(a, s)
      call b%reset(N, 10)
      do k = 1, 3
         call b%push(s(:, k), y(:, k), kept)
         call check(error, kept, 'a pair of positive curvature is kept')
         if (allocated(error)) return
         rho = 1.0_wp/dot_product(y(:, k), s(:, k))
         h = matmul(matmul(e - rho*outer(s(:, k), y(:, k)), h), e - rho*outer(y(:, k), s(:, k))) &
            + rho*outer(s(:, k), s(:, k))
      end do
      r = [1.0_wp, -1.0_wp, 2.0_wp, 0.5_wp, -3.0_wp]
      q = r
      call b%first_loop(q, alpha)
      z = kinv_apply(q)
      call b%second_loop(alpha, z)
      call check_close(error, maxval(abs(z - matmul(h, r))), 0.0_wp, 0.0_wp, &
         'two-loop H r = dense BFGS H r', atol=1.0e-12_wp*maxval(abs(matmul(h, r))))
      if (allocated(error)) return
      ! secant condition of the newest pair: H y3 = s3
      q = y(:, 3)
      call b%first_loop(q, alpha)
      z = kinv_apply(q)
      call b%second_loop(alpha, z)
      call check_close(error, maxval(abs(z - s(:, 3))), 0.0_wp, 0.0_wp, 'H y = s', &
         atol=1.0e-12_wp)
   end subroutine test_bfgs

   subroutine test_bfgs_skip(error)
      type(error_t), allocatable, intent(out) :: error
      type(bfgs_t) :: b
      logical :: kept
      call b%reset(2, 4)
      call b%push([1.0_wp, 0.0_wp], [-1.0_wp, 0.0_wp], kept)
      call check(error, .not. kept .and. b%m == 0 .and. b%skipped == 1, &
         'y.s < 0 (unloading) is skipped: H stays positive definite')
   end subroutine test_bfgs_skip

   !> Runs the search on g; returns the final step, the evaluations and g there.
   subroutine search(g, eta, evals, gend)
      interface
         real(wp) function g(x)
            import :: wp
            real(wp), intent(in) :: x
         end function g
      end interface
      real(wp), intent(out) :: eta, gend
      integer, intent(out) :: evals
      type(line_search_t) :: ls
      real(wp) :: e
      call ls%start(g(0.0_wp), g(1.0_wp))
      gend = g(1.0_wp)
      do while (ls%next(e))
         gend = g(e)
         call ls%update(gend)
      end do
      eta = ls%eta
      evals = ls%evals
   end subroutine search

   real(wp) function g_linear(x)
      real(wp), intent(in) :: x
      g_linear = 1.0_wp - 3.0_wp*x
   end function g_linear

   real(wp) function g_tanh(x)
      real(wp), intent(in) :: x
      g_tanh = tanh(2.0_wp*(0.25_wp - x))
   end function g_tanh

   real(wp) function g_far(x)
      real(wp), intent(in) :: x
      g_far = 1.0_wp - 0.1_wp*x
   end function g_far

   !> A linear slope (quadratic energy, minimiser 1/3): one regula-falsi step is exact.
   subroutine test_ls_linear(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: eta, gend
      integer :: evals
      call search(g_linear, eta, evals, gend)
      call check_close(error, eta, 1.0_wp/3.0_wp, 1.0e-12_wp, 'minimiser 1/3 found')
      if (allocated(error)) return
      call check(error, evals == 1, 'in one evaluation')
   end subroutine test_ls_linear

   !> Minimiser 0.25 of a non-quadratic energy: the search stops where |g| <= 0.8 g(0), the
   !> last evaluation at the step returned, within 6 evaluations.
   subroutine test_ls_tanh(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: eta, gend
      integer :: evals
      call search(g_tanh, eta, evals, gend)
      call check(error, abs(g_tanh(eta)) <= 0.8_wp*g_tanh(0.0_wp) .and. evals <= 6 .and. &
         gend == g_tanh(eta), 'slope reduced to 0.8 g(0) at the returned step')
      if (allocated(error)) return
      call check(error, abs(eta - 0.25_wp) < 0.2_wp, 'step near the minimiser 0.25')
   end subroutine test_ls_tanh

   !> Minimiser at 10, beyond the Newton step: the secant extrapolates, capped at 2.
   subroutine test_ls_extrapolate(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: eta, gend
      integer :: evals
      call search(g_far, eta, evals, gend)
      call check_close(error, eta, 2.0_wp, 0.0_wp, 'extrapolated step capped at 2')
   end subroutine test_ls_extrapolate

   !> du = (1, 0), v_r = 0, v_q = (1, 0), dl = 1: roots 0 and -2; -2 would reverse the
   !> increment. Without a real root the vertex is taken.
   subroutine test_arc_root(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: dtau
      real(wp), allocatable :: du_prev(:)
      logical :: ok
      call arc_root([1.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp], 1.0_wp, dtau, ok)
      call check(error, ok, 'real roots')
      if (allocated(error)) return
      call check_close(error, dtau, 0.0_wp, 0.0_wp, 'the root that keeps the direction', &
         atol=1.0e-14_wp)
      if (allocated(error)) return
      ! a path that continues: du = (1, 1), v_r = (0, -1) (residual pulls back), v_q = (1, 0)
      call arc_root([1.0_wp, 1.0_wp], [0.0_wp, -1.0_wp], [1.0_wp, 0.0_wp], sqrt(2.0_wp), &
         dtau, ok)
      call check_close(error, dtau, sqrt(2.0_wp) - 1.0_wp, 1.0e-14_wp, &
         '(1 + dtau)^2 = 2: the forward root')
      if (allocated(error)) return
      ! the residual step alone exceeds dl: no real root; the vertex (closest point) is taken
      call arc_root([0.0_wp, 0.0_wp], [0.0_wp, 2.0_wp], [1.0_wp, 0.0_wp], 1.0_wp, dtau, ok)
      call check(error, ok .and. abs(dtau) < 1.0e-14_wp, 'no real root: the vertex -b/2a = 0')
      if (allocated(error)) return
      du_prev = [1.0_wp, -1.0_wp]
      call check(error, arc_predictor_sign(du_prev, [-1.0_wp, 0.0_wp]) < 0.0_wp, &
         'predictor follows the previous increment')
      if (allocated(error)) return
      ! the first increment of a path: no previous increment, the load rises
      deallocate (du_prev)
      call check(error, arc_predictor_sign(du_prev, [-1.0_wp, 0.0_wp]) > 0.0_wp, &
         'no previous increment: the predictor raises the load')
   end subroutine test_arc_root

   subroutine test_adapt(error)
      type(error_t), allocatable, intent(out) :: error
      call check_close(error, adapt_length(1.0_wp, 24, 6, 0.01_wp, 10.0_wp), 0.5_wp, 1.0e-14_wp, &
         '4x the wanted iterations halves the length')
      if (allocated(error)) return
      call check_close(error, adapt_length(1.0_wp, 1, 6, 0.01_wp, 10.0_wp), 2.0_wp, 1.0e-14_wp, &
         'growth capped at 2')
      if (allocated(error)) return
      call check_close(error, adapt_length(8.0_wp, 1, 6, 0.01_wp, 10.0_wp), 10.0_wp, 1.0e-14_wp, &
         'length capped at the maximum')
   end subroutine test_adapt

   pure function outer(a, b) result(m)
      real(wp), intent(in) :: a(:), b(:)
      real(wp) :: m(size(a), size(b))
      integer :: j
      do j = 1, size(b)
         m(:, j) = a*b(j)
      end do
   end function outer

   !> The chain of a modified-Newton run starts with a remembered stronger method and that
   !> method's own chain; a weaker lead (a NEWTON run that fell back to quasi-Newton) and
   !> FALLBACK=NO change nothing; without quasi-Newton (Katona) modified Newton takes its place.
   subroutine test_chain_lead(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      model%solver%method = METHOD_MODIFIED
      model%solver%fallback = .true.
      call same(method_chain(model, .true.), [METHOD_MODIFIED, METHOD_QUASI, METHOD_NEWTON], &
         'modified Newton, no lead')
      if (allocated(error)) return
      call same(method_chain(model, .true., 0), [METHOD_MODIFIED, METHOD_QUASI, METHOD_NEWTON], &
         'modified Newton, lead 0')
      if (allocated(error)) return
      call same(method_chain(model, .true., METHOD_QUASI), [METHOD_QUASI, METHOD_NEWTON], &
         'modified Newton, lead quasi-Newton')
      if (allocated(error)) return
      call same(method_chain(model, .true., METHOD_NEWTON), [METHOD_NEWTON, METHOD_QUASI], &
         'modified Newton, lead Newton')
      if (allocated(error)) return
      call same(method_chain(model, .false., METHOD_NEWTON), [METHOD_NEWTON, METHOD_MODIFIED], &
         'Katona, lead Newton')
      if (allocated(error)) return
      model%solver%method = METHOD_NEWTON
      call same(method_chain(model, .true., METHOD_QUASI), [METHOD_NEWTON, METHOD_QUASI], &
         'Newton, lead quasi-Newton (weaker: ignored)')
      if (allocated(error)) return
      model%solver%method = METHOD_MODIFIED
      model%solver%fallback = .false.
      call same(method_chain(model, .true., METHOD_NEWTON), [METHOD_MODIFIED], &
         'FALLBACK=NO, lead Newton (ignored)')
   contains
      subroutine same(got, want, what)
         integer, intent(in) :: got(:), want(:)
         character(len=*), intent(in) :: what
         logical :: ok
         ok = size(got) == size(want)
         if (ok) ok = all(got == want)
         call check(error, ok, what)
      end subroutine same
   end subroutine test_chain_lead

end module test_driver_nonlinear
