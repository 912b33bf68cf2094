!> A Lobatto (Newton–Cotes) line joint lumps its forces on the doublets: a stress field
!> prescribed along it (the initial stresses, the steady pore pressure) gets nodal forces
!> that differ from the consistent forces int N^T sigma of the same field, which the
!> massif beside it (Gauss rule) takes exactly (doc/theory.md, "Lobatto joints and the
!> initial state"). This module gives the difference: the joint's Gauss twin (same element
!> and nodes, Gauss points, exact for a linear field along a straight element) integrates
!> the field, and the element adds the consistent-minus-lumped vector to its forces.
module pecplas_joints_consistent
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_joints, only: joint_set_t
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t, joint_force
   use pecplas_joints_elements_factory, only: new_joint_element
   use pecplas_joints_elements_line, only: line_joint_t
   use pecplas_joints_points, only: joint_set_element
   implicit none (type, external)
   private

   public :: lobatto_twin, fix_forces

contains

   !> For a joint set integrated by Lobatto points (GOODMAN4, GOODMAN6, THIN_LAYER with
   !> INTEGRATION=LOBATTO): `twin`, the same element with Gauss points, and found = .true.;
   !> any other set (Gauss, springs, Katona): found = .false., twin unallocated.
   subroutine lobatto_twin(set, twin, found, error)
      type(joint_set_t), intent(in) :: set
      class(joint_element_t), allocatable, intent(out) :: twin
      logical, intent(out) :: found
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      found = .false.
      if (set%is_katona()) return
      call joint_set_element(set, elem, error)
      if (allocated(error)) return
      select type (elem)
      class is (line_joint_t)
         if (.not. elem%lobatto) return
         call new_joint_element(set%type_name(), size(set%conn, 1), 'GAUSS', set%thickness, &
            twin, error)
         if (allocated(error)) return
         found = .true.
      end select
   end subroutine lobatto_twin

   !> fe = sum_g D_g^T s_g dA_g - sum_i D_i^T s_i dA_i: the consistent (twin points `pg`,
   !> values sg(2, :)) less the lumped (points `pts`, values s(2, :)) nodal forces of one
   !> field, (sigma_n, tau) compression positive as the law's stress.
   pure subroutine fix_forces(pg, sg, pts, s, fe)
      type(joint_point_t), intent(in) :: pg(:), pts(:)
      real(wp), intent(in) :: sg(:, :), s(:, :)
      real(wp), intent(out) :: fe(:)
      real(wp) :: lumped(size(fe))
      integer :: i
      fe = 0.0_wp
      lumped = 0.0_wp
      do i = 1, size(pg)
         call joint_force(pg(i), sg(:, i), fe)
      end do
      do i = 1, size(pts)
         call joint_force(pts(i), s(:, i), lumped)
      end do
      fe = fe - lumped
   end subroutine fix_forces

end module pecplas_joints_consistent
