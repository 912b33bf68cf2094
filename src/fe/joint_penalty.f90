!> Default penalty stiffness of the laws that enforce continuity with springs (Frank,
!> doc/theory.md §7, (I.10)): K = 1e5 E_ryg R_max, R_max the largest diagonal term of the massif
!> stiffness (a force per displacement; with the pore water's stiffness in undrained sets,
!> pecplas_fe_water_stiffness). Laws take stiffness per unit measure (they map a
!> relative displacement to a stress, the element multiplies by the tributary measure), so
!> K is divided by the mean measure of the joint points that use the law.
module pecplas_fe_joint_penalty
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_massif_kinematics, only: massif_rule_t
   use pecplas_massif_element_matrices, only: massif_stiffness
   use pecplas_massif_materials_type, only: NCOMP
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t
   use pecplas_joints_points, only: joint_set_element, joint_element_points
   use pecplas_joints_state, only: joint_state_t
   use pecplas_fe_joint_assembly, only: reset_joint_tangents
   use pecplas_fe_water_stiffness, only: set_elastic_tangent
   use pecplas_joints_laws_spring, only: spring_law_t
   implicit none (type, external)
   private

   public :: set_default_penalties, massif_rmax, mean_point_measure

contains

   !> Gives every law that asks for a default penalty (the spring / Frank law without KN or
   !> KT) K = default_penalty(R_max) / mean measure of its points, then refreshes the stored
   !> joint tangents. Called once after set-up, before the first factorisation. A law used by
   !> no joint set keeps asking (it is never updated).
   subroutine set_default_penalties(model, rules, jstate, error)
      type(model_t), intent(inout) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      type(joint_state_t), intent(inout) :: jstate
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: rmax, mean, k
      logical :: done
      integer :: i
      if (.not. (allocated(model%laws) .and. allocated(model%joint_sets))) return
      done = .false.
      rmax = -1.0_wp
      do i = 1, size(model%laws)
         select type (law => model%laws(i)%law)
         class is (spring_law_t)
            if (.not. law%needs_penalty) cycle
            if (.not. any(model%joint_sets%law_index == i)) cycle
            if (rmax < 0.0_wp) call massif_rmax(model, rules, rmax, error)
            if (allocated(error)) return
            call mean_point_measure(model, i, mean, error)
            if (allocated(error)) return
            k = law%default_penalty(rmax)/mean
            call law%set_penalty(k, k)
            done = .true.
         end select
      end do
      if (done) call reset_joint_tangents(model, jstate)
   end subroutine set_default_penalties

   !> Largest diagonal term of the assembled elastic massif stiffness, over all dofs; an
   !> undrained set counts with its pore water's stiffness (K_w/n) m m^T, as the assembly.
   subroutine massif_rmax(model, rules, rmax, error)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      real(wp), intent(out) :: rmax
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: diag(:, :), ke(:, :), d(:, :, :)
      real(wp) :: delastic(NCOMP, NCOMP)
      integer :: s, e, j, nn
      allocate (diag(2, model%mesh%nnode()), source=0.0_wp)
      do s = 1, size(rules)
         associate (set => model%mesh%esets(s))
            nn = rules(s)%nnode
            allocate (ke(2*nn, 2*nn), d(NCOMP, NCOMP, rules(s)%ngauss))
            ! an undrained set with its pore water: stiffer in compression, as assembled
            call set_elastic_tangent(model, s, set%material_index, delastic)
            d = spread(delastic, 3, rules(s)%ngauss)
            do e = 1, size(set%conn, 2)
               call massif_stiffness(rules(s), model%analysis%kind, model%analysis%thickness, &
                  model%mesh%x(:, set%conn(:, e)), d, ke, error)
               if (allocated(error)) return
               do j = 1, nn
                  diag(:, set%conn(j, e)) = diag(:, set%conn(j, e)) + &
                     [ke(2*j - 1, 2*j - 1), ke(2*j, 2*j)]
               end do
            end do
            deallocate (ke, d)
         end associate
      end do
      rmax = maxval(diag)
   end subroutine massif_rmax

   !> Mean measure (tributary length or area) of the points of the joint sets using law
   !> `ilaw`; 1 when no set uses it.
   subroutine mean_point_measure(model, ilaw, mean, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: ilaw
      real(wp), intent(out) :: mean
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t), allocatable :: pts(:)
      real(wp) :: total
      integer :: s, e, n
      total = 0.0_wp
      n = 0
      mean = 1.0_wp
      if (.not. allocated(model%joint_sets)) return
      do s = 1, size(model%joint_sets)
         associate (set => model%joint_sets(s))
            if (set%law_index /= ilaw) cycle
            call joint_set_element(set, elem, error)
            if (allocated(error)) return
            if (allocated(pts)) deallocate (pts)
            allocate (pts(elem%npoint()))
            do e = 1, size(set%conn, 2)
               call joint_element_points(model, set, elem, e, pts, error)
               if (allocated(error)) return
               total = total + sum(pts%da)
               n = n + size(pts)
            end do
         end associate
      end do
      if (n > 0 .and. total > 0.0_wp) mean = total/real(n, wp)
   end subroutine mean_point_measure

end module pecplas_fe_joint_penalty
