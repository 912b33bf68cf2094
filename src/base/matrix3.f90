!> Closed-form algebra of 3 x 3 matrices (the local Jacobians of the return mappings of the
!> interface laws and of the plates' hinges).
module pecplas_base_matrix3
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: inverse3

contains

   !> Inverse of a 3x3 matrix by cofactors (det = 0: singular, b undefined).
   pure subroutine inverse3(a, b, det)
      real(wp), intent(in) :: a(3, 3)
      real(wp), intent(out) :: b(3, 3), det
      b(1, 1) = a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)
      b(1, 2) = a(1, 3)*a(3, 2) - a(1, 2)*a(3, 3)
      b(1, 3) = a(1, 2)*a(2, 3) - a(1, 3)*a(2, 2)
      b(2, 1) = a(2, 3)*a(3, 1) - a(2, 1)*a(3, 3)
      b(2, 2) = a(1, 1)*a(3, 3) - a(1, 3)*a(3, 1)
      b(2, 3) = a(1, 3)*a(2, 1) - a(1, 1)*a(2, 3)
      b(3, 1) = a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1)
      b(3, 2) = a(1, 2)*a(3, 1) - a(1, 1)*a(3, 2)
      b(3, 3) = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
      det = a(1, 1)*b(1, 1) + a(1, 2)*b(2, 1) + a(1, 3)*b(3, 1)
      if (det /= 0.0_wp) b = b/det
   end subroutine inverse3

end module pecplas_base_matrix3
