!> Cylindrical arc-length constraint (Crisfield 1981): within an increment of length dl the
!> free displacement increment Δu obeys ||Δu|| = dl while the step fraction tau (the load
!> factor of the step) is an unknown. An iteration with v_r = K^-1 r (residual at the
!> current tau) and v_q = K^-1 q (q = the step's load per unit tau) moves
!>     Δu <- Δu + v_r + dtau v_q,    tau <- tau + dtau,
!> with dtau a root of  a dtau^2 + b dtau + c = 0,  a = v_q.v_q, b = 2 v_q.(Δu + v_r),
!> c = (Δu + v_r).(Δu + v_r) - dl^2. Of the two roots the one whose new Δu makes the
!> smallest angle with the Δu of the previous iteration is taken, so the path does not
!> turn back on itself; without a real root the iteration takes the vertex -b/(2a), the
!> point of the line closest to the constraint, which the next iterations restore (the
!> caller shortens dl when the increment still fails). The predictor's sign follows the previous converged increment
!> (sign of Δu_prev . v_q), +1 for the first one.
module pecplas_solve_arc_length
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: arc_root, arc_predictor_sign, adapt_length

contains

   !> dtau of the corrector (see the module); without a real root it is the vertex -b/(2a)
   !> and ok is true. ok is false only when a = v_q.v_q is not positive (v_q zero or NaN) or
   !> dtau is NaN.
   !> `direction` (default du): the increment the new one should not turn back from (the
   !> predictor's direction when du is still zero).
   subroutine arc_root(du, vr, vq, dl, dtau, ok, direction)
      real(wp), intent(in) :: du(:), vr(:), vq(:), dl
      real(wp), intent(in), optional :: direction(:)
      real(wp), intent(out) :: dtau
      logical, intent(out) :: ok
      real(wp) :: a, b, c, disc, r1, r2, cos1, cos2, q
      real(wp), allocatable :: w(:)
      w = du + vr
      a = dot_product(vq, vq)
      b = 2.0_wp*dot_product(vq, w)
      c = dot_product(w, w) - dl**2
      dtau = 0.0_wp
      ok = .false.
      if (.not. (a > 0.0_wp)) return
      disc = b*b - 4.0_wp*a*c
      if (disc < 0.0_wp) then
         ! no point of the line dtau -> du + v_r + dtau v_q lies on the sphere (a sharp turn
         ! of the path, a change of slip or contact states): its point closest to the sphere,
         ! the vertex of the quadratic; the next iterations restore the length
         dtau = -b/(2.0_wp*a)
         ok = dtau == dtau
         return
      end if
      ! roots without cancellation
      q = -0.5_wp*(b + sign(sqrt(disc), b))
      if (q /= 0.0_wp) then
         r1 = q/a
         r2 = c/q
      else
         r1 = 0.0_wp
         r2 = 0.0_wp
      end if
      if (present(direction)) then
         cos1 = dot_product(direction, w + r1*vq)
         cos2 = dot_product(direction, w + r2*vq)
      else
         cos1 = dot_product(du, w + r1*vq)
         cos2 = dot_product(du, w + r2*vq)
      end if
      dtau = merge(r1, r2, cos1 >= cos2)
      ok = dtau == dtau
   end subroutine arc_root

   !> Sign of the predictor: along the previous converged increment; +1 (the load rises)
   !> when there is none, as at the first increment of a path, whose caller holds `du_prev`
   !> unallocated (an allocatable dummy: an unallocated actual is then defined behaviour; it
   !> crashed the release build at the first increment of a second arc-length step).
   pure real(wp) function arc_predictor_sign(du_prev, vq) result(s)
      real(wp), allocatable, intent(in) :: du_prev(:)
      real(wp), intent(in) :: vq(:)
      s = 1.0_wp
      if (.not. allocated(du_prev)) return
      if (size(du_prev) == size(vq)) then
         if (dot_product(du_prev, vq) < 0.0_wp) s = -1.0_wp
      end if
   end function arc_predictor_sign

   !> Next increment length from the iterations the last one needed: dl sqrt(wanted / used),
   !> the factor kept within [1/4, 2] and the length within [dl_min, dl_max].
   pure real(wp) function adapt_length(dl, used, wanted, dl_min, dl_max) result(dl_new)
      real(wp), intent(in) :: dl, dl_min, dl_max
      integer, intent(in) :: used, wanted
      real(wp) :: f
      f = sqrt(real(max(wanted, 1), wp)/real(max(used, 1), wp))
      f = min(max(f, 0.25_wp), 2.0_wp)
      dl_new = min(max(dl*f, dl_min), dl_max)
   end function adapt_length

end module pecplas_solve_arc_length
