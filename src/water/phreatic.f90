!> A phreatic level (doc/theory.md, Groundwater): a horizontal line y = h, or a polyline
!> (x_1, h_1), ..., (x_n, h_n) with increasing x, read as the level h(x) by linear
!> interpolation. Below it the pore pressure is hydrostatic, p = gamma_w (h(x) - y); at and
!> above it p = 0 (no suction). Pore pressures are positive in compression (a water
!> pressure); stresses elsewhere are tension positive, so the total stress is
!> sigma = sigma' - p m with m = (1, 1, 1, 0).
module pecplas_water_phreatic
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: phreatic_t

   type :: phreatic_t
      !> Name given in the deck (*WATER, NAME=...).
      character(len=:), allocatable :: name
      !> Unit weight of water (force / volume).
      real(wp) :: gamma_w = 0.0_wp
      !> The level's points (one point: horizontal at y(1); x ignored).
      real(wp), allocatable :: x(:), y(:)
      !> Deck position (messages).
      character(len=:), allocatable :: file
      integer :: line = 0
   contains
      procedure :: head => phreatic_head
      procedure :: pressure => phreatic_pressure
      procedure :: covers => phreatic_covers
   end type phreatic_t

contains

   !> The level h(x): linear between the points of the polyline.
   pure real(wp) function phreatic_head(this, x) result(h)
      class(phreatic_t), intent(in) :: this
      real(wp), intent(in) :: x
      integer :: k, n
      n = size(this%y)
      h = this%y(1)
      if (n == 1) return
      h = this%y(n)
      if (x <= this%x(1)) then
         h = this%y(1)
         return
      end if
      do k = 2, n
         if (x <= this%x(k)) then
            h = this%y(k - 1) + (this%y(k) - this%y(k - 1))*(x - this%x(k - 1))/ &
               (this%x(k) - this%x(k - 1))
            return
         end if
      end do
   end function phreatic_head

   !> Hydrostatic pore pressure at the point xy: gamma_w (h - y) below the level, 0 above.
   pure real(wp) function phreatic_pressure(this, xy) result(p)
      class(phreatic_t), intent(in) :: this
      real(wp), intent(in) :: xy(2)
      p = this%gamma_w*max(this%head(xy(1)) - xy(2), 0.0_wp)
   end function phreatic_pressure

   !> True when the level spans the model's width [xmin, xmax] (a horizontal level always).
   pure logical function phreatic_covers(this, xmin, xmax) result(ok)
      class(phreatic_t), intent(in) :: this
      real(wp), intent(in) :: xmin, xmax
      ok = size(this%y) == 1
      if (ok) return
      ok = this%x(1) <= xmin .and. this%x(size(this%x)) >= xmax
   end function phreatic_covers

end module pecplas_water_phreatic
