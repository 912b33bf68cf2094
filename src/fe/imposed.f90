!> The linear response of the internal forces to a change of the imposed displacements:
!> f = K(:, c) dup_c, the columns of the constrained DOFs of the stiffness times their
!> change (nodal layout), element by element over the elements that touch a moved DOF.
!> With it an increment of imposed displacement enters the first iteration as a load on
!> the free equations, r = F_ext - F_int(u_n) - K_fc dup_c, as in CalculiX and Abaqus,
!> instead of a strained row of elements whose residual the iterations would have to undo.
module pecplas_fe_imposed
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_fe_dofs, only: dofs_t
   use pecplas_fe_state, only: fe_state_t, set_material
   use pecplas_massif_kinematics, only: MAX_NODES, massif_rule_t
   use pecplas_massif_element_matrices, only: massif_stiffness
   use pecplas_massif_materials_type, only: NCOMP
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t, joint_stiffness
   use pecplas_joints_points, only: joint_set_element, joint_element_points
   use pecplas_fe_element_context, only: element_context
   use pecplas_fe_water_stiffness, only: add_water_stiffness, set_elastic_tangent
   use pecplas_fe_joint_assembly, only: set_law
   implicit none (type, external)
   private

   public :: imposed_forces

contains

   !> f(2, nnode) = K dup for `dup` nonzero only on constrained DOFs (zero elsewhere);
   !> `tangent`: the points' stored tangents (full Newton), else the elastic ones, as in
   !> pecplas_fe_assembly's assemble_stiffness.
   subroutine imposed_forces(model, dofs, rules, state, dup, tangent, f, error)
      type(model_t), intent(in) :: model
      type(dofs_t), intent(in) :: dofs
      type(massif_rule_t), intent(in) :: rules(:)
      type(fe_state_t), intent(in) :: state
      real(wp), intent(in) :: dup(:, :)
      logical, intent(in) :: tangent
      real(wp), intent(out) :: f(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: xe(2, MAX_NODES), ue(2*MAX_NODES), ke(2*MAX_NODES, 2*MAX_NODES), &
         fe(2*MAX_NODES), delastic(NCOMP, NCOMP), kwn
      real(wp), allocatable :: d(:, :, :)
      logical, allocatable :: moved(:)
      integer :: s, e, k, nn, nd, m
      f = 0.0_wp
      moved = any(dup /= 0.0_wp .and. dofs%eq == 0, dim=1)
      if (.not. any(moved)) return
      do s = 1, size(rules)
         if (.not. state%sets(s)%active) cycle
         associate (set => model%mesh%esets(s), st => state%sets(s))
            nn = rules(s)%nnode
            nd = 2*nn
            ! an undrained set: plus the pore water's volumetric stiffness, as in the assembly
            m = set_material(model, s, st)
            kwn = model%water%kwn(s, m)
            call set_elastic_tangent(model, s, m, delastic)
            d = spread(delastic, 3, st%ngauss)
            do e = 1, size(set%conn, 2)
               if (.not. any(moved(set%conn(:, e)))) cycle
               do k = 1, nn
                  xe(:, k) = model%mesh%x(:, set%conn(k, e))
                  ue(2*k - 1:2*k) = merge(dup(:, set%conn(k, e)), 0.0_wp, &
                     dofs%eq(:, set%conn(k, e)) == 0)
               end do
               if (tangent .and. allocated(st%tangent)) then
                  d = st%tangent(:, :, :, e)
                  call add_water_stiffness(kwn, d)
               end if
               call massif_stiffness(rules(s), model%analysis%kind, model%analysis%thickness, &
                  xe(:, 1:nn), d, ke(1:nd, 1:nd), error)
               if (allocated(error)) then
                  call element_context(error, model, s, e)
                  return
               end if
               fe(1:nd) = matmul(ke(1:nd, 1:nd), ue(1:nd))
               do k = 1, nn
                  f(:, set%conn(k, e)) = f(:, set%conn(k, e)) + fe(2*k - 1:2*k)
               end do
            end do
         end associate
      end do
      call add_joint_part(model, dofs, state, dup, moved, tangent, f, error)
   end subroutine imposed_forces

   !> The joint elements' part of imposed_forces (Katona sets carry no stiffness).
   subroutine add_joint_part(model, dofs, state, dup, moved, tangent, f, error)
      type(model_t), intent(in) :: model
      type(dofs_t), intent(in) :: dofs
      type(fe_state_t), intent(in) :: state
      real(wp), intent(in) :: dup(:, :)
      logical, intent(in) :: moved(:), tangent
      real(wp), intent(inout) :: f(:, :)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t), allocatable :: pts(:)
      real(wp), allocatable :: ke(:, :), ue(:)
      real(wp) :: c(2, 2)
      integer :: s, e, ip, k, nn
      if (.not. allocated(model%joint_sets)) return
      do s = 1, size(model%joint_sets)
         ! Katona sets have no law and no stiffness: their doublets are the contact operator's
         if (model%joint_sets(s)%is_katona()) cycle
         if (.not. state%joints%sets(s)%active) cycle
         associate (set => model%joint_sets(s), st => state%joints%sets(s), &
                    law => model%laws(set_law(model%joint_sets(s), state%joints%sets(s)))%law)
            call joint_set_element(set, elem, error)
            if (allocated(error)) return
            nn = elem%nnode()
            if (allocated(pts)) deallocate (pts, ke, ue)
            allocate (pts(elem%npoint()), ke(2*nn, 2*nn), ue(2*nn))
            do e = 1, size(set%conn, 2)
               if (.not. any(moved(set%conn(:, e)))) cycle
               call joint_element_points(model, set, elem, e, pts, error)
               if (allocated(error)) return
               ke = 0.0_wp
               do ip = 1, size(pts)
                  if (tangent) then
                     c = st%tangent(:, :, ip, e)
                  else
                     call law%elastic_tangent(st%hist(:, ip, e), c)
                  end if
                  call joint_stiffness(pts(ip), c, ke)
               end do
               do k = 1, nn
                  ue(2*k - 1:2*k) = merge(dup(:, set%conn(k, e)), 0.0_wp, &
                     dofs%eq(:, set%conn(k, e)) == 0)
               end do
               ue = matmul(ke, ue)
               do k = 1, nn
                  f(:, set%conn(k, e)) = f(:, set%conn(k, e)) + ue(2*k - 1:2*k)
               end do
            end do
         end associate
      end do
   end subroutine add_joint_part

end module pecplas_fe_imposed
