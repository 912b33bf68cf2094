!> A whole-file copy made by the kernel (copy_file_range through a C shim): the second copy
!> of a new results file gets the first one's bytes without HDF5 writing them again.
module pecplas_io_results_kernel_copy
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
   implicit none (type, external)
   private

   public :: kernel_copy

   interface
      integer(c_int) function c_kernel_copy(from, to) bind(c, name='pecplas_kernel_copy')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: from(*), to(*)
      end function c_kernel_copy
   end interface

contains

   !> Copies file `from` to the new file `to` (which must not exist). False when the kernel
   !> or the file system refuses or the copy fails: `to` is then absent, and the caller
   !> writes the copy itself.
   logical function kernel_copy(from, to) result(ok)
      character(len=*), intent(in) :: from, to
      ok = c_kernel_copy(from//c_null_char, to//c_null_char) == 0
   end function kernel_copy

end module pecplas_io_results_kernel_copy
