!> Which elements a rank assembles when the stiffness is partitioned among the ranks of an
!> MPI run (doc/mpi.md): every element set, massif or joint, is cut into `nranks`
!> contiguous blocks of nearly equal length and rank r assembles block r. The sum over the
!> ranks of the partial matrices is the whole stiffness; MUMPS adds the parts (distributed
!> assembled input). Katona contact sets (zero blocks that only carry the pattern of the
!> augmentation) stay whole on rank 0, which alone adds the augmentation.
module pecplas_fe_share
   use pecplas_base_kinds, only: ik8
   use pecplas_base_parallel, only: parallel_rank, parallel_size
   implicit none (type, external)
   private

   public :: share_t, share_of_run

   !> Rank `rank` of `nranks` (the default, one rank, is the whole assembly).
   type :: share_t
      integer :: rank = 0, nranks = 1
   contains
      procedure :: range => share_range
      procedure :: whole => share_whole
   end type share_t

contains

   !> This process's share: partitioned among the MPI ranks when `partitioned`, else whole.
   function share_of_run(partitioned) result(share)
      logical, intent(in) :: partitioned
      type(share_t) :: share
      if (.not. partitioned) return
      share%rank = parallel_rank()
      share%nranks = max(1, parallel_size())
   end function share_of_run

   !> Items first..last of n (last = first - 1 when the block is empty).
   pure subroutine share_range(this, n, first, last)
      class(share_t), intent(in) :: this
      integer, intent(in) :: n
      integer, intent(out) :: first, last
      first = int((int(n, ik8)*this%rank)/this%nranks) + 1
      last = int((int(n, ik8)*(this%rank + 1))/this%nranks)
   end subroutine share_range

   !> True when this share is the whole assembly (one rank).
   pure logical function share_whole(this)
      class(share_t), intent(in) :: this
      share_whole = this%nranks <= 1
   end function share_whole

end module pecplas_fe_share
