!> How a run ended, as an enumerator: the increment loop, the adaptive and advice drivers and
!> the command line compare these values; the words ('completed', 'limit load', ...) exist
!> only here and are used where a status is written (results file, console, tables).
!>
!>   RUN_COMPLETED    every step reached its end (a safety step's end: its factor found);
!>   RUN_LIMIT_LOAD   the load-displacement path has a maximum (doc/theory.md section 4);
!>   RUN_DIVERGED     no equilibrium was found at any cut, and no limit was established;
!>   RUN_STOPPED      an arc-length step used its MAX_INCREMENTS before its target, a safety
!>                    step its MAX_INCREMENTS before failure (its factor a lower bound), or a
!>                    homogeneous path stopped before its last target;
!>   RUN_FAILED       the run ended on an error (the results file keeps what converged);
!>   RUN_INTERRUPTED  a termination signal or --stop-after-increments: goes on with --restart.
!> RUN_NOT_RUN marks a configuration that was never run (advice tables).
module pecplas_base_run_status
   implicit none (type, external)
   private

   enum, bind(c)
      enumerator :: RUN_NOT_RUN = 0, RUN_COMPLETED, RUN_LIMIT_LOAD, RUN_DIVERGED, RUN_STOPPED, &
         RUN_FAILED, RUN_INTERRUPTED
   end enum
   public :: RUN_NOT_RUN, RUN_COMPLETED, RUN_LIMIT_LOAD, RUN_DIVERGED, RUN_STOPPED, RUN_FAILED, &
      RUN_INTERRUPTED
   public :: status_name, is_run_status

   !> STATUS_NAMES(s) is the results-file and console word of status s (s >= 1).
   character(len=*), parameter :: STATUS_NAMES(6) = [character(len=11) :: 'completed', &
      'limit load', 'diverged', 'stopped', 'failed', 'interrupted']

contains

   !> The word of `status` as written to the results file and the console; 'not run' for
   !> RUN_NOT_RUN, 'unknown' for a value that is no status.
   pure function status_name(status) result(name)
      integer, intent(in) :: status
      character(len=:), allocatable :: name
      if (status == RUN_NOT_RUN) then
         name = 'not run'
      else if (is_run_status(status)) then
         name = trim(STATUS_NAMES(status))
      else
         name = 'unknown'
      end if
   end function status_name

   !> True when `status` is the status of a run that ended (RUN_COMPLETED .. RUN_INTERRUPTED).
   elemental logical function is_run_status(status)
      integer, intent(in) :: status
      is_run_status = status >= RUN_COMPLETED .and. status <= size(STATUS_NAMES)
   end function is_run_status

end module pecplas_base_run_status
