!> Initial stresses (*INITIAL_STRESS, thesis §II.1.1) put into the integration-point state:
!> massif points take the homogeneous or geostatic stress at their position; joint points take
!> the stress of the adjacent massif (the element set around the joint's first face-1 node)
!> projected on the joint frame, sigma_n = -n.sigma.n, tau = t.sigma.n, which also
!> initialises the law history (e.g. MODJOIN's sigma_n0).
module pecplas_fe_initial
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_initial, only: initial_stress_t, geostatic_stress
   use pecplas_fe_state, only: fe_state_t
   use pecplas_massif_kinematics, only: massif_rule_t
   use pecplas_massif_element_matrices, only: massif_gauss_coordinates
   use pecplas_fe_joint_initial, only: joint_stress_from_massif, set_joint_stress
   use pecplas_joints_points, only: joint_point_geometry
   implicit none (type, external)
   private

   public :: apply_initial_stresses

contains

   subroutine apply_initial_stresses(model, rules, state, error)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      type(fe_state_t), intent(inout) :: state
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: xg(:, :), xy(:, :, :), t(:, :, :), sigma0(:, :, :)
      real(wp) :: stress(4)
      integer :: s, e, g, js, eset
      logical :: hit

      do s = 1, size(model%mesh%esets)
         associate (set => model%mesh%esets(s), st => state%sets(s))
            allocate (xg(2, st%ngauss))
            do e = 1, size(set%conn, 2)
               call massif_gauss_coordinates(rules(s), model%mesh%x(:, set%conn(:, e)), xg)
               do g = 1, st%ngauss
                  call stress_at(model, s, xg(:, g), st%stress(:, g, e), hit)
               end do
            end do
            st%stress_trial = st%stress
            deallocate (xg)
         end associate
      end do
      if (.not. allocated(model%joint_sets)) return
      do js = 1, size(model%joint_sets)
         eset = adjacent_set(model, model%joint_sets(js)%conn(1, 1))
         call joint_point_geometry(model, js, xy, t, error)
         if (allocated(error)) return
         allocate (sigma0(2, size(xy, 2), size(xy, 3)), source=0.0_wp)
         do e = 1, size(xy, 3)
            do g = 1, size(xy, 2)
               stress = 0.0_wp
               call stress_at(model, eset, xy(:, g, e), stress, hit)
               if (hit) sigma0(:, g, e) = joint_stress_from_massif(stress, t(:, g, e))
            end do
         end do
         call set_joint_stress(model, state%joints, js, sigma0, error)
         if (allocated(error)) return
         deallocate (sigma0)
      end do
   end subroutine apply_initial_stresses

   !> Stress of element set `s` at point x from the *INITIAL_STRESS entries (later entries
   !> win); `stress` is left unchanged and hit = .false. when no entry covers the set.
   subroutine stress_at(model, s, x, stress, hit)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      real(wp), intent(in) :: x(2)
      real(wp), intent(inout) :: stress(4)
      logical, intent(out) :: hit
      integer :: i
      hit = .false.
      if (s == 0) return
      do i = 1, size(model%initial_stresses)
         associate (init => model%initial_stresses(i))
            if (init%eset /= 0 .and. init%eset /= s) cycle
            hit = .true.
            if (init%kind == 'GEOSTATIC') then
               stress = geostatic_stress(init, model%materials( &
                  model%mesh%esets(s)%material_index)%m%unit_weight, x(2))
            else
               stress = init%stress
            end if
         end associate
      end do
   end subroutine stress_at

   !> The element set of the first element that uses `node` (0 if none).
   integer function adjacent_set(model, node) result(k)
      type(model_t), intent(in) :: model
      integer, intent(in) :: node
      integer :: s
      do s = 1, size(model%mesh%esets)
         if (any(model%mesh%esets(s)%conn == node)) then
            k = s
            return
         end if
      end do
      k = 0
   end function adjacent_set

end module pecplas_fe_initial
