!> Anchor contributions to the global problem (pecplas_structures_anchor): state set-up,
!> stiffness blocks (the elastic EA/L for modified Newton, the last update's tangent for
!> full Newton; zero while a set is inactive or prestressed, so that the pattern stays the
!> same) and internal forces with the bar update. Called by pecplas_fe_assembly.
module pecplas_fe_anchor_assembly
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_model_phase_plan, only: initial_anchor_activity
   use pecplas_fe_dofs, only: dofs_t
   use pecplas_fe_share, only: share_t
   use pecplas_linalg_sparse, only: coo_t
   use pecplas_structures_anchor, only: bar_nodes, bar_vector, bar_elongation, bar_update
   use pecplas_structures_anchor_state, only: anchor_state_t
   implicit none (type, external)
   private

   public :: setup_anchor_state, add_anchor_stiffness, add_anchor_forces, anchor_scale

contains

   !> Zero forces and plastic elongations, e0 = 0, the sets first activated by a step
   !> inactive until then.
   subroutine setup_anchor_state(model, astate)
      type(model_t), intent(in) :: model
      type(anchor_state_t), intent(out) :: astate
      logical, allocatable :: active(:)
      integer :: s, n
      allocate (astate%sets(0))
      if (.not. allocated(model%anchors)) return
      deallocate (astate%sets)
      allocate (astate%sets(size(model%anchors)))
      allocate (active(size(model%anchors)))
      active = initial_anchor_activity(model)
      do s = 1, size(model%anchors)
         n = model%anchors(s)%nbar()
         associate (st => astate%sets(s))
            st%active = active(s)
            allocate (st%force(n), st%force_trial(n), st%plastic(n), st%plastic_trial(n), &
               st%e0(n), st%force_start(n), source=0.0_wp)
            allocate (st%tangent(n))
            st%tangent = model%anchors(s)%ea/model%anchors(s)%length
         end associate
      end do
   end subroutine setup_anchor_state

   !> Out-of-plane factor t / L_s of set s: nodal forces per unit of the force of one
   !> anchor (t the model's thickness; anchors are plane strain only, the deck reader
   !> refuses them in axisymmetry).
   pure real(wp) function anchor_scale(model, s) result(c)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      c = model%analysis%thickness/model%anchors(s)%spacing
   end function anchor_scale

   !> Adds the bars' blocks to `coo` (free equations of `dofs`); `tangent`: the last
   !> update's dN/de, else EA/L (zero for an inactive or prestressing set). `share`: the
   !> bars are rank 0's in a partitioned assembly.
   subroutine add_anchor_stiffness(model, dofs, astate, tangent, coo, share)
      type(model_t), intent(in) :: model
      type(dofs_t), intent(in) :: dofs
      type(anchor_state_t), intent(in) :: astate
      logical, intent(in) :: tangent
      type(coo_t), intent(inout) :: coo
      type(share_t), intent(in), optional :: share
      real(wp), allocatable :: g(:), ke(:, :)
      integer, allocatable :: idx(:)
      real(wp) :: k
      integer :: s, i, nn
      if (.not. allocated(model%anchors)) return
      if (present(share)) then
         if (share%rank /= 0) return
      end if
      do s = 1, size(model%anchors)
         associate (set => model%anchors(s), st => astate%sets(s))
            nn = bar_nodes(set)
            allocate (g(2*nn), ke(2*nn, 2*nn), idx(2*nn))
            do i = 1, set%nbar()
               k = 0.0_wp
               if (st%active .and. .not. st%prestressing) then
                  k = set%ea/set%length(i)
                  if (tangent) k = st%tangent(i)
               end if
               g = bar_vector(set, i)
               ke = k*anchor_scale(model, s)*spread(g, 2, 2*nn)*spread(g, 1, 2*nn)
               idx(1:2) = dofs%eq(1:2, set%conn(1, i))
               if (nn == 2) idx(3:4) = dofs%eq(1:2, set%conn(2, i))
               call coo%add_block(idx, ke)
            end do
            deallocate (g, ke, idx)
         end associate
      end do
   end subroutine add_anchor_stiffness

   !> Adds the bars' internal forces at the trial displacements u to fint(2, nnode),
   !> updating their trial state.
   subroutine add_anchor_forces(model, u, astate, fint)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: u(:, :)
      type(anchor_state_t), intent(inout) :: astate
      real(wp), intent(inout) :: fint(:, :)
      real(wp), allocatable :: g(:)
      real(wp) :: f
      integer :: s, i, nn
      if (.not. allocated(model%anchors)) return
      do s = 1, size(model%anchors)
         associate (set => model%anchors(s), st => astate%sets(s))
            if (.not. st%active) then
               st%force_trial = 0.0_wp
               cycle
            end if
            nn = bar_nodes(set)
            do i = 1, set%nbar()
               call bar_update(set, st, i, bar_elongation(set, i, u))
               g = bar_vector(set, i)
               f = st%force_trial(i)*anchor_scale(model, s)
               fint(:, set%conn(1, i)) = fint(:, set%conn(1, i)) + f*g(1:2)
               if (nn == 2) fint(:, set%conn(2, i)) = fint(:, set%conn(2, i)) + f*g(3:4)
            end do
         end associate
      end do
   end subroutine add_anchor_forces

end module pecplas_fe_anchor_assembly
