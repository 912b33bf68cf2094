!> The step's load path and load vectors, the internal forces and the residual on the free
!> equations, and conversions between nodal arrays (2, nnode) and vectors of the free
!> equations, shared by every increment method (pecplas_solve_method).
module pecplas_solve_residual
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, ERR_SINGULAR, ERR_RUN
   use pecplas_base_timers, only: wall_time
   use pecplas_model_type, only: model_t
   use pecplas_fe_assembly, only: internal_forces
   use pecplas_problem_type, only: problem_t
   use pecplas_joints_state, only: joint_state_t
   use pecplas_joints_laws_type, only: MODE_SLIP, MODE_OPEN
   implicit none (type, external)
   private

   !> Loads and reactions below this fraction of the held load are roundoff.
   real(wp), parameter :: HELD_ROUNDOFF = 1.0e-10_wp

   public :: path_factor, load_vectors, internal_forces_at, free_residual, free_part, add_free, &
      joint_signature

contains

   !> The load path of a step: pattern factor f0 + (ftarget - f0) tau at step fraction tau,
   !> from the factor f0 at the start of the step to its target ftarget.
   elemental real(wp) function path_factor(f0, ftarget, tau) result(f)
      real(wp), intent(in) :: f0, ftarget, tau
      f = f0 + (ftarget - f0)*tau
   end function path_factor

   !> The step's loads at step fraction tau: F_ext = fbase + tau fq, with fbase the initial
   !> stress forces plus the patterns at their step-start factors f0 and fq the change of the
   !> force patterns over the step; up the imposed displacements at fraction `tau_up`. In a
   !> phased run the held load of the active sets stands for the initial-stress forces and
   !> the phase's carried out-of-balance c goes from fbase to zero: fbase + c, fq - c.
   subroutine load_vectors(problem, f0, ftarget, tau_up, fbase, fq, up)
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: f0(:), ftarget(:), tau_up
      real(wp), allocatable, intent(out) :: fbase(:, :), fq(:, :), up(:, :)
      integer :: p
      fbase = problem%system%initial_force
      allocate (fq, up, mold=fbase)
      fq = 0.0_wp
      up = 0.0_wp
      do p = 1, size(f0)
         fbase = fbase + f0(p)*problem%system%pattern_force(:, :, p)
         if (ftarget(p) /= f0(p)) fq = fq + (ftarget(p) - f0(p))*problem%system%pattern_force(:, :, p)
         up = up + path_factor(f0(p), ftarget(p), tau_up)*problem%system%pattern_disp(:, :, p)
      end do
      ! a phase's supports hold their dofs where they were installed
      if (allocated(problem%phase%held_u)) up = up + problem%phase%held_u
      ! a phase's out-of-balance, carried from the step start to zero at its end
      if (allocated(problem%phase%carried)) then
         fbase = fbase + problem%phase%carried
         fq = fq - problem%phase%carried
      end if
   end subroutine load_vectors

   !> Internal forces fint at the nodal displacements u from the converged state (timed as
   !> the residual). A material or law that cannot return is a run error (the attempt fails,
   !> the increment is retried or cut); a singular system stays ERR_SINGULAR.
   subroutine internal_forces_at(model, problem, u, fint, error)
      type(model_t), intent(in) :: model
      type(problem_t), intent(inout) :: problem
      real(wp), intent(in) :: u(:, :)
      real(wp), intent(out) :: fint(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: t0
      t0 = wall_time()
      call internal_forces(model, problem%system%rules, u, problem%state, fint, error, &
         problem%stats%time%laws)
      problem%stats%time%residual = problem%stats%time%residual + (wall_time() - t0)
      if (allocated(error)) then
         if (error%kind /= ERR_SINGULAR) error%kind = ERR_RUN
      end if
   end subroutine internal_forces_at

   !> r = F_ext - F_int on the free equations, the reactions (F_int - F_ext on the supported
   !> ones), ||r|| and the reference of the convergence test: the applied loads and
   !> reactions (not the initial-stress forces, which would loosen the criterion; those only
   !> when nothing else acts).
   subroutine free_residual(problem, fext, fint, r, reaction, rnorm, ref)
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: fext(:, :), fint(:, :)
      real(wp), intent(out) :: r(:), reaction(:, :), rnorm, ref
      real(wp) :: held
      integer :: i, d, k
      reaction = fint - fext
      do i = 1, size(fint, 2)
         do d = 1, 2
            k = problem%system%dofs%eq(d, i)
            if (k > 0) then
               r(k) = fext(d, i) - fint(d, i)
               reaction(d, i) = 0.0_wp
            end if
         end do
      end do
      rnorm = norm2(r)
      if (allocated(problem%phase%base_reaction)) then
         ! a phased run: the reactions from those of the K0 state (its weight's)
         ref = max(free_norm(problem, fext, problem%system%initial_force), &
            norm2(reaction - problem%phase%base_reaction))
      else
         ref = max(free_norm(problem, fext, problem%system%initial_force), norm2(reaction))
      end if
      ! nothing acts beyond the held load but roundoff (a nil step on a balanced state, joints
      ! closed back onto the initial state by imposed displacements: loads and reactions nil):
      ! measured against the held load, the initial-stress forces
      held = free_norm(problem, problem%system%initial_force)
      if (ref <= HELD_ROUNDOFF*held) ref = held
   end subroutine free_residual

   !> norm2(pack(a - b, eq > 0)) (b absent: of a), the free equations' entries in array
   !> order, without the temporaries of the difference, the mask and the packed copy.
   real(wp) function free_norm(problem, a, b) result(v)
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: a(:, :)
      real(wp), intent(in), optional :: b(:, :)
      real(wp), allocatable :: w(:)
      integer :: i, d, k
      allocate (w(size(a)))
      k = 0
      ! two loops, not one testing present(b) inside: -O3 versions the single loop on the
      ! strides of a and b and reads b's descriptor when b is absent (harmless: both versions
      ! compute the same; but memcheck reports it as a read of an undefined value)
      if (present(b)) then
         do i = 1, size(a, 2)
            do d = 1, size(a, 1)
               if (problem%system%dofs%eq(d, i) <= 0) cycle
               k = k + 1
               w(k) = a(d, i) - b(d, i)
            end do
         end do
      else
         do i = 1, size(a, 2)
            do d = 1, size(a, 1)
               if (problem%system%dofs%eq(d, i) <= 0) cycle
               k = k + 1
               w(k) = a(d, i)
            end do
         end do
      end if
      v = norm2(w(1:k))
   end function free_norm

   !> The free equations' entries of a nodal array.
   function free_part(problem, a) result(v)
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: a(:, :)
      real(wp), allocatable :: v(:)
      integer :: k
      allocate (v(problem%system%dofs%neq))
      do k = 1, problem%system%dofs%neq
         v(k) = a(problem%system%dofs%eq_dir(k), problem%system%dofs%eq_node(k))
      end do
   end function free_part

   !> u = u + v on the free equations.
   subroutine add_free(problem, v, u)
      type(problem_t), intent(in) :: problem
      real(wp), intent(in) :: v(:)
      real(wp), intent(inout) :: u(:, :)
      integer :: k
      do k = 1, problem%system%dofs%neq
         u(problem%system%dofs%eq_dir(k), problem%system%dofs%eq_node(k)) = &
            u(problem%system%dofs%eq_dir(k), problem%system%dofs%eq_node(k)) + v(k)
      end do
   end subroutine add_free

   !> A number that changes when the trial slip/open states of the joint points change
   !> (the count of slipping points plus 100003 times the open ones).
   pure integer function joint_signature(joints) result(sig)
      type(joint_state_t), intent(in) :: joints
      integer :: s
      sig = 0
      if (.not. allocated(joints%sets)) return
      do s = 1, size(joints%sets)
         sig = sig + count(joints%sets(s)%mode_trial == MODE_SLIP) + &
            100003*count(joints%sets(s)%mode_trial == MODE_OPEN)
      end do
   end function joint_signature

end module pecplas_solve_residual
