!> Read-only access to a results file (tests, post-processing tools): attributes,
!> whole datasets, the run status and the fields of one increment. Paths are absolute
!> HDF5 paths such as '/history/time' or '/' for the root group's attributes.
module pecplas_io_results_reader
   use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_f_pointer, c_size_t, c_char, &
      c_associated
   use hdf5, only: hid_t, hsize_t, size_t, h5fopen_f, h5fclose_f, h5dopen_f, h5dclose_f, &
      h5dread_f, h5dget_space_f, h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f, &
      h5sclose_f, h5aopen_by_name_f, h5aread_f, h5aclose_f, h5aget_type_f, h5aget_space_f, &
      h5tis_variable_str_f, h5tget_size_f, h5tget_cset_f, h5tset_cset_f, h5tcopy_f, h5tset_size_f, h5tclose_f, &
      h5lexists_f, h5aexists_by_name_f, h5dvlen_reclaim_f, H5F_ACC_RDONLY_F, H5T_STRING, &
      H5T_FORTRAN_S1, H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, H5P_DEFAULT_F, h5fget_filesize_f, &
      h5aexists_f, h5aopen_f, h5sget_simple_extent_npoints_f
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_io_results_h5, only: h5_init, increment_group
   use pecplas_io_results_checksum, only: values_checksum, CHECKSUM_ATTR
   implicit none (type, external)
   private

   public :: results_reader_t

   type :: results_reader_t
      private
      integer(hid_t) :: file = -1
   contains
      procedure :: open => reader_open
      procedure :: close => reader_close
      procedure :: exists => reader_exists
      procedure :: has_attribute => reader_has_attribute
      procedure, private :: attr_string, attr_int, attr_real
      !> attribute(object, name, value, error): value is a string, integer or real.
      generic :: attribute => attr_string, attr_int, attr_real
      procedure, private :: read_real_1, read_real_2, read_real_3, read_int_1, read_int_2
      !> dataset(path, values, error): values allocatable of the dataset's Fortran shape.
      generic :: dataset => read_real_1, read_real_2, read_real_3, read_int_1, read_int_2
      !> flat(path, values, error): a real dataset of any rank as the vector of its values
      !> in memory order (what a Fortran array of its shape holds, column-major).
      procedure :: flat => read_real_flat
      procedure :: history_length => reader_history_length
      procedure :: displacement => reader_displacement
      final :: reader_final
   end type results_reader_t

   interface
      !> Length of a C string (variable-length HDF5 strings are C strings).
      pure function c_strlen(s) bind(c, name='strlen') result(n)
         import :: c_ptr, c_size_t
         type(c_ptr), value, intent(in) :: s
         integer(c_size_t) :: n
      end function c_strlen
   end interface

contains

   !> Opens `path` read-only.
   subroutine reader_open(this, path, error)
      class(results_reader_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer :: err
      call this%close()
      call h5_init(error)
      if (allocated(error)) return
      call h5fopen_f(path, H5F_ACC_RDONLY_F, this%file, err)
      if (err /= 0) then
         this%file = -1
         call fatal_error(error, 'cannot open results file '//path)
      end if
   end subroutine reader_open

   !> Closes the file (no-op when not open); also done by the finaliser.
   subroutine reader_close(this)
      class(results_reader_t), intent(inout) :: this
      integer :: err
      if (this%file > 0) call h5fclose_f(this%file, err)
      this%file = -1
   end subroutine reader_close

   subroutine reader_final(this)
      type(results_reader_t), intent(inout) :: this
      call this%close()
   end subroutine reader_final

   !> True when every component of `path` exists.
   logical function reader_exists(this, path) result(found)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: path
      integer :: i, n, err
      found = .false.
      if (this%file <= 0) return
      n = len_trim(path)
      if (n > 1 .and. path(n:n) == '/') n = n - 1
      if (path(:n) == '/') then
         found = .true.
         return
      end if
      ! h5lexists_f fails (printing an HDF5 trace) when a parent is missing: check each
      ! parent first, then the path itself
      do i = 1, n
         if (i < n .and. (i == 1 .or. path(i:i) /= '/')) cycle
         if (i < n) then
            call h5lexists_f(this%file, path(:i - 1), found, err)
         else
            call h5lexists_f(this%file, path(:n), found, err)
         end if
         if (err /= 0 .or. .not. found) then
            found = .false.
            return
         end if
      end do
   end function reader_exists

   !> True when object (a path, '/' for the root) exists and has attribute `name`.
   logical function reader_has_attribute(this, object, name) result(found)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: object, name
      integer :: err
      found = .false.
      if (object /= '/' .and. .not. this%exists(object)) return
      call h5aexists_by_name_f(this%file, object, name, found, err)
      if (err /= 0) found = .false.
   end function reader_has_attribute

   !> A string attribute, variable-length or fixed-length.
   subroutine attr_string(this, object, name, value, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: object, name
      character(len=:), allocatable, intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: attr, ftype, mtype, space
      type(c_ptr), target :: cstr
      type(c_ptr) :: buf
      character(kind=c_char), pointer :: chars(:)
      character(len=:), allocatable, target :: fixed
      integer(size_t) :: n
      logical :: variable
      integer :: err, e2, i, cset
      value = ''
      call open_attr(this, object, name, attr, error)
      if (allocated(error)) return
      mtype = -1; space = -1
      call h5aget_type_f(attr, ftype, err)
      if (err == 0) call h5tis_variable_str_f(ftype, variable, err)
      if (err == 0 .and. variable) then
         call h5tcopy_f(H5T_STRING, mtype, err)
         ! same character set as the file, else HDF5 finds no conversion
         if (err == 0) call h5tget_cset_f(ftype, cset, err)
         if (err == 0) call h5tset_cset_f(mtype, cset, err)
         buf = c_loc(cstr)
         if (err == 0) call h5aread_f(attr, mtype, buf, err)
         if (err == 0 .and. c_associated(cstr)) then
            call c_f_pointer(cstr, chars, [c_strlen(cstr)])
            value = repeat(' ', size(chars))
            do i = 1, size(chars)
               value(i:i) = chars(i)
            end do
            call h5aget_space_f(attr, space, e2)
            call h5dvlen_reclaim_f(mtype, space, H5P_DEFAULT_F, buf, e2)
         end if
      else if (err == 0) then
         call h5tget_size_f(ftype, n, err)
         allocate (character(len=n) :: fixed)
         if (err == 0) call h5tcopy_f(H5T_FORTRAN_S1, mtype, err)
         if (err == 0) call h5tset_size_f(mtype, n, err)
         if (err == 0) call h5tget_cset_f(ftype, cset, err)
         if (err == 0) call h5tset_cset_f(mtype, cset, err)
         buf = c_loc(fixed)
         if (err == 0) call h5aread_f(attr, mtype, buf, err)
         i = index(fixed, achar(0))
         if (i > 0) fixed = fixed(:i - 1)
         value = trim(fixed)
      end if
      if (space > 0) call h5sclose_f(space, e2)
      if (mtype > 0) call h5tclose_f(mtype, e2)
      call h5tclose_f(ftype, e2)
      call h5aclose_f(attr, e2)
      if (err /= 0) call fatal_error(error, 'cannot read string attribute '//name//' of '//object)
   end subroutine attr_string

   subroutine attr_int(this, object, name, value, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: object, name
      integer, intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: attr
      integer, target :: buf
      type(c_ptr) :: ptr
      integer :: err, e2
      value = 0
      call open_attr(this, object, name, attr, error)
      if (allocated(error)) return
      ptr = c_loc(buf)
      err = -1
      if (one_value(attr)) call h5aread_f(attr, H5T_NATIVE_INTEGER, ptr, err)
      call h5aclose_f(attr, e2)
      if (err /= 0) call fatal_error(error, 'cannot read integer attribute '//name)
      value = buf
   end subroutine attr_int

   subroutine attr_real(this, object, name, value, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: object, name
      real(wp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: attr
      real(wp), target :: buf
      type(c_ptr) :: ptr
      integer :: err, e2
      value = 0.0_wp
      call open_attr(this, object, name, attr, error)
      if (allocated(error)) return
      ptr = c_loc(buf)
      err = -1
      if (one_value(attr)) call h5aread_f(attr, H5T_NATIVE_DOUBLE, ptr, err)
      call h5aclose_f(attr, e2)
      if (err /= 0) call fatal_error(error, 'cannot read real attribute '//name)
      value = buf
   end subroutine attr_real

   !> True when the attribute holds exactly one value: a scalar read of a (damaged) larger
   !> attribute would write past its one-value buffer.
   logical function one_value(attr)
      integer(hid_t), intent(in) :: attr
      integer(hid_t) :: space
      integer(hsize_t) :: npoints
      integer :: err, e2
      one_value = .false.
      call h5aget_space_f(attr, space, err)
      if (err /= 0) return
      call h5sget_simple_extent_npoints_f(space, npoints, err)
      call h5sclose_f(space, e2)
      one_value = err == 0 .and. npoints == 1
   end function one_value

   subroutine open_attr(this, object, name, attr, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: object, name
      integer(hid_t), intent(out) :: attr
      type(error_t), allocatable, intent(out) :: error
      integer :: err
      attr = -1
      if (.not. this%has_attribute(object, name)) then
         call fatal_error(error, 'results file has no attribute '//name//' on '//object)
         return
      end if
      call h5aopen_by_name_f(this%file, object, name, attr, err)
      if (err /= 0) call fatal_error(error, 'cannot open attribute '//name//' of '//object)
   end subroutine open_attr

   !> Opens dataset `path`, checks its rank and returns its Fortran dimensions.
   subroutine open_dataset(this, path, rank, dset, dims, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: path
      integer, intent(in) :: rank
      integer(hid_t), intent(out) :: dset
      integer, intent(out) :: dims(rank)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: space
      integer(hsize_t) :: d(rank), maxd(rank)
      integer :: err, e2, ndims
      dset = -1
      dims = 0
      if (.not. this%exists(path)) then
         call fatal_error(error, 'results file has no dataset '//path)
         return
      end if
      call h5dopen_f(this%file, path, dset, err)
      if (err == 0) call h5dget_space_f(dset, space, err)
      if (err == 0) call h5sget_simple_extent_ndims_f(space, ndims, err)
      if (err == 0 .and. ndims == rank) then
         call h5sget_simple_extent_dims_f(space, d, maxd, err)
         if (err == rank) err = 0
      end if
      if (err == 0) call h5sclose_f(space, e2)
      if (err /= 0 .or. ndims /= rank) then
         if (dset > 0) call h5dclose_f(dset, e2)
         dset = -1
         call fatal_error(error, 'cannot read dataset '//path//' as an array of that rank')
         return
      end if
      call check_extent(this, path, d, error)
      if (allocated(error)) then
         call h5dclose_f(dset, e2)
         dset = -1
         return
      end if
      dims = int(d)
   end subroutine open_dataset

   !> A damaged file may give a dataset any extent: one that needs more bytes than the whole
   !> file holds (at 4 bytes a value, the smallest stored here), or more values than an
   !> integer counts, is refused before anything is allocated.
   subroutine check_extent(this, path, d, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: path
      integer(hsize_t), intent(in) :: d(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hsize_t) :: fsize
      real(wp) :: n
      integer :: err
      character(len=40) :: buf
      n = product(real(d, wp))
      call h5fget_filesize_f(this%file, fsize, err)
      if (err /= 0) fsize = huge(fsize)
      if (any(d < 0) .or. n > real(huge(1), wp) .or. 4.0_wp*n > real(fsize, wp)) then
         write (buf, '(es10.3)') n
         call fatal_error(error, 'dataset '//path//' is damaged: its shape says '// &
            trim(adjustl(buf))//' values, more than the file holds')
      end if
   end subroutine check_extent

   !> Reads the open dataset into `ptr` (n values) and closes it.
   subroutine read_and_close(dset, mtype, n, ptr, path, error)
      integer(hid_t), intent(inout) :: dset
      integer(hid_t), intent(in) :: mtype
      integer, intent(in) :: n
      type(c_ptr), intent(in) :: ptr
      character(len=*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      type(c_ptr) :: buf
      integer :: err, e2
      err = 0
      buf = ptr   ! h5dread_f wants a definable pointer
      if (n > 0) call h5dread_f(dset, mtype, buf, err)
      if (err == 0 .and. mtype == H5T_NATIVE_DOUBLE) call verify_checksum(dset, n, ptr, path, &
         error)
      call h5dclose_f(dset, e2)
      dset = -1
      if (err /= 0) call fatal_error(error, 'cannot read dataset '//path)
   end subroutine read_and_close

   !> The n values read at `ptr` against the dataset's checksum attribute, when it has one
   !> (every real dataset the program writes; files of earlier versions have none).
   subroutine verify_checksum(dset, n, ptr, path, error)
      integer(hid_t), intent(in) :: dset
      integer, intent(in) :: n
      type(c_ptr), intent(in) :: ptr
      character(len=*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      real(wp), pointer :: v(:)
      real(wp), target :: stored
      real(wp) :: computed
      type(c_ptr) :: sp
      integer(hid_t) :: attr
      logical :: found
      integer :: err, e2
      call h5aexists_f(dset, CHECKSUM_ATTR, found, err)
      if (err /= 0 .or. .not. found) return
      call h5aopen_f(dset, CHECKSUM_ATTR, attr, err)
      if (err /= 0) then
         call fatal_error(error, 'dataset '//path//' is damaged: its checksum cannot be read')
         return
      end if
      sp = c_loc(stored)   ! h5aread_f wants a definable pointer
      err = -1
      if (one_value(attr)) call h5aread_f(attr, H5T_NATIVE_DOUBLE, sp, err)
      call h5aclose_f(attr, e2)
      computed = 0.0_wp   ! the checksum of no values
      if (n > 0) then
         call c_f_pointer(ptr, v, [n])
         computed = values_checksum(v, n)
      end if
      if (err /= 0 .or. .not. (stored == computed)) call fatal_error(error, &
         'dataset '//path//' is damaged: its values do not match their checksum')
   end subroutine verify_checksum

   subroutine read_real_1(this, path, values, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: path
      real(wp), allocatable, target, intent(out) :: values(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer :: d(1)
      call open_dataset(this, path, 1, dset, d, error)
      if (allocated(error)) return
      allocate (values(d(1)))
      call read_and_close(dset, H5T_NATIVE_DOUBLE, size(values), c_loc(values), path, error)
   end subroutine read_real_1

   subroutine read_real_2(this, path, values, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: path
      real(wp), allocatable, target, intent(out) :: values(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer :: d(2)
      call open_dataset(this, path, 2, dset, d, error)
      if (allocated(error)) return
      allocate (values(d(1), d(2)))
      call read_and_close(dset, H5T_NATIVE_DOUBLE, size(values), c_loc(values), path, error)
   end subroutine read_real_2

   subroutine read_real_3(this, path, values, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: path
      real(wp), allocatable, target, intent(out) :: values(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer :: d(3)
      call open_dataset(this, path, 3, dset, d, error)
      if (allocated(error)) return
      allocate (values(d(1), d(2), d(3)))
      call read_and_close(dset, H5T_NATIVE_DOUBLE, size(values), c_loc(values), path, error)
   end subroutine read_real_3

   subroutine read_int_1(this, path, values, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: path
      integer, allocatable, target, intent(out) :: values(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer :: d(1)
      call open_dataset(this, path, 1, dset, d, error)
      if (allocated(error)) return
      allocate (values(d(1)))
      call read_and_close(dset, H5T_NATIVE_INTEGER, size(values), c_loc(values), path, error)
   end subroutine read_int_1

   subroutine read_int_2(this, path, values, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: path
      integer, allocatable, target, intent(out) :: values(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer :: d(2)
      call open_dataset(this, path, 2, dset, d, error)
      if (allocated(error)) return
      allocate (values(d(1), d(2)))
      call read_and_close(dset, H5T_NATIVE_INTEGER, size(values), c_loc(values), path, error)
   end subroutine read_int_2

   subroutine read_real_flat(this, path, values, error)
      class(results_reader_t), intent(in) :: this
      character(len=*), intent(in) :: path
      real(wp), allocatable, target, intent(out) :: values(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset, space
      integer(hsize_t) :: d(7), maxd(7)
      integer :: err, e2, ndims
      if (.not. this%exists(path)) then
         call fatal_error(error, 'results file has no dataset '//path)
         return
      end if
      d = 1
      call h5dopen_f(this%file, path, dset, err)
      if (err /= 0) then
         call fatal_error(error, 'cannot open dataset '//path)
         return
      end if
      call h5dget_space_f(dset, space, err)
      if (err == 0) call h5sget_simple_extent_ndims_f(space, ndims, err)
      if (err == 0 .and. (ndims < 0 .or. ndims > size(d))) err = -1
      if (err == 0 .and. ndims > 0) then
         call h5sget_simple_extent_dims_f(space, d(:ndims), maxd(:ndims), err)
         if (err == ndims) err = 0
      end if
      if (err == 0) call h5sclose_f(space, e2)
      if (err /= 0) then
         call h5dclose_f(dset, e2)
         call fatal_error(error, 'cannot read dataset '//path//' as a vector')
         return
      end if
      call check_extent(this, path, d(:max(ndims, 0)), error)
      if (allocated(error)) then
         call h5dclose_f(dset, e2)
         return
      end if
      allocate (values(product(d(:max(ndims, 0)))))
      call read_and_close(dset, H5T_NATIVE_DOUBLE, size(values), c_loc(values), path, error)
   end subroutine read_real_flat

   !> Number of rows of /history (converged increments written).
   subroutine reader_history_length(this, n, error)
      class(results_reader_t), intent(in) :: this
      integer, intent(out) :: n
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: time(:)
      n = 0
      call this%dataset('/history/time', time, error)
      if (allocated(error)) return
      n = size(time)
   end subroutine reader_history_length

   !> Displacement (2, nnode) of global increment k (error if k has no fields).
   subroutine reader_displacement(this, k, u, error)
      class(results_reader_t), intent(in) :: this
      integer, intent(in) :: k
      real(wp), allocatable, intent(out) :: u(:, :)
      type(error_t), allocatable, intent(out) :: error
      call this%dataset(increment_group(k)//'/displacement', u, error)
   end subroutine reader_displacement

end module pecplas_io_results_reader
