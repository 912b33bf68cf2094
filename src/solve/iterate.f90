!> The equilibrium iterations of one increment (thesis Annex A, extended): from the last
!> converged state to the load of step fraction tau1 (load control), or along an arc of
!> length dl with tau unknown (pecplas_solve_arc_length), by one of three methods:
!>   MODIFIED_NEWTON  the factorised stiffness of the run (the thesis's method);
!>   QUASI_NEWTON     the same factorisation with BFGS updates (pecplas_solve_bfgs);
!>   NEWTON           the consistent tangent refactorised every iteration,
!> each with an optional line search (pecplas_solve_line_search; not with arc-length).
!> An increment of imposed displacement enters the first iteration through the operator,
!> K du = F_ext - F_int(u_n) - K_fc dup (the stiffness columns of the constrained DOFs
!> times their change), so that the whole body follows the moved nodes from the start;
!> its later iterations, like every update, integrate each point from the converged state.
!> Full Newton with a previous increment of the same step (att%du_start) starts instead
!> from the linear extrapolation u_n + (dtau/dtau_prev) du_prev of the free DOFs, the
!> imposed ones at their new values, and iterates from there with the tangent of that
!> state (Abaqus's default extrapolation of a static step; doc/theory.md §4). A full Newton
!> step that re-closes joint points open at the iterate deep into their penalty is shortened
!> (pecplas_solve_reclosure).
!> The increment ends converged (||r|| <= tol ||F||), or failed with a reason: the
!> iteration cap, a stagnating residual, cycling joint states, a residual that blew up, a
!> singular tangent, a material that could not return, no real arc-length root.
!> newton_method_t is this solver behind the contract of pecplas_solve_method.
module pecplas_solve_iterate
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, ERR_SINGULAR, ERR_RUN
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: METHOD_MODIFIED, METHOD_QUASI, METHOD_NEWTON
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_stiffness, only: factorise_stiffness
   use pecplas_base_timers, only: wall_time
   use pecplas_solve_bfgs, only: bfgs_t
   use pecplas_solve_line_search, only: line_search_t
   use pecplas_solve_arc_length, only: arc_root, arc_predictor_sign
   use pecplas_solve_residual, only: load_vectors, free_residual, free_part, add_free, &
      joint_signature, internal_forces_at
   use pecplas_solve_method, only: attempt_t, outcome_t, increment_method_t
   use pecplas_fe_imposed, only: imposed_forces
   use pecplas_solve_reclosure, only: joint_snapshot_t, take_snapshot, reclosure_limit, &
      RESIDUAL_GROWTH
   implicit none (type, external)
   private

   public :: newton_method_t

   !> Modified Newton, quasi-Newton (BFGS) and full Newton (att%method), with or without
   !> line search, under load or arc-length control.
   type, extends(increment_method_t) :: newton_method_t
   contains
      procedure :: solve_increment => newton_solve_increment
   end type newton_method_t

   !> Memory of the BFGS pairs (2 n reals each): every pair of the increment while they fit
   !> in BFGS_BYTES, else the newest ones (at least BFGS_MIN_PAIRS; limited memory).
   real(wp), parameter :: BFGS_BYTES = 256.0_wp*2.0_wp**20
   integer, parameter :: BFGS_MIN_PAIRS = 10
   !> Early give-up of a single-factorisation method that is not the chain's last (see
   !> `hopeless` and attempt_t%budget), judged from MIN_RATE_ITERS iterations on.
   integer, parameter :: MIN_RATE_ITERS = 8, RATE_SPAN = 4, QN_SPAN = 8, QN_BLOCK = 4

contains

   !> The contract of pecplas_solve_method: iterate_increment.
   subroutine newton_solve_increment(this, model, problem, att, fint_conv, u, fint, reaction, &
         out, error)
      class(newton_method_t), intent(inout) :: this
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(attempt_t), intent(in) :: att
      real(wp), intent(in) :: fint_conv(:, :)
      real(wp), allocatable, intent(out) :: u(:, :), fint(:, :), reaction(:, :)
      type(outcome_t), intent(out) :: out
      type(error_t), allocatable, intent(out) :: error
      call iterate_increment(model, problem, att, fint_conv, u, fint, reaction, out, error)
   end subroutine newton_solve_increment

   !> One increment from the converged state (problem%state, with internal forces
   !> `fint_conv`): u, fint (internal forces) and reaction at the end, and the outcome.
   subroutine iterate_increment(model, problem, att, fint_conv, u, fint, reaction, out, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(attempt_t), intent(in) :: att
      real(wp), intent(in) :: fint_conv(:, :)
      real(wp), allocatable, intent(out) :: u(:, :), fint(:, :), reaction(:, :)
      type(outcome_t), intent(out) :: out
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: fext(:, :), fbase(:, :), fq(:, :), up(:, :), r(:), q(:), &
         du(:), vq(:), gfree(:), gold(:), hist(:), dtot(:), u_iter(:, :)
      integer, allocatable :: states(:)
      type(bfgs_t) :: bfgs
      type(line_search_t) :: ls
      type(joint_snapshot_t) :: snap
      real(wp) :: rnorm, ref, tau, dtau, eta, g0, g1, rfull
      integer :: neq, it
      logical :: moved, ok, elastic_now, imposed, extrapolated, reclose

      neq = problem%system%dofs%neq
      out%reason = ''
      call load_vectors(problem, att%f0, att%ftarget, merge(att%tau0, att%tau1, att%arc), &
         fbase, fq, up)
      tau = merge(att%tau0, att%tau1, att%arc)
      fext = fbase + tau*fq
      u = problem%state%u
      where (problem%system%dofs%eq == 0) u = up
      moved = any(u /= problem%state%u) .or. (tau /= att%tau0 .and. any(fq /= 0.0_wp))
      allocate (reaction(2, size(u, 2)), r(neq), du(neq), gfree(neq), dtot(neq), source=0.0_wp)
      allocate (hist(0:model%solver%max_iterations + 1), states(0:model%solver%max_iterations + 1))
      hist = 0.0_wp
      states = 0
      if (att%method == METHOD_QUASI) call bfgs%reset(neq, min(model%solver%max_iterations, &
         max(BFGS_MIN_PAIRS, int(BFGS_BYTES/(16.0_wp*max(neq, 1))))))
      q = free_part(problem, fq)
      fint = fint_conv
      ! moved imposed displacements: their linear response is the first iteration's load
      ! (load control; an arc-length increment keeps them at the step-start fraction)
      imposed = any(u /= problem%state%u) .and. .not. att%arc
      if (any(u /= problem%state%u) .and. att%arc) then
         call forces(u, error)
         if (allocated(error)) return
      end if
      out%tau = tau
      ! full Newton under load control: start from the extrapolated increment
      extrapolated = .false.
      ! (apply_operator reads it at the arc predictor, before the iterations set it: left
      ! undefined, a full-Newton arc of a run with a separate tangent solver, the fallback of
      ! modified and quasi-Newton, took the elastic or the tangent factor by chance, and the
      ! release build, the debug build and --quiet ended the same probe differently)
      elastic_now = .false.
      if (imposed .and. att%method == METHOD_NEWTON .and. allocated(att%du_start)) then
         if (size(att%du_start) == neq) then
            extrapolated = .true.
            imposed = .false.
            dtot = att%du_start
            call add_free(problem, dtot, u)
            call forces(u, error)
            if (allocated(error)) then
               ! a point that cannot return there: the tangent predictor after all, on the
               ! elastic stiffness (the points' tangents are no longer the converged ones)
               if (error%kind /= ERR_RUN) return
               deallocate (error)
               problem%state%converged_tangents = .false.
               extrapolated = .false.
               imposed = .true.
               dtot = 0.0_wp
               u = problem%state%u
               where (problem%system%dofs%eq == 0) u = up
               fint = fint_conv
            end if
         end if
      end if

      if (att%arc) then
         ! predictor: tangent (or stiffness) response to the step load, along the last
         ! converged increment
         if (att%method == METHOD_NEWTON) then
            call refactorise(error)
            if (allocated(error)) return
         end if
         allocate (vq(neq))
         call apply_operator(q, vq, error)
         if (allocated(error)) return
         if (.not. (norm2(vq) > 0.0_wp)) then
            out%reason = 'the step load does not move the free nodes (no arc-length direction)'
            return
         end if
         if (secant_predictor()) then
            ! on a plateau: along the last converged increment, the load unchanged
            dtau = 0.0_wp
            dtot = (att%dl/norm2(att%du_prev))*att%du_prev
         else
            dtau = arc_predictor_sign(att%du_prev, vq)*att%dl/norm2(vq)
            dtot = dtau*vq
         end if
         tau = tau + dtau
         fext = fbase + tau*fq
         u_iter = u
         call add_free(problem, dtot, u)
         gold = free_part(problem, fint)
         call forces(u, error)
         if (allocated(error)) return
         if (att%method == METHOD_QUASI) call push_pair(u - u_iter)
         moved = .true.
      end if

      it = 0
      do
         call free_residual(problem, fext, fint, r, reaction, rnorm, ref)
         out%residual = 0.0_wp
         if (ref > 0.0_wp) out%residual = rnorm/ref
         hist(it) = out%residual
         states(it) = joint_signature(problem%state%joints)
         out%iterations = it
         out%tau = tau
         if ((rnorm <= model%solver%tolerance*ref .or. rnorm == 0.0_wp) .and. &
             (it > 0 .or. .not. moved)) then
            out%converged = .true.
            exit
         end if
         out%blowup = .not. (rnorm < huge(1.0_wp))
         if (out%blowup) then
            out%reason = 'the residual became infinite or NaN'
            return
         end if
         if (it >= model%solver%max_iterations) then
            out%reason = cap_reason(hist(0:it), states(0:it), model%solver%max_iterations)
            return
         end if
         if (att%give_up_early .and. it >= MIN_RATE_ITERS) then
            if (hopeless(hist(0:it), model%solver%tolerance, &
                min(model%solver%max_iterations, att%budget), att%method == METHOD_MODIFIED)) then
               out%reason = 'stagnating residual (its rate would miss the iteration cap)'
               out%gave_up = .true.
               return
            end if
         end if
         elastic_now = .false.
         ! full Newton: the tangent of the current iterate; at the first iteration the last
         ! factorisation (the previous increment's tangent) unless there is none yet, or the
         ! elastic stiffness when imposed displacements move and the points' tangents are a
         ! discarded attempt's (after a rollback: see subtract_imposed)
         if (att%method == METHOD_NEWTON .and. it == 0 .and. imposed .and. &
             .not. problem%state%converged_tangents) then
            call elastic_operator(error)
            if (allocated(error)) return
         else if (att%method == METHOD_NEWTON .and. (it > 0 .or. extrapolated .or. &
             .not. tangent_ready())) then
            call refactorise(error)
            if (allocated(error)) return
         end if
         if (it == 0 .and. imposed) then
            call subtract_imposed(error)
            if (allocated(error)) return
         end if
         call apply_operator(r, du, error)
         if (allocated(error)) return
         if (att%arc) then
            if (att%method /= METHOD_MODIFIED .or. .not. allocated(vq)) then
               if (.not. allocated(vq)) allocate (vq(neq))
               call apply_operator(q, vq, error)
               if (allocated(error)) return
            end if
            call arc_root(dtot, du, vq, att%dl, dtau, ok)
            if (.not. ok) then
               out%reason = 'the arc-length constraint has no real root'
               return
            end if
            du = du + dtau*vq
            tau = tau + dtau
            fext = fbase + tau*fq
         end if
         u_iter = u
         gold = free_part(problem, fint)
         ! full Newton: the re-closure limit (pecplas_solve_reclosure) needs the joint
         ! points' states at the iterate the step starts from (not at the first step of an
         ! imposed increment, whose trial state is still the converged one)
         reclose = att%method == METHOD_NEWTON .and. .not. att%arc .and. &
            .not. (it == 0 .and. imposed)
         if (reclose) call take_snapshot(model, problem%state%joints, snap)
         call add_free(problem, du, u)
         call forces(u, error)
         if (allocated(error)) return
         if (reclose) then
            eta = reclosure_limit(model, problem%state%joints, snap)
            if (eta < 1.0_wp) then
               call free_residual(problem, fext, fint, gfree, reaction, rfull, ref)
               if (rfull > RESIDUAL_GROWTH*rnorm) then
                  du = eta*du
                  u = u_iter
                  call add_free(problem, du, u)
                  call forces(u, error)
                  if (allocated(error)) return
                  problem%stats%reclosure_limits = problem%stats%reclosure_limits + 1
               end if
            end if
         end if
         eta = 1.0_wp
         ! (not along the first step of an imposed increment: its residual at eta = 0 is
         ! that of the linear response, not of a state the search could return to)
         if (att%line_search .and. .not. att%arc .and. .not. (it == 0 .and. imposed)) then
            g0 = dot_product(du, r)
            call free_residual(problem, fext, fint, gfree, reaction, rnorm, ref)
            g1 = dot_product(du, gfree)
            call ls%start(g0, g1)
            do while (ls%next(eta))
               u = u_iter
               call add_free(problem, eta*du, u)
               call forces(u, error)
               if (allocated(error)) then
                  if (error%kind /= ERR_RUN) return
                  deallocate (error)
                  call ls%update(ieee_nan())
                  cycle
               end if
               call free_residual(problem, fext, fint, gfree, reaction, rnorm, ref)
               call ls%update(dot_product(du, gfree))
            end do
            out%line_searches = out%line_searches + ls%evals
            eta = ls%eta
         end if
         dtot = dtot + eta*du
         ! a BFGS pair relates free displacements to free forces: not the imposed step
         if (att%method == METHOD_QUASI .and. .not. (it == 0 .and. imposed)) &
            call push_pair(u - u_iter)
         it = it + 1
      end do
      out%du = dtot

   contains

      !> r = r - K_fc dup on the free equations, dup the change of the imposed displacements
      !> (u holds the new ones, the free DOFs the converged values), K the matrix of the
      !> operator: the points' consistent tangents (Newton, and quasi-Newton on a Newton
      !> run's tangent) or the elastic stiffness (modified Newton, quasi-Newton on it, and
      !> Newton when the tangents are not the converged state's); hist(0) becomes the
      !> linearised residual.
      subroutine subtract_imposed(err)
         type(error_t), allocatable, intent(out) :: err
         real(wp), allocatable :: fimp(:, :)
         logical :: tangent
         select case (att%method)
         case (METHOD_NEWTON)
            tangent = .not. elastic_now
         case (METHOD_QUASI)
            tangent = .not. problem%linear%separate_tangent
         case default
            tangent = .false.
         end select
         allocate (fimp, mold=u)
         call imposed_forces(model, problem%system%dofs, problem%system%rules, problem%state, &
            u - problem%state%u, tangent, fimp, err)
         if (allocated(err)) return
         r = r - free_part(problem, fimp)
         if (ref > 0.0_wp) hist(0) = norm2(r)/ref
      end subroutine subtract_imposed

      !> The arc predictor along the previous increment (att%secant): asked for, that
      !> increment at hand, and the predictor's operator not the consistent tangent (the
      !> elastic stiffness's response to the load on a plateau is a load many times the
      !> limit: step fraction 6.5 for an arc of 0.35 on the T6 footing of theory.md).
      logical function secant_predictor() result(yes)
         yes = .false.
         if (.not. att%secant .or. .not. allocated(att%du_prev)) return
         if (size(att%du_prev) /= neq) return
         ! (one that moved the loaded points back unloads: the load's response then)
         if (.not. (dot_product(att%du_prev, q) > 0.0_wp)) return
         yes = att%method /= METHOD_NEWTON .or. elastic_now
      end function secant_predictor

      !> Internal forces at u (a failed material return is a run error: the increment fails).
      subroutine forces(uu, err)
         real(wp), intent(in) :: uu(:, :)
         type(error_t), allocatable, intent(out) :: err
         call internal_forces_at(model, problem, uu, fint, err)
      end subroutine forces

      !> BFGS pair from the step du_step (nodal layout) and the change of free internal forces.
      subroutine push_pair(du_step)
         real(wp), intent(in) :: du_step(:, :)
         logical :: kept
         call bfgs%push(free_part(problem, du_step), free_part(problem, fint) - gold, kept)
      end subroutine push_pair

      !> Full Newton, first iteration after a rollback: the elastic stiffness (the run's own
      !> factorisation when it keeps one apart from the tangent's, else factorised now).
      subroutine elastic_operator(err)
         type(error_t), allocatable, intent(out) :: err
         elastic_now = .true.
         if (.not. problem%linear%separate_tangent) call factorise_stiffness(model, problem, &
            .false., err)
      end subroutine elastic_operator

      !> Full Newton: the consistent tangent at the current state. A singular tangent (a
      !> perfectly plastic zone, a joint in full slip) is no mechanism of the model: this
      !> iteration uses the elastic stiffness instead.
      subroutine refactorise(err)
         type(error_t), allocatable, intent(out) :: err
         call factorise_stiffness(model, problem, .true., err, tangent_solver=.true.)
         if (allocated(err)) then
            if (err%kind /= ERR_SINGULAR) return
            deallocate (err)
            elastic_now = .true.
            problem%stats%singular_tangents = problem%stats%singular_tangents + 1
            if (.not. problem%linear%separate_tangent) call factorise_stiffness(model, problem, &
               .false., err)
         end if
      end subroutine refactorise

      logical function tangent_ready()
         tangent_ready = .true.
         if (problem%linear%separate_tangent) tangent_ready = problem%linear%tangent_factorised
      end function tangent_ready

      !> x = (iteration operator) b: K^-1 b, H b (BFGS), or K_t^-1 b.
      subroutine apply_operator(b, x, err)
         real(wp), intent(in), contiguous :: b(:)
         real(wp), intent(out), contiguous :: x(:)
         type(error_t), allocatable, intent(out) :: err
         real(wp), allocatable :: bq(:), alpha(:)
         real(wp) :: t0
         t0 = wall_time()
         select case (att%method)
         case (METHOD_QUASI)
            bq = b
            allocate (alpha(max(bfgs%m, 1)))
            call bfgs%first_loop(bq, alpha)
            call problem%linear%solver%solve(bq, x, err)
            if (.not. allocated(err)) call bfgs%second_loop(alpha, x)
         case (METHOD_NEWTON)
            if (problem%linear%separate_tangent .and. .not. elastic_now) then
               call problem%linear%tsolver%solve(b, x, err)
            else
               call problem%linear%solver%solve(b, x, err)
            end if
         case default
            call problem%linear%solver%solve(b, x, err)
         end select
         problem%stats%solves = problem%stats%solves + 1
         problem%stats%time%solve = problem%stats%time%solve + (wall_time() - t0)
      end subroutine apply_operator

   end subroutine iterate_increment

   !> Why the iteration cap was reached: cycling joint states (the residual stalls while the
   !> count of slipping/open points keeps changing), a stagnating residual, or the cap alone.
   function cap_reason(hist, states, cap) result(reason)
      real(wp), intent(in) :: hist(0:)
      integer, intent(in) :: states(0:)
      integer, intent(in) :: cap
      character(len=:), allocatable :: reason
      integer :: n, k, changes
      character(len=16) :: buf
      n = ubound(hist, 1)
      write (buf, '(i0)') cap
      reason = 'iteration cap ('//trim(buf)//') reached'
      if (n < 10) return
      k = n - 9
      if (minval(hist(k:n)) < 0.5_wp*minval(hist(0:k - 1))) return
      changes = count(states(k:n) /= states(k - 1:n - 1))
      if (changes >= 3) then
         reason = 'cycling joint states (the residual stalls while slip/open states flip)'
      else
         reason = 'stagnating residual'
      end if
   end function cap_reason

   !> Whether a single-factorisation method followed by a stronger one in the chain should
   !> give up: true when the residual's contraction predicts more than `budget`
   !> iterations to reach `tol` (or no contraction at all). Modified Newton converges
   !> linearly: its rate is the mean contraction of the last RATE_SPAN iterations. BFGS
   !> converges irregularly (it speeds up as pairs accumulate, single steps may raise the
   !> residual): its rate compares the smallest residual of the last QN_BLOCK iterations
   !> with the smallest of the QN_BLOCK iterations QN_SPAN earlier, so that a single bad step
   !> does not decide, and it is judged from QN_SPAN + QN_BLOCK iterations on.
   pure logical function hopeless(hist, tol, budget, linear)
      real(wp), intent(in) :: hist(0:)
      real(wp), intent(in) :: tol
      integer, intent(in) :: budget
      logical, intent(in) :: linear
      real(wp) :: rate, need, now, before
      integer :: n, span
      n = ubound(hist, 1)
      hopeless = .false.
      span = RATE_SPAN
      if (linear) then
         now = hist(n)
         before = hist(n - RATE_SPAN)
      else
         if (n < QN_SPAN + QN_BLOCK) return
         span = QN_SPAN
         now = minval(hist(n - QN_BLOCK + 1:n))
         before = minval(hist(n - QN_SPAN - QN_BLOCK + 1:n - QN_SPAN))
      end if
      if (.not. (before > 0.0_wp) .or. .not. (now > 0.0_wp)) return
      rate = (now/before)**(1.0_wp/span)
      if (rate >= 1.0_wp) then
         hopeless = .true.
         return
      end if
      need = log(tol/now)/log(rate)
      hopeless = n + need > real(budget, wp)
   end function hopeless

   pure real(wp) function ieee_nan() result(x)
      use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
      x = ieee_value(x, ieee_quiet_nan)
   end function ieee_nan

end module pecplas_solve_iterate
