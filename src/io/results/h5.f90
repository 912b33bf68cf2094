!> Thin, error-returning helpers over the HDF5 Fortran API used by the results writer:
!> datasets written in one call, extendible history datasets, string/number attributes,
!> and the naming rules of the results file (group names, increment groups).
!>
!> Library lifetime: `h5_init` calls h5open_f, which is safe to repeat (several files may be
!> open in one process, e.g. the test suite); h5close_f is never called because it would
!> invalidate every other open file's type ids. The HDF5 C library releases itself at exit.
!>
!> Strings are variable-length UTF-8 so that h5py reads them as `str`. Reals are IEEE
!> 64-bit little-endian in the file, integers 32-bit little-endian.
module pecplas_io_results_h5
   use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_null_char, c_null_ptr, c_char
   use hdf5, only: hid_t, hsize_t, h5open_f, h5screate_simple_f, h5screate_f, h5sclose_f, &
      h5dcreate_f, h5dwrite_f, h5dclose_f, h5dopen_f, h5dset_extent_f, h5dget_space_f, &
      h5sselect_hyperslab_f, h5gcreate_f, h5gclose_f, h5acreate_f, h5adelete_f, h5aexists_f, &
      h5awrite_f, h5aclose_f, h5tcopy_f, h5tset_cset_f, h5tclose_f, h5pcreate_f, &
      h5pset_chunk_f, h5pclose_f, h5eset_auto_f, H5T_STRING, H5T_CSET_UTF8_F, H5T_IEEE_F64LE, H5T_STD_I32LE, &
      H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, H5S_SCALAR_F, H5S_UNLIMITED_F, H5S_SELECT_SET_F, &
      H5P_DATASET_CREATE_F, h5oopen_f, h5oclose_f, h5lexists_f
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_io_results_checksum, only: values_checksum, CHECKSUM_ATTR
   implicit none (type, external)
   private

   public :: h5_init, h5_group, h5_close_group, h5_write, h5_attr, h5_history_dataset, h5_append
   public :: safe_name, increment_group, h5_describe, h5_object_attr, h5_exists

   !> Rows per chunk of the extendible history datasets.
   integer(hsize_t), parameter :: HISTORY_CHUNK = 64

   !> Writes a whole array as a new dataset `name` under `loc` (Fortran shape kept: h5py
   !> sees the reversed shape, e.g. coordinates (2, nnode) -> (nnode, 2)).
   interface h5_write
      module procedure write_real_1, write_real_2, write_real_3, write_int_1, write_int_2
   end interface h5_write

   !> Creates or overwrites an attribute of `loc` (a file id means the root group).
   interface h5_attr
      module procedure attr_string, attr_strings, attr_int, attr_real
   end interface h5_attr

   !> Writes row `row` (1-based) of an extendible history dataset, growing it first.
   interface h5_append
      module procedure append_real, append_int, append_real_row
   end interface h5_append

contains

   !> Opens the HDF5 library (idempotent) and turns its own error stack printing off: every
   !> failure is reported once, by the caller, as one line naming the file and the object.
   subroutine h5_init(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: err
      call h5open_f(err)
      if (err /= 0) then
         call fatal_error(error, 'HDF5: cannot initialise the library')
         return
      end if
      call h5eset_auto_f(0, err)
   end subroutine h5_init

   !> Group name safe for HDF5 links and XDMF paths: characters other than letters, digits,
   !> '_', '-' and '.' become '_' (the original name is kept in a `name` attribute).
   pure function safe_name(name) result(safe)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: safe
      integer :: i
      safe = trim(name)
      if (len(safe) == 0) safe = '_'
      do i = 1, len(safe)
         select case (safe(i:i))
         case ('A':'Z', 'a':'z', '0':'9', '_', '-', '.')
         case default
            safe(i:i) = '_'
         end select
      end do
      if (safe == '.') safe = '_'
   end function safe_name

   !> Path of the field group of global increment k: /increments/000042.
   pure function increment_group(k) result(path)
      integer, intent(in) :: k
      character(len=:), allocatable :: path
      character(len=16) :: buf
      if (k >= 0 .and. k <= 999999) then
         write (buf, '(i6.6)') k
      else
         write (buf, '(i0)') k
      end if
      path = '/increments/'//trim(buf)
   end function increment_group

   !> True when every link of `path` (relative to `loc`, or absolute) exists: h5lexists_f
   !> alone fails when a parent is missing.
   logical function h5_exists(loc, path) result(found)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: path
      integer :: i, err
      found = .false.
      do i = 2, len(path) + 1
         if (i <= len(path)) then
            if (path(i:i) /= '/') cycle
         end if
         call h5lexists_f(loc, path(:i - 1), found, err)
         if (err /= 0 .or. .not. found) then
            found = .false.
            return
         end if
      end do
   end function h5_exists

   !> Creates group `name` under `loc` and returns its id (close with h5_close_group).
   subroutine h5_group(loc, name, gid, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer(hid_t), intent(out) :: gid
      type(error_t), allocatable, intent(out) :: error
      integer :: err
      gid = -1
      call h5gcreate_f(loc, name, gid, err)
      if (err /= 0) gid = -1
      if (err /= 0) call fatal_error(error, 'HDF5: cannot create group '//name)
   end subroutine h5_group

   !> Closes a group opened by h5_group (no-op when gid is not valid); sets gid = -1.
   subroutine h5_close_group(gid)
      integer(hid_t), intent(inout) :: gid
      integer :: err
      if (gid > 0) call h5gclose_f(gid, err)
      gid = -1
   end subroutine h5_close_group

   subroutine write_real_1(loc, name, a, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      real(wp), intent(in), target, contiguous :: a(:)
      type(error_t), allocatable, intent(out) :: error
      call write_ptr(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &
         shape(a, kind=hsize_t), ptr_of_real(a, size(a)), error, &
         values_checksum(a, size(a)))
   end subroutine write_real_1

   subroutine write_real_2(loc, name, a, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      real(wp), intent(in), target, contiguous :: a(:, :)
      type(error_t), allocatable, intent(out) :: error
      call write_ptr(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &
         shape(a, kind=hsize_t), ptr_of_real(a, size(a)), error, &
         values_checksum(a, size(a)))
   end subroutine write_real_2

   subroutine write_real_3(loc, name, a, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      real(wp), intent(in), target, contiguous :: a(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      call write_ptr(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &
         shape(a, kind=hsize_t), ptr_of_real(a, size(a)), error, &
         values_checksum(a, size(a)))
   end subroutine write_real_3

   subroutine write_int_1(loc, name, a, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer, intent(in), target, contiguous :: a(:)
      type(error_t), allocatable, intent(out) :: error
      call write_ptr(loc, name, H5T_STD_I32LE, H5T_NATIVE_INTEGER, &
         shape(a, kind=hsize_t), ptr_of_int(a, size(a)), error)
   end subroutine write_int_1

   subroutine write_int_2(loc, name, a, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer, intent(in), target, contiguous :: a(:, :)
      type(error_t), allocatable, intent(out) :: error
      call write_ptr(loc, name, H5T_STD_I32LE, H5T_NATIVE_INTEGER, &
         shape(a, kind=hsize_t), ptr_of_int(a, size(a)), error)
   end subroutine write_int_2

   !> C address of a real array of any rank (null when empty: c_loc needs a nonzero size).
   function ptr_of_real(a, n) result(ptr)
      integer, intent(in) :: n
      real(wp), intent(in), target :: a(n)
      type(c_ptr) :: ptr
      ptr = c_null_ptr
      if (n > 0) ptr = c_loc(a)
   end function ptr_of_real

   function ptr_of_int(a, n) result(ptr)
      integer, intent(in) :: n
      integer, intent(in), target :: a(n)
      type(c_ptr) :: ptr
      ptr = c_null_ptr
      if (n > 0) ptr = c_loc(a)
   end function ptr_of_int

   subroutine write_ptr(loc, name, ftype, mtype, dims, ptr, error, checksum)
      integer(hid_t), intent(in) :: loc, ftype, mtype
      character(len=*), intent(in) :: name
      integer(hsize_t), intent(in) :: dims(:)
      type(c_ptr), intent(in) :: ptr
      type(error_t), allocatable, intent(out) :: error
      !> The values' checksum (pecplas_io_results_checksum), kept as the dataset's attribute.
      real(wp), intent(in), optional :: checksum
      real(wp), target :: buf
      integer(hid_t) :: space, dset
      integer :: err, e2
      space = -1; dset = -1
      call h5screate_simple_f(size(dims), dims, space, err)
      if (err == 0) call h5dcreate_f(loc, name, ftype, space, dset, err)
      if (err == 0 .and. product(dims) > 0) call h5dwrite_f(dset, mtype, ptr, err)
      if (err == 0 .and. present(checksum)) then
         buf = checksum
         call write_attr(dset, CHECKSUM_ATTR, H5T_IEEE_F64LE, [integer(hsize_t) ::], c_loc(buf), &
            err, H5T_NATIVE_DOUBLE)
      end if
      if (dset > 0) call h5dclose_f(dset, e2)
      if (space > 0) call h5sclose_f(space, e2)
      if (err /= 0) call fatal_error(error, 'HDF5: cannot write dataset '//name)
   end subroutine write_ptr

   !> Creates an empty extendible dataset: 1-D of integers/reals when width < 0, else 2-D
   !> (width, rows) of reals. Both axes are unlimited so that width 0 (no pattern) is valid.
   subroutine h5_history_dataset(loc, name, integers, width, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      logical, intent(in) :: integers
      integer, intent(in) :: width
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: space, dset, plist, ftype
      integer :: err, e2
      space = -1; dset = -1; plist = -1
      ftype = H5T_IEEE_F64LE
      if (integers) ftype = H5T_STD_I32LE
      call h5pcreate_f(H5P_DATASET_CREATE_F, plist, err)
      if (width < 0) then
         if (err == 0) call h5pset_chunk_f(plist, 1, [HISTORY_CHUNK], err)
         if (err == 0) call h5screate_simple_f(1, [0_hsize_t], space, err, [H5S_UNLIMITED_F])
      else
         if (err == 0) call h5pset_chunk_f(plist, 2, [int(max(width, 1), hsize_t), &
            HISTORY_CHUNK], err)
         if (err == 0) call h5screate_simple_f(2, [int(width, hsize_t), 0_hsize_t], space, err, &
            [H5S_UNLIMITED_F, H5S_UNLIMITED_F])
      end if
      if (err == 0) call h5dcreate_f(loc, name, ftype, space, dset, err, plist)
      if (dset > 0) call h5dclose_f(dset, e2)
      if (space > 0) call h5sclose_f(space, e2)
      if (plist > 0) call h5pclose_f(plist, e2)
      if (err /= 0) call fatal_error(error, 'HDF5: cannot create history dataset '//name)
   end subroutine h5_history_dataset

   subroutine append_real(loc, name, row, value, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer, intent(in) :: row
      real(wp), intent(in) :: value
      type(error_t), allocatable, intent(out) :: error
      real(wp), target :: buf(1)
      buf = value
      call append_ptr(loc, name, H5T_NATIVE_DOUBLE, -1, row, c_loc(buf), error)
   end subroutine append_real

   subroutine append_int(loc, name, row, value, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer, intent(in) :: row, value
      type(error_t), allocatable, intent(out) :: error
      integer, target :: buf(1)
      buf = value
      call append_ptr(loc, name, H5T_NATIVE_INTEGER, -1, row, c_loc(buf), error)
   end subroutine append_int

   subroutine append_real_row(loc, name, row, values, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer, intent(in) :: row
      real(wp), intent(in), target, contiguous :: values(:)
      type(error_t), allocatable, intent(out) :: error
      call append_ptr(loc, name, H5T_NATIVE_DOUBLE, size(values), row, &
         ptr_of_real(values, size(values)), error)
   end subroutine append_real_row

   subroutine append_ptr(loc, name, mtype, width, row, ptr, error)
      integer(hid_t), intent(in) :: loc, mtype
      character(len=*), intent(in) :: name
      integer, intent(in) :: width, row
      type(c_ptr), intent(in) :: ptr
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset, fspace, mspace
      integer(hsize_t) :: extent(2), start(2), count(2)
      integer :: err, e2, r
      dset = -1; fspace = -1; mspace = -1
      if (width < 0) then
         r = 1
         extent(1) = int(row, hsize_t)
         start(1) = int(row - 1, hsize_t)
         count(1) = 1
      else
         r = 2
         extent = [int(width, hsize_t), int(row, hsize_t)]
         start = [0_hsize_t, int(row - 1, hsize_t)]
         count = [int(width, hsize_t), 1_hsize_t]
      end if
      call h5dopen_f(loc, name, dset, err)
      if (err == 0) call h5dset_extent_f(dset, extent(:r), err)
      if (err == 0 .and. product(count(:r)) > 0) then
         call h5dget_space_f(dset, fspace, err)
         if (err == 0) call h5sselect_hyperslab_f(fspace, H5S_SELECT_SET_F, start(:r), &
            count(:r), err)
         if (err == 0) call h5screate_simple_f(r, count(:r), mspace, err)
         if (err == 0) call h5dwrite_f(dset, mtype, ptr, err, mspace, fspace)
      end if
      if (mspace > 0) call h5sclose_f(mspace, e2)
      if (fspace > 0) call h5sclose_f(fspace, e2)
      if (dset > 0) call h5dclose_f(dset, e2)
      if (err /= 0) call fatal_error(error, 'HDF5: cannot append to history dataset '//name)
   end subroutine append_ptr

   !> Attributes `units` and (when given) `components` of the object (dataset or group) at
   !> `path` under `loc`, which must exist.
   subroutine h5_describe(loc, path, units, error, components)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: path, units
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in), optional :: components(:)
      integer(hid_t) :: obj
      integer :: err
      call h5oopen_f(loc, path, obj, err)
      if (err /= 0) then
         call fatal_error(error, 'HDF5: cannot open '//path//' to describe it')
         return
      end if
      call attr_string(obj, 'units', units, error)
      if (.not. allocated(error) .and. present(components)) &
         call attr_strings(obj, 'components', components, error)
      call h5oclose_f(obj, err)
   end subroutine h5_describe

   !> String-list attribute `name` of the object (dataset or group) at `path` under `loc`.
   subroutine h5_object_attr(loc, path, name, values, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: path, name, values(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: obj
      integer :: err
      call h5oopen_f(loc, path, obj, err)
      if (err /= 0) then
         call fatal_error(error, 'HDF5: cannot open '//path)
         return
      end if
      call attr_strings(obj, name, values, error)
      call h5oclose_f(obj, err)
   end subroutine h5_object_attr

   !> Scalar variable-length UTF-8 string attribute.
   subroutine attr_string(loc, name, value, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name, value
      type(error_t), allocatable, intent(out) :: error
      character(len=:, kind=c_char), allocatable, target :: buf
      type(c_ptr), target :: ptr(1)
      integer(hid_t) :: vtype
      integer :: err, e2
      ! heap copy: the deck text may be far larger than the stack
      buf = value//c_null_char
      ptr(1) = c_loc(buf)
      call vlen_string_type(vtype, err)
      if (err == 0) call write_attr(loc, name, vtype, [integer(hsize_t) ::], c_loc(ptr), err)
      if (vtype > 0) call h5tclose_f(vtype, e2)
      if (err /= 0) call fatal_error(error, 'HDF5: cannot write attribute '//name)
   end subroutine attr_string

   !> 1-D attribute of variable-length strings (trailing blanks of each entry dropped).
   subroutine attr_strings(loc, name, values, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name, values(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=len(values) + 1, kind=c_char), allocatable, target :: buf(:)
      type(c_ptr), allocatable, target :: ptr(:)
      type(c_ptr) :: start
      integer(hid_t) :: vtype
      integer :: err, e2, i
      allocate (buf(size(values)), ptr(size(values)))
      do i = 1, size(values)
         buf(i) = trim(values(i))//c_null_char
         ptr(i) = c_loc(buf(i))
      end do
      start = c_null_ptr
      if (size(values) > 0) start = c_loc(ptr)
      call vlen_string_type(vtype, err)
      if (err == 0) call write_attr(loc, name, vtype, [int(size(values), hsize_t)], start, err)
      if (vtype > 0) call h5tclose_f(vtype, e2)
      if (err /= 0) call fatal_error(error, 'HDF5: cannot write attribute '//name)
   end subroutine attr_strings

   subroutine attr_int(loc, name, value, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      integer, intent(in) :: value
      type(error_t), allocatable, intent(out) :: error
      integer, target :: buf
      integer :: err
      buf = value
      call write_attr(loc, name, H5T_STD_I32LE, [integer(hsize_t) ::], c_loc(buf), err, &
         H5T_NATIVE_INTEGER)
      if (err /= 0) call fatal_error(error, 'HDF5: cannot write attribute '//name)
   end subroutine attr_int

   subroutine attr_real(loc, name, value, error)
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: value
      type(error_t), allocatable, intent(out) :: error
      real(wp), target :: buf
      integer :: err
      buf = value
      call write_attr(loc, name, H5T_IEEE_F64LE, [integer(hsize_t) ::], c_loc(buf), err, &
         H5T_NATIVE_DOUBLE)
      if (err /= 0) call fatal_error(error, 'HDF5: cannot write attribute '//name)
   end subroutine attr_real

   subroutine vlen_string_type(vtype, err)
      integer(hid_t), intent(out) :: vtype
      integer, intent(out) :: err
      vtype = -1
      call h5tcopy_f(H5T_STRING, vtype, err)
      if (err == 0) call h5tset_cset_f(vtype, H5T_CSET_UTF8_F, err)
   end subroutine vlen_string_type

   !> Opens attribute `name` when it exists (status is rewritten), else creates it; then
   !> writes `ptr` with memory type `mtype` (default: the file type). dims = [] is scalar.
   subroutine write_attr(loc, name, ftype, dims, ptr, err, mtype)
      integer(hid_t), intent(in) :: loc, ftype
      character(len=*), intent(in) :: name
      integer(hsize_t), intent(in) :: dims(:)
      type(c_ptr), intent(in) :: ptr
      integer, intent(out) :: err
      integer(hid_t), intent(in), optional :: mtype
      integer(hid_t) :: space, attr
      logical :: exists
      integer :: e2
      space = -1; attr = -1
      ! an existing attribute is replaced: reopening it would keep its old shape and type
      ! (a list written again with more entries would lose them)
      call h5aexists_f(loc, name, exists, err)
      if (err /= 0) return
      if (exists) call h5adelete_f(loc, name, err)
      if (err /= 0) return
      if (size(dims) == 0) then
         call h5screate_f(H5S_SCALAR_F, space, err)
      else
         call h5screate_simple_f(size(dims), dims, space, err)
      end if
      if (err == 0) call h5acreate_f(loc, name, ftype, space, attr, err)
      if (err == 0 .and. product(dims) > 0) then
         if (present(mtype)) then
            call h5awrite_f(attr, mtype, ptr, err)
         else
            call h5awrite_f(attr, ftype, ptr, err)
         end if
      end if
      if (attr > 0) call h5aclose_f(attr, e2)
      if (space > 0) call h5sclose_f(space, e2)
   end subroutine write_attr

end module pecplas_io_results_h5
