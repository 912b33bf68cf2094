!> The `/restart` group of a results file: the full state of the last converged increment,
!> as named datasets read back as flat real vectors (the driver packs and unpacks them:
!> pecplas_solve_restart). It is replaced at every converged increment (written as
!> /restart_next, then renamed), so the file holds one state whatever the number of
!> increments. An item that is one of the increment's fields (displacement, stresses,
!> strains, material states) is given by reference (`field`): when that field is written,
!> the item is an HDF5 hard link to its dataset (no second copy; read back in the same
!> memory order, as a flat vector), else the writer puts the field's values. An item's own
!> dataset is written in place and, while the item is a link, kept as `<item>.spare`: a
!> dataset deleted would leave its file space lost at the next commit (HDF5 keeps no free
!> space across a close), a leak of one state every few increments under *OUTPUT, EVERY=n
!> (measured: Tresca footing, 180 increments, fields every 3rd: 11.9 MB deleting, 7.5 MB
!> with spares; 10.96 MB either way with fields every 2nd). The results
!> writer flushes a copy of the file only once the increment, /restart included, is whole,
!> and never writes the copy a killed run leaves for reading (pecplas_io_results_file).
module pecplas_io_results_restart
   use, intrinsic :: iso_c_binding, only: c_loc
   use hdf5, only: hid_t, hsize_t, h5lexists_f, h5ldelete_f, h5lmove_f, h5gopen_f, h5dopen_f, &
      h5dclose_f, h5dget_space_f, h5sclose_f, h5sget_simple_extent_dims_f, h5dwrite_f, &
      h5lcreate_hard_f, h5oget_info_f, h5o_info_t, h5oopen_f, h5oclose_f, &
      h5sget_simple_extent_ndims_f, H5T_NATIVE_DOUBLE, H5O_TYPE_DATASET_F, h5aopen_f, h5awrite_f, &
      h5aclose_f
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_io_results_h5, only: h5_group, h5_close_group, h5_write, h5_attr
   use pecplas_io_results_checksum, only: values_checksum, deck_checksum, CHECKSUM_ATTR
   use pecplas_io_results_reader, only: results_reader_t
   implicit none (type, external)
   private

   public :: restart_item_t, restart_data_t, write_restart_next, swap_restart, read_restart_group
   public :: restart_next_open, restart_put, restart_link

   !> Group name in the results file.
   character(len=*), parameter, public :: RESTART_GROUP = 'restart'
   character(len=*), parameter :: NEXT = RESTART_GROUP//'_next', SWAP = RESTART_GROUP//'_swap'
   !> Suffix of a dataset kept while its item is a link (restart_link, restart_put).
   character(len=*), parameter :: SPARE = '.spare'

   type :: restart_item_t
      character(len=:), allocatable :: name
      real(wp), allocatable :: v(:)
      !> Instead of v: the field of the increment written with this state that holds the
      !> same values in the same order ('displacement', or 'stress', 'strain', 'state' of
      !> element set `set`); resolved by the results writer (pecplas_io_results_file).
      character(len=:), allocatable :: field
      integer :: set = 0
   end type restart_item_t

   !> The named arrays of one restart state, in writing order: items(1:n) (the array grows
   !> by doubling, its items moved, not copied).
   type :: restart_data_t
      type(restart_item_t), allocatable :: items(:)
      integer :: n = 0
   contains
      procedure :: add => data_add
      procedure :: add_field => data_add_field
      procedure :: get => data_get
      procedure :: has => data_has
      procedure :: length => data_length
   end type restart_data_t

contains

   !> Appends the array `v` (any values; integers are stored exactly as reals) as `name`.
   subroutine data_add(this, name, v)
      class(restart_data_t), intent(inout) :: this
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: v(:)
      call grow(this)
      this%items(this%n)%name = name
      this%items(this%n)%v = v
   end subroutine data_add

   !> Appends `name` by reference: the values of the increment's field `field` ('displacement',
   !> or 'stress', 'strain', 'state' of element set `set`), which the results writer links
   !> or writes; no copy is made.
   subroutine data_add_field(this, name, field, set)
      class(restart_data_t), intent(inout) :: this
      character(len=*), intent(in) :: name, field
      integer, intent(in) :: set
      call grow(this)
      this%items(this%n)%name = name
      this%items(this%n)%field = field
      this%items(this%n)%set = set
   end subroutine data_add_field

   !> One more item (n + 1), the array grown by doubling with its items moved.
   subroutine grow(this)
      class(restart_data_t), intent(inout) :: this
      type(restart_item_t), allocatable :: grown(:)
      integer :: i
      if (.not. allocated(this%items)) allocate (this%items(16))
      if (this%n == size(this%items)) then
         allocate (grown(2*this%n))
         do i = 1, this%n
            call move_alloc(this%items(i)%name, grown(i)%name)
            call move_alloc(this%items(i)%v, grown(i)%v)
            call move_alloc(this%items(i)%field, grown(i)%field)
            grown(i)%set = this%items(i)%set
         end do
         call move_alloc(grown, this%items)
      end if
      this%n = this%n + 1
   end subroutine grow

   !> The array `name` of `n` values; an error naming it when absent or of another size.
   subroutine data_get(this, name, n, v, error)
      class(restart_data_t), intent(in) :: this
      character(len=*), intent(in) :: name
      integer, intent(in) :: n
      real(wp), allocatable, intent(out) :: v(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      character(len=24) :: a, b
      if (allocated(this%items)) then
         do i = 1, this%n
            if (this%items(i)%name /= name) cycle
            if (.not. allocated(this%items(i)%v)) then
               call fatal_error(error, 'restart data '//name//' is a reference to a field, '// &
                  'not values')
               return
            end if
            if (size(this%items(i)%v) /= n) then
               write (a, '(i0)') size(this%items(i)%v)
               write (b, '(i0)') n
               call fatal_error(error, 'restart data '//name//' has '//trim(a)// &
                  ' values where this deck needs '//trim(b))
               return
            end if
            v = this%items(i)%v
            return
         end do
      end if
      call fatal_error(error, 'restart data has no '//name)
   end subroutine data_get

   !> True when the data holds an item `name`.
   logical function data_has(this, name)
      class(restart_data_t), intent(in) :: this
      character(len=*), intent(in) :: name
      integer :: i
      data_has = .false.
      if (.not. allocated(this%items)) return
      do i = 1, this%n
         if (this%items(i)%name == name) data_has = .true.
      end do
   end function data_has

   !> Number of values of the item `name` (-1: no such item with values).
   integer function data_length(this, name) result(n)
      class(restart_data_t), intent(in) :: this
      character(len=*), intent(in) :: name
      integer :: i
      n = -1
      if (.not. allocated(this%items)) return
      do i = 1, this%n
         if (this%items(i)%name /= name) cycle
         if (allocated(this%items(i)%v)) n = size(this%items(i)%v)
         return
      end do
   end function data_length

   !> Writes `data` (items with values only) as /restart_next of the open file `file`,
   !> overwritten in place (see restart_put); swap_restart then renames it /restart, before
   !> the flush of the increment.
   subroutine write_restart_next(file, data, error)
      integer(hid_t), intent(in) :: file
      type(restart_data_t), intent(in) :: data
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: g
      integer :: i
      call restart_next_open(file, g, error)
      if (allocated(error)) return
      do i = 1, data%n
         if (.not. allocated(data%items(i)%v)) then
            call fatal_error(error, 'restart data '//data%items(i)%name//' is a reference '// &
               'to the field '//data%items(i)%field//', which only the results writer resolves')
         else
            call restart_put(g, data%items(i)%name, size(data%items(i)%v), data%items(i)%v, &
               error)
         end if
         if (allocated(error)) exit
      end do
      call h5_close_group(g)
   end subroutine write_restart_next

   !> Opens (creates the first time) the group /restart_next of `file`; close it with
   !> h5_close_group.
   subroutine restart_next_open(file, g, error)
      integer(hid_t), intent(in) :: file
      integer(hid_t), intent(out) :: g
      type(error_t), allocatable, intent(out) :: error
      logical :: found
      integer :: err
      call h5lexists_f(file, NEXT, found, err)
      if (found) then
         call h5gopen_f(file, NEXT, g, err)
         if (err /= 0) call fatal_error(error, 'HDF5: cannot open group '//NEXT)
      else
         call h5_group(file, NEXT, g, error)
      end if
   end subroutine restart_next_open

   !> After write_restart_next: the two names swap by link moves (the next
   !> write_restart_next overwrites what was /restart). The caller flushes.
   subroutine swap_restart(file, error)
      integer(hid_t), intent(in) :: file
      type(error_t), allocatable, intent(out) :: error
      logical :: found
      integer :: err
      call h5lexists_f(file, RESTART_GROUP, found, err)
      if (found) call h5lmove_f(file, RESTART_GROUP, file, SWAP, err)
      if (err == 0) call h5lmove_f(file, NEXT, file, RESTART_GROUP, err)
      if (err == 0 .and. found) call h5lmove_f(file, SWAP, file, NEXT, err)
      if (err /= 0) call fatal_error(error, 'cannot write the restart group')
   end subroutine swap_restart

   !> Item `name` of the open group g as a hard link to the dataset `target` (a path in the
   !> file) in place of what it was. A dataset of its own it had is kept as `name.spare`
   !> for restart_put to take back: deleted, its file space would be lost (HDF5 does not
   !> keep free space across the close that commits each increment).
   subroutine restart_link(file, g, name, target, error)
      integer(hid_t), intent(in) :: file, g
      character(len=*), intent(in) :: name, target
      type(error_t), allocatable, intent(out) :: error
      logical :: found
      integer :: err
      call h5lexists_f(g, name, found, err)
      if (found) then
         if (own_dataset(g, name)) then
            call h5lexists_f(g, name//SPARE, found, err)
            if (found) call h5ldelete_f(g, name//SPARE, err)
            call h5lmove_f(g, name, g, name//SPARE, err)
         else
            call h5ldelete_f(g, name, err)
         end if
      end if
      call h5lcreate_hard_f(file, target, g, name, err)
      if (err /= 0) call fatal_error(error, 'HDF5: cannot link restart item '//name//' to '// &
         target)
   end subroutine restart_link

   !> Item `name` of the open group g: the n values v (any contiguous array, passed by
   !> sequence association), written in place into the dataset of its own that holds it or
   !> is kept as `name.spare`, when of n values (so no file space is freed and lost), else
   !> into a new dataset. A dataset that is also another name's (a hard link to an
   !> increment's field, made by restart_link) is never written: its link is removed.
   subroutine restart_put(g, name, n, v, error)
      integer(hid_t), intent(in) :: g
      character(len=*), intent(in) :: name
      integer, intent(in) :: n
      real(wp), intent(in), target :: v(n)
      type(error_t), allocatable, intent(out) :: error
      logical :: found, done
      integer :: err
      call write_in_place(g, name, n, v, done, error)
      if (done .or. allocated(error)) return
      call h5lexists_f(g, name//SPARE, found, err)
      if (found) then
         call h5lmove_f(g, name//SPARE, g, name, err)
         call write_in_place(g, name, n, v, done, error)
         if (done .or. allocated(error)) return
      end if
      call h5_write(g, name, v, error)
   end subroutine restart_put

   !> Writes v into the dataset `name` of g when it is its own (no other name) and of n
   !> values (done); else removes the name `name` if present (not done).
   subroutine write_in_place(g, name, n, v, done, error)
      integer(hid_t), intent(in) :: g
      character(len=*), intent(in) :: name
      integer, intent(in) :: n
      real(wp), intent(in), target :: v(n)
      logical, intent(out) :: done
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(1), maxdims(1)
      type(h5o_info_t) :: info
      logical :: found
      integer :: err, e2, rank
      done = .false.
      dims = 0
      call h5lexists_f(g, name, found, err)
      if (.not. found) return
      ! one open for the reference count, the extent, the values and the checksum
      call h5dopen_f(g, name, dset, err)
      if (err /= 0) then
         call h5ldelete_f(g, name, err)
         return
      end if
      call h5oget_info_f(dset, info, err)
      rank = -1
      if (err == 0 .and. info%rc == 1) then
         call h5dget_space_f(dset, space, err)
         if (err == 0) call h5sget_simple_extent_ndims_f(space, rank, err)
         ! the rank first: the dimensions are written for every axis
         if (err == 0 .and. rank == 1) call h5sget_simple_extent_dims_f(space, dims, maxdims, &
            e2)
         if (err == 0) call h5sclose_f(space, e2)
      end if
      if (err == 0 .and. rank == 1 .and. dims(1) == int(n, hsize_t)) then
         if (n > 0) call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, c_loc(v), err)
         ! the checksum of the new values (h5_write keeps one with every real dataset)
         if (err == 0) call put_checksum(dset, values_checksum(v, n), error)
         call h5dclose_f(dset, e2)
         if (err /= 0 .and. .not. allocated(error)) call fatal_error(error, &
            'HDF5: cannot write restart dataset '//name)
         done = .true.
         return
      end if
      call h5dclose_f(dset, e2)
      call h5ldelete_f(g, name, err)
   end subroutine write_in_place

   !> The checksum attribute of the open dataset `dset`, its value written over the one there
   !> (a real scalar, as h5_write makes it), or made by h5_attr when there is none.
   subroutine put_checksum(dset, sum, error)
      integer(hid_t), intent(in) :: dset
      real(wp), intent(in) :: sum
      type(error_t), allocatable, intent(out) :: error
      real(wp), target :: buf
      integer(hid_t) :: attr
      integer :: err, e2
      buf = sum
      call h5aopen_f(dset, CHECKSUM_ATTR, attr, err)
      if (err == 0) then
         call h5awrite_f(attr, H5T_NATIVE_DOUBLE, c_loc(buf), err)
         call h5aclose_f(attr, e2)
      end if
      if (err /= 0) call h5_attr(dset, CHECKSUM_ATTR, sum, error)
   end subroutine put_checksum

   !> True when the object `name` of g is a dataset with no other name (reference count 1).
   logical function own_dataset(g, name) result(own)
      integer(hid_t), intent(in) :: g
      character(len=*), intent(in) :: name
      type(h5o_info_t) :: info
      integer(hid_t) :: obj
      integer :: err, e2
      own = .false.
      call h5oopen_f(g, name, obj, err)
      if (err /= 0) return
      call h5oget_info_f(obj, info, err)
      own = err == 0 .and. info%rc == 1 .and. info%type == H5O_TYPE_DATASET_F
      call h5oclose_f(obj, e2)
   end function own_dataset

   !> Reads /restart of the results file `path` into `data` (items named by `names`) and what
   !> identifies its deck, `deck_sum` (deck_checksum of pecplas_io_results_checksum): the
   !> file's `deck_text_checksum`, or for a file of an earlier version the checksum of its
   !> deck text. That text is a variable-length string kept in HDF5's global heap, which the
   !> library may loop on or crash on when that part of the file is damaged: it is read only
   !> when there is no checksum. An error when the file cannot be read or holds no restart
   !> group.
   subroutine read_restart_group(path, names, data, deck_sum, error)
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: names(:)
      type(restart_data_t), intent(out) :: data
      real(wp), intent(out) :: deck_sum
      type(error_t), allocatable, intent(out) :: error
      type(results_reader_t) :: reader
      real(wp), allocatable :: v(:)
      character(len=:), allocatable :: deck_text
      integer :: i
      call reader%open(path, error)
      if (allocated(error)) return
      if (.not. reader%exists('/'//RESTART_GROUP)) then
         call fatal_error(error, path//' holds no restart data (/'//RESTART_GROUP// &
            ' group): it was written before restart files existed, or before its first '// &
            'converged increment')
         return
      end if
      if (reader%has_attribute('/', 'deck_text_checksum')) then
         call reader%attribute('/', 'deck_text_checksum', deck_sum, error)
         if (.not. allocated(error) .and. .not. (deck_sum >= 0.0_wp)) call fatal_error(error, &
            'its deck text checksum is damaged')
      else
         call reader%attribute('/', 'deck_text', deck_text, error)
         if (.not. allocated(error)) deck_sum = deck_checksum(deck_text)
      end if
      if (allocated(error)) return
      do i = 1, size(names)
         if (.not. reader%exists('/'//RESTART_GROUP//'/'//trim(names(i)))) cycle
         ! a linked field keeps its shape: read as the flat vector of its values
         call reader%flat('/'//RESTART_GROUP//'/'//trim(names(i)), v, error)
         if (allocated(error)) return
         call data%add(trim(names(i)), v)
      end do
   end subroutine read_restart_group

end module pecplas_io_results_restart
