!> The pore pressures of the run state (doc/theory.md, Groundwater): the steady pore
!> pressure of each massif point under the level in force, set at the start of every phase,
!> and the excess pore pressure made by undrained loading, set to zero when a phase asks.
module pecplas_fe_pore
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_fe_state, only: fe_state_t, set_material
   use pecplas_massif_kinematics, only: massif_rule_t
   use pecplas_massif_element_matrices, only: massif_gauss_coordinates
   use pecplas_base_error, only: error_t
   use pecplas_joints_points, only: joint_point_geometry, joint_set_element, joint_element_points
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t
   use pecplas_joints_consistent, only: lobatto_twin, fix_forces
   use pecplas_fe_joint_side, only: mesh_index_t
   implicit none (type, external)
   private

   public :: setup_pore, set_steady_pressures, reset_excess

contains

   !> Pore pressure arrays for every element set and joint set (a model with water, joint
   !> states set up), steady under the level in force before the first step.
   subroutine setup_pore(model, rules, state, error)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      type(fe_state_t), intent(inout) :: state
      type(error_t), allocatable, intent(out) :: error
      integer :: s
      if (.not. model%water%used()) return
      do s = 1, size(state%sets)
         call state%sets(s)%pore%init(state%sets(s)%ngauss, size(model%mesh%esets(s)%conn, 2))
      end do
      if (allocated(state%joints%sets)) then
         do s = 1, size(state%joints%sets)
            if (model%joint_sets(s)%is_katona()) cycle
            associate (js => state%joints%sets(s))
               allocate (js%pore(js%npoint, size(model%joint_sets(s)%conn, 2)), source=0.0_wp)
            end associate
         end do
      end if
      call set_steady_pressures(model, rules, state, model%water%level_at(1), error)
   end subroutine setup_pore

   !> Steady pore pressures of every point under level k (0: none): massif points by their
   !> set and material, joint points by the rule of joint_wet.
   subroutine set_steady_pressures(model, rules, state, k, error)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      type(fe_state_t), intent(inout) :: state
      integer, intent(in) :: k
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: xg(:, :), xy(:, :, :), t(:, :, :)
      type(mesh_index_t) :: index
      integer :: s, e, g, m
      do s = 1, size(state%sets)
         associate (st => state%sets(s), set => model%mesh%esets(s))
            if (.not. st%pore%on()) cycle
            m = set_material(model, s, st)
            allocate (xg(2, st%ngauss))
            do e = 1, size(set%conn, 2)
               call massif_gauss_coordinates(rules(s), model%mesh%x(:, set%conn(:, e)), xg)
               do g = 1, st%ngauss
                  st%pore%steady(g, e) = model%water%pressure(k, s, m, xg(:, g))
               end do
            end do
            deallocate (xg)
         end associate
      end do
      if (.not. allocated(state%joints%sets)) return
      if (.not. any([(allocated(state%joints%sets(s)%pore), s = 1, size(state%joints%sets))])) &
         return
      call index%build(model)
      do s = 1, size(state%joints%sets)
         associate (js => state%joints%sets(s))
            if (.not. allocated(js%pore)) cycle
            js%pore = 0.0_wp
            if (allocated(js%pore_fix)) js%pore_fix = 0.0_wp
            if (k <= 0) cycle
            call joint_point_geometry(model, s, xy, t, error)
            if (allocated(error)) return
            do e = 1, size(js%pore, 2)
               if (.not. joint_wet(model, state, index, model%joint_sets(s)%conn(:, e))) cycle
               do g = 1, size(js%pore, 1)
                  js%pore(g, e) = model%water%levels(k)%pressure(xy(:, g, e))
               end do
            end do
         end associate
         call lobatto_pore_fix(model, state, index, s, k, error)
         if (allocated(error)) return
      end do
   end subroutine set_steady_pressures

   !> A Lobatto joint set: the consistent less the lumped nodal forces of its steady pore
   !> pressures under level k (pecplas_joints_consistent); zero where the joint is dry.
   subroutine lobatto_pore_fix(model, state, index, s, k, error)
      type(model_t), intent(in) :: model
      type(fe_state_t), intent(inout) :: state
      type(mesh_index_t), intent(in) :: index
      integer, intent(in) :: s, k
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem, twin
      type(joint_point_t), allocatable :: pts(:), pg(:)
      real(wp), allocatable :: sg(:, :), sp(:, :), fix(:, :)
      integer :: e, g
      logical :: found
      associate (set => model%joint_sets(s), js => state%joints%sets(s))
         call lobatto_twin(set, twin, found, error)
         if (allocated(error) .or. .not. found) return
         call joint_set_element(set, elem, error)
         if (allocated(error)) return
         allocate (pts(elem%npoint()), pg(twin%npoint()), sg(2, twin%npoint()), &
            sp(2, elem%npoint()))
         allocate (fix(2*elem%nnode(), size(set%conn, 2)), source=0.0_wp)
         do e = 1, size(set%conn, 2)
            if (k <= 0) exit
            if (.not. joint_wet(model, state, index, set%conn(:, e))) cycle
            call joint_element_points(model, set, elem, e, pts, error)
            if (allocated(error)) return
            call joint_element_points(model, set, twin, e, pg, error)
            if (allocated(error)) return
            sg = 0.0_wp
            do g = 1, size(pg)
               sg(1, g) = model%water%levels(k)%pressure(pg(g)%x)
            end do
            sp = 0.0_wp
            sp(1, :) = js%pore(:, e)
            call fix_forces(pg, sg, pts, sp, fix(:, e))
         end do
         js%pore_fix = fix
      end associate
   end subroutine lobatto_pore_fix

   !> The rule for a joint element with nodes `conn`: it takes the steady pore pressure of
   !> its position when the massif on either side is wet (a porous material, not *DRY):
   !> where both sides are wet they agree (the steady pore pressure depends on the position
   !> only); a joint between a dry structure and soil takes the soil's; between two dry
   !> sides, none.
   logical function joint_wet(model, state, index, conn) result(wet)
      type(model_t), intent(in) :: model
      type(fe_state_t), intent(in) :: state
      type(mesh_index_t), intent(in) :: index
      integer, intent(in) :: conn(:)
      integer :: i, j, s
      wet = .false.
      do i = 1, size(conn)
         do j = index%head(conn(i)), index%head(conn(i) + 1) - 1
            s = index%node_set(j)
            if (model%water%wet(s, set_material(model, s, state%sets(s)))) then
               wet = .true.
               return
            end if
         end do
      end do
   end function joint_wet

   !> Excess pore pressures back to zero (converged and trial).
   subroutine reset_excess(state)
      type(fe_state_t), intent(inout) :: state
      integer :: s
      do s = 1, size(state%sets)
         if (.not. state%sets(s)%pore%on()) cycle
         state%sets(s)%pore%excess = 0.0_wp
         state%sets(s)%pore%excess_trial = 0.0_wp
      end do
   end subroutine reset_excess

end module pecplas_fe_pore
