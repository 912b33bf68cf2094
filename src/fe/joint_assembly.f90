!> Joint contributions to the global problem: state set-up, stiffness blocks (elastic
!> tangent of the law for modified Newton, consistent tangent for full Newton) and internal
!> forces with the law update at every joint point. Called by the massif assembly
!> (pecplas_fe_assembly), which owns the global matrix and vectors. A Katona set
!> (joint_set_t%is_katona) has no law: its points carry the doublets' stresses
!> (pecplas_joints_katona_results), no history, no stiffness.
module pecplas_fe_joint_assembly
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_fe_dofs, only: dofs_t
   use pecplas_linalg_sparse, only: coo_t
   use pecplas_joints_laws_type, only: MODE_STICK, interface_law_t
   use pecplas_model_joints, only: joint_set_t
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t, joint_strain, &
      joint_force, joint_stiffness
   use pecplas_joints_state, only: joint_state_t, joint_set_state_t
   use pecplas_joints_points, only: joint_set_element, joint_element_points, element_context
   use pecplas_linalg_threads, only: PARALLEL_MIN_ELEMENTS
   use pecplas_fe_share, only: share_t
   implicit none (type, external)
   private

   public :: set_law, setup_joint_state, reset_joint_tangents, add_joint_stiffness, add_joint_forces

contains

   !> Allocates the state of every joint set: zero stress and strain, the law history from
   !> zero initial stress, mode stick, tangents = elastic tangents (zero for a Katona set).
   subroutine setup_joint_state(model, jstate, error)
      type(model_t), intent(in) :: model
      type(joint_state_t), intent(out) :: jstate
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      integer :: s, np, nel, ns, ip, e
      allocate (jstate%sets(0))
      if (.not. allocated(model%joint_sets)) return
      deallocate (jstate%sets)
      allocate (jstate%sets(size(model%joint_sets)))
      do s = 1, size(model%joint_sets)
         associate (set => model%joint_sets(s), st => jstate%sets(s))
            ns = 0
            if (.not. set%is_katona()) then
               if (set%law_index < 1 .or. set%law_index > size(model%laws)) then
                  call fatal_error(error, 'joint set '//set%name//' has no interface law')
                  return
               end if
               ns = model%laws(set%law_index)%law%nstate()
            end if
            call joint_set_element(set, elem, error)
            if (allocated(error)) return
            np = elem%npoint()
            nel = size(set%conn, 2)
            st%npoint = np
            st%nstate = ns
            allocate (st%eps(2, np, nel), st%sigma(2, np, nel), source=0.0_wp)
            allocate (st%hist(ns, np, nel), source=0.0_wp)
            allocate (st%mode(np, nel), source=MODE_STICK)
            if (.not. set%is_katona()) then
               do e = 1, nel
                  do ip = 1, np
                     call model%laws(set%law_index)%law%init_state(st%sigma(:, ip, e), &
                        st%hist(:, ip, e))
                  end do
               end do
            end if
            allocate (st%eps_trial, source=st%eps)
            allocate (st%sigma_trial, source=st%sigma)
            allocate (st%hist_trial, source=st%hist)
            allocate (st%mode_trial, source=st%mode)
            allocate (st%tangent(2, 2, np, nel))
         end associate
      end do
      call reset_joint_tangents(model, jstate)
   end subroutine setup_joint_state

   !> Sets every stored tangent to the law's elastic tangent of the converged state (after
   !> set-up, or after a law changed, e.g. a default penalty stiffness was given); zero for
   !> a Katona set.
   subroutine reset_joint_tangents(model, jstate)
      type(model_t), intent(in) :: model
      type(joint_state_t), intent(inout) :: jstate
      integer :: s, e, ip
      if (.not. allocated(jstate%sets)) return
      do s = 1, size(jstate%sets)
         associate (st => jstate%sets(s), set => model%joint_sets(s))
            if (set%is_katona()) then
               st%tangent = 0.0_wp
               cycle
            end if
            do e = 1, size(st%tangent, 4)
               do ip = 1, st%npoint
                  call model%laws(set_law(set, st))%law%elastic_tangent(st%hist(:, ip, e), &
                     st%tangent(:, :, ip, e))
               end do
            end do
         end associate
      end do
   end subroutine reset_joint_tangents

   !> Adds the joint stiffness blocks to `coo` (free equations of `dofs`). `tangent`: the
   !> consistent tangents of the last update (full Newton); otherwise the elastic tangent
   !> of each point's converged state (modified Newton). Elements run in parallel (OpenMP),
   !> each at a triplet offset counted beforehand: the triplet order is the serial one.
   !> `share`: this rank's elements only (pecplas_fe_share; Katona sets whole on rank 0).
   subroutine add_joint_stiffness(model, dofs, jstate, tangent, coo, error, share)
      type(model_t), intent(in) :: model
      type(dofs_t), intent(in) :: dofs
      type(joint_state_t), intent(in) :: jstate
      logical, intent(in) :: tangent
      type(coo_t), intent(inout) :: coo
      type(error_t), allocatable, intent(out) :: error
      type(share_t), intent(in), optional :: share
      type(error_t), allocatable :: err
      type(share_t) :: part
      class(joint_element_t), allocatable :: elem
      type(joint_point_t), allocatable :: pts(:)
      real(wp), allocatable :: ke(:, :)
      integer, allocatable :: idx(:), offset(:)
      real(wp) :: c(2, 2)
      integer :: s, e, ip, nd, nel, bad, e1, e2
      if (.not. allocated(model%joint_sets)) return
      if (present(share)) part = share
      do s = 1, size(model%joint_sets)
         associate (set => model%joint_sets(s), st => jstate%sets(s))
            ! Katona sets add zero blocks (they have no stiffness): the pattern keeps the
            ! doublet couplings that the augmented form of a singular R needs
            call joint_set_element(set, elem, error)
            if (allocated(error)) return
            nd = 2*elem%nnode()
            nel = size(set%conn, 2)
            call part%range(nel, e1, e2)
            if (set%is_katona() .and. .not. part%whole()) then
               e1 = 1
               e2 = merge(nel, 0, part%rank == 0)
            end if
            allocate (idx(nd), offset(nel + 1))
            offset(e1) = coo%nnz
            do e = e1, e2
               call equations(dofs, set%conn(:, e), idx)
               offset(e + 1) = offset(e) + coo%block_size(idx)
            end do
            deallocate (idx) ! private in the loop below
            call coo%reserve(offset(e2 + 1) - coo%nnz)
            bad = huge(bad)
            !$omp parallel default(shared) private(e, ip, c, pts, ke, idx, err) &
            !$omp if (e2 - e1 + 1 >= PARALLEL_MIN_ELEMENTS)
            allocate (pts(elem%npoint()), ke(nd, nd), idx(nd))
            !$omp do schedule(static)
            do e = e1, e2
               call joint_element_points(model, set, elem, e, pts, err)
               if (allocated(err)) then
                  !$omp critical (pecjoin_assembly_bad)
                  bad = min(bad, e)
                  !$omp end critical (pecjoin_assembly_bad)
                  cycle
               end if
               ke = 0.0_wp
               ! an inactive set (phases) adds zero blocks: the pattern stays the same
               if (st%active) then
                  do ip = 1, size(pts)
                     if (tangent .or. set%is_katona()) then
                        c = st%tangent(:, :, ip, e)
                     else
                        call model%laws(set_law(set, st))%law%elastic_tangent(st%hist(:, ip, e), c)
                     end if
                     call joint_stiffness(pts(ip), c, ke)
                  end do
               end if
               call equations(dofs, set%conn(:, e), idx)
               call coo%put_block(offset(e), idx, ke)
            end do
            !$omp end do
            deallocate (pts, ke, idx)
            !$omp end parallel
            coo%nnz = offset(e2 + 1)
            deallocate (offset)
            if (bad <= nel) then
               ! again, serially, for the message of the first failing element
               allocate (pts(elem%npoint()))
               call joint_element_points(model, set, elem, bad, pts, error)
               if (.not. allocated(error)) call fatal_error(error, 'joint element failed')
               return
            end if
         end associate
      end do
   end subroutine add_joint_stiffness

   !> Index in model%laws of the law of a joint set: the *JOINTS one, or the one a phase
   !> changed it to.
   pure integer function set_law(set, st) result(l)
      type(joint_set_t), intent(in) :: set
      type(joint_set_state_t), intent(in) :: st
      l = set%law_index
      if (st%law > 0) l = st%law
   end function set_law

   !> Equation numbers (u1, v1, u2, v2, ...) of an element's nodes `conn`.
   pure subroutine equations(dofs, conn, idx)
      type(dofs_t), intent(in) :: dofs
      integer, intent(in) :: conn(:)
      integer, intent(out) :: idx(:)
      idx(1::2) = dofs%eq(1, conn)
      idx(2::2) = dofs%eq(2, conn)
   end subroutine equations

   !> Adds the joint internal forces for the trial displacements `u` to fint(2, nnode),
   !> updating the trial stress, strain, history, mode and tangent of every point from the
   !> converged state. Elements run in parallel (OpenMP), each updating its own points and
   !> element vector; the vectors are added to fint serially in element order, so fint does
   !> not depend on the number of threads, to the last bit.
   subroutine add_joint_forces(model, u, jstate, fint, error)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: u(:, :)
      type(joint_state_t), intent(inout) :: jstate
      real(wp), intent(inout) :: fint(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: err
      class(joint_element_t), allocatable :: elem
      type(joint_point_t), allocatable :: pts(:)
      real(wp), allocatable :: fe(:, :)
      integer :: s, e, nd, nel, j, bad
      if (.not. allocated(model%joint_sets)) return
      do s = 1, size(model%joint_sets)
         ! Katona sets: their multipliers are added by pecplas_solve_katona_increment
         if (model%joint_sets(s)%is_katona()) cycle
         if (.not. jstate%sets(s)%active) cycle
         associate (set => model%joint_sets(s), st => jstate%sets(s), &
                    law => model%laws(set_law(model%joint_sets(s), jstate%sets(s)))%law)
            call joint_set_element(set, elem, error)
            if (allocated(error)) return
            nd = 2*elem%nnode()
            nel = size(set%conn, 2)
            allocate (fe(nd, nel))
            bad = huge(bad)
            !$omp parallel default(shared) private(e, pts, err) &
            !$omp if (nel >= PARALLEL_MIN_ELEMENTS)
            allocate (pts(elem%npoint()))
            !$omp do schedule(static)
            do e = 1, nel
               call joint_element_forces(model, set, elem, law, e, u, st, pts, fe(:, e), err)
               if (allocated(err)) then
                  !$omp critical (pecjoin_assembly_bad)
                  bad = min(bad, e)
                  !$omp end critical (pecjoin_assembly_bad)
               end if
            end do
            !$omp end do
            deallocate (pts)
            !$omp end parallel
            if (bad <= nel) then
               ! again, serially, for the message of the first failing element
               allocate (pts(elem%npoint()))
               call joint_element_forces(model, set, elem, law, bad, u, st, pts, fe(:, bad), &
                  error)
               if (.not. allocated(error)) call fatal_error(error, 'joint update failed')
               return
            end if
            do e = 1, nel
               do j = 1, size(set%conn, 1)
                  fint(:, set%conn(j, e)) = fint(:, set%conn(j, e)) + fe(2*j - 1:2*j, e)
               end do
            end do
            deallocate (fe)
         end associate
      end do
   end subroutine add_joint_forces

   !> Element vector fe of joint element e, updating the trial state of its points from the
   !> converged one (only this element's columns of `st` are written). An error names the
   !> element.
   subroutine joint_element_forces(model, set, elem, law, e, u, st, pts, fe, error)
      type(model_t), intent(in) :: model
      type(joint_set_t), intent(in) :: set
      class(joint_element_t), intent(in) :: elem
      class(interface_law_t), intent(in) :: law
      integer, intent(in) :: e
      real(wp), intent(in) :: u(:, :)
      type(joint_set_state_t), intent(inout) :: st
      type(joint_point_t), intent(inout) :: pts(:)
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: ue(size(fe)), eps(2), deps(2)
      integer :: ip
      call joint_element_points(model, set, elem, e, pts, error)
      if (allocated(error)) return
      ue = reshape(u(:, set%conn(:, e)), [size(fe)])
      fe = 0.0_wp
      do ip = 1, size(pts)
         eps = joint_strain(pts(ip), ue)
         deps = eps - st%eps(:, ip, e)
         st%hist_trial(:, ip, e) = st%hist(:, ip, e)
         call law%update(st%sigma(:, ip, e), deps, st%hist_trial(:, ip, e), &
            st%sigma_trial(:, ip, e), st%tangent(:, :, ip, e), st%mode_trial(ip, e), error)
         if (allocated(error)) then
            call element_context(error, set, e)
            return
         end if
         st%eps_trial(:, ip, e) = eps
         if (allocated(st%pore)) then
            ! the total normal stress (compression positive): effective + pore pressure
            call joint_force(pts(ip), st%sigma_trial(:, ip, e) + [st%pore(ip, e), 0.0_wp], fe)
         else
            call joint_force(pts(ip), st%sigma_trial(:, ip, e), fe)
         end if
      end do
      ! Lobatto joints: the prescribed fields (initial stresses, steady pore pressures)
      ! with their consistent nodal forces (pecplas_joints_consistent)
      if (allocated(st%sigma0_fix)) fe = fe + st%sigma0_fix(:, e)
      if (allocated(st%pore) .and. allocated(st%pore_fix)) fe = fe + st%pore_fix(:, e)
   end subroutine joint_element_forces

end module pecplas_fe_joint_assembly
