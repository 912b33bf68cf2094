!> Initial stresses (*INITIAL_STRESS, thesis §II.1.1) put into the integration-point state:
!> massif points take the homogeneous or geostatic stress at their position; each joint
!> point takes, at its own position, the initial stress of the massif beside its element
!> (pecplas_fe_joint_side: the element on face 1, the mean over the sets around a spring's
!> node) projected on the joint frame, sigma_n = -n.sigma.n, tau = t.sigma.n, which also
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
   use pecplas_joints_points, only: joint_point_geometry, joint_set_element, joint_element_points
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t
   use pecplas_joints_consistent, only: lobatto_twin, fix_forces
   use pecplas_fe_joint_side, only: mesh_index_t, beside_sets
   implicit none (type, external)
   private

   public :: mesh_index_t

   public :: apply_initial_stresses, initial_set_stress, initial_joint_set_stress

contains

   subroutine apply_initial_stresses(model, rules, state, error)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      type(fe_state_t), intent(inout) :: state
      type(error_t), allocatable, intent(out) :: error
      integer :: s, js
      type(mesh_index_t) :: index

      do s = 1, size(model%mesh%esets)
         call initial_set_stress(model, rules, s, state%sets(s)%stress)
         state%sets(s)%stress_trial = state%sets(s)%stress
      end do
      if (.not. allocated(model%joint_sets)) return
      if (size(model%joint_sets) == 0) return
      call index%build(model)
      do js = 1, size(model%joint_sets)
         call initial_joint_set_stress(model, index, state, js, error)
         if (allocated(error)) return
      end do
   end subroutine apply_initial_stresses

   !> The *INITIAL_STRESS stress of massif set s at its integration points
   !> (4, ngauss, nel); points no entry covers keep their value.
   subroutine initial_set_stress(model, rules, s, stress)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      integer, intent(in) :: s
      real(wp), intent(inout) :: stress(:, :, :)
      real(wp), allocatable :: xg(:, :)
      integer :: e, g
      logical :: hit
      associate (set => model%mesh%esets(s))
         allocate (xg(2, size(stress, 2)))
         do e = 1, size(set%conn, 2)
            call massif_gauss_coordinates(rules(s), model%mesh%x(:, set%conn(:, e)), xg)
            do g = 1, size(stress, 2)
               call stress_at(model, s, xg(:, g), stress(:, g, e), hit)
            end do
         end do
      end associate
   end subroutine initial_set_stress

   !> Joint set js: each point takes the initial stress of the massif beside it, projected
   !> on the joint frame (module header); `index` built by mesh_index_t%build.
   subroutine initial_joint_set_stress(model, index, state, js, error)
      type(model_t), intent(in) :: model
      type(mesh_index_t), intent(in) :: index
      type(fe_state_t), intent(inout) :: state
      integer, intent(in) :: js
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: xy(:, :, :), t(:, :, :), sigma0(:, :, :)
      real(wp) :: stress(4)
      integer, allocatable :: sets(:)
      integer :: e, g
      logical :: hit
      call joint_point_geometry(model, js, xy, t, error)
      if (allocated(error)) return
      allocate (sigma0(2, size(xy, 2), size(xy, 3)), source=0.0_wp)
      do e = 1, size(xy, 3)
         call beside_sets(model, index, model%joint_sets(js), e, sets)
         do g = 1, size(xy, 2)
            call mean_stress_at(model, sets, xy(:, g, e), stress, hit)
            if (hit) sigma0(:, g, e) = joint_stress_from_massif(stress, t(:, g, e))
         end do
      end do
      call set_joint_stress(model, state%joints, js, sigma0, error)
      if (allocated(error)) return
      call lobatto_initial_fix(model, index, state, js, sigma0, error)
   end subroutine initial_joint_set_stress

   !> A Lobatto joint set: the consistent less the lumped nodal forces of its initial
   !> stresses (sigma0 at its points; the same field at the points of its Gauss twin), so
   !> that it carries the initial field as the massif beside it does (pecplas_joints_consistent).
   subroutine lobatto_initial_fix(model, index, state, js, sigma0, error)
      type(model_t), intent(in) :: model
      type(mesh_index_t), intent(in) :: index
      type(fe_state_t), intent(inout) :: state
      integer, intent(in) :: js
      real(wp), intent(in) :: sigma0(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem, twin
      type(joint_point_t), allocatable :: pts(:), pg(:)
      real(wp), allocatable :: sg(:, :), fix(:, :)
      real(wp) :: stress(4)
      integer, allocatable :: sets(:)
      integer :: e, g
      logical :: found, hit
      associate (set => model%joint_sets(js))
         call lobatto_twin(set, twin, found, error)
         if (allocated(error) .or. .not. found) return
         call joint_set_element(set, elem, error)
         if (allocated(error)) return
         allocate (pts(elem%npoint()), pg(twin%npoint()), sg(2, twin%npoint()))
         allocate (fix(2*elem%nnode(), size(set%conn, 2)))
         do e = 1, size(set%conn, 2)
            call joint_element_points(model, set, elem, e, pts, error)
            if (allocated(error)) return
            call joint_element_points(model, set, twin, e, pg, error)
            if (allocated(error)) return
            call beside_sets(model, index, set, e, sets)
            sg = 0.0_wp
            do g = 1, size(pg)
               call mean_stress_at(model, sets, pg(g)%x, stress, hit)
               if (hit) sg(:, g) = joint_stress_from_massif(stress, pg(g)%t)
            end do
            call fix_forces(pg, sg, pts, sigma0(:, :, e), fix(:, e))
         end do
         state%joints%sets(js)%sigma0_fix = fix
      end associate
   end subroutine lobatto_initial_fix

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
            if (init%kind == 'GEOSTATIC' .and. model%water%level_at(1) > 0) then
               stress = effective_geostatic(model, init, s, x)
            else if (init%kind == 'GEOSTATIC') then
               stress = geostatic_stress(init, model%materials( &
                  model%mesh%esets(s)%material_index)%m%unit_weight, x(2))
            else
               stress = init%stress
            end if
         end associate
      end do
   end subroutine stress_at

   !> Geostatic effective stress of set s at x under the level of the first step:
   !> sigma'_v = q + gamma_unsat d_dry + (gamma_sat - gamma_w) d_wet, d_dry and d_wet the
   !> thicknesses of [y, y_s] above and below the level (doc/theory.md, Groundwater);
   !> sigma'_h = K0 sigma'_v. A dry set or a NON_POROUS material: gamma_unsat throughout.
   pure function effective_geostatic(model, init, s, x) result(stress)
      type(model_t), intent(in) :: model
      type(initial_stress_t), intent(in) :: init
      integer, intent(in) :: s
      real(wp), intent(in) :: x(2)
      real(wp) :: stress(4), h, sv, dry, wet, gam
      integer :: m, k
      m = model%mesh%esets(s)%material_index
      k = model%water%level_at(1)
      gam = model%materials(m)%m%unit_weight
      if (.not. model%water%wet(s, m)) then
         stress = geostatic_stress(init, gam, x(2))
         return
      end if
      h = model%water%levels(k)%head(x(1))
      dry = max(0.0_wp, init%surface - max(x(2), h))
      wet = max(0.0_wp, min(init%surface, h) - x(2))
      sv = init%surcharge + gam*dry + (model%water%mats(m)%gamma_sat - &
         model%water%levels(k)%gamma_w)*wet
      stress = [-init%k0*sv, -sv, -init%k0*sv, 0.0_wp]
   end function effective_geostatic

   !> Mean over the element sets `sets` of their initial stress at x, of those that an
   !> *INITIAL_STRESS entry covers (hit = .false. when none does; stress 0).
   subroutine mean_stress_at(model, sets, x, stress, hit)
      type(model_t), intent(in) :: model
      integer, intent(in) :: sets(:)
      real(wp), intent(in) :: x(2)
      real(wp), intent(out) :: stress(4)
      logical, intent(out) :: hit
      real(wp) :: one(4)
      integer :: i, n
      logical :: h
      stress = 0.0_wp
      n = 0
      do i = 1, size(sets)
         one = 0.0_wp
         call stress_at(model, sets(i), x, one, h)
         if (.not. h) cycle
         stress = stress + one
         n = n + 1
      end do
      hit = n > 0
      if (n > 1) stress = stress/real(n, wp)
   end subroutine mean_stress_at

end module pecplas_fe_initial
