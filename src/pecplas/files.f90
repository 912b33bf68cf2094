!> Small file-system helpers (directory creation, path pieces) for the command layer.
module pecplas_files
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   implicit none (type, external)
   private

   public :: make_directories, path_stem, path_dir

   interface
      integer(c_int) function c_mkdir(path, mode) bind(C, name='mkdir')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: mode
      end function c_mkdir
   end interface

contains

   !> Creates `dir` and its parents (like mkdir -p); existing directories are fine.
   subroutine make_directories(dir)
      character(len=*), intent(in) :: dir
      integer :: i
      integer(c_int) :: rc
      if (len_trim(dir) == 0) return
      do i = 2, len_trim(dir)
         if (dir(i:i) == '/') rc = c_mkdir(dir(1:i - 1)//c_null_char, int(o'755', c_int))
      end do
      rc = c_mkdir(trim(dir)//c_null_char, int(o'755', c_int))
   end subroutine make_directories

   !> File name without directory and extension: 'input/pile.inp' -> 'pile'.
   function path_stem(path) result(stem)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: stem
      integer :: i, j
      i = index(path, '/', back=.true.)
      stem = path(i + 1:len_trim(path))
      j = index(stem, '.', back=.true.)
      if (j > 1) stem = stem(1:j - 1)
   end function path_stem

   !> Directory part of a path ('' when none): 'output/a.h5' -> 'output'.
   function path_dir(path) result(dir)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: dir
      integer :: i
      i = index(path, '/', back=.true.)
      dir = ''
      if (i > 1) dir = path(1:i - 1)
   end function path_dir

end module pecplas_files
