!> The pore pressures of the run state (doc/theory.md, Groundwater): the steady pore
!> pressure of each massif point under the level in force, set at the start of every phase,
!> and the excess pore pressure made by undrained loading, set to zero when a phase asks.
module pecplas_fe_pore
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_fe_state, only: fe_state_t, set_state_t
   use pecplas_massif_kinematics, only: massif_rule_t
   use pecplas_massif_element_matrices, only: massif_gauss_coordinates
   implicit none (type, external)
   private

   public :: setup_pore, set_steady_pressures, reset_excess, pore_material

contains

   !> Pore pressure arrays for every element set (a model with water), steady under the
   !> level in force before the first step.
   subroutine setup_pore(model, rules, state)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      type(fe_state_t), intent(inout) :: state
      integer :: s
      if (.not. model%water%used()) return
      do s = 1, size(state%sets)
         call state%sets(s)%pore%init(state%sets(s)%ngauss, size(model%mesh%esets(s)%conn, 2))
      end do
      call set_steady_pressures(model, rules, state, model%water%level_at(1))
   end subroutine setup_pore

   !> Index in model%materials of the material that set s has now.
   pure integer function pore_material(model, s, st) result(m)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      type(set_state_t), intent(in) :: st
      m = model%mesh%esets(s)%material_index
      if (st%material > 0) m = st%material
   end function pore_material

   !> Steady pore pressures of every point under level k (0: none).
   subroutine set_steady_pressures(model, rules, state, k)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      type(fe_state_t), intent(inout) :: state
      integer, intent(in) :: k
      real(wp), allocatable :: xg(:, :)
      integer :: s, e, g, m
      do s = 1, size(state%sets)
         associate (st => state%sets(s), set => model%mesh%esets(s))
            if (.not. st%pore%on()) cycle
            m = pore_material(model, s, st)
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
   end subroutine set_steady_pressures

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
