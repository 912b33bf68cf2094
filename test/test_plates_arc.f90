!> A uniform load on curved 3-node plate elements (doc/theory.md, §12 Plates): the consistent
!> nodal forces f_k = q ∫ N_k |dx/dxi| w dxi against their closed forms on a parabola
!> (pecplas_structures_beam_arc). Registered in the plates suite (test_plates).
module test_plates_arc
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_plates, only: plate_section_t
   use pecplas_structures_beam, only: beam_line_load
   use pecplas_testing, only: check_close
   implicit none (type, external)
   private
   public :: test_arc_symmetric, test_arc_length

   real(wp), parameter :: PI = acos(-1.0_wp)
   !> Tolerance relative to |q| times the chord times the thickness (2 pi r_max): the rule's
   !> bound, 1e-15 of that (ARC_TOL), plus the round-off of its sums, 8 points per part and
   !> at most 32 parts here (the mid node near an end), 256 terms of ~10 flops: 2560 eps =
   !> 5.7e-13, and of the closed forms (a few sqrt and asinh of numbers of order 1).
   !> Measured: 3e-16 at most.
   real(wp), parameter :: TOL = 1.0e-12_wp

contains

   !> The parabola through (-1, 0), (1, 0) and the mid node (0, c), c = 0.5, under q = (3, -2):
   !> x(xi) = (xi, c (1 - xi^2)), |dx/dxi| = sqrt(1 + a^2 xi^2) with a = 2c, so f_1 = f_2 =
   !> q t I2 and f_3 = q t (2 I0 - 2 I2), I0 = ∫_0^1 sqrt(1 + a^2 xi^2) = sqrt(1 + a^2)/2 +
   !> asinh(a)/(2a), I2 = ∫_0^1 xi^2 sqrt(1 + a^2 xi^2) = (2a^2 + 1) sqrt(1 + a^2)/(8a^2) -
   !> asinh(a)/(8a^3) (thickness t = 2). In axisymmetry the same curve moved to r0 = 3
   !> (r = r0 + xi along it): f_1 = 2 pi q (r0 - 1) I2, f_2 = 2 pi q (r0 + 1) I2, f_3 =
   !> 2 pi q r0 (2 I0 - 2 I2). The element's 3-point rule gave f_1 and f_3 off by 7.4e-4 and
   !> -2.1e-3 of q t (plane strain).
   subroutine test_arc_symmetric(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: C = 0.5_wp, A = 2.0_wp*C, T = 2.0_wp, R0 = 3.0_wp, &
         Q(2) = [3.0_wp, -2.0_wp]
      type(plate_section_t) :: section
      real(wp) :: x(2, 3), fe(9), i0, i2, expect(9), scale
      i0 = sqrt(1.0_wp + A*A)/2.0_wp + asinh(A)/(2.0_wp*A)
      i2 = (2.0_wp*A*A + 1.0_wp)*sqrt(1.0_wp + A*A)/(8.0_wp*A*A) - asinh(A)/(8.0_wp*A**3)
      x = reshape([-1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, C], [2, 3])
      call beam_line_load(x, section, .false., T, Q, fe)
      expect = [T*i2*Q, 0.0_wp, T*i2*Q, 0.0_wp, T*(2.0_wp*i0 - 2.0_wp*i2)*Q, 0.0_wp]
      scale = norm2(Q)*2.0_wp*T
      call check_close(error, maxval(abs(fe - expect)), 0.0_wp, 0.0_wp, 'plane strain: '// &
         'the nodal forces of q on the parabola', atol=TOL*scale)
      if (allocated(error)) return
      x(1, :) = x(1, :) + R0
      call beam_line_load(x, section, .true., T, Q, fe)
      expect = 2.0_wp*PI*[(R0 - 1.0_wp)*i2*Q, 0.0_wp, (R0 + 1.0_wp)*i2*Q, 0.0_wp, &
         R0*(2.0_wp*i0 - 2.0_wp*i2)*Q, 0.0_wp]
      scale = norm2(Q)*2.0_wp*2.0_wp*PI*(R0 + 1.0_wp)
      call check_close(error, maxval(abs(fe - expect)), 0.0_wp, 0.0_wp, 'axisymmetric: '// &
         'the nodal forces of q on the parabola of revolution', atol=TOL*scale)
   end subroutine test_arc_symmetric

   !> Asymmetric parabolas (the mid node off the middle of the chord and off the chord): the
   !> forces sum to q t times the arc length, L = ∫ sqrt(A xi^2 + B xi + C) over [-1, 1] with
   !> dx/dxi = d0 + d1 xi, A = |d1|^2, B = 2 d0.d1, C = |d0|^2, in closed form
   !> sqrt(A)/2 [u sqrt(u^2 + k^2) + k^2 asinh(u / k)] at u = xi + B/(2A), k^2 = C/A - u0^2;
   !> among them the wall x = y (10 - y)/20 of the curved water tests, its element 0 <= y <= 2
   !> (3.4e-10 of the length off with the 3-point rule), and a mid node near an end.
   subroutine test_arc_length(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: T = 1.5_wp, Q(2) = [-1.0_wp, 4.0_wp]
      type(plate_section_t) :: section
      real(wp) :: x(2, 3), fe(9), length
      integer :: k
      do k = 1, 3
         select case (k)
         case (1)
            x = reshape([-1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.3_wp, 0.8_wp], [2, 3])
         case (2)
            x = reshape([0.0_wp, 0.0_wp, 0.8_wp, 2.0_wp, 0.45_wp, 1.0_wp], [2, 3])
         case default
            x = reshape([0.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, 1.8_wp, 0.3_wp], [2, 3])
         end select
         call beam_line_load(x, section, .false., T, Q, fe)
         length = arc_length(x)
         call check_close(error, maxval(abs(fe(1:2) + fe(4:5) + fe(7:8) - T*length*Q)), &
            0.0_wp, 0.0_wp, 'the forces on parabola '//achar(48 + k)//' sum to q t L', &
            atol=TOL*norm2(Q)*T*norm2(x(:, 2) - x(:, 1)))
         if (allocated(error)) return
      end do
   end subroutine test_arc_length

   !> Arc length of the 3-node element x(2, 3) (ends, mid), in closed form.
   real(wp) function arc_length(x) result(length)
      real(wp), intent(in) :: x(2, 3)
      real(wp) :: d0(2), d1(2), qa, qb, qc, k2, k
      d0 = 0.5_wp*(x(:, 2) - x(:, 1))
      d1 = x(:, 1) + x(:, 2) - 2.0_wp*x(:, 3)
      qa = dot_product(d1, d1)
      qb = 2.0_wp*dot_product(d0, d1)
      qc = dot_product(d0, d0)
      k2 = qc/qa - (qb/(2.0_wp*qa))**2
      k = sqrt(k2)
      length = sqrt(qa)/2.0_wp*(g(1.0_wp + qb/(2.0_wp*qa)) - g(-1.0_wp + qb/(2.0_wp*qa)))
   contains
      real(wp) function g(u)
         real(wp), intent(in) :: u
         g = u*sqrt(u*u + k2) + k2*asinh(u/k)
      end function g
   end function arc_length

end module test_plates_arc
