!> Re-assembly of a CSC matrix from a repeated triplet sequence (full Newton assembles the
!> same connectivity at every iteration). The first conversion records, for each triplet,
!> its position in the CSC value array; when the next sequence is the same (same entries
!> in the same order, checked entry by entry), the values are scattered through that map
!> instead of sorting again. Any difference falls back to `coo_to_csc` and a new map.
module pecplas_linalg_sparse_reuse
   use pecplas_base_kinds, only: wp, ik4
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_linalg_sparse, only: coo_t, csc_t, coo_to_csc
   use pecplas_linalg_sparse_pattern, only: pattern_from_blocks
   implicit none (type, external)
   private

   public :: csc_builder_t

   !> Triplet storage kept between assemblies (no page faults for a new buffer each time)
   !> and the scatter map of its last sequence. Lives in the problem state.
   type :: csc_builder_t
      !> Triplets of the current assembly: fill with coo%add / coo%add_block after `start`.
      type(coo_t) :: coo
      !> map(p): 1-based position in csc%values of triplet p of the mapped sequence.
      integer(ik4), allocatable :: map(:)
      !> Length of the mapped sequence (-1: no map), and nnz and order of its CSC matrix.
      integer :: nmap = -1, nzmap = -1, nmat = -1
      logical :: upper = .false.
      !> Conversions done through the map or a kept pattern (fast), and by the full sort or
      !> a new pattern (full).
      integer :: fast = 0, full = 0
      !> Key of the pattern built by `pattern`: the element equation lists and the extra
      !> triplets' positions it was built from, and the matrix order (-1: none).
      integer(ik4), allocatable :: eptr(:), elist(:), xrows(:), xcols(:)
      integer :: npat = -1
      !> Entries added by an assembly on the kept pattern (counted when it is built): the
      !> element-block entries kept (as many as add_block triplets) plus the triplets of `coo`.
      integer :: entries = 0
      !> Positions in csc%values of the element-block entries on the kept pattern, block
      !> after block, each block's kept entries column by column: recorded by the first
      !> assembly that reuses a pattern, then replayed (no search). bstate: 0 none,
      !> 1 recording, 2 valid; bnext: next block expected; bcur: positions used so far.
      integer(ik4), allocatable :: bmap(:), bpos(:, :)
      integer :: bstate = 0, bnext = 1, bcur = 0
   contains
      procedure :: start => builder_start
      procedure :: finish => builder_finish
      procedure :: pattern => builder_pattern
      procedure :: add_block => builder_add_block
      procedure :: add_extra => builder_add_extra
      procedure :: forget => builder_forget
      procedure :: positioned => builder_positioned
   end type csc_builder_t

contains

   !> Empties the triplet list for an n x n matrix, keeping the storage when it fits.
   subroutine builder_start(this, n, capacity, upper_only)
      class(csc_builder_t), intent(inout) :: this
      integer, intent(in) :: n, capacity
      logical, intent(in), optional :: upper_only
      logical :: upper
      upper = .false.
      if (present(upper_only)) upper = upper_only
      if (allocated(this%coo%rows) .and. this%coo%n == n .and. &
          (this%coo%upper_only .eqv. upper)) then
         call this%coo%clear()
         if (size(this%coo%rows) < capacity) call this%coo%reserve(capacity)
      else
         call this%coo%init(n, capacity, upper)
         this%nmap = -1
      end if
   end subroutine builder_start

   !> CSC matrix of the triplets added since `start`. `csc` must be the matrix of the
   !> previous call (only its values may have been changed since): on the fast path its
   !> pattern is kept and only the values are rebuilt.
   subroutine builder_finish(this, csc, error)
      class(csc_builder_t), intent(inout) :: this
      type(csc_t), intent(inout) :: csc
      type(error_t), allocatable, intent(out) :: error
      if (reusable(this, csc)) then
         if (scatter(this, csc)) then
            this%fast = this%fast + 1
            return
         end if
      end if
      call coo_to_csc(this%coo, csc, error)
      if (allocated(error)) return
      call build_map(this, csc, error)
      this%full = this%full + 1
   end subroutine builder_finish

   !> The map may apply: same length, order, storage kind and matrix size as when built.
   logical function reusable(this, csc)
      class(csc_builder_t), intent(in) :: this
      type(csc_t), intent(in) :: csc
      reusable = .false.
      if (this%nmap /= this%coo%nnz .or. this%nmat /= this%coo%n) return
      if (.not. allocated(csc%values) .or. .not. allocated(csc%colptr) .or. &
          .not. allocated(csc%rowind)) return
      if (csc%n /= this%nmat .or. (csc%upper .neqv. this%upper)) return
      if (size(csc%values) /= this%nzmap .or. csc%nnz() /= this%nzmap) return
      reusable = .true.
   end function reusable

   !> values = sum over triplets through the map, in triplet order (the order in which
   !> coo_to_csc sums duplicates, so the result is the same to the last bit). Checks
   !> on the way that triplet p is the entry (row, column) its map position holds, which
   !> is the triplet p of the mapped sequence: false at the first difference (then the
   !> full conversion also reports any index out of range).
   logical function scatter(this, csc) result(ok)
      type(csc_builder_t), intent(in) :: this
      type(csc_t), intent(inout) :: csc
      integer :: p, q, j
      ok = .false.
      csc%values = 0.0_wp
      do p = 1, this%coo%nnz
         q = this%map(p)
         j = this%coo%cols(p)
         if (j < 1 .or. j > csc%n) return
         if (q <= csc%colptr(j) .or. q > csc%colptr(j + 1)) return
         if (csc%rowind(q) + 1 /= this%coo%rows(p)) return
         csc%values(q) = csc%values(q) + this%coo%vals(p)
      end do
      ok = .true.
   end function scatter

   !> map(p) = position of triplet p in the CSC matrix just built from the same triplets.
   subroutine build_map(this, csc, error)
      type(csc_builder_t), intent(inout) :: this
      type(csc_t), intent(in) :: csc
      type(error_t), allocatable, intent(out) :: error
      integer :: p, q
      this%nmap = -1
      if (allocated(this%map)) then
         if (size(this%map) < this%coo%nnz) deallocate (this%map)
      end if
      if (.not. allocated(this%map)) allocate (this%map(max(this%coo%nnz, 1)))
      do p = 1, this%coo%nnz
         q = csc%locate(int(this%coo%rows(p)), int(this%coo%cols(p)))
         if (q == 0) then
            call fatal_error(error, 'csc_builder: triplet missing from its own CSC matrix')
            return
         end if
         this%map(p) = int(q, ik4)
      end do
      this%nmap = this%coo%nnz
      this%nzmap = csc%nnz()
      this%nmat = csc%n
      this%upper = csc%upper
   end subroutine build_map

   !> Element assembly without triplets: `csc` gets the pattern of the blocks
   !> elist(eptr(b) : eptr(b+1)-1) and of the triplets in `coo` (added since `start`) with
   !> zero values. The pattern of the previous call is kept when it was built from the same
   !> lists and triplet positions and `csc` is still that matrix (fast); otherwise it is
   !> built anew (full). The caller then adds the element blocks (csc%add_block) and the
   !> triplets (add_extra) in the order of the serial triplet sequence, which gives the
   !> values of coo_to_csc to the last bit.
   subroutine builder_pattern(this, eptr, elist, csc, error)
      class(csc_builder_t), intent(inout) :: this
      integer(ik4), intent(in) :: eptr(:), elist(:)
      type(csc_t), intent(inout) :: csc
      type(error_t), allocatable, intent(out) :: error
      integer :: nx, b
      nx = this%coo%nnz
      this%bnext = 1
      this%bcur = 0
      ! a kept pattern: the same lists and triplets as the last call, so as many entries
      if (same_key(this, eptr, elist, csc)) then
         call zero_values(csc%values)
         this%fast = this%fast + 1
         ! a pattern used a second time: record the block positions for the next ones
         if (this%bstate /= 2) then
            if (allocated(this%bmap)) then
               if (size(this%bmap) < this%entries - nx) deallocate (this%bmap)
            end if
            if (.not. allocated(this%bmap)) allocate (this%bmap(max(this%entries - nx, 1)))
            this%bstate = 1
         end if
         return
      end if
      this%entries = nx
      do b = 1, size(eptr) - 1
         this%entries = this%entries + this%coo%block_size(elist(eptr(b):eptr(b + 1) - 1))
      end do
      this%bstate = 0
      this%npat = -1
      call pattern_from_blocks(this%coo%n, this%coo%upper_only, eptr, elist, this%coo, csc, &
         error)
      if (allocated(error)) return
      this%eptr = eptr
      this%elist = elist
      this%xrows = this%coo%rows(1:nx)
      this%xcols = this%coo%cols(1:nx)
      this%npat = this%coo%n
      this%full = this%full + 1
   end subroutine builder_pattern

   !> v = 0 on the element loops' threads (the matrix's values, each assembly).
   subroutine zero_values(v)
      real(wp), intent(inout) :: v(:)
      integer, parameter :: PIECE = 65536
      integer :: i
      !$omp parallel do default(shared) private(i) schedule(static) &
      !$omp if (size(v) >= 4*PIECE)
      do i = 1, size(v), PIECE
         v(i:min(i + PIECE - 1, size(v))) = 0.0_wp
      end do
      !$omp end parallel do
   end subroutine zero_values

   logical function same_key(this, eptr, elist, csc)
      class(csc_builder_t), intent(in) :: this
      integer(ik4), intent(in) :: eptr(:), elist(:)
      type(csc_t), intent(in) :: csc
      integer :: nx
      nx = this%coo%nnz
      same_key = .false.
      if (this%npat /= this%coo%n .or. csc%n /= this%npat) return
      if (.not. allocated(csc%colptr) .or. .not. allocated(csc%rowind) .or. &
          .not. allocated(csc%values)) return
      if (csc%upper .neqv. this%coo%upper_only) return
      if (size(csc%values) /= csc%nnz() .or. size(csc%rowind) /= csc%nnz()) return
      if (size(this%eptr) /= size(eptr) .or. size(this%elist) /= size(elist) .or. &
          size(this%xrows) /= nx) return
      if (any(this%eptr /= eptr)) return
      if (any(this%elist /= elist)) return
      if (any(this%xrows /= this%coo%rows(1:nx))) return
      if (any(this%xcols /= this%coo%cols(1:nx))) return
      same_key = .true.
   end function same_key

   !> csc%values(idx(r), idx(c)) += kblock(r, c) for the next element block of the kept
   !> pattern (the blocks come in the order of the `pattern` lists), as csc%add_block does:
   !> through the recorded positions when they are valid, else by searching (and recording).
   !> A block other than the one expected drops the positions (csc%add_block then).
   subroutine builder_add_block(this, csc, idx, kblock, error)
      class(csc_builder_t), intent(inout) :: this
      type(csc_t), intent(inout) :: csc
      integer, intent(in) :: idx(:)
      real(wp), intent(in) :: kblock(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: b, nd, r, c, q
      logical :: same
      nd = size(idx)
      b = this%bnext
      same = this%bstate > 0 .and. this%npat == csc%n .and. b < size(this%eptr)
      if (same) same = this%eptr(b + 1) - this%eptr(b) == nd
      if (same) same = all(this%elist(this%eptr(b):this%eptr(b + 1) - 1) == idx)
      if (.not. same) then
         this%bstate = 0
         call csc%add_block(idx, kblock, error)
         return
      end if
      this%bnext = b + 1
      q = this%bcur
      if (this%bstate == 2) then
         do c = 1, nd
            if (idx(c) <= 0) cycle
            do r = 1, nd
               if (idx(r) <= 0 .or. (csc%upper .and. idx(r) > idx(c))) cycle
               q = q + 1
               csc%values(this%bmap(q)) = csc%values(this%bmap(q)) + kblock(r, c)
            end do
         end do
      else
         if (allocated(this%bpos)) then
            if (size(this%bpos, 1) < nd) deallocate (this%bpos)
         end if
         if (.not. allocated(this%bpos)) allocate (this%bpos(nd, nd))
         call csc%add_block(idx, kblock, error, this%bpos)
         if (allocated(error)) then
            this%bstate = 0
            return
         end if
         do c = 1, nd
            if (idx(c) <= 0) cycle
            do r = 1, nd
               if (idx(r) <= 0 .or. (csc%upper .and. idx(r) > idx(c))) cycle
               q = q + 1
               this%bmap(q) = this%bpos(r, c)
            end do
         end do
      end if
      this%bcur = q
   end subroutine builder_add_block

   !> Adds the triplets of `coo` to csc%values in their order (after the element blocks);
   !> the end of an assembly, which validates block positions recorded for all the blocks.
   subroutine builder_add_extra(this, csc, error)
      class(csc_builder_t), intent(inout) :: this
      type(csc_t), intent(inout) :: csc
      type(error_t), allocatable, intent(out) :: error
      integer :: p, q
      if (this%bstate == 1) then
         this%bstate = 0
         if (this%bnext == size(this%eptr) .and. this%bcur == this%entries - this%coo%nnz) &
            this%bstate = 2
      end if
      do p = 1, this%coo%nnz
         q = csc%locate(int(this%coo%rows(p)), int(this%coo%cols(p)))
         if (q == 0) then
            call fatal_error(error, 'csc_builder: triplet missing from the pattern')
            return
         end if
         csc%values(q) = csc%values(q) + this%coo%vals(p)
      end do
   end subroutine builder_add_extra

   !> Whether add_block records or replays the blocks' positions in this assembly (a kept
   !> pattern); if not (a new pattern), each block is searched for in the columns, and the
   !> blocks may as well be added by other means (pecplas_linalg_sparse_columns).
   logical function builder_positioned(this)
      class(csc_builder_t), intent(in) :: this
      builder_positioned = this%bstate > 0
   end function builder_positioned

   !> Forgets the kept pattern (the next `pattern` builds one).
   subroutine builder_forget(this)
      class(csc_builder_t), intent(inout) :: this
      this%npat = -1
      this%bstate = 0
   end subroutine builder_forget

end module pecplas_linalg_sparse_reuse
