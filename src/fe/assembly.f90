!> Assembly of the massif elements: stiffness (COO → CSC, or a rescatter of the values when
!> the triplet sequence repeats), internal forces with the material update at every
!> integration point, external forces of the load patterns. The joint
!> elements (PECJOIN) add their blocks and forces through pecplas_fe_joint_assembly.
module pecplas_fe_assembly
   use pecplas_base_kinds, only: wp, ik4
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_fe_dofs, only: dofs_t
   use pecplas_fe_state, only: fe_state_t, set_state_t, set_material
   use pecplas_massif_kinematics, only: MAX_NODES, massif_rule_t, massif_gauss_derivs
   use pecplas_massif_point_kernels, only: point_strain, point_force_add
   use pecplas_massif_element_matrices, only: massif_stiffness
   use pecplas_fe_water_stiffness, only: add_water_stiffness
   use pecplas_massif_materials_type, only: NCOMP, material_t
   use pecplas_linalg_sparse, only: csc_t
   use pecplas_linalg_sparse_reuse, only: csc_builder_t
   use pecplas_fe_joint_assembly, only: add_joint_stiffness, add_joint_forces
   use pecplas_fe_anchor_assembly, only: add_anchor_stiffness, add_anchor_forces
   use pecplas_fe_plate_assembly, only: add_plate_stiffness, add_plate_forces
   use pecplas_base_timers, only: wall_time
   use pecplas_linalg_threads, only: PARALLEL_MIN_ELEMENTS, openmp_threads
   use pecplas_linalg_sparse_columns, only: add_blocks_by_columns
   use pecplas_fe_element_context, only: element_context
   use pecplas_fe_share, only: share_t
   implicit none (type, external)
   private

   public :: assemble_stiffness, internal_forces

contains

   !> Global stiffness on the free equations. `tangent`: consistent tangents stored in the
   !> state (full Newton); otherwise the elastic tangent of each material (modified Newton).
   !> `builder` keeps the pattern between calls: `k` must be the matrix it built last time
   !> (or empty). The pattern comes from the element equation lists (no triplet per entry;
   !> kept while the lists repeat); element matrices are computed in parallel (OpenMP) in
   !> chunks and added serially in element order, then the joint blocks, so k is that of
   !> the serial triplet sequence summed by coo_to_csc, to the last bit.
   !> `share`: only this rank's elements (pecplas_fe_share), for the ranks of an MPI run
   !> whose solver adds the parts; default: every element. `upper`: only the upper triangle
   !> is stored (a symmetric matrix for CHOLMOD, which reads no more: half the memory and
   !> half the additions); default: the whole matrix.
   subroutine assemble_stiffness(model, dofs, rules, state, tangent, builder, k, error, share, &
      upper)
      type(model_t), intent(in) :: model
      type(dofs_t), intent(in) :: dofs
      type(massif_rule_t), intent(in) :: rules(:)
      type(fe_state_t), intent(in) :: state
      logical, intent(in) :: tangent
      type(csc_builder_t), intent(inout) :: builder
      type(csc_t), intent(inout) :: k
      type(error_t), allocatable, intent(out) :: error
      type(share_t), intent(in), optional :: share
      logical, intent(in), optional :: upper
      type(error_t), allocatable :: joint_error
      type(share_t) :: part
      integer(ik4), allocatable :: eptr(:), elist(:)
      integer :: s, e, nd, nb, nl, e1, e2

      if (present(share)) part = share
      ! equation lists of this share's massif elements, set after set
      nb = 0; nl = 0
      do s = 1, size(rules)
         call part%range(size(model%mesh%esets(s)%conn, 2), e1, e2)
         nb = nb + max(e2 - e1 + 1, 0)
         nl = nl + 2*rules(s)%nnode*max(e2 - e1 + 1, 0)
      end do
      allocate (eptr(nb + 1), elist(nl))
      eptr(1) = 1; nb = 0
      do s = 1, size(rules)
         nd = 2*rules(s)%nnode
         call part%range(size(model%mesh%esets(s)%conn, 2), e1, e2)
         do e = e1, e2
            nb = nb + 1
            eptr(nb + 1) = eptr(nb) + int(nd, ik4)
            call element_equations(dofs, model%mesh%esets(s)%conn(:, e), elist(eptr(nb):eptr(nb + 1) - 1))
         end do
      end do
      ! the joint blocks as triplets (few); a failure is reported after the massif's own
      call builder%start(dofs%neq, 16, upper)
      call add_joint_stiffness(model, dofs, state%joints, tangent, builder%coo, joint_error, part)
      ! the plate blocks after the joints' (none without plates)
      if (.not. allocated(joint_error)) call add_plate_stiffness(model, dofs, state%plates, &
         tangent, builder%coo, joint_error, part)
      call add_anchor_stiffness(model, dofs, state%anchors, tangent, builder%coo, part)
      if (allocated(joint_error)) builder%coo%nnz = 0
      call builder%pattern(eptr, elist, k, error)
      if (allocated(joint_error)) call builder%forget()
      if (allocated(error)) return
      do s = 1, size(rules)
         call add_set_stiffness(model, dofs, rules(s), s, state%sets(s), tangent, part, builder, &
            k, error)
         if (allocated(error)) return
      end do
      if (allocated(joint_error)) then
         call move_alloc(joint_error, error)
         return
      end if
      call builder%add_extra(k, error)
      if (allocated(error)) return
      ! every rank: an orphan's diagonal is in the pattern of the ranks whose (inactive)
      ! elements hold its node, not necessarily rank 0's
      if (allocated(state%orphan_eq)) call add_orphans(k, state%orphan_eq)
   end subroutine assemble_stiffness

   !> A diagonal entry, the largest of the matrix, at each free equation that no active
   !> element holds (its row and column are otherwise zero: the system stays regular and
   !> the equation, never loaded, gives a zero displacement increment). In an MPI run each
   !> rank adds it where its part of the pattern holds the entry; the ranks' parts are
   !> summed, so the entry may be a multiple of it: the equation is decoupled from the
   !> others, and its value changes no displacement.
   subroutine add_orphans(k, orphan_eq)
      type(csc_t), intent(inout) :: k
      integer, intent(in) :: orphan_eq(:)
      real(wp), allocatable :: diag(:)
      integer :: i, q
      if (size(orphan_eq) == 0) return
      allocate (diag(k%n))
      call k%diagonal(diag)
      do i = 1, size(orphan_eq)
         q = k%locate(orphan_eq(i), orphan_eq(i))
         if (q > 0) k%values(q) = k%values(q) + max(maxval(abs(diag)), 1.0_wp)
      end do
   end subroutine add_orphans

   !> Adds the stiffness of this share's elements of massif set s to k (pattern ready):
   !> element matrices in parallel, CHUNK elements at a time, added serially in order
   !> (through the builder's recorded positions when the pattern is reused).
   subroutine add_set_stiffness(model, dofs, rule, s, st, tangent, part, builder, k, error)
      type(model_t), intent(in) :: model
      type(dofs_t), intent(in) :: dofs
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: s
      type(set_state_t), intent(in) :: st
      logical, intent(in) :: tangent
      type(share_t), intent(in) :: part
      type(csc_builder_t), intent(inout) :: builder
      type(csc_t), intent(inout) :: k
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: CHUNK = 2048
      type(error_t), allocatable :: err
      real(wp), allocatable :: ke(:, :, :), d(:, :, :)
      real(wp) :: delastic(NCOMP, NCOMP), kwn
      integer, allocatable :: idx(:), idxs(:, :), parts(:)
      integer :: e, c0, c1, nd, bad, e1, e2, nparts
      logical :: stored
      associate (set => model%mesh%esets(s), &
                 mat => model%materials(set_material(model, s, st))%m)
         nd = 2*rule%nnode
         ! an undrained set: the pore water's volumetric stiffness K_w/n (0: none)
         kwn = model%water%kwn(s, set_material(model, s, st))
         call part%range(size(set%conn, 2), e1, e2)
         if (.not. st%active) then
            ! zero blocks: the pattern (of every element) and the block order stay the same
            allocate (ke(nd, nd, 1), source=0.0_wp)
            allocate (idx(nd))
            do e = e1, e2
               call element_equations(dofs, set%conn(:, e), idx)
               call builder%add_block(k, idx, ke(:, :, 1), error)
               if (allocated(error)) return
            end do
            return
         end if
         ! the points' own tangents, or the elastic one (asked for, or the material's only)
         stored = tangent .and. allocated(st%tangent)
         ! the stored tangents are passed in place; the elastic one is spread once
         if (.not. stored) then
            call mat%elastic_tangent(delastic)
            allocate (d(NCOMP, NCOMP, st%ngauss))
            d = spread(delastic, 3, st%ngauss)
         end if
         allocate (ke(nd, nd, min(CHUNK, max(e2 - e1 + 1, 1))), idx(nd))
         ! a new pattern with a team: the blocks are added by threads owning column ranges
         ! (the same sums); a kept one: serially through the recorded positions
         nparts = 1
         if (e2 - e1 + 1 >= PARALLEL_MIN_ELEMENTS .and. .not. builder%positioned()) &
            nparts = openmp_threads()
         if (nparts > 1) then
            parts = k%column_parts(nparts)
            allocate (idxs(nd, size(ke, 3)))
         end if
         bad = huge(bad)
         do c0 = e1, e2, CHUNK
            c1 = min(c0 + CHUNK - 1, e2)
            !$omp parallel default(shared) private(e, err) &
            !$omp if (e2 - e1 + 1 >= PARALLEL_MIN_ELEMENTS)
            !$omp do schedule(static)
            do e = c0, c1
               if (stored) then
                  call element_stiffness(model, rule, set%conn(:, e), st%tangent(:, :, :, e), &
                     ke(:, :, e - c0 + 1), err, kwn)
               else
                  call element_stiffness(model, rule, set%conn(:, e), d, ke(:, :, e - c0 + 1), &
                     err, kwn)
               end if
               if (allocated(err)) then
                  !$omp critical (pecplas_assembly_bad)
                  bad = min(bad, e)
                  !$omp end critical (pecplas_assembly_bad)
               end if
            end do
            !$omp end do
            !$omp end parallel
            if (bad <= e2) exit
            if (nparts > 1) then
               do e = c0, c1
                  call element_equations(dofs, set%conn(:, e), idxs(:, e - c0 + 1))
               end do
               call add_blocks_by_columns(k, c1 - c0 + 1, idxs, ke, parts, error)
               if (allocated(error)) return
               cycle
            end if
            do e = c0, c1
               call element_equations(dofs, set%conn(:, e), idx)
               call builder%add_block(k, idx, ke(:, :, e - c0 + 1), error)
               if (allocated(error)) return
            end do
         end do
         if (bad <= e2) then
            ! again, serially, for the message of the first failing element
            deallocate (ke)
            allocate (ke(nd, nd, 1))
            if (stored) then
               call element_stiffness(model, rule, set%conn(:, bad), st%tangent(:, :, :, bad), &
                  ke(:, :, 1), error, kwn)
            else
               call element_stiffness(model, rule, set%conn(:, bad), d, ke(:, :, 1), error, kwn)
            end if
            if (.not. allocated(error)) call fatal_error(error, 'element stiffness failed')
            call element_context(error, model, s, bad)
         end if
      end associate
   end subroutine add_set_stiffness

   !> Equation numbers (u1, v1, u2, v2, ...) of an element's nodes `conn`.
   pure subroutine element_equations(dofs, conn, idx)
      type(dofs_t), intent(in) :: dofs
      integer, intent(in) :: conn(:)
      integer(ik4), intent(out) :: idx(:)
      idx(1::2) = dofs%eq(1, conn)
      idx(2::2) = dofs%eq(2, conn)
   end subroutine element_equations

   !> Stiffness ke of one massif element with nodes `conn` and point tangents d; with
   !> kwn > 0 (an undrained set) plus that of the pore water, D_w = kwn m m^T.
   subroutine element_stiffness(model, rule, conn, d, ke, error, kwn)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: conn(:)
      real(wp), contiguous, intent(in) :: d(:, :, :)
      real(wp), contiguous, intent(out) :: ke(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in) :: kwn
      real(wp) :: xe(2, MAX_NODES)
      real(wp), allocatable :: dw(:, :, :), kw(:, :)
      integer :: k
      ! gathered into a fixed array: x(:, conn) as an argument is a heap temporary
      do k = 1, size(conn)
         xe(:, k) = model%mesh%x(:, conn(k))
      end do
      call massif_stiffness(rule, model%analysis%kind, model%analysis%thickness, &
         xe(:, 1:size(conn)), d, ke, error)
      if (allocated(error) .or. .not. (kwn > 0.0_wp)) return
      allocate (dw(NCOMP, NCOMP, size(d, 3)), source=0.0_wp)
      call add_water_stiffness(kwn, dw)
      allocate (kw, mold=ke)
      call massif_stiffness(rule, model%analysis%kind, model%analysis%thickness, &
         xe(:, 1:size(conn)), dw, kw, error)
      ke = ke + kw
   end subroutine element_stiffness

   !> Internal forces fint(2, ncolumns) = sum B^T sigma dV for the trial displacements `u`,
   !> updating trial stresses, strains, history and tangents from the converged state.
   !> `law_time` (if present) accumulates the wall time of the constitutive updates (summed
   !> over threads). Elements run in parallel (OpenMP), CHUNK at a time, each updating its own
   !> points and element vector; the vectors are then added to fint serially in element
   !> order, so fint does not depend on the number of threads, to the last bit. (The chunks
   !> keep the element vectors in a small array used again, not one of the whole set
   !> touched afresh by every call: 32 MB at 1e6 equations.)
   subroutine internal_forces(model, rules, u, state, fint, error, law_time)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      real(wp), intent(in) :: u(:, :)
      type(fe_state_t), intent(inout) :: state
      real(wp), intent(out) :: fint(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(inout), optional :: law_time
      integer, parameter :: CHUNK = 2048
      type(error_t), allocatable :: err
      real(wp), allocatable :: fe(:, :)
      real(wp) :: t0, tlaw
      integer :: s, e, nn, nel, j, bad, c0, c1
      logical :: timed

      timed = present(law_time)
      tlaw = 0.0_wp
      fint = 0.0_wp
      do s = 1, size(rules)
         if (.not. state%sets(s)%active) cycle
         associate (set => model%mesh%esets(s), st => state%sets(s))
            nn = rules(s)%nnode; nel = size(set%conn, 2)
            allocate (fe(2*nn, min(CHUNK, max(nel, 1))))
            bad = huge(bad)
            do c0 = 1, nel, CHUNK
               c1 = min(c0 + CHUNK - 1, nel)
               !$omp parallel do default(shared) private(e, err) reduction(+:tlaw) &
               !$omp schedule(static) if (nel >= PARALLEL_MIN_ELEMENTS)
               do e = c0, c1
                  call element_forces(model, rules(s), s, e, u, st, fe(:, e - c0 + 1), timed, &
                     tlaw, err)
                  if (allocated(err)) then
                     !$omp critical (pecplas_assembly_bad)
                     bad = min(bad, e)
                     !$omp end critical (pecplas_assembly_bad)
                  end if
               end do
               !$omp end parallel do
               if (bad <= nel) then
                  ! again, serially, for the message of the first failing element
                  call element_forces(model, rules(s), s, bad, u, st, fe(:, 1), .false., t0, &
                     error)
                  if (.not. allocated(error)) call fatal_error(error, 'element update failed')
                  call element_context(error, model, s, bad)
                  return
               end if
               do e = c0, c1
                  do j = 1, nn
                     fint(:, set%conn(j, e)) = fint(:, set%conn(j, e)) + &
                        fe(2*j - 1:2*j, e - c0 + 1)
                  end do
               end do
            end do
            deallocate (fe)
         end associate
      end do
      if (timed) t0 = wall_time()
      call add_joint_forces(model, u, state%joints, fint, error)
      if (.not. allocated(error)) call add_anchor_forces(model, u, state%anchors, fint)
      if (.not. allocated(error)) call add_plate_forces(model, u, state%plates, fint, error)
      if (timed) law_time = law_time + tlaw + (wall_time() - t0)
   end subroutine internal_forces

   !> Element vector fe = sum B^T sigma dV of element e of set s, updating the trial state of
   !> its points from the converged one (only this element's columns of `st` are written).
   !> Points go in groups of up to GROUP (all of an element for the rules in use): the
   !> strains of the group, then its constitutive updates, then its forces, so that the
   !> clock (only when `timed` and the material is not linear) is read twice per group,
   !> not per point: ~40 ns a read, as much as the rest of a point's kinematics.
   subroutine element_forces(model, rule, s, e, u, st, fe, timed, tlaw, error)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: s, e
      real(wp), intent(in) :: u(:, :)
      type(set_state_t), intent(inout) :: st
      real(wp), intent(out) :: fe(:)
      logical, intent(in) :: timed
      real(wp), intent(inout) :: tlaw
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: GROUP = 16
      ! fixed sizes: automatic arrays would be allocated on the heap for every element
      real(wp) :: xe(2, MAX_NODES), ue(2*MAX_NODES), eps(NCOMP, GROUP), deps(NCOMP), t0
      real(wp) :: dpoint(NCOMP, NCOMP), dndx(2, MAX_NODES, GROUP), hr(MAX_NODES, GROUP)
      real(wp) :: dvol(GROUP), total(NCOMP), kwn
      class(material_t), allocatable :: pmat
      integer :: g, g0, g1, nn, k, m
      logical :: clocked, varies
      associate (conn => model%mesh%esets(s)%conn(:, e), &
                 mat => model%materials(set_material(model, s, st))%m)
         nn = rule%nnode
         do k = 1, nn
            xe(:, k) = model%mesh%x(:, conn(k))
            ue(2*k - 1:2*k) = u(:, conn(k))
         end do
         fe = 0.0_wp
         t0 = 0.0_wp
         ! a linear material's update (a matrix product) is not timed: reading the clock
         ! would cost more than the update itself
         clocked = timed .and. allocated(st%tangent)
         kwn = 0.0_wp
         varies = .false.
         m = set_material(model, s, st)
         if (st%pore%on()) then
            kwn = model%water%kwn(s, m)
            varies = model%water%mats(m)%cu_varies()
         end if
         do g0 = 1, st%ngauss, GROUP
            g1 = min(g0 + GROUP - 1, st%ngauss)
            do g = g0, g1
               call massif_gauss_derivs(rule, g, model%analysis%kind, &
                  model%analysis%thickness, xe, dndx(:, :, g - g0 + 1), hr(:, g - g0 + 1), &
                  dvol(g - g0 + 1), error)
               if (allocated(error)) return
               call point_strain(nn, dndx(:, :, g - g0 + 1), hr(:, g - g0 + 1), ue, &
                  eps(:, g - g0 + 1))
            end do
            if (clocked) t0 = wall_time()
            do g = g0, g1
               deps = eps(:, g - g0 + 1) - st%strain(:, g, e)
               st%hist_trial(:, g, e) = st%hist(:, g, e)
               if (varies) then
                  ! UNDRAINED_B with c_u rising with depth: the point's own strength
                  call mat%with_cohesion(model%water%mats(m)%cu_at(dot_product( &
                     xe(2, 1:nn), rule%n(1:nn, g))), pmat, error)
                  if (allocated(error)) exit
                  if (allocated(st%tangent)) then
                     call pmat%update(st%stress(:, g, e), deps, st%hist_trial(:, g, e), &
                        st%stress_trial(:, g, e), st%tangent(:, :, g, e), error)
                  else
                     call pmat%update(st%stress(:, g, e), deps, st%hist_trial(:, g, e), &
                        st%stress_trial(:, g, e), dpoint, error)
                  end if
               else if (allocated(st%tangent)) then
                  call mat%update(st%stress(:, g, e), deps, st%hist_trial(:, g, e), &
                     st%stress_trial(:, g, e), st%tangent(:, :, g, e), error)
               else
                  call mat%update(st%stress(:, g, e), deps, st%hist_trial(:, g, e), &
                     st%stress_trial(:, g, e), dpoint, error)
               end if
               if (allocated(error)) exit
               ! undrained: the excess pore pressure of the volume change, d p = -kwn d eps_v
               if (kwn > 0.0_wp) st%pore%excess_trial(g, e) = st%pore%excess(g, e) - &
                  kwn*(deps(1) + deps(2) + deps(3))
            end do
            if (clocked) tlaw = tlaw + (wall_time() - t0)
            if (allocated(error)) return
            do g = g0, g1
               st%strain_trial(:, g, e) = eps(:, g - g0 + 1)
               if (st%pore%on()) then
                  ! the total stress sigma' - p m (tension positive, p compression positive)
                  total = st%stress_trial(:, g, e)
                  total(1:3) = total(1:3) - (st%pore%steady(g, e) + st%pore%excess_trial(g, e))
                  call point_force_add(nn, dndx(:, :, g - g0 + 1), hr(:, g - g0 + 1), &
                     dvol(g - g0 + 1), total, fe)
               else
                  call point_force_add(nn, dndx(:, :, g - g0 + 1), hr(:, g - g0 + 1), &
                     dvol(g - g0 + 1), st%stress_trial(:, g, e), fe)
               end if
            end do
         end do
      end associate
   end subroutine element_forces

end module pecplas_fe_assembly
