!> Statuses of interface runs are claims about the run (doc/theory.md §4, "Convergence,
!> increment cutting and statuses"), checked here against bounds that statics give.
!>
!> A block pushed along a Katona interface (test/data/katona/push_block_arc.inp: c = 5 kPa,
!> phi = 30, no tensile strength) by a horizontal force on its top, under arc-length control.
!> The block's top is free and its initial stress, -100 kPa, is a dead load: vertical
!> equilibrium keeps the contact force at N = 100 kN/m whatever the horizontal force, so the
!> block slides only at T >= N tan(phi) = 57.735 kN/m, and at most at c L + N tan(phi) =
!> 62.735 kN/m (the whole 1 m in contact). A 'limit load' must lie in that range, less the
!> resolution of the load-controlled probe that establishes a mechanism (PROBE_STEP = 1e-3 of
!> the step's load of 100 kN/m: 0.1 kN/m): the true limit lies between the last converged
!> load and the failed probe. (Before: 'limit load' at 54.38 kN/m under 10 arc increments,
!> declared a mechanism when the probe step failed because one doublet's contact states did
!> not settle, not because the system was singular; load control carries 60.6 kN/m.)
!>
!> A joint opened, slid and closed back (test/data/joints/close_back.inp) ends in the initial
!> state moved along the joint: loads and reactions nil, the joint at sigma_n = 100 kPa,
!> tau = 0. The run must complete there (before: 'diverged' after 27 cuts of the closing
!> step, each remaining increment failing against a reference of loads and reactions at
!> roundoff, 1e-12 kN/m, while the residual was 1e-13).
module test_pecjoin_claims
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_pecjoin_claims

   character(len=*), parameter :: DIR = 'build/test_out/claims', DATA = 'test/data/katona/'
   !> N tan(phi) and c L + N tan(phi) of the pushed block (kN/m), and the probe's resolution.
   real(wp), parameter :: T_LOW = 57.735026918962575_wp, T_HIGH = 62.735026918962575_wp, &
      PROBE = 0.1_wp

contains

   subroutine collect_pecjoin_claims(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('katona_push_arc10_claim', test_push_arc10), &
               new_unittest('katona_push_arc40_limit', test_push_arc40), &
               new_unittest('joint_closed_back_completes', test_close_back)]
   end subroutine collect_pecjoin_claims

   !> 10 arc increments: whatever the status, a limit load is within the statics bounds.
   subroutine test_push_arc10(error)
      type(error_t), allocatable, intent(out) :: error
      call push(10, .false., error)
   end subroutine test_push_arc10

   !> 40 arc increments: the path reaches the limit (measured 60.635 kN/m), which must be
   !> claimed and lie within the bounds.
   subroutine test_push_arc40(error)
      type(error_t), allocatable, intent(out) :: error
      call push(40, .true., error)
   end subroutine test_push_arc40

   !> Completes, in one increment per step; sigma_n = 100 kPa and tau = 0 at every point within
   !> the convergence test's bound (TOLERANCE 1e-4 of the held load, 100 kPa: 1e-2 kPa).
   subroutine test_close_back(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      character(len=200) :: buf
      integer :: code
      call make_directories(DIR)
      code = run_deck('test/data/joints/close_back.inp', DIR//'/close_back.h5', .true., model, &
         problem)
      write (buf, '(a,i0,a,i0,a)') ' (exit ', code, ', ', problem%stats%increments, ' increments)'
      call check(error, code == 0 .and. problem%stats%increments == 3, &
         'the joint closed back onto its initial state completes'//trim(buf))
      if (allocated(error)) return
      associate (st => problem%state%joints%sets(1))
         write (buf, '(a,2es12.4)') ' sigma_n - 100, |tau|: ', maxval(abs(st%sigma(1, :, :) - &
            100.0_wp)), maxval(abs(st%sigma(2, :, :)))
         call check(error, maxval(abs(st%sigma(1, :, :) - 100.0_wp)) <= 1.0e-2_wp .and. &
            maxval(abs(st%sigma(2, :, :))) <= 1.0e-2_wp, &
            'the joint is back at sigma_n = 100 kPa, tau = 0'//trim(buf))
      end associate
   end subroutine test_close_back

   subroutine push(increments, must_claim, error)
      integer, intent(in) :: increments
      logical, intent(in) :: must_claim
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: rd
      character(len=:), allocatable :: text, deck, h5, status
      character(len=40) :: name
      character(len=200) :: buf
      real(wp) :: load
      integer :: code, u, n, i
      call make_directories(DIR)
      write (name, '(a,i0)') 'push_block_arc', increments
      deck = DIR//'/'//trim(name)//'.inp'
      h5 = DIR//'/'//trim(name)//'.h5'
      open (newunit=u, file=DATA//'push_block_arc.inp', access='stream', form='unformatted')
      inquire (unit=u, size=n)
      allocate (character(len=n) :: text)
      read (u) text
      close (u)
      i = index(text, 'INCREMENTS=10,')
      write (buf, '(a,i0,a)') 'INCREMENTS=', increments, ','
      text = text(:i - 1)//trim(buf)//text(i + len('INCREMENTS=10,'):)
      open (newunit=u, file=deck, access='stream', form='unformatted', status='replace')
      write (u) text
      close (u)
      code = run_deck(deck, h5, .true., model, problem)
      call rd%open(h5, error)
      if (allocated(error)) return
      call rd%attribute('/', 'status', status, error)
      call rd%close()
      if (allocated(error)) return
      load = problem%state%factors(1)
      write (buf, '(a,i0,a,f10.4,a)') ' (exit ', code, ', status '//status//', last load ', &
         load, ' kN/m)'
      write (*, '(a)') '       '//trim(buf)
      call check(error, status /= 'completed' .and. code == 3, &
         'the block cannot carry 100 kN/m: the run stops'//trim(buf))
      if (allocated(error)) return
      if (must_claim) then
         call check(error, status == 'limit load', 'the limit is reached and claimed'//trim(buf))
         if (allocated(error)) return
      end if
      if (status /= 'limit load') return
      call check(error, load >= T_LOW - PROBE .and. load <= T_HIGH, &
         'a limit load between N tan(phi) - 0.1 and c L + N tan(phi) kN/m'//trim(buf))
   end subroutine push

end module test_pecjoin_claims
