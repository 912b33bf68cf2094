!> Katona doublets in the joint results, like any other interface: the multipliers divided
!> by the tributary measure are the stresses (sigma_n, tau) = (N, T) / A, the relative
!> displacements and the mode are the doublet's. A SPRING set has one point per doublet; a
!> line joint's points take the N_a-weighted stresses of their doublets (the interpolation
!> of the nodal stresses), their own relative displacements and the mode of the doublet of
!> largest weight. Written into the trial joint state, which the driver commits.
module pecplas_joints_katona_results
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_joints_state, only: joint_state_t
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t, joint_strain
   use pecplas_joints_points, only: joint_set_element, joint_element_points
   use pecplas_joints_katona_type, only: katona_t
   use pecplas_joints_katona_doublets, only: doublet_weights
   implicit none (type, external)
   private

   public :: katona_joint_fields

contains

   !> Fills eps_trial, sigma_trial, mode_trial of the Katona sets from the trial doublets
   !> and the nodal displacements u.
   subroutine katona_joint_fields(model, kt, u, jstate, error)
      type(model_t), intent(in) :: model
      type(katona_t), intent(in) :: kt
      real(wp), intent(in) :: u(:, :)
      type(joint_state_t), intent(inout) :: jstate
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t), allocatable :: pts(:)
      integer, allocatable :: of_node(:)
      real(wp), allocatable :: sig(:, :)
      real(wp) :: wgt(3)
      integer, parameter :: face1(3) = [1, 2, 5]
      integer :: s, k, e, ip, j, npair, nd
      if (kt%nd == 0) return
      allocate (sig(2, kt%nd), of_node(model%mesh%nnode()))
      do k = 1, kt%nd
         sig(:, k) = 0.0_wp
         if (kt%area(k) > 0.0_wp) sig(:, k) = kt%f_trial(:, k)/kt%area(k)
      end do
      do s = 1, size(model%joint_sets)
         if (.not. any(kt%set_of == s)) cycle
         associate (set => model%joint_sets(s), st => jstate%sets(s))
            of_node = 0
            do k = 1, kt%nd
               if (kt%set_of(k) == s) of_node(kt%node(1, k)) = k
            end do
            if (set%is_spring()) then
               do e = 1, size(set%conn, 2)
                  k = of_node(set%conn(1, e))
                  st%sigma_trial(:, 1, e) = sig(:, k)
                  st%eps_trial(:, 1, e) = kt%z_trial(:, k)
                  st%mode_trial(1, e) = kt%mode_trial(k)
               end do
               cycle
            end if
            call joint_set_element(set, elem, error)
            if (allocated(error)) return
            if (allocated(pts)) deallocate (pts)
            allocate (pts(elem%npoint()))
            nd = 2*size(set%conn, 1)
            npair = size(set%conn, 1)/2
            do e = 1, size(set%conn, 2)
               call joint_element_points(model, set, elem, e, pts, error)
               if (allocated(error)) return
               do ip = 1, size(pts)
                  ! normalised (a thin layer's D holds N / thickness), over the doublets of
                  ! non-zero measure (an axis node of a quadratic axisymmetric edge has none)
                  wgt = doublet_weights(pts(ip), npair)
                  do j = 1, npair
                     if (kt%area(of_node(set%conn(face1(j), e))) <= 0.0_wp) wgt(j) = 0.0_wp
                  end do
                  wgt = wgt/sum(wgt(1:npair))
                  st%sigma_trial(:, ip, e) = 0.0_wp
                  do j = 1, npair
                     k = of_node(set%conn(face1(j), e))
                     st%sigma_trial(:, ip, e) = st%sigma_trial(:, ip, e) + wgt(j)*sig(:, k)
                  end do
                  j = maxloc(wgt(1:npair), dim=1)
                  st%mode_trial(ip, e) = kt%mode_trial(of_node(set%conn(face1(j), e)))
                  st%eps_trial(:, ip, e) = joint_strain(pts(ip), &
                     reshape(u(:, set%conn(:, e)), [nd]))
               end do
            end do
         end associate
      end do
   end subroutine katona_joint_fields

end module pecplas_joints_katona_results
