!> Partitioned assembly (pecplas_fe_share): the stiffness parts of N ranks, assembled here
!> one after the other in a serial run, add up to the whole stiffness, every element is
!> assembled exactly once, and each part holds about 1/N of the work. This is what MUMPS
!> receives in an MPI run (`make test-mpi` runs whole decks on 2 ranks against the serial
!> solvers).
module test_fe_share
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_prepare, only: prepare_run
   use pecplas_io_results_increment, only: joint_points_t
   use pecplas_fe_assembly, only: assemble_stiffness
   use pecplas_fe_share, only: share_t
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_linalg_sparse_reuse, only: csc_builder_t
   use pecplas_joints_katona_operator, only: add_augmentation
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_fe_share

   !> Ranks simulated: three, so that a middle rank (neither first nor last) is covered.
   integer, parameter :: NRANKS = 3

contains

   subroutine collect_fe_share(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('ranges', test_ranges), &
               new_unittest('parts_sum_goodman', test_goodman), &
               new_unittest('parts_sum_katona', test_katona)]
   end subroutine collect_fe_share

   !> Blocks of n items over N ranks: contiguous, disjoint, covering 1..n, lengths within
   !> one of each other (also n < N: empty blocks, first = last + 1).
   subroutine test_ranges(error)
      type(error_t), allocatable, intent(out) :: error
      type(share_t) :: sh
      integer :: n, r, first, last, next, lo, hi
      do n = 0, 11
         next = 1
         lo = huge(lo)
         hi = 0
         do r = 0, NRANKS - 1
            sh = share_t(rank=r, nranks=NRANKS)
            call sh%range(n, first, last)
            call check(error, first == next .and. last >= first - 1, 'contiguous blocks')
            if (allocated(error)) return
            next = last + 1
            lo = min(lo, last - first + 1)
            hi = max(hi, last - first + 1)
         end do
         call check(error, next == n + 1 .and. hi - lo <= 1, 'blocks cover 1..n evenly')
         if (allocated(error)) return
      end do
      sh = share_t()
      call sh%range(7, first, last)
      call check(error, sh%whole() .and. first == 1 .and. last == 7, 'default share: all')
   end subroutine test_ranges

   !> The default deck (S2 pile, Goodman joints): massif and joint sets split.
   subroutine test_goodman(error)
      type(error_t), allocatable, intent(out) :: error
      call check_parts('input/default.inp', .false., error)
   end subroutine test_goodman

   !> The S2 Katona deck: Katona sets whole on rank 0, whose part takes the augmentation.
   subroutine test_katona(error)
      type(error_t), allocatable, intent(out) :: error
      call check_parts('input/s2/s2_katona.inp', .true., error)
   end subroutine test_katona

   !> For the elastic stiffness and the stored tangents: the NRANKS parts add up to the
   !> whole within 1e-13 of its largest entry (the same element blocks, added in another
   !> order: roundoff), their triplets are exactly the whole's (each element once), and
   !> no part has more than 0.45 of them (a third, plus the joints and the Katona sets).
   subroutine check_parts(path, katona, error)
      character(len=*), intent(in) :: path
      logical, intent(in) :: katona
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(joint_points_t), allocatable :: jpoints(:)
      type(csc_builder_t) :: bwhole, bpart
      type(csc_t) :: whole, part
      real(wp), allocatable :: summed(:)
      integer :: nflipped, r, ntrip, nsum, pass, j, p, q
      logical :: tangent
      call read_deck(path, model, error)
      if (allocated(error)) return
      call prepare_run(model, problem, nflipped, jpoints, error)
      if (allocated(error)) return
      call check(error, problem%katona%active .eqv. katona, 'deck '//path//' has Katona '// &
         'contact as expected')
      if (allocated(error)) return
      do pass = 1, 2
         tangent = pass == 2
         call assemble_stiffness(model, problem%system%dofs, problem%system%rules, problem%state, tangent, &
            bwhole, whole, error)
         if (allocated(error)) return
         ntrip = bwhole%entries
         allocate (summed(whole%nnz()), source=0.0_wp)
         nsum = 0
         do r = 0, NRANKS - 1
            call assemble_stiffness(model, problem%system%dofs, problem%system%rules, problem%state, &
               tangent, bpart, part, error, share_t(rank=r, nranks=NRANKS))
            if (allocated(error)) return
            nsum = nsum + bpart%entries
            call check(error, bpart%entries <= 0.45_wp*ntrip, 'part of about a third')
            if (allocated(error)) return
            if (katona .and. r == 0) then
               ! rank 0 holds the doublet couplings that the augmentation adds to
               problem%katona%alpha = 1.0_wp
               call add_augmentation(problem%katona, problem%system%dofs, part, error)
               if (.not. allocated(error)) call add_augmentation(problem%katona, &
                  problem%system%dofs, whole, error)
               problem%katona%alpha = 0.0_wp
               if (allocated(error)) return
            end if
            do j = 1, part%n
               do p = part%colptr(j) + 1, part%colptr(j + 1)
                  q = whole%locate(part%rowind(p) + 1, j)
                  call check(error, q > 0, 'part pattern inside the whole pattern')
                  if (allocated(error)) return
                  summed(q) = summed(q) + part%values(p)
               end do
            end do
         end do
         call check(error, nsum == ntrip, 'every element block assembled once')
         if (allocated(error)) return
         call check_close(error, maxval(abs(summed - whole%values)), 0.0_wp, 0.0_wp, &
            'sum of the parts vs whole', atol=1.0e-13_wp*maxval(abs(whole%values)))
         if (allocated(error)) return
         deallocate (summed)
      end do
   end subroutine check_parts

end module test_fe_share
