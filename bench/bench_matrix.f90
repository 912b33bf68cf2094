!> The assembled matrix of a benchmark run in an HDF5 file, so that a bare solver can
!> factorise it in a process of its own: datasets colptr, rowind (0-based CSC, as csc_t)
!> and values, attribute upper (1: only the upper triangle stored). Written by pecplas-bench
!> and pecplas-bench-tangent, read by pecplas-bench-bare.
module bench_matrix
   use hdf5, only: hid_t, h5fcreate_f, H5F_ACC_TRUNC_F
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_io_results_h5, only: h5_init, h5_write, h5_attr
   use pecplas_io_results_reader, only: results_reader_t
   implicit none (type, external)
   private
   public :: create_matrix_file, read_matrix_file

contains

   !> Creates `path` with the matrix k in it; the file is left open as `f` for more
   !> datasets (close it with h5fclose_f).
   subroutine create_matrix_file(path, k, f, error)
      character(len=*), intent(in) :: path
      type(csc_t), intent(in) :: k
      integer(hid_t), intent(out) :: f
      type(error_t), allocatable, intent(out) :: error
      integer :: err
      f = -1
      call h5_init(error)
      if (allocated(error)) return
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, f, err)
      if (err /= 0) then
         call fatal_error(error, 'cannot create '//path)
         return
      end if
      call h5_attr(f, 'upper', merge(1, 0, k%upper), error)
      if (.not. allocated(error)) call h5_write(f, 'colptr', k%colptr, error)
      if (.not. allocated(error)) call h5_write(f, 'rowind', k%rowind, error)
      if (.not. allocated(error)) call h5_write(f, 'values', k%values, error)
   end subroutine create_matrix_file

   !> The matrix of a file written by create_matrix_file.
   subroutine read_matrix_file(path, k, error)
      character(len=*), intent(in) :: path
      type(csc_t), intent(out) :: k
      type(error_t), allocatable, intent(out) :: error
      type(results_reader_t) :: r
      integer :: upper
      call r%open(path, error)
      if (.not. allocated(error)) call r%attribute('/', 'upper', upper, error)
      if (.not. allocated(error)) call r%dataset('/colptr', k%colptr, error)
      if (.not. allocated(error)) call r%dataset('/rowind', k%rowind, error)
      if (.not. allocated(error)) call r%dataset('/values', k%values, error)
      call r%close()
      if (allocated(error)) return
      k%n = size(k%colptr) - 1
      k%upper = upper == 1
   end subroutine read_matrix_file

end module bench_matrix
