!> Wall-clock time spent in each phase of a run, for the summary and the benchmarks.
module pecplas_base_timers
   use pecplas_base_kinds, only: wp, ik8
   implicit none (type, external)
   private

   public :: timers_t, wall_time

   type :: timers_t
      real(wp) :: assembly = 0.0_wp, factorisation = 0.0_wp, solve = 0.0_wp
      real(wp) :: residual = 0.0_wp, output = 0.0_wp, setup = 0.0_wp
      !> Part of `residual` spent in the constitutive updates (stress integration at the
      !> massif Gauss points and the joint force routine, whose cost is its law updates).
      !> The updates of linear elastic sets are not timed (a clock read costs more).
      real(wp) :: laws = 0.0_wp
      !> MUMPS runs (doc/mpi.md): this rank's stiffness assembly time (wall, CPU), and the
      !> smallest and largest over the ranks (updated at each assembly; zero otherwise).
      real(wp) :: rank_wall = 0.0_wp, rank_cpu = 0.0_wp
      real(wp) :: rank_wall_min = 0.0_wp, rank_wall_max = 0.0_wp
      real(wp) :: rank_cpu_min = 0.0_wp, rank_cpu_max = 0.0_wp
   end type timers_t

contains

   !> Seconds from an arbitrary origin (system_clock, 64-bit).
   real(wp) function wall_time()
      integer(ik8) :: count, rate
      call system_clock(count, rate)
      wall_time = real(count, wp)/real(rate, wp)
   end function wall_time

end module pecplas_base_timers
