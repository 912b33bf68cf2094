!> One load increment of a model with Katona contact (doc/theory.md §6.5, the Katona incremental-
!> iterative path with a bordered saddle-point solve): katona_method_t, the increment solver
!> of pecplas_solve_method for such models (pecplas_solve_method_factory chooses it). The load
!> path, the load vectors, the internal forces and the residual are those of every method
!> (pecplas_solve_residual); the rest of the driver (fallback chain, cuts, limit loads,
!> output) is shared.
!>
!> Each outer iteration linearises the massif (and any penalty joints) at u_j and solves
!>     [R  D^T] [du]   [F - f_int(u_j)]
!>     [D   0 ] [f ] = [d - D u_j     ]     (rows of d by contact state)
!> by the bordered (Schur complement) form of pecplas_joints_katona_states: R (or R_a when R is
!> singular) stays factorised, the flexibility G = D R_a^-1 D^T is built once per numeric
!> factorisation (so once per run under modified Newton with an elastic massif), and each
!> state iteration is one dense LU of order 2 nd. Two sparse solves per outer iteration:
!> w = D R_a^-1 r and du = R_a^-1 (r - D^T h). With a linear massif the first outer
!> iteration is exact and the second only confirms the residual.
module pecplas_solve_katona_increment
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, ERR_SINGULAR
   use pecplas_model_type, only: model_t
   use pecplas_problem_type, only: problem_t
   use pecplas_model_options, only: METHOD_NEWTON
   use pecplas_solve_stiffness, only: factorise_stiffness
   use pecplas_base_timers, only: wall_time
   use pecplas_joints_laws_type, only: MODE_OPEN
   use pecplas_joints_katona_operator, only: relative_displacements, add_contact_forces, &
      apply_d_free, add_dt_free, build_flexibility
   use pecplas_joints_katona_states, only: solve_states
   use pecplas_joints_katona_results, only: katona_joint_fields
   use pecplas_solve_arc_length, only: arc_root, arc_predictor_sign
   use pecplas_solve_method, only: attempt_t, outcome_t, increment_method_t
   use pecplas_solve_residual, only: load_vectors, internal_forces_at, free_residual, &
      free_part, add_free
   use pecplas_fe_imposed, only: imposed_forces
   implicit none (type, external)
   private

   public :: katona_method_t, update_flexibility

   !> Katona contact iterated inside modified Newton (the run's factorisation) or full Newton
   !> (att%method == METHOD_NEWTON: the consistent tangent every outer iteration); no
   !> quasi-Newton.
   type, extends(increment_method_t) :: katona_method_t
   contains
      procedure :: solve_increment => katona_solve_increment
      procedure :: has_quasi_newton => katona_has_quasi_newton
   end type katona_method_t

   !> Arc-length data of a Katona increment: the free step load q (per unit step fraction)
   !> and its nodal form fq, the length dl and the previous converged increment (the
   !> predictor's direction, may be empty); on exit the step
   !> fraction reached, the free increment du, ok / reason.
   type :: katona_arc_t
      real(wp), allocatable :: q(:), fq(:, :), vq(:), du(:), du_prev(:)
      real(wp) :: dl = 0.0_wp, tau = 0.0_wp, dtau = 0.0_wp
      integer :: vq_stamp = -1
      logical :: ok = .true.
      character(len=:), allocatable :: reason
   end type katona_arc_t

   !> Fixed-point rounds of contact states and load step per outer iteration.
   integer, parameter :: MAX_ARC_LOOPS = 30

   !> Residual accepted whatever the loads when below this fraction of the internal forces.
   real(wp), parameter :: ROUNDOFF_FLOOR = 1.0e-10_wp

contains

   pure logical function katona_has_quasi_newton(this) result(yes)
      class(katona_method_t), intent(in) :: this
      yes = .false.
   end function katona_has_quasi_newton

   !> The contract of pecplas_solve_method: u, fint (without contact forces), reaction (with
   !> them) at the end. Arc-length control (pecplas_solve_arc_length) when att%arc: the loads
   !> grow from those of step fraction att%tau0 by dtau fq, dtau an unknown held by
   !> ||Δu|| = att%dl; the load-factor row and column border the same saddle-point system:
   !> per outer iteration v_q = R^-1 q joins v_r = R^-1 r, and the contact states and dtau
   !> are solved together by a short fixed point (states for dtau, dtau for the states'
   !> forces).
   subroutine katona_solve_increment(this, model, problem, att, fint_conv, u, fint, reaction, &
         out, error)
      class(katona_method_t), intent(inout) :: this
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      type(attempt_t), intent(in) :: att
      real(wp), intent(in) :: fint_conv(:, :)
      real(wp), allocatable, intent(out) :: u(:, :), fint(:, :), reaction(:, :)
      type(outcome_t), intent(out) :: out
      type(error_t), allocatable, intent(out) :: error
      type(katona_arc_t) :: arc
      real(wp), allocatable :: fext(:, :), fbase(:, :), fq(:, :), up(:, :), fc(:, :), r(:), &
         rhs(:), v(:), w(:), zj(:, :), h(:)
      !> Arc-length work vectors (arc_states, phi_at).
      real(wp), allocatable :: vr(:), base(:), tmp(:), dirn(:)
      integer, allocatable :: flips(:)
      real(wp) :: rnorm, ref, t0, tau
      integer :: k, nstates, nit, n2
      logical :: newton, imposed

      out%reason = ''
      newton = att%method == METHOD_NEWTON
      associate (kt => problem%katona, dofs => problem%system%dofs, iters => out%iterations, &
                 residual => out%residual, converged => out%converged, blowup => out%blowup)
         n2 = 2*kt%nd
         tau = merge(att%tau0, att%tau1, att%arc)
         call load_vectors(problem, att%f0, att%ftarget, tau, fbase, fq, up)
         fext = fbase + tau*fq
         out%tau = tau
         if (att%arc) then
            arc%fq = fq
            arc%q = free_part(problem, fq)
            arc%dl = att%dl
            arc%tau = att%tau0
            if (allocated(att%du_prev)) then
               if (size(att%du_prev) > 0) arc%du_prev = att%du_prev
            end if
         end if
         u = problem%state%u
         where (dofs%eq == 0) u = up
         allocate (fint, mold=fint_conv)
         ! moved imposed displacements (load control): their linear response is the first
         ! outer iteration's load, as in pecplas_solve_iterate; the internal forces are then
         ! those of the converged state until the first update
         imposed = any(u /= problem%state%u) .and. .not. att%arc
         ! before the first converged increment the driver's fint_conv is the initial-stress
         ! load, which holds the initial contact forces too: the massif's own is needed here
         if (imposed .and. problem%stats%increments == 0) then
            call internal_forces_at(model, problem, problem%state%u, fint, error)
            if (allocated(error)) return
         else if (.not. imposed .and. (any(u /= problem%state%u) .or. &
                  problem%stats%increments == 0)) then
            call internal_forces_at(model, problem, u, fint, error)
            if (allocated(error)) return
         else
            fint = fint_conv
         end if
         call kt%begin_increment()
         allocate (flips(kt%nd), source=0)
         allocate (r(dofs%neq), rhs(dofs%neq), v(dofs%neq), w(n2), h(n2), zj(2, kt%nd))
         allocate (fc(2, size(u, 2)), reaction(2, size(u, 2)))
         converged = .false.
         blowup = .false.
         iters = 0
         nstates = 0
         do
            fc = 0.0_wp
            call add_contact_forces(kt, kt%f_trial, fc)
            call free_residual(problem, fext, fint + fc, r, reaction, rnorm, ref)
            rhs = free_part(problem, fext - fint)
            if (iters == 0 .and. imposed) then
               call subtract_imposed(error)
               if (allocated(error)) return
            end if
            residual = 0.0_wp
            if (ref > 0.0_wp) residual = rnorm/ref
            ! at least one solve: the states must be checked against the new loads. A state of
            ! nil load and reactions (a joint passing through zero stress, or bodies apart,
            ! under displacement control) has ref ~ roundoff: its residual is then measured
            ! against the internal forces and the forces of the run so far (ROUNDOFF_FLOOR)
            if (iters > 0 .and. (rnorm <= model%solver%tolerance*ref .or. rnorm == 0.0_wp .or. &
                rnorm <= ROUNDOFF_FLOOR*max(norm2(pack(fint, dofs%eq > 0)), kt%force_scale))) then
               ! converged by the roundoff floor: the residual recorded is relative to the
               ! forces it was measured against (rnorm over a roundoff ref would read as a
               ! residual far above the tolerance in the history)
               if (rnorm > model%solver%tolerance*ref) residual = rnorm/max(ref, &
                  norm2(pack(fint, dofs%eq > 0)), kt%force_scale)
               kt%force_scale = max(kt%force_scale, ref, norm2(fc))
               converged = .true.
               exit
            end if
            blowup = .not. (rnorm < huge(1.0_wp))
            if (blowup) then
               out%reason = 'the residual became infinite or NaN'
               return
            end if
            if (iters >= model%solver%max_iterations) then
               out%reason = 'contact iteration cap reached'
               return
            end if
            if (newton .and. iters > 0) then
               call factorise_stiffness(model, problem, .true., error)
               if (allocated(error)) then
                  if (error%kind /= ERR_SINGULAR) return
                  deallocate (error)
                  call factorise_stiffness(model, problem, .false., error)
                  if (allocated(error)) return
               end if
            end if
            call update_flexibility(problem, error)
            if (allocated(error)) return
            t0 = wall_time()
            call problem%linear%solver%solve(rhs, v, error)
            if (allocated(error)) return
            call relative_displacements(kt, u, zj)
            problem%stats%time%solve = problem%stats%time%solve + (wall_time() - t0)
            if (att%arc) then
               call arc_states(arc, iters == 0, v, error)
               if (allocated(error)) return
               if (.not. arc%ok) then
                  out%reason = arc%reason
                  return
               end if
               fext = fext + arc%dtau*arc%fq
               out%tau = arc%tau
            else
               call apply_d_free(kt, dofs, v, w)
               t0 = wall_time()
               call solve_states(kt, w, reshape(zj, [n2]), h, flips, nit, error)
               kt%time_states = kt%time_states + (wall_time() - t0)
               nstates = nstates + nit
               if (allocated(error)) return
               t0 = wall_time()
               call add_dt_free(kt, dofs, -h, rhs)
               call problem%linear%solver%solve(rhs, v, error)
               problem%stats%time%solve = problem%stats%time%solve + (wall_time() - t0)
               if (allocated(error)) return
               problem%stats%solves = problem%stats%solves + 2
            end if
            iters = iters + 1
            call add_free(problem, v, u)
            call internal_forces_at(model, problem, u, fint, error)
            if (allocated(error)) return
         end do
         ! converged: bookkeeping, joint results, and the contact state is accepted
         kt%state_iterations = kt%state_iterations + nstates
         kt%last_state_iterations = nstates
         kt%max_state_iterations = max(kt%max_state_iterations, nstates)
         call relative_displacements(kt, u, kt%z_trial)
         do k = 1, kt%nd
            if (kt%mode_trial(k) /= MODE_OPEN) kt%max_penetration = max(kt%max_penetration, &
               kt%z_trial(1, k) - kt%gap0(k))
         end do
         call katona_joint_fields(model, kt, u, problem%state%joints, error)
         if (allocated(error)) return
         call kt%commit()
         out%du = free_part(problem, u - problem%state%u)
      end associate

   contains

      !> rhs = rhs - K_fc dup on the free equations (pecplas_fe_imposed), dup the change of
      !> the imposed displacements, K the matrix the first outer iteration solves with: the
      !> points' converged tangents under full Newton (its first iteration keeps the last
      !> factorised tangent), else the elastic stiffness.
      subroutine subtract_imposed(err)
         type(error_t), allocatable, intent(out) :: err
         real(wp), allocatable :: fimp(:, :)
         allocate (fimp, mold=u)
         call imposed_forces(model, problem%system%dofs, problem%system%rules, &
            problem%state, u - problem%state%u, newton .and. problem%state%converged_tangents, &
            fimp, err)
         if (allocated(err)) return
         rhs = rhs - free_part(problem, fimp)
      end subroutine subtract_imposed

      !> One arc-length outer iteration: v = v_r on entry (R^-1 of the residual at the current
      !> load), the displacement step on exit; arc%dtau the load step, arc%ok false when the
      !> constraint has no real root or the states and dtau do not settle.
      subroutine arc_states(arc, first, v, err)
         type(katona_arc_t), intent(inout) :: arc
         logical, intent(in) :: first
         real(wp), intent(inout) :: v(:)
         type(error_t), allocatable, intent(out) :: err
         real(wp) :: dtau, dnew, x, xa, fa, fb, fx
         integer :: loop
         logical :: bracketed
         associate (kt => problem%katona, dofs => problem%system%dofs)
            if (.not. allocated(arc%vq) .or. arc%vq_stamp /= problem%stats%factorisations) then
               if (allocated(arc%vq)) deallocate (arc%vq)
               allocate (arc%vq(dofs%neq))
               call problem%linear%solver%solve(arc%q, arc%vq, err)
               if (allocated(err)) return
               arc%vq_stamp = problem%stats%factorisations
               problem%stats%solves = problem%stats%solves + 1
            end if
            if (.not. allocated(arc%du)) allocate (arc%du(dofs%neq), source=0.0_wp)
            vr = v
            dtau = 0.0_wp
            dirn = arc%du
            if (first) then
               dtau = arc%dl/norm2(arc%vq)
               if (allocated(arc%du_prev)) dtau = arc_predictor_sign(arc%du_prev, arc%vq)*dtau
               dirn = dtau*arc%vq
            end if
            if (allocated(tmp)) deallocate (tmp)
            allocate (tmp(dofs%neq))
            ! the constraint phi(x) = ||Δu + v(x)||^2 - dl^2, v(x) with the contact states of
            ! load step x: fixed-point proposals (the quadratic's root for the states at x),
            ! regula falsi (Illinois) once two iterates bracket the root
            arc%ok = .false.
            call phi_at(arc, dtau, fb, dnew, err)
            if (allocated(err) .or. .not. arc%ok) return
            xa = dtau
            fa = fb
            bracketed = .false.
            do loop = 1, MAX_ARC_LOOPS
               if (abs(fb) <= 1.0e-10_wp*arc%dl**2 .and. abs(dnew - dtau) <= 1.0e-8_wp* &
                   max(abs(dtau), 1.0e-12_wp)) exit
               if (bracketed) then
                  x = dtau - fb*(dtau - xa)/(fb - fa)
               else
                  x = dnew
               end if
               call phi_at(arc, x, fx, dnew, err)
               if (allocated(err) .or. .not. arc%ok) return
               if (fx*fb < 0.0_wp) then
                  xa = dtau
                  fa = fb
                  bracketed = .true.
               else if (bracketed) then
                  ! the retained end stays: halve its value (Illinois)
                  fa = 0.5_wp*fa
               end if
               dtau = x
               fb = fx
            end do
            arc%ok = abs(fb) <= 1.0e-8_wp*arc%dl**2
            if (.not. arc%ok) then
               arc%reason = 'contact states and the arc-length load step do not settle'
               return
            end if
            v = base + dtau*arc%vq
            arc%du = arc%du + v
            arc%tau = arc%tau + dtau
            arc%dtau = dtau
         end associate


      end subroutine arc_states

      !> Contact states for load step xx; base = v_r - R^-1 D^T h, phi of the constraint,
      !> the quadratic's root for these states (arc%ok false when it has none).
      subroutine phi_at(arc, xx, phi, root, e2)
         type(katona_arc_t), intent(inout) :: arc
         real(wp), intent(in) :: xx
         real(wp), intent(out) :: phi, root
         type(error_t), allocatable, intent(out) :: e2
         associate (kt => problem%katona, dofs => problem%system%dofs)
            call apply_d_free(kt, dofs, vr + xx*arc%vq, w)
            call solve_states(kt, w, reshape(zj, [n2]), h, flips, nit, e2)
            nstates = nstates + nit
            if (allocated(e2)) return
            tmp = 0.0_wp
            call add_dt_free(kt, dofs, -h, tmp)
            call problem%linear%solver%solve(tmp, v, e2)
            if (allocated(e2)) return
            problem%stats%solves = problem%stats%solves + 1
            base = vr + v
            phi = sum((arc%du + base + xx*arc%vq)**2) - arc%dl**2
            call arc_root(arc%du, base, arc%vq, arc%dl, root, arc%ok, dirn)
            if (.not. arc%ok) arc%reason = 'the arc-length constraint has no real root'
         end associate
      end subroutine phi_at

   end subroutine katona_solve_increment

   !> Builds the flexibility G = D R_a^-1 D^T of the Katona doublets from the factorisation
   !> in hand, unless G already belongs to it (counted: builds, solves, time).
   subroutine update_flexibility(problem, error)
      type(problem_t), intent(inout) :: problem
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: t0
      associate (kt => problem%katona)
         if (kt%g_stamp == problem%stats%factorisations) return
         t0 = wall_time()
         call build_flexibility(kt, problem%system%dofs, problem%linear%solver, kt%g, error)
         if (allocated(error)) return
         kt%g_stamp = problem%stats%factorisations
         kt%g_builds = kt%g_builds + 1
         kt%time_flexibility = kt%time_flexibility + (wall_time() - t0)
         problem%stats%solves = problem%stats%solves + 2*kt%nd
      end associate
   end subroutine update_flexibility

end module pecplas_solve_katona_increment
