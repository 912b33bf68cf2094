!> Assembly of the massif elements: stiffness (COO → CSC, or a rescatter of the values when
!> the triplet sequence repeats), internal forces with the material update at every
!> integration point, external forces of the load patterns. The joint
!> elements (PECJOIN) add their blocks and forces through pecjoin_assembly.
module pecplas_fe_assembly
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t, fatal_error
   use pecplas_model, only: model_t
   use pecplas_fe_element_context, only: element_context
   use pecplas_fe_dofs, only: dofs_t
   use pecplas_fe_state, only: fe_state_t
   use pecplas_massif_kinematics, only: massif_rule_t, massif_point_t, massif_gauss_point
   use pecplas_massif_element_matrices, only: massif_stiffness
   use pecplas_massif_materials_type, only: NCOMP
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_linalg_sparse_reuse, only: csc_builder_t
   use pecjoin_assembly, only: add_joint_stiffness, add_joint_forces
   use pecplas_driver_timers, only: wall_time
   implicit none (type, external)
   private

   public :: assemble_stiffness, internal_forces

contains

   !> Global stiffness on the free equations. `tangent`: consistent tangents stored in the
   !> state (full Newton); otherwise the elastic tangent of each material (modified Newton).
   !> `builder` keeps the triplet storage and the scatter map between calls: `k` must be the
   !> matrix it built last time (or empty); a repeated triplet sequence only rescatters values.
   subroutine assemble_stiffness(model, dofs, rules, state, tangent, builder, k, error)
      type(model_t), intent(in) :: model
      type(dofs_t), intent(in) :: dofs
      type(massif_rule_t), intent(in) :: rules(:)
      type(fe_state_t), intent(in) :: state
      logical, intent(in) :: tangent
      type(csc_builder_t), intent(inout) :: builder
      type(csc_t), intent(inout) :: k
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: xe(:, :), ke(:, :), d(:, :, :)
      real(wp) :: delastic(NCOMP, NCOMP)
      integer, allocatable :: idx(:)
      integer :: s, e, nn, nd, capacity

      capacity = 0
      do s = 1, size(rules)
         nd = 2*rules(s)%nnode
         capacity = capacity + nd*nd*size(model%mesh%esets(s)%conn, 2)
      end do
      call builder%start(dofs%neq, capacity)
      do s = 1, size(rules)
         associate (set => model%mesh%esets(s), st => state%sets(s), &
                    mat => model%materials(model%mesh%esets(s)%material_index)%m)
            nn = rules(s)%nnode; nd = 2*nn
            allocate (xe(2, nn), ke(nd, nd), idx(nd), d(NCOMP, NCOMP, st%ngauss))
            if (.not. tangent) then
               call mat%elastic_tangent(delastic)
               d = spread(delastic, 3, st%ngauss)
            end if
            do e = 1, size(set%conn, 2)
               xe = model%mesh%x(:, set%conn(:, e))
               idx(1:nd:2) = dofs%eq(1, set%conn(:, e))
               idx(2:nd:2) = dofs%eq(2, set%conn(:, e))
               if (tangent) d = st%tangent(:, :, :, e)
               call massif_stiffness(rules(s), model%analysis%kind, model%analysis%thickness, &
                  xe, d, ke, error)
               if (allocated(error)) then
                  call element_context(error, model, s, e)
                  return
               end if
               call builder%coo%add_block(idx, ke)
            end do
            deallocate (xe, ke, idx, d)
         end associate
      end do
      call add_joint_stiffness(model, dofs, state%joints, tangent, builder%coo, error)
      if (allocated(error)) return
      call builder%finish(k, error)
   end subroutine assemble_stiffness

   !> Internal forces fint(2, nnode) = sum B^T sigma dV for the trial displacements `u`,
   !> updating trial stresses, strains, history and tangents from the converged state.
   !> `law_time` (if present) accumulates the wall time of the constitutive updates.
   subroutine internal_forces(model, rules, u, state, fint, error, law_time)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      real(wp), intent(in) :: u(:, :)
      type(fe_state_t), intent(inout) :: state
      real(wp), intent(out) :: fint(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(inout), optional :: law_time
      real(wp), allocatable :: xe(:, :), ue(:), fe(:)
      type(massif_point_t) :: pt
      real(wp) :: eps(NCOMP), deps(NCOMP), t0, tlaw
      integer :: s, e, g, nn, nd, j
      logical :: timed

      ! the clock is read around each point update only when asked (a vDSO call, ~20 ns)
      timed = present(law_time)
      tlaw = 0.0_wp
      t0 = 0.0_wp
      fint = 0.0_wp
      do s = 1, size(rules)
         associate (set => model%mesh%esets(s), st => state%sets(s), &
                    mat => model%materials(model%mesh%esets(s)%material_index)%m)
            nn = rules(s)%nnode; nd = 2*nn
            allocate (xe(2, nn), ue(nd), fe(nd))
            do e = 1, size(set%conn, 2)
               xe = model%mesh%x(:, set%conn(:, e))
               ue = reshape(u(:, set%conn(:, e)), [nd])
               fe = 0.0_wp
               do g = 1, st%ngauss
                  call massif_gauss_point(rules(s), g, model%analysis%kind, &
                     model%analysis%thickness, xe, pt, error)
                  if (allocated(error)) then
                     call element_context(error, model, s, e)
                     return
                  end if
                  eps = matmul(pt%b(:, 1:nd), ue)
                  deps = eps - st%strain(:, g, e)
                  st%hist_trial(:, g, e) = st%hist(:, g, e)
                  if (timed) t0 = wall_time()
                  call mat%update(st%stress(:, g, e), deps, st%hist_trial(:, g, e), &
                     st%stress_trial(:, g, e), st%tangent(:, :, g, e), error)
                  if (timed) tlaw = tlaw + (wall_time() - t0)
                  if (allocated(error)) then
                     call element_context(error, model, s, e)
                     return
                  end if
                  st%strain_trial(:, g, e) = eps
                  fe = fe + matmul(st%stress_trial(:, g, e), pt%b(:, 1:nd))*pt%dvol
               end do
               do j = 1, nn
                  fint(:, set%conn(j, e)) = fint(:, set%conn(j, e)) + fe(2*j - 1:2*j)
               end do
            end do
            deallocate (xe, ue, fe)
         end associate
      end do
      if (timed) t0 = wall_time()
      call add_joint_forces(model, u, state%joints, fint, error)
      if (timed) law_time = law_time + tlaw + (wall_time() - t0)
   end subroutine internal_forces

end module pecplas_fe_assembly
