!> The one contract of an increment solver: from the last converged state (problem%state,
!> with internal forces fint_conv) to the load of step fraction tau1 (load control), or along
!> an arc of length dl with the step fraction unknown (arc-length control), the load given
!> by an attempt_t in one form for every method: the step's path of pattern factors
!> f0 + (ftarget - f0) tau (pecplas_solve_residual's path_factor, turned into load vectors by
!> its load_vectors). On exit u, the internal forces and the reactions at the end, and an
!> outcome_t (converged, or why not).
!>
!> Newton-type methods (pecplas_solve_iterate: modified Newton, BFGS, full Newton) and Katona
!> contact (pecplas_solve_katona_increment: the states of the contact doublets iterated
!> inside modified or full Newton) implement it; pecplas_solve_method_factory chooses one for
!> a model, and pecplas_solve_attempts runs it through the fallback chain and the cuts.
module pecplas_solve_method
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_options, only: METHOD_MODIFIED
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_residual, only: path_factor
   implicit none (type, external)
   private

   public :: attempt_t, outcome_t, increment_method_t, CHAIN_BUDGET

   !> Default of attempt_t%budget.
   integer, parameter :: CHAIN_BUDGET = 20

   !> What to try: method, line search, control, and the step's load path
   !> factors(tau) = f0 + (ftarget - f0) tau.
   type :: attempt_t
      !> METHOD_MODIFIED, METHOD_QUASI or METHOD_NEWTON (pecplas_model_options).
      integer :: method = METHOD_MODIFIED
      logical :: line_search = .false.
      !> Give up as soon as the residual's rate shows the cap will be missed (a later method
      !> of the chain takes over); false for the last method, which runs to the cap.
      logical :: give_up_early = .false.
      !> The iterations the method may be predicted to need before it gives up early:
      !> min(cap, budget). The chain's first attempts use CHAIN_BUDGET: a full-Newton
      !> increment takes 3 to 7 iterations, each costing a residual plus an assembly and
      !> factorisation of the tangent, about two residuals on the 2 000-equation footing of
      !> doc/bench/peer_footing.md (a ratio that grows with the mesh), so a
      !> single-factorisation crawl predicted past 20 saves little or nothing.
      integer :: budget = CHAIN_BUDGET
      !> Arc-length control (tau unknown, ||Δu|| = dl); else load control to tau1.
      logical :: arc = .false.
      real(wp) :: dl = 0.0_wp
      !> Previous converged free increment (the arc predictor's sign); may be empty.
      real(wp), allocatable :: du_prev(:)
      !> Arc-length on a plateau window: where the predictor's operator is not the consistent
      !> tangent (single-factorisation methods, a singular tangent replaced by the elastic
      !> stiffness), the predictor is du_prev scaled to dl at the same load (secant) instead
      !> of that operator's response to the load (doc/theory.md section 4, "Plateau").
      logical :: secant = .false.
      !> Load control: the previous converged free increment of the step scaled to this
      !> one's size, the start of a full-Newton increment whose imposed displacements move
      !> (linear extrapolation, pecplas_solve_iterate); empty: the tangent predictor.
      real(wp), allocatable :: du_start(:)
      real(wp), allocatable :: f0(:), ftarget(:)
      real(wp) :: tau0 = 0.0_wp, tau1 = 0.0_wp
   contains
      !> The pattern factors at step fraction tau.
      procedure :: factors => attempt_factors
   end type attempt_t

   type :: outcome_t
      logical :: converged = .false., blowup = .false.
      integer :: iterations = 0, line_searches = 0
      real(wp) :: residual = 0.0_wp
      !> Step fraction reached (tau1 under load control).
      real(wp) :: tau = 0.0_wp
      !> Why it failed ('' when converged); singular: the system of the states the iteration
      !> reached has no unique solution (a mechanism under those states).
      character(len=:), allocatable :: reason
      logical :: singular = .false.
      !> The attempt gave up early (att%give_up_early: its rate would miss the cap).
      logical :: gave_up = .false.
      !> Free displacement increment of the increment.
      real(wp), allocatable :: du(:)
   end type outcome_t

   !> An increment solver (module header).
   type, abstract :: increment_method_t
   contains
      procedure(solve_increment_i), deferred :: solve_increment
      !> Whether the method can take quasi-Newton (BFGS) iterations; the fallback chain
      !> (pecplas_solve_attempts) puts modified Newton in their place when not.
      procedure :: has_quasi_newton => method_has_quasi_newton
   end type increment_method_t

   abstract interface
      !> One increment (module header). A run error (a material that cannot return, a
      !> contact state iteration that cannot settle) or a singular system comes back as
      !> `error` with the kind ERR_RUN or ERR_SINGULAR: the attempt failed, the run goes on.
      subroutine solve_increment_i(this, model, problem, att, fint_conv, u, fint, reaction, &
            out, error)
         import :: increment_method_t, model_t, problem_t, attempt_t, outcome_t, error_t, wp
         class(increment_method_t), intent(inout) :: this
         type(model_t), intent(in) :: model
         type(problem_t), intent(inout) :: problem
         type(attempt_t), intent(in) :: att
         real(wp), intent(in) :: fint_conv(:, :)
         real(wp), allocatable, intent(out) :: u(:, :), fint(:, :), reaction(:, :)
         type(outcome_t), intent(out) :: out
         type(error_t), allocatable, intent(out) :: error
      end subroutine solve_increment_i
   end interface

contains

   pure function attempt_factors(this, tau) result(f)
      class(attempt_t), intent(in) :: this
      real(wp), intent(in) :: tau
      real(wp) :: f(size(this%f0))
      f = path_factor(this%f0, this%ftarget, tau)
   end function attempt_factors

   pure logical function method_has_quasi_newton(this) result(yes)
      class(increment_method_t), intent(in) :: this
      yes = .true.
   end function method_has_quasi_newton

end module pecplas_solve_method
