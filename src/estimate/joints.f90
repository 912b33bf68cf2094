!> Error indicator of the joint elements: smoothness of the traction along each joint set.
!> Each element's tractions (sigma_n, tau) are fitted by a line in the position along the
!> element and extrapolated to its two face-1 end nodes; the recovered traction t* of a node
!> is the mean of the extrapolations of the elements that meet there, and inside an element
!> t* is interpolated linearly between its end nodes. The indicator is
!>   eta_e^2 = sum_points (t* - t_h)^T K^-1 (t* - t_h) dA,
!> K the law's elastic stiffness at the point, so it has the units of sqrt(energy) like the
!> massif indicator. It vanishes for a traction field linear along the joint and grows with
!> the jump of traction between neighbouring elements (a slip front, an opening tip).
!> Springs (isolated doublets with no neighbours along a line) get eta = 0.
module pecplas_estimate_joints
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_joints_state, only: joint_state_t
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t, MAX_JOINT_POINTS
   use pecplas_joints_points, only: joint_set_element, joint_element_points
   use pecplas_estimate_type, only: eta_set_t
   implicit none (type, external)
   private

   public :: joint_indicators

contains

   !> Indicators eta(s)%eta(nel) of every joint set (empty array without joints).
   subroutine joint_indicators(model, joints, eta, error)
      type(model_t), intent(in) :: model
      type(joint_state_t), intent(in) :: joints
      type(eta_set_t), allocatable, intent(out) :: eta(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: s, nset
      nset = 0
      if (allocated(model%joint_sets)) nset = size(model%joint_sets)
      allocate (eta(nset))
      do s = 1, nset
         call set_indicator(model, s, joints, eta(s)%eta, error)
         if (allocated(error)) return
      end do
   end subroutine joint_indicators

   subroutine set_indicator(model, s, joints, eta, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      type(joint_state_t), intent(in) :: joints
      real(wp), allocatable, intent(out) :: eta(:)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t) :: pts(MAX_JOINT_POINTS)
      real(wp), allocatable :: lam(:, :), da(:, :), ends(:, :, :), tnode(:, :)
      integer, allocatable :: cnt(:)
      real(wp) :: k(2, 2), kinv(2, 2), det, d(2), tstar(2), chord(2)
      integer :: e, g, nel, np, j

      associate (set => model%joint_sets(s), st => joints%sets(s))
         nel = size(set%conn, 2)
         allocate (eta(nel), source=0.0_wp)
         ! (a Katona set has no stiffness at its points: no energy to measure)
         if (set%is_spring() .or. set%is_katona() .or. nel == 0) return
         call joint_set_element(set, elem, error)
         if (allocated(error)) return
         np = elem%npoint()
         allocate (lam(np, nel), da(np, nel), ends(2, 2, nel))
         allocate (tnode(2, model%mesh%nnode()), source=0.0_wp)
         allocate (cnt(model%mesh%nnode()), source=0)
         do e = 1, nel
            call joint_element_points(model, set, elem, e, pts(1:np), error)
            if (allocated(error)) return
            associate (x1 => model%mesh%x(:, set%conn(1, e)), x2 => model%mesh%x(:, set%conn(2, e)))
               chord = x2 - x1
               do g = 1, np
                  lam(g, e) = dot_product(pts(g)%x - x1, chord)/max(dot_product(chord, chord), &
                     tiny(1.0_wp))
               end do
            end associate
            da(:, e) = pts(1:np)%da
            call line_ends(lam(:, e), st%sigma(:, :, e), ends(:, :, e))
            do j = 1, 2
               tnode(:, set%conn(j, e)) = tnode(:, set%conn(j, e)) + ends(:, j, e)
               cnt(set%conn(j, e)) = cnt(set%conn(j, e)) + 1
            end do
         end do
         do e = 1, nel
            do g = 1, np
               tstar = (1.0_wp - lam(g, e))*tnode(:, set%conn(1, e))/cnt(set%conn(1, e)) + &
                  lam(g, e)*tnode(:, set%conn(2, e))/cnt(set%conn(2, e))
               d = tstar - st%sigma(:, g, e)
               call model%laws(set%law_index)%law%elastic_tangent(st%hist(:, g, e), k)
               det = k(1, 1)*k(2, 2) - k(1, 2)*k(2, 1)
               if (.not. (abs(det) > 0.0_wp)) cycle ! no stiffness: no energy to measure
               kinv = reshape([k(2, 2), -k(2, 1), -k(1, 2), k(1, 1)], [2, 2])/det
               eta(e) = eta(e) + abs(dot_product(d, matmul(kinv, d)))*da(g, e)
            end do
         end do
         eta = sqrt(eta)
      end associate
   end subroutine set_indicator

   !> Values at lam = 0 and 1 of the least-squares line through (lam(g), t(:, g)); the
   !> mean when the points do not fix a line (one point).
   pure subroutine line_ends(lam, t, ends)
      real(wp), intent(in) :: lam(:), t(:, :)
      real(wp), intent(out) :: ends(2, 2)
      real(wp) :: lm, tm(2), slope(2), var
      integer :: g, np
      np = size(lam)
      lm = sum(lam)/np
      tm = sum(t(:, 1:np), dim=2)/np
      var = sum((lam - lm)**2)
      slope = 0.0_wp
      if (var > 1.0e-12_wp) then
         do g = 1, np
            slope = slope + (lam(g) - lm)*(t(:, g) - tm)
         end do
         slope = slope/var
      end if
      ends(:, 1) = tm - slope*lm
      ends(:, 2) = tm + slope*(1.0_wp - lm)
   end subroutine line_ends

end module pecplas_estimate_joints
