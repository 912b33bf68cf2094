!> Map from user ids (node ids, Gmsh tags) to internal numbers 1..n.
!> A dense table when the ids are compact (O(1) lookup), sorted keys with binary search
!> otherwise (O(log n)), so that sparse ids like 1, 10**9 cost no memory.
module pecplas_model_node_lookup
   use iso_fortran_env, only: int64
   use pecplas_base_error, only: error_t, input_error
   use pecplas_model_mesh, only: mesh_t
   implicit none (type, external)
   private

   public :: node_lookup_t

   !> Built once from a list of ids; `index(id)` returns the position of `id` in that
   !> list (the internal number), or 0 when `id` is not in it.
   type :: node_lookup_t
      private
      logical :: dense = .true.
      !> Dense: table(id - lo + 1) is the internal number (0 = none).
      integer(int64) :: lo = 0
      integer, allocatable :: table(:)
      !> Sparse: sorted ids and their internal numbers.
      integer, allocatable :: keys(:), vals(:)
   contains
      procedure :: build => lookup_build
      procedure :: build_ids => lookup_build_ids
      procedure :: index => lookup_index
   end type node_lookup_t

contains

   !> Lookup of the mesh's user node ids; an id given twice is an error naming it.
   subroutine lookup_build(this, mesh, error)
      class(node_lookup_t), intent(out) :: this
      type(mesh_t), intent(in) :: mesh
      type(error_t), allocatable, intent(out) :: error
      if (.not. allocated(mesh%node_id)) then
         allocate (this%table(0))
         return
      end if
      call this%build_ids(mesh%node_id, 'node id', error)
   end subroutine lookup_build

   !> Lookup of `ids(i) -> i`. A repeated id is an error "<what> N is defined twice".
   subroutine lookup_build_ids(this, ids, what, error)
      class(node_lookup_t), intent(out) :: this
      integer, intent(in) :: ids(:)
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      integer(int64) :: span
      integer :: i, n, slot
      character(len=16) :: buf
      n = size(ids)
      if (n == 0) then
         allocate (this%table(0))
         return
      end if
      this%lo = minval(ids)
      span = int(maxval(ids), int64) - this%lo + 1
      ! A table up to ~4x the number of ids is cheaper than sorting and searching.
      this%dense = span <= 4_int64*n + 1024
      if (this%dense) then
         allocate (this%table(span))
         this%table = 0
         do i = 1, n
            slot = int(ids(i) - this%lo + 1)
            if (this%table(slot) /= 0) then
               write (buf, '(i0)') ids(i)
               call input_error(error, what//' '//trim(buf)//' is defined twice')
               return
            end if
            this%table(slot) = i
         end do
      else
         this%keys = ids
         this%vals = [(i, i=1, n)]
         call sort_pairs(this%keys, this%vals)
         do i = 2, n
            if (this%keys(i) == this%keys(i - 1)) then
               write (buf, '(i0)') this%keys(i)
               call input_error(error, what//' '//trim(buf)//' is defined twice')
               return
            end if
         end do
      end if
   end subroutine lookup_build_ids

   !> Internal number of user id `id`, 0 if unknown.
   pure integer function lookup_index(this, id) result(k)
      class(node_lookup_t), intent(in) :: this
      integer, intent(in) :: id
      integer(int64) :: slot
      integer :: a, b, m
      k = 0
      if (this%dense) then
         if (.not. allocated(this%table)) return
         slot = int(id, int64) - this%lo + 1
         if (slot >= 1 .and. slot <= size(this%table, kind=int64)) k = this%table(slot)
      else
         a = 1; b = size(this%keys)
         do while (a <= b)
            m = (a + b)/2
            if (this%keys(m) == id) then
               k = this%vals(m)
               return
            else if (this%keys(m) < id) then
               a = m + 1
            else
               b = m - 1
            end if
         end do
      end if
   end function lookup_index

   !> Sorts keys ascending, carrying vals along (bottom-up merge sort, O(n log n), stable).
   subroutine sort_pairs(keys, vals)
      integer, intent(inout) :: keys(:), vals(:)
      integer, allocatable :: k2(:), v2(:)
      integer :: n, width, lo, mid, hi, i, j, p
      n = size(keys)
      allocate (k2(n), v2(n))
      width = 1
      do while (width < n)
         lo = 1
         do while (lo <= n)
            mid = min(lo + width, n + 1)
            hi = min(lo + 2*width, n + 1)
            i = lo; j = mid; p = lo
            do while (p < hi)
               if (j >= hi) then
                  k2(p) = keys(i); v2(p) = vals(i); i = i + 1
               else if (i < mid) then
                  if (keys(i) <= keys(j)) then
                     k2(p) = keys(i); v2(p) = vals(i); i = i + 1
                  else
                     k2(p) = keys(j); v2(p) = vals(j); j = j + 1
                  end if
               else
                  k2(p) = keys(j); v2(p) = vals(j); j = j + 1
               end if
               p = p + 1
            end do
            lo = hi
         end do
         keys = k2; vals = v2
         width = 2*width
      end do
   end subroutine sort_pairs

end module pecplas_model_node_lookup
