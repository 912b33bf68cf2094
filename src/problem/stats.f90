!> What a run counts and times for its summary and its results file: increments, iterations,
!> cuts, factorisations, solves, line searches, singular tangents, re-closure limits of full
!> Newton, increments converged by each method, and the phase timers.
module pecplas_problem_stats
   use pecplas_base_timers, only: timers_t
   implicit none (type, external)
   private

   public :: run_stats_t

   type :: run_stats_t
      integer :: increments = 0, iterations = 0, cuts = 0, factorisations = 0, solves = 0
      !> Line-search residual evaluations; tangents found singular (elastic used instead);
      !> increments converged by each method (modified, quasi-, full Newton) and under
      !> arc-length control.
      integer :: line_searches = 0, singular_tangents = 0, arc_increments = 0
      !> Full Newton steps shortened by the re-closure limit (pecplas_solve_reclosure).
      integer :: reclosure_limits = 0
      integer :: by_method(3) = 0
      type(timers_t) :: time
      !> A restarted run (pecplas_solve_restart): the increment it resumed after, the counts
      !> of pecplas_problem_counts of the run before it, read from the restart data
      !> (unallocated in data of an earlier version, which hold none), and this process's
      !> own counts when the step loop resumed (its set-up and the refactorisations of the
      !> restore are no part of the uninterrupted run).
      logical :: restarted = .false.
      integer :: resumed_after = 0
      integer, allocatable :: earlier(:), at_resume(:)
   end type run_stats_t

end module pecplas_problem_stats
