!> The counts a run's summary prints beside its increments, iterations and cuts (which the
!> restart position carries itself): factorisations, solves, line-search residuals, singular
!> tangents, increments under arc-length control and by each method, and the Katona contact's
!> state iterations (total and largest per increment), flexibility builds and frozen doublets,
!> and the joint re-closure limits.
!> A restarted run adds its own counts since the resume to those of the run before it (its
!> restart data), so that its summary gives the whole run's, as the uninterrupted run's does.
module pecplas_problem_counts
   use pecplas_problem_type, only: problem_t
   implicit none (type, external)
   private

   public :: NCOUNT, C_FACTORISATIONS, C_SOLVES, C_LINE_SEARCHES, C_SINGULAR, C_ARC, &
      C_METHOD, C_STATE_ITERATIONS, C_MAX_STATE_ITERATIONS, C_G_BUILDS, C_FROZEN, C_RECLOSURE
   public :: process_counts, whole_counts, whole_known, mark_resume

   !> Positions in the counts (C_METHOD: the first of the three methods, modified,
   !> quasi- and full Newton).
   integer, parameter :: C_FACTORISATIONS = 1, C_SOLVES = 2, C_LINE_SEARCHES = 3, &
      C_SINGULAR = 4, C_ARC = 5, C_METHOD = 6, C_STATE_ITERATIONS = 9, &
      C_MAX_STATE_ITERATIONS = 10, C_G_BUILDS = 11, C_FROZEN = 12, C_RECLOSURE = 13
   !> Number of counts (the length of the restart item `counters`).
   integer, parameter :: NCOUNT = 13

contains

   !> This process's counts.
   pure function process_counts(problem) result(c)
      type(problem_t), intent(in) :: problem
      integer :: c(NCOUNT)
      associate (s => problem%stats, k => problem%katona)
         c = [s%factorisations, s%solves, s%line_searches, s%singular_tangents, &
            s%arc_increments, s%by_method, k%state_iterations, k%max_state_iterations, &
            k%g_builds, k%frozen, s%reclosure_limits]
      end associate
   end function process_counts

   !> Whether whole_counts are the whole run's: true but for a run restarted from data that
   !> hold no counts (written by an earlier version), where they are this process's.
   pure logical function whole_known(problem)
      type(problem_t), intent(in) :: problem
      whole_known = .not. problem%stats%restarted .or. allocated(problem%stats%earlier)
   end function whole_known

   !> The whole run's counts: this process's, plus, in a restarted run, those of the run
   !> before it less this process's at the resume (the largest state iterations of one
   !> increment: the larger of the two).
   pure function whole_counts(problem) result(c)
      type(problem_t), intent(in) :: problem
      integer :: c(NCOUNT), own(NCOUNT)
      own = process_counts(problem)
      c = own
      if (.not. allocated(problem%stats%earlier)) return
      if (.not. allocated(problem%stats%at_resume)) return
      associate (e => problem%stats%earlier, r => problem%stats%at_resume)
         c = e + own - r
         c(C_MAX_STATE_ITERATIONS) = max(e(C_MAX_STATE_ITERATIONS), own(C_MAX_STATE_ITERATIONS))
      end associate
   end function whole_counts

   !> Records this process's counts where the restarted step loop resumes.
   subroutine mark_resume(problem)
      type(problem_t), intent(inout) :: problem
      problem%stats%at_resume = process_counts(problem)
   end subroutine mark_resume

end module pecplas_problem_counts
