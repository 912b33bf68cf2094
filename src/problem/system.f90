!> The discretised system of a run: the element objects and their integration rules, the
!> equation numbering, and the load vectors at factor 1. Built once from the model
!> (pecplas_problem_type's setup_problem); nothing in it changes while the run goes on.
module pecplas_problem_system
   use pecplas_base_kinds, only: wp
   use pecplas_fe_dofs, only: dofs_t
   use pecplas_massif_elements_type, only: massif_element_box_t
   use pecplas_massif_kinematics, only: massif_rule_t
   implicit none (type, external)
   private

   public :: discrete_system_t

   type :: discrete_system_t
      type(massif_element_box_t), allocatable :: elems(:)
      !> Integration rule with tabulated shape functions, per element set.
      type(massif_rule_t), allocatable :: rules(:)
      type(dofs_t) :: dofs
      !> Pattern vectors at factor 1: forces and imposed displacements (2, nnode, npattern).
      real(wp), allocatable :: pattern_force(:, :, :), pattern_disp(:, :, :)
      !> Nodal forces of the initial stresses, held as a constant load so that the initial
      !> state is in equilibrium (2, nnode); zero without *INITIAL_STRESS.
      real(wp), allocatable :: initial_force(:, :)
   end type discrete_system_t

end module pecplas_problem_system
