!> The pore water's share of the stiffness of an undrained element set (doc/theory.md §14):
!> D_w = (K_w/n) m m^T with m = (1, 1, 1, 0) (xx, yy, zz, xy), on top of the skeleton's
!> tangent D'. The one place the term is written: the assembly, the first iteration's
!> response to imposed displacements, the default penalties of spring joints and the error
!> estimate all take it from here. K_w/n is 0 for a drained, dry or non-porous set, and then
!> nothing is added (not even + 0): drained operators are the skeleton's, to the bit.
module pecplas_fe_water_stiffness
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_massif_materials_type, only: NCOMP
   implicit none (type, external)
   private

   public :: add_water_stiffness, set_elastic_tangent

   !> d += (K_w/n) m m^T, for one tangent d(NCOMP, NCOMP) or one per point d(NCOMP, NCOMP, :).
   interface add_water_stiffness
      module procedure add_water_stiffness_point, add_water_stiffness_points
   end interface add_water_stiffness

contains

   pure subroutine add_water_stiffness_point(kwn, d)
      !> K_w/n of the set (model%water%kwn); 0: none.
      real(wp), intent(in) :: kwn
      real(wp), intent(inout) :: d(:, :)
      if (.not. (kwn > 0.0_wp)) return
      d(1:3, 1:3) = d(1:3, 1:3) + kwn
   end subroutine add_water_stiffness_point

   pure subroutine add_water_stiffness_points(kwn, d)
      !> K_w/n of the set (model%water%kwn); 0: none.
      real(wp), intent(in) :: kwn
      real(wp), intent(inout) :: d(:, :, :)
      if (.not. (kwn > 0.0_wp)) return
      d(1:3, 1:3, :) = d(1:3, 1:3, :) + kwn
   end subroutine add_water_stiffness_points

   !> Elastic tangent of element set s made of material m (model%materials index): the
   !> skeleton's D' plus, for an undrained wet set, the pore water's (K_w/n) m m^T, the
   !> stiffness the assembly gives the set's elastic operator.
   subroutine set_elastic_tangent(model, s, m, d)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s, m
      real(wp), intent(out) :: d(NCOMP, NCOMP)
      call model%materials(m)%m%elastic_tangent(d)
      call add_water_stiffness(model%water%kwn(s, m), d)
   end subroutine set_elastic_tangent

end module pecplas_fe_water_stiffness
