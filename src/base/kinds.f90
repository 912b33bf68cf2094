!> Working precision and integer kinds of the whole project.
module pecplas_base_kinds
   use, intrinsic :: iso_fortran_env, only: real64, int32, int64
   implicit none (type, external)
   private

   !> Working precision for every real quantity.
   integer, parameter, public :: wp = real64
   !> Integer kind for large counts (sparse nonzeros, file offsets).
   integer, parameter, public :: ik8 = int64
   integer, parameter, public :: ik4 = int32
end module pecplas_base_kinds
