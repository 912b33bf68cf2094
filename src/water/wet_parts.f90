!> The wet parts of a line (a plate element, an element side) under a phreatic level
!> (doc/theory.md, Groundwater): where the hydrostatic pressure p = gamma_w (h(x) - y)+
!> is positive, cut where it has a kink, so that the water's load can be integrated exactly
!> on each part. The line is isoparametric in its parameter a in [0, 1]: straight between
!> its two ends (2 nodes), or quadratic through its ends and its mid node at a = 1/2
!> (3 nodes). The unfloored pressure p_u = gamma_w (h(x) - y) is continuous; between the
!> points where the line crosses the x of a vertex of a polyline level (h is linear between
!> them) it is a polynomial of degree nen - 1 in a; the floor max(0, p_u) adds a kink at each
!> root of p_u. On a part between two consecutive cuts p is therefore one polynomial, and a
!> Gauss rule exact for the integrand's degree integrates the load exactly.
module pecplas_water_wet_parts
   use pecplas_base_kinds, only: wp
   use pecplas_base_sort, only: sort_short
   use pecplas_water_phreatic, only: phreatic_t
   implicit none (type, external)
   private

   public :: wet_parts, line_point, line_lowest

contains

   !> The parts [from(i), to(i)] of the line with nodes x(2, nen) (ends, then the mid node)
   !> on which level's pressure p is positive, in increasing a, with p_u at each part's
   !> start, middle and end in p(:, i) (p_u is a polynomial of degree nen - 1 on a part, so
   !> these three values give it exactly). `split`: whether the line has a cut strictly
   !> inside (a root of p_u or a kink of a polyline level): false when p is one polynomial
   !> over the whole line, p = 0 or p = p_u, which the interpolation of its nodal values
   !> reproduces exactly.
   pure subroutine wet_parts(level, x, from, to, p, split)
      type(phreatic_t), intent(in) :: level
      real(wp), intent(in) :: x(:, :)
      real(wp), allocatable, intent(out) :: from(:), to(:), p(:, :)
      logical, intent(out) :: split
      real(wp), allocatable :: cuts(:), roots(:), pieces(:)
      real(wp) :: ends(3), a, b
      integer :: i, j, nen
      nen = size(x, 2)
      allocate (from(0), to(0), p(3, 0))
      ! the kinks of a polyline level: where x(a) crosses a vertex's x
      cuts = [0.0_wp, 1.0_wp]
      if (size(level%y) > 1) then
         do i = 1, size(level%x)
            roots = roots01(nen, line_point(x, 0.0_wp, 1) - level%x(i), &
               line_point(x, 0.5_wp, 1) - level%x(i), line_point(x, 1.0_wp, 1) - level%x(i))
            cuts = [cuts, roots]
         end do
         call sort_unique(cuts)
      end if
      split = size(cuts) > 2
      do i = 1, size(cuts) - 1
         a = cuts(i)
         b = cuts(i + 1)
         ends = [unfloored(level, x, a), unfloored(level, x, 0.5_wp*(a + b)), &
            unfloored(level, x, b)]
         roots = roots01(nen, ends(1), ends(2), ends(3))
         if (size(roots) > 0) split = .true.
         pieces = [a, a + (b - a)*roots, b]
         do j = 1, size(pieces) - 1
            if (.not. (pieces(j + 1) > pieces(j))) cycle
            ends = [unfloored(level, x, pieces(j)), &
               unfloored(level, x, 0.5_wp*(pieces(j) + pieces(j + 1))), &
               unfloored(level, x, pieces(j + 1))]
            if (.not. (ends(2) > 0.0_wp)) cycle
            from = [from, pieces(j)]
            to = [to, pieces(j + 1)]
            p = reshape([p, ends], [3, size(from)])
         end do
      end do
   end subroutine wet_parts

   !> Coordinate c (1: x, 2: y) of the line with nodes x(2, nen) at a in [0, 1].
   pure real(wp) function line_point(x, a, c) result(v)
      real(wp), intent(in) :: x(:, :), a
      integer, intent(in) :: c
      if (size(x, 2) == 2) then
         v = (1.0_wp - a)*x(c, 1) + a*x(c, 2)
      else
         v = (1.0_wp - a)*(1.0_wp - 2.0_wp*a)*x(c, 1) + a*(2.0_wp*a - 1.0_wp)*x(c, 2) + &
            4.0_wp*a*(1.0_wp - a)*x(c, 3)
      end if
   end function line_point

   !> The lowest y of the line with nodes x(2, nen) over 0 <= a <= 1: at a node, or where
   !> the parabola y(a) of a curved 3-node line has its minimum inside (below its nodes).
   pure real(wp) function line_lowest(x) result(v)
      real(wp), intent(in) :: x(:, :)
      real(wp) :: c1, c2, a
      v = min(x(2, 1), x(2, 2))
      if (size(x, 2) < 3) return
      ! the mid node lies on the line too (so a side with a node below a level is never
      ! found dry by the rounding of the minimum)
      v = min(v, x(2, 3))
      ! y(a) = y1 + c1 a + c2 a^2
      c2 = 2.0_wp*(x(2, 1) + x(2, 2)) - 4.0_wp*x(2, 3)
      c1 = 4.0_wp*x(2, 3) - 3.0_wp*x(2, 1) - x(2, 2)
      if (.not. c2 > 0.0_wp) return
      a = -0.5_wp*c1/c2
      if (a > 0.0_wp .and. a < 1.0_wp) v = min(v, line_point(x, a, 2))
   end function line_lowest

   !> p_u = gamma_w (h(x) - y) at a on the line (no floor).
   pure real(wp) function unfloored(level, x, a) result(pu)
      type(phreatic_t), intent(in) :: level
      real(wp), intent(in) :: x(:, :), a
      pu = level%gamma_w*(level%head(line_point(x, a, 1)) - line_point(x, a, 2))
   end function unfloored

   !> The roots in (0, 1), ascending, of the polynomial of degree nen - 1 in t with the values
   !> f0, fm, f1 at t = 0, 1/2, 1 (nen = 2: the straight line through f0 and f1).
   pure function roots01(nen, f0, fm, f1) result(r)
      integer, intent(in) :: nen
      real(wp), intent(in) :: f0, fm, f1
      real(wp), allocatable :: r(:)
      real(wp) :: c2, c1, disc, q, r1, r2
      allocate (r(0))
      if (nen == 2) then
         if ((f0 < 0.0_wp .and. f1 > 0.0_wp) .or. (f0 > 0.0_wp .and. f1 < 0.0_wp)) &
            r = [f0/(f0 - f1)]
      else
         ! f(t) = f0 + c1 t + c2 t^2
         c2 = 2.0_wp*(f0 + f1) - 4.0_wp*fm
         c1 = 4.0_wp*fm - 3.0_wp*f0 - f1
         if (c2 == 0.0_wp) then
            if (c1 /= 0.0_wp) r = [-f0/c1]
         else
            disc = c1*c1 - 4.0_wp*c2*f0
            if (disc < 0.0_wp) return
            ! the stable pair: q / c2 and f0 / q
            q = -0.5_wp*(c1 + sign(sqrt(disc), c1))
            if (q == 0.0_wp) then
               r = [0.0_wp]
            else
               r1 = q/c2
               r2 = f0/q
               r = [min(r1, r2), max(r1, r2)]
            end if
         end if
      end if
      r = pack(r, r > 0.0_wp .and. r < 1.0_wp)
   end function roots01

   !> Sorts v ascending and drops repeated values.
   pure subroutine sort_unique(v)
      real(wp), allocatable, intent(inout) :: v(:)
      call sort_short(v)
      v = pack(v, [.true., v(2:) > v(:size(v) - 1)])
   end subroutine sort_unique

end module pecplas_water_wet_parts
