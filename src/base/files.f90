!> Small file-system helpers (directory creation, path pieces, rename, identity of two
!> paths) for the command layer and the results writer.
module pecplas_base_files
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_long_long
   use, intrinsic :: iso_fortran_env, only: int64, output_unit, error_unit
   implicit none (type, external)
   private

   public :: make_directories, path_stem, path_dir, path_base, rename_file, remove_file, &
      link_file, symlink_file, same_file, process_id, free_bytes, exit_now

   interface
      integer(c_int) function c_mkdir(path, mode) bind(C, name='mkdir')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: mode
      end function c_mkdir
      integer(c_int) function c_rename(from, to) bind(C, name='rename')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: from(*), to(*)
      end function c_rename
      integer(c_int) function c_link(from, to) bind(C, name='link')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: from(*), to(*)
      end function c_link
      integer(c_int) function c_symlink(target, to) bind(C, name='symlink')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: target(*), to(*)
      end function c_symlink
      integer(c_int) function c_unlink(path) bind(C, name='unlink')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
      end function c_unlink
      integer(c_int) function c_same_file(a, b) bind(C, name='pecplas_same_file')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: a(*), b(*)
      end function c_same_file
      integer(c_int) function c_getpid() bind(C, name='pecplas_getpid')
         import :: c_int
      end function c_getpid
      integer(c_long_long) function c_free_bytes(path) bind(C, name='pecplas_free_bytes')
         import :: c_long_long, c_char
         character(kind=c_char), intent(in) :: path(*)
      end function c_free_bytes
      subroutine c_exit_now(code) bind(C, name='pecplas_exit_now')
         import :: c_int
         integer(c_int), value :: code
      end subroutine c_exit_now
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

   !> File name without its directory: 'output/a.h5' -> 'a.h5'.
   pure function path_base(path) result(base)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: base
      base = path(index(path, '/', back=.true.) + 1:len_trim(path))
   end function path_base

   !> Renames `from` onto `to` (atomic within one file system: `to` is either the old or
   !> the new file, never a mixture); false on failure.
   logical function rename_file(from, to) result(ok)
      character(len=*), intent(in) :: from, to
      ok = c_rename(from//c_null_char, to//c_null_char) == 0
   end function rename_file

   !> Makes `to` (which must not exist) another name of the file `from` (a hard link);
   !> false on failure (e.g. a file system without hard links).
   logical function link_file(from, to) result(ok)
      character(len=*), intent(in) :: from, to
      ok = c_link(from//c_null_char, to//c_null_char) == 0
   end function link_file

   !> Makes `to` (which must not exist) a symbolic link to `from`'s base name: both must be
   !> in the same directory; false on failure.
   logical function symlink_file(from, to) result(ok)
      character(len=*), intent(in) :: from, to
      ok = c_symlink(path_base(from)//c_null_char, to//c_null_char) == 0
   end function symlink_file

   !> Removes `path` if it exists (errors ignored).
   subroutine remove_file(path)
      character(len=*), intent(in) :: path
      integer(c_int) :: rc
      rc = c_unlink(path//c_null_char)
   end subroutine remove_file

   !> True when both paths exist and are the same file (also through links or other
   !> spellings of the path).
   logical function same_file(a, b)
      character(len=*), intent(in) :: a, b
      same_file = c_same_file(a//c_null_char, b//c_null_char) == 1
   end function same_file

   !> Id of this process.
   integer function process_id()
      process_id = c_getpid()
   end function process_id

   !> Bytes still writable in the file system of `path` (-1 when unknown).
   integer(int64) function free_bytes(path)
      character(len=*), intent(in) :: path
      free_bytes = int(c_free_bytes(path//c_null_char), int64)
   end function free_bytes

   !> Flushes standard output and error and ends the process with `code` at once, without
   !> the libraries' exit handlers (the command layer's way out after an HDF5 failure).
   subroutine exit_now(code)
      integer, intent(in) :: code
      flush (output_unit)
      flush (error_unit)
      call c_exit_now(int(code, c_int))
   end subroutine exit_now

end module pecplas_base_files
