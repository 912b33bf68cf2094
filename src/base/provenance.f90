!> What `pecplas --version` prints: program version, the commit it was built from, the
!> compiler and options, and the versions of the linked libraries (SuiteSparse through a C
!> shim, HDF5 through h5get_libversion_f; MUMPS is not built into this program).
module pecplas_base_provenance
   use, intrinsic :: iso_c_binding, only: c_int, c_char
   use, intrinsic :: iso_fortran_env, only: compiler_version
   use hdf5, only: h5get_libversion_f
   use pecplas_base_version, only: PROGRAM_NAME, VERSION
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private

   public :: build_commit, version_lines

   interface
      integer(c_int) function c_build_commit(buf, n) bind(c, name='pecplas_build_commit')
         import :: c_int, c_char
         character(kind=c_char), intent(out) :: buf(*)
         integer(c_int), value :: n
      end function c_build_commit
      subroutine c_suitesparse_versions(v) bind(c, name='pecplas_suitesparse_versions')
         import :: c_int
         integer(c_int), intent(out) :: v(12)
      end subroutine c_suitesparse_versions
   end interface

contains

   !> The commit (git describe) the program was built from, 'unknown' outside git.
   function build_commit() result(commit)
      character(len=:), allocatable :: commit
      character(kind=c_char) :: buf(128)
      integer :: n, i
      n = c_build_commit(buf, size(buf, kind=c_int))
      allocate (character(len=n) :: commit)
      do i = 1, n
         commit(i:i) = buf(i)
      end do
   end function build_commit

   !> The lines printed by --version (blank-padded), `key: value` after the first.
   function version_lines() result(lines)
      character(len=:), allocatable :: lines(:)
      integer(c_int) :: v(12)
      integer :: major, minor, release, err
      character(len=:), allocatable :: hdf5
      call c_suitesparse_versions(v)
      call h5get_libversion_f(major, minor, release, err)
      hdf5 = 'unknown'
      if (err == 0) hdf5 = itoa(major)//'.'//itoa(minor)//'.'//itoa(release)
      lines = [character(len=400) :: PROGRAM_NAME//' '//VERSION, &
         'commit: '//build_commit(), &
         'compiler: '//compiler_version(), &
         'SuiteSparse: '//dotted(v(7:9))//' (CHOLMOD '//dotted(v(1:3))//', linked '// &
         dotted(v(10:12))//'; UMFPACK '//dotted(v(4:6))//')', &
         'HDF5: '//hdf5, &
         'MUMPS: not built']
   end function version_lines

   pure function dotted(v) result(s)
      integer(c_int), intent(in) :: v(3)
      character(len=:), allocatable :: s
      s = itoa(int(v(1)))//'.'//itoa(int(v(2)))//'.'//itoa(int(v(3)))
   end function dotted

end module pecplas_base_provenance
