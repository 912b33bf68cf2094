!> Program name and version, written to every results file.
module pecplas_base_version
   implicit none (type, external)
   private
   character(len=*), parameter, public :: PROGRAM_NAME = 'PECPLAS'
   character(len=*), parameter, public :: VERSION = '0.1.0'
end module pecplas_base_version
