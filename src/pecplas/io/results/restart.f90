!> The `/restart` group of a results file: the full state of the last converged increment,
!> as named 1-D real datasets (the driver packs and unpacks them: pecplas_driver_restart).
!> It is replaced at every converged increment (written as /restart_next, then renamed), so
!> the file holds one copy whatever the number of increments. The results writer flushes a
!> copy of the file only once the increment, /restart included, is whole, and never writes
!> the copy a killed run leaves for reading (pecplas_io_results_file).
module pecplas_io_results_restart
   use, intrinsic :: iso_c_binding, only: c_loc
   use hdf5, only: hid_t, hsize_t, h5lexists_f, h5ldelete_f, h5lmove_f, h5gopen_f, h5dopen_f, &
      h5dclose_f, h5dget_space_f, h5sclose_f, h5sget_simple_extent_dims_f, h5dwrite_f, &
      H5T_NATIVE_DOUBLE
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t, fatal_error
   use pecplas_io_results_h5, only: h5_group, h5_close_group, h5_write
   use pecplas_io_results_reader, only: results_reader_t
   implicit none (type, external)
   private

   public :: restart_item_t, restart_data_t, write_restart_next, swap_restart, read_restart_group

   !> Group name in the results file.
   character(len=*), parameter, public :: RESTART_GROUP = 'restart'
   character(len=*), parameter :: NEXT = RESTART_GROUP//'_next', SWAP = RESTART_GROUP//'_swap'

   type :: restart_item_t
      character(len=:), allocatable :: name
      real(wp), allocatable :: v(:)
   end type restart_item_t

   !> The named arrays of one restart state, in writing order: items(1:n) (the array grows
   !> by doubling, its items moved, not copied).
   type :: restart_data_t
      type(restart_item_t), allocatable :: items(:)
      integer :: n = 0
   contains
      procedure :: add => data_add
      procedure :: get => data_get
   end type restart_data_t

contains

   !> Appends the array `v` (any values; integers are stored exactly as reals) as `name`.
   subroutine data_add(this, name, v)
      class(restart_data_t), intent(inout) :: this
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: v(:)
      type(restart_item_t), allocatable :: grown(:)
      integer :: i
      if (.not. allocated(this%items)) allocate (this%items(16))
      if (this%n == size(this%items)) then
         allocate (grown(2*this%n))
         do i = 1, this%n
            call move_alloc(this%items(i)%name, grown(i)%name)
            call move_alloc(this%items(i)%v, grown(i)%v)
         end do
         call move_alloc(grown, this%items)
      end if
      this%n = this%n + 1
      this%items(this%n)%name = name
      this%items(this%n)%v = v
   end subroutine data_add

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

   !> Writes `data` as /restart_next of the open file `file`, overwritten in place (both
   !> restart groups keep their datasets, so no file space is freed and reused);
   !> swap_restart then renames it /restart, before the flush of the increment.
   subroutine write_restart_next(file, data, error)
      integer(hid_t), intent(in) :: file
      type(restart_data_t), intent(in) :: data
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: g
      logical :: found
      integer :: i, err
      call h5lexists_f(file, NEXT, found, err)
      if (found) then
         call h5gopen_f(file, NEXT, g, err)
      else
         call h5_group(file, NEXT, g, error)
         if (allocated(error)) return
      end if
      do i = 1, data%n
         call overwrite(g, data%items(i)%name, data%items(i)%v, error)
         if (allocated(error)) exit
      end do
      call h5_close_group(g)
   end subroutine write_restart_next

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

   !> Writes v as dataset `name` of group g: in place when it exists with the same length,
   !> else (re)created.
   subroutine overwrite(g, name, v, error)
      integer(hid_t), intent(in) :: g
      character(len=*), intent(in) :: name
      real(wp), intent(in), target, contiguous :: v(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(1), maxdims(1)
      logical :: found
      integer :: err, e2
      call h5lexists_f(g, name, found, err)
      if (found) then
         call h5dopen_f(g, name, dset, err)
         call h5dget_space_f(dset, space, err)
         call h5sget_simple_extent_dims_f(space, dims, maxdims, e2)
         call h5sclose_f(space, e2)
         if (e2 == 1 .and. dims(1) == size(v, kind=hsize_t)) then
            if (size(v) > 0) call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, c_loc(v), err)
            call h5dclose_f(dset, e2)
            if (err /= 0) call fatal_error(error, 'HDF5: cannot write restart dataset '//name)
            return
         end if
         call h5dclose_f(dset, e2)
         call h5ldelete_f(g, name, err)
      end if
      call h5_write(g, name, v, error)
   end subroutine overwrite

   !> Reads /restart of the results file `path` into `data` (items named by `names`) and its
   !> deck text. An error when the file cannot be read or holds no restart group.
   subroutine read_restart_group(path, names, data, deck_text, error)
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: names(:)
      type(restart_data_t), intent(out) :: data
      character(len=:), allocatable, intent(out) :: deck_text
      type(error_t), allocatable, intent(out) :: error
      type(results_reader_t) :: reader
      real(wp), allocatable :: v(:)
      integer :: i
      call reader%open(path, error)
      if (allocated(error)) return
      if (.not. reader%exists('/'//RESTART_GROUP)) then
         call fatal_error(error, path//' holds no restart data (/'//RESTART_GROUP// &
            ' group): it was written before restart files existed, or before its first '// &
            'converged increment')
         return
      end if
      call reader%attribute('/', 'deck_text', deck_text, error)
      if (allocated(error)) return
      do i = 1, size(names)
         if (.not. reader%exists('/'//RESTART_GROUP//'/'//trim(names(i)))) cycle
         call reader%dataset('/'//RESTART_GROUP//'/'//trim(names(i)), v, error)
         if (allocated(error)) return
         call data%add(trim(names(i)), v)
      end do
   end subroutine read_restart_group

end module pecplas_io_results_restart
