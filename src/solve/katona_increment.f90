!> One load increment of a model with Katona contact (doc/theory.md §6.5, the Katona incremental-
!> iterative path with a bordered saddle-point solve). Replaces the driver's Newton loop for
!> such models only (pecplas_solve_increments dispatches here); the rest of the driver
!> (cuts, limit loads, output) is shared.
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
   use pecplas_base_error, only: error_t, ERR_SINGULAR, ERR_RUN
   use pecplas_model_type, only: model_t
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_stiffness, only: factorise_stiffness
   use pecplas_base_timers, only: wall_time
   use pecplas_fe_assembly, only: internal_forces
   use pecplas_joints_laws_type, only: MODE_OPEN
   use pecplas_joints_katona_operator, only: relative_displacements, add_contact_forces, &
      apply_d_free, add_dt_free, build_flexibility
   use pecplas_joints_katona_states, only: solve_states
   use pecplas_joints_katona_results, only: katona_joint_fields
   use pecplas_solve_arc_length, only: arc_root, arc_predictor_sign
   implicit none (type, external)
   private

   public :: katona_increment, katona_arc_t

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

   !> Same contract as the driver's solve_increment: u, fint (without contact forces),
   !> reaction (with them) at the end; converged / blowup / iterations / residual.
   !> Arc-length control (pecplas_solve_arc_length) when `arc` is present: the loads grow
   !> from those of `factors` by dtau fq, dtau an unknown held by ||Δu|| = arc%dl; the
   !> load-factor row and column border the same saddle-point system: per outer iteration
   !> v_q = R^-1 q joins v_r = R^-1 r, and the contact states and dtau are solved together
   !> by a short fixed point (states for dtau, dtau for the states' forces).
   subroutine katona_increment(model, problem, factors, fint_conv, newton, u, fint, reaction, &
         converged, blowup, iters, residual, error, arc)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      real(wp), intent(in) :: factors(:), fint_conv(:, :)
      !> Consistent tangents every outer iteration (else the run's factorisation).
      logical, intent(in) :: newton
      real(wp), allocatable, intent(out) :: u(:, :), fint(:, :), reaction(:, :)
      logical, intent(out) :: converged, blowup
      integer, intent(out) :: iters
      real(wp), intent(out) :: residual
      type(error_t), allocatable, intent(out) :: error
      type(katona_arc_t), intent(inout), optional :: arc
      real(wp), allocatable :: fext(:, :), up(:, :), fc(:, :), r(:), rhs(:), v(:), w(:), &
         zj(:, :), h(:)
      !> Arc-length work vectors (arc_states, phi_at).
      real(wp), allocatable :: vr(:), base(:), tmp(:), dirn(:)
      integer, allocatable :: flips(:)
      real(wp) :: rnorm, ref, t0
      integer :: p, i, d, k, nstates, nit, n2

      associate (kt => problem%katona, dofs => problem%system%dofs)
         n2 = 2*kt%nd
         fext = problem%system%initial_force
         allocate (up(2, size(fint_conv, 2)), source=0.0_wp)
         do p = 1, size(factors)
            fext = fext + factors(p)*problem%system%pattern_force(:, :, p)
            up = up + factors(p)*problem%system%pattern_disp(:, :, p)
         end do
         u = problem%state%u
         where (dofs%eq == 0) u = up
         allocate (fint, mold=fint_conv)
         ! before the first converged increment the driver's fint_conv is the initial-stress
         ! load, which holds the initial contact forces too: the massif's own is needed here
         if (any(u /= problem%state%u) .or. problem%stats%increments == 0) then
            t0 = wall_time()
            call internal_forces(model, problem%system%rules, u, problem%state, fint, error, &
               problem%stats%time%laws)
            problem%stats%time%residual = problem%stats%time%residual + (wall_time() - t0)
            if (allocated(error)) call as_run_error(error)
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
            reaction = fint + fc - fext
            do i = 1, size(u, 2)
               do d = 1, 2
                  k = dofs%eq(d, i)
                  if (k > 0) then
                     r(k) = -reaction(d, i)
                     rhs(k) = fext(d, i) - fint(d, i)
                     reaction(d, i) = 0.0_wp
                  end if
               end do
            end do
            rnorm = norm2(r)
            ref = max(norm2(pack(fext - problem%system%initial_force, dofs%eq > 0)), norm2(reaction))
            if (ref == 0.0_wp) ref = norm2(pack(problem%system%initial_force, dofs%eq > 0))
            residual = 0.0_wp
            if (ref > 0.0_wp) residual = rnorm/ref
            ! at least one solve: the states must be checked against the new loads. A state of
            ! nil load and reactions (a joint passing through zero stress, or bodies apart,
            ! under displacement control) has ref ~ roundoff: its residual is then measured
            ! against the internal forces and the forces of the run so far (ROUNDOFF_FLOOR)
            if (iters > 0 .and. (rnorm <= model%solver%tolerance*ref .or. rnorm == 0.0_wp .or. &
                rnorm <= ROUNDOFF_FLOOR*max(norm2(pack(fint, dofs%eq > 0)), kt%force_scale))) then
               kt%force_scale = max(kt%force_scale, ref, norm2(fc))
               converged = .true.
               exit
            end if
            blowup = .not. (rnorm < huge(1.0_wp))
            if (iters >= model%solver%max_iterations .or. blowup) return
            if (newton .and. iters > 0) then
               call factorise_stiffness(model, problem, .true., error)
               if (allocated(error)) then
                  if (error%kind /= ERR_SINGULAR) return
                  deallocate (error)
                  call factorise_stiffness(model, problem, .false., error)
                  if (allocated(error)) return
               end if
            end if
            if (kt%g_stamp /= problem%stats%factorisations) then
               t0 = wall_time()
               call build_flexibility(kt, dofs, problem%linear%solver, kt%g, error)
               if (allocated(error)) return
               kt%g_stamp = problem%stats%factorisations
               kt%g_builds = kt%g_builds + 1
               kt%time_flexibility = kt%time_flexibility + (wall_time() - t0)
               problem%stats%solves = problem%stats%solves + n2
            end if
            t0 = wall_time()
            call problem%linear%solver%solve(rhs, v, error)
            if (allocated(error)) return
            call relative_displacements(kt, u, zj)
            problem%stats%time%solve = problem%stats%time%solve + (wall_time() - t0)
            if (present(arc)) then
               call arc_states(arc, iters == 0, v, error)
               if (allocated(error)) return
               if (.not. arc%ok) return
               fext = fext + arc%dtau*arc%fq
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
            do k = 1, dofs%neq
               u(dofs%eq_dir(k), dofs%eq_node(k)) = u(dofs%eq_dir(k), dofs%eq_node(k)) + v(k)
            end do
            t0 = wall_time()
            call internal_forces(model, problem%system%rules, u, problem%state, fint, error, &
               problem%stats%time%laws)
            problem%stats%time%residual = problem%stats%time%residual + (wall_time() - t0)
            if (allocated(error)) call as_run_error(error)
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
      end associate

   contains

      !> One arc-length outer iteration: v = v_r on entry (R^-1 of the residual at the current
      !> load), the displacement step on exit; arc%dtau the load step, arc%ok false when the
      !> constraint has no real root or the states and dtau do not settle.
      subroutine arc_states(arc, first, v, err)
         type(katona_arc_t), intent(inout) :: arc
         logical, intent(in) :: first
         real(wp), intent(inout) :: v(:)
         type(error_t), allocatable, intent(out) :: err
         real(wp) :: dtau, dnew, x, xa, fa, fb, fx
         integer :: loop, side
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
            side = 0
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
                  side = 0
               else if (bracketed) then
                  ! the retained end stays: halve its value (Illinois)
                  side = side + 1
                  if (side >= 1) fa = 0.5_wp*fa
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

   end subroutine katona_increment

   !> A material that cannot return cuts the increment (as in the driver).
   subroutine as_run_error(error)
      type(error_t), allocatable, intent(inout) :: error
      if (error%kind /= ERR_SINGULAR) error%kind = ERR_RUN
   end subroutine as_run_error

end module pecplas_solve_katona_increment
