!> Sparse matrices for finite-element assembly: a triplet (COO) builder and the compressed
!> sparse column (CSC) form that CHOLMOD and UMFPACK read without copying.
!>
!> Equation numbers are 1-based everywhere in Fortran; only the CSC index arrays are 0-based
!> (`colptr(1) = 0`, `colptr(n+1) = nnz`) because they go to C as they are.
module pecplas_linalg_sparse
   use pecplas_base_kinds, only: wp, ik4, ik8
   use pecplas_base_error, only: error_t, fatal_error
   implicit none (type, external)
   private

   public :: coo_t, csc_t, coo_to_csc

   !> Triplet builder. `add_block` appends whole element matrices; entries are summed only
   !> when converted to CSC. With `upper_only`, entries below the diagonal are dropped at once
   !> (half the memory for symmetric matrices given to CHOLMOD).
   type :: coo_t
      integer :: n = 0
      !> Number of triplets stored.
      integer :: nnz = 0
      logical :: upper_only = .false.
      integer(ik4), allocatable :: rows(:), cols(:)
      real(wp), allocatable :: vals(:)
   contains
      procedure :: init => coo_init
      procedure :: reserve => coo_reserve
      procedure :: clear => coo_clear
      procedure :: add => coo_add
      procedure :: add_block => coo_add_block
      procedure :: block_size => coo_block_size
      procedure :: put_block => coo_put_block
   end type coo_t

   !> Compressed sparse column matrix: rows sorted ascending and unique within each column.
   type :: csc_t
      integer :: n = 0
      !> True when only the upper triangle (row <= column) of a symmetric matrix is stored.
      logical :: upper = .false.
      !> 0-based column starts, size n+1.
      integer(ik4), allocatable :: colptr(:)
      !> 0-based row indices, size nnz.
      integer(ik4), allocatable :: rowind(:)
      real(wp), allocatable :: values(:)
   contains
      procedure :: nnz => csc_nnz
      procedure :: matvec => csc_matvec
      procedure :: locate => csc_locate
      procedure :: diagonal => csc_diagonal
      procedure :: add_block => csc_add_block
      procedure :: column_parts => csc_column_parts
      procedure :: is_symmetric => csc_is_symmetric
      procedure :: whole_nnz => csc_whole_nnz
      procedure :: upper_of_whole => csc_upper_of_whole
   end type csc_t

contains

   !> Starts an empty n x n matrix with room for `capacity` triplets.
   subroutine coo_init(this, n, capacity, upper_only)
      class(coo_t), intent(inout) :: this
      integer, intent(in) :: n, capacity
      logical, intent(in), optional :: upper_only
      this%n = n
      this%nnz = 0
      this%upper_only = .false.
      if (present(upper_only)) this%upper_only = upper_only
      if (allocated(this%rows)) deallocate (this%rows, this%cols, this%vals)
      allocate (this%rows(max(capacity, 16)), this%cols(max(capacity, 16)), this%vals(max(capacity, 16)))
   end subroutine coo_init

   !> Forgets the triplets but keeps the storage (re-assembly with the same size).
   subroutine coo_clear(this)
      class(coo_t), intent(inout) :: this
      this%nnz = 0
   end subroutine coo_clear

   !> Makes room for at least `extra` more triplets; grows geometrically so that many small
   !> requests cost O(total) copies.
   subroutine coo_reserve(this, extra)
      class(coo_t), intent(inout) :: this
      integer, intent(in) :: extra
      integer(ik4), allocatable :: itmp(:)
      real(wp), allocatable :: rtmp(:)
      integer :: cap, need
      if (.not. allocated(this%rows)) call this%init(this%n, extra)
      need = this%nnz + extra
      cap = size(this%rows)
      if (need <= cap) return
      cap = int(min(max(2.0_wp*cap, real(need, wp)), real(huge(cap), wp)))
      allocate (itmp(cap)); itmp(1:this%nnz) = this%rows(1:this%nnz); call move_alloc(itmp, this%rows)
      allocate (itmp(cap)); itmp(1:this%nnz) = this%cols(1:this%nnz); call move_alloc(itmp, this%cols)
      allocate (rtmp(cap)); rtmp(1:this%nnz) = this%vals(1:this%nnz); call move_alloc(rtmp, this%vals)
   end subroutine coo_reserve

   !> Appends a(i, j) += v (1-based indices).
   subroutine coo_add(this, i, j, v)
      class(coo_t), intent(inout) :: this
      integer, intent(in) :: i, j
      real(wp), intent(in) :: v
      if (this%upper_only .and. i > j) return
      if (this%nnz >= size(this%rows)) call this%reserve(1)
      this%nnz = this%nnz + 1
      this%rows(this%nnz) = int(i, ik4)
      this%cols(this%nnz) = int(j, ik4)
      this%vals(this%nnz) = v
   end subroutine coo_add

   !> Appends an element matrix: a(idx(r), idx(c)) += kblock(r, c); entries whose equation
   !> number is <= 0 (eliminated degrees of freedom) are skipped.
   subroutine coo_add_block(this, idx, kblock)
      class(coo_t), intent(inout) :: this
      integer, intent(in) :: idx(:)
      real(wp), intent(in) :: kblock(:, :)
      integer :: m
      m = this%block_size(idx)
      if (this%nnz + m > size(this%rows)) call this%reserve(m)
      call this%put_block(this%nnz, idx, kblock)
      this%nnz = this%nnz + m
   end subroutine coo_add_block

   !> Number of triplets add_block stores for the equation numbers idx.
   integer function coo_block_size(this, idx) result(m)
      class(coo_t), intent(in) :: this
      integer, intent(in) :: idx(:)
      integer :: r, c
      if (.not. this%upper_only) then
         m = count(idx > 0)**2
         return
      end if
      m = 0
      do c = 1, size(idx)
         if (idx(c) <= 0) cycle
         do r = 1, size(idx)
            if (idx(r) > 0 .and. idx(r) <= idx(c)) m = m + 1
         end do
      end do
   end function coo_block_size

   !> Writes the triplets of add_block at positions k0+1 .. k0+block_size(idx), storage
   !> reserved, `nnz` untouched: element loops run in parallel, each element at its own
   !> offset, and the triplet order is that of serial add_block calls.
   subroutine coo_put_block(this, k0, idx, kblock)
      class(coo_t), intent(inout) :: this
      integer, intent(in) :: k0, idx(:)
      real(wp), intent(in) :: kblock(:, :)
      integer :: r, c, k
      k = k0
      do c = 1, size(idx)
         if (idx(c) <= 0) cycle
         do r = 1, size(idx)
            if (idx(r) <= 0) cycle
            if (this%upper_only .and. idx(r) > idx(c)) cycle
            k = k + 1
            this%rows(k) = int(idx(r), ik4)
            this%cols(k) = int(idx(c), ik4)
            this%vals(k) = kblock(r, c)
         end do
      end do
   end subroutine coo_put_block

   !> Converts triplets to CSC in O(nnz + n): a counting sort by column, duplicates summed
   !> with a row marker, then two counting-sort transposes, which leave the rows ascending.
   subroutine coo_to_csc(coo, csc, error)
      type(coo_t), intent(in) :: coo
      type(csc_t), intent(out) :: csc
      type(error_t), allocatable, intent(out) :: error
      integer(ik4), allocatable :: ri(:), ci(:), cp(:), rp(:), nxt(:), mark(:)
      real(wp), allocatable :: rv(:), cv(:)
      integer :: n, nt, nz, i, j, k, p, q
      n = coo%n
      nt = coo%nnz
      if (nt > 0) then
         if (minval(coo%rows(1:nt)) < 1 .or. maxval(coo%rows(1:nt)) > n .or. &
             minval(coo%cols(1:nt)) < 1 .or. maxval(coo%cols(1:nt)) > n) then
            call fatal_error(error, 'coo_to_csc: triplet index outside 1..n')
            return
         end if
      end if
      csc%n = n
      csc%upper = coo%upper_only
      ! 1. bucket the triplets by column (cp holds 1-based column starts here)
      allocate (cp(n + 1), nxt(n), ri(nt), rv(nt))
      cp = 0
      do k = 1, nt
         cp(coo%cols(k) + 1) = cp(coo%cols(k) + 1) + 1
      end do
      cp(1) = 1
      do j = 1, n
         cp(j + 1) = cp(j + 1) + cp(j)
      end do
      nxt = cp(1:n)
      do k = 1, nt
         j = coo%cols(k)
         ri(nxt(j)) = coo%rows(k)
         rv(nxt(j)) = coo%vals(k)
         nxt(j) = nxt(j) + 1
      end do
      ! 2. sum duplicates in place: mark(i) = where row i went in the current column
      allocate (mark(n))
      mark = 0
      nz = 0
      do j = 1, n
         q = nz + 1
         do p = cp(j), cp(j + 1) - 1
            i = ri(p)
            if (mark(i) >= q) then
               rv(mark(i)) = rv(mark(i)) + rv(p)
            else
               nz = nz + 1
               mark(i) = nz
               ri(nz) = int(i, ik4)
               rv(nz) = rv(p)
            end if
         end do
         cp(j) = q
      end do
      cp(n + 1) = nz + 1
      deallocate (mark)
      ! 3. transpose to rows (columns come out ascending within each row)
      allocate (rp(n + 1), ci(nz), cv(nz))
      call counting_transpose(n, cp, ri, rv, rp, ci, cv, nxt)
      deallocate (ri, rv)
      ! 4. transpose back: rows now ascending within each column
      allocate (csc%rowind(nz), csc%values(nz))
      call counting_transpose(n, rp, ci, cv, cp, csc%rowind, csc%values, nxt)
      csc%colptr = cp - 1_ik4
      csc%rowind = csc%rowind - 1_ik4
   end subroutine coo_to_csc

   !> Transposes a compressed matrix with 1-based starts `ap`, indices `ai`, values `ax`
   !> into `bp`, `bi`, `bx`. Stable: the new minor indices come out ascending.
   subroutine counting_transpose(n, ap, ai, ax, bp, bi, bx, nxt)
      integer, intent(in) :: n
      integer(ik4), intent(in) :: ap(:), ai(:)
      real(wp), intent(in) :: ax(:)
      integer(ik4), intent(out) :: bp(:), bi(:), nxt(:)
      real(wp), intent(out) :: bx(:)
      integer :: j, p, i
      bp = 0
      do p = 1, ap(n + 1) - 1
         bp(ai(p) + 1) = bp(ai(p) + 1) + 1
      end do
      bp(1) = 1
      do j = 1, n
         bp(j + 1) = bp(j + 1) + bp(j)
      end do
      nxt = bp(1:n)
      do j = 1, n
         do p = ap(j), ap(j + 1) - 1
            i = ai(p)
            bi(nxt(i)) = int(j, ik4)
            bx(nxt(i)) = ax(p)
            nxt(i) = nxt(i) + 1
         end do
      end do
   end subroutine counting_transpose

   !> Number of stored nonzeros.
   pure integer function csc_nnz(this) result(nnz)
      class(csc_t), intent(in) :: this
      nnz = 0
      if (allocated(this%colptr)) nnz = this%colptr(this%n + 1)
   end function csc_nnz

   !> y = A x (the mirrored lower triangle is included when only the upper one is stored).
   subroutine csc_matvec(this, x, y)
      class(csc_t), intent(in) :: this
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: y(:)
      integer :: j, p, i
      y = 0.0_wp
      do j = 1, this%n
         do p = this%colptr(j) + 1, this%colptr(j + 1)
            i = this%rowind(p) + 1
            y(i) = y(i) + this%values(p)*x(j)
            if (this%upper .and. i /= j) y(j) = y(j) + this%values(p)*x(i)
         end do
      end do
   end subroutine csc_matvec

   !> Position in `values` of entry (i, j) (1-based), or 0 when it is not stored.
   pure integer function csc_locate(this, i, j) result(pos)
      class(csc_t), intent(in) :: this
      integer, intent(in) :: i, j
      integer :: lo, hi, mid
      pos = 0
      lo = this%colptr(j) + 1
      hi = this%colptr(j + 1)
      do while (lo <= hi)
         mid = (lo + hi)/2
         if (this%rowind(mid) + 1 == i) then
            pos = mid
            return
         else if (this%rowind(mid) + 1 < i) then
            lo = mid + 1
         else
            hi = mid - 1
         end if
      end do
   end function csc_locate

   !> Diagonal of the matrix (zero where no diagonal entry is stored).
   subroutine csc_diagonal(this, d)
      class(csc_t), intent(in) :: this
      real(wp), intent(out) :: d(:)
      integer :: j, p
      do j = 1, this%n
         d(j) = 0.0_wp
         ! upper storage: the diagonal, when stored, is the column's last entry
         p = this%colptr(j + 1)
         if (this%upper .and. p > this%colptr(j)) then
            if (this%rowind(p) + 1 == j) then
               d(j) = this%values(p)
               cycle
            end if
         end if
         p = this%locate(j, j)
         if (p > 0) d(j) = this%values(p)
      end do
   end subroutine csc_diagonal

   !> Re-assembly on a fixed pattern: values(idx(r), idx(c)) += kblock(r, c), skipping
   !> idx <= 0 (and the lower triangle when only the upper one is stored). An entry missing
   !> from the pattern is an error (the pattern was built from other connectivity). The
   !> block's rows are sorted once; each column is then walked along with them (rows are
   !> sorted in a CSC column) instead of searching every entry. `pos(r, c)`, if present,
   !> receives the 1-based position in `values` of each entry added (others untouched).
   !> `first`, `last`: only the columns first..last (threads that own disjoint column
   !> ranges add one block sequence at once, each entry's terms in the sequence's order).
   subroutine csc_add_block(this, idx, kblock, error, pos, first, last)
      class(csc_t), intent(inout) :: this
      integer, intent(in) :: idx(:)
      real(wp), intent(in) :: kblock(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer(ik4), intent(inout), optional :: pos(:, :)
      integer, intent(in), optional :: first, last
      integer :: order(size(idx)), nr, r, c, p, hi, k, row, c1, c2
      character(len=64) :: buf
      c1 = 1
      c2 = this%n
      if (present(first)) c1 = max(first, 1)
      if (present(last)) c2 = last
      nr = 0
      do r = 1, size(idx)
         if (idx(r) <= 0) cycle
         nr = nr + 1
         k = nr
         do while (k > 1)
            if (idx(order(k - 1)) <= idx(r)) exit
            order(k) = order(k - 1)
            k = k - 1
         end do
         order(k) = r
      end do
      do c = 1, size(idx)
         if (idx(c) < c1 .or. idx(c) > c2) cycle
         p = this%colptr(idx(c)) + 1
         hi = this%colptr(idx(c) + 1)
         do k = 1, nr
            r = order(k)
            row = idx(r)
            if (this%upper .and. row > idx(c)) exit
            do while (p < hi)
               if (this%rowind(p) + 1 >= row) exit
               p = p + 1
            end do
            if (p > hi) then
               p = 0
            else if (this%rowind(p) + 1 /= row) then
               p = 0
            end if
            if (p == 0) then
               write (buf, '(a,i0,a,i0,a)') '(', row, ',', idx(c), ')'
               call fatal_error(error, 'csc add_block: entry '//trim(buf)//' not in the pattern')
               return
            end if
            this%values(p) = this%values(p) + kblock(r, c)
            if (present(pos)) pos(r, c) = int(p, ik4)
         end do
      end do
   end subroutine csc_add_block

   !> Columns split into nparts ranges of about equal stored entries: part p holds the
   !> columns first(p) .. first(p+1)-1 (possibly none).
   pure function csc_column_parts(this, nparts) result(first)
      class(csc_t), intent(in) :: this
      integer, intent(in) :: nparts
      integer :: first(nparts + 1)
      integer :: p, j
      integer(ik8) :: target
      first(1) = 1
      j = 1
      do p = 2, nparts
         target = (int(this%colptr(this%n + 1), ik8)*(p - 1))/nparts
         do while (j <= this%n)
            if (this%colptr(j) >= target) exit
            j = j + 1
         end do
         first(p) = j
      end do
      first(nparts + 1) = this%n + 1
   end function csc_column_parts

   !> True when |a(i,j) - a(j,i)| <= tol * max|a| for every stored entry.
   logical function csc_is_symmetric(this, tol) result(sym)
      class(csc_t), intent(in) :: this
      real(wp), intent(in) :: tol
      real(wp) :: amax, aji
      integer :: j, p, i, q
      sym = .true.
      if (this%upper .or. this%nnz() == 0) return
      amax = maxval(abs(this%values))
      do j = 1, this%n
         do p = this%colptr(j) + 1, this%colptr(j + 1)
            i = this%rowind(p) + 1
            q = this%locate(j, i)
            aji = 0.0_wp
            if (q > 0) aji = this%values(q)
            if (abs(this%values(p) - aji) > tol*amax) then
               sym = .false.
               return
            end if
         end do
      end do
   end function csc_is_symmetric

   !> Upper storage with a symmetric pattern: the number of entries of the whole matrix
   !> (each entry off the diagonal twice); otherwise nnz.
   pure integer function csc_whole_nnz(this) result(nnz)
      class(csc_t), intent(in) :: this
      integer :: j, p
      nnz = this%nnz()
      if (.not. this%upper) return
      do j = 1, this%n
         do p = this%colptr(j) + 1, this%colptr(j + 1)
            if (this%rowind(p) + 1 /= j) nnz = nnz + 1
         end do
      end do
   end function csc_whole_nnz

   !> Upper storage: v = its values taken from `whole`, the values (CSC order, rows
   !> ascending) of the whole matrix of the symmetric pattern, of size whole_nnz(). Whole
   !> column j holds the rows of column j here first (those up to j), then one row for each
   !> entry (j, c), c > j, stored here.
   pure subroutine csc_upper_of_whole(this, whole, v)
      class(csc_t), intent(in) :: this
      real(wp), intent(in) :: whole(:)
      real(wp), allocatable, intent(out) :: v(:)
      integer, allocatable :: below(:)
      integer :: j, p, i, w, m
      allocate (below(this%n), v(this%nnz()))
      below = 0
      do j = 1, this%n
         do p = this%colptr(j) + 1, this%colptr(j + 1)
            i = this%rowind(p) + 1
            if (i /= j) below(i) = below(i) + 1
         end do
      end do
      w = 0
      do j = 1, this%n
         m = this%colptr(j + 1) - this%colptr(j)
         v(this%colptr(j) + 1:this%colptr(j + 1)) = whole(w + 1:w + m)
         w = w + m + below(j)
      end do
   end subroutine csc_upper_of_whole

end module pecplas_linalg_sparse
