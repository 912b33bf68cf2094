!> Plate contributions to the global problem: state set-up, stiffness blocks (the elastic
!> section for modified Newton, the consistent tangent for full Newton), internal forces with
!> the section update at every point, and the consistent loads of plate line loads and plate
!> weight. A plate node's dofs are its two translations (the node's column of the nodal
!> arrays) and its rotation (row 1 of its rotation column, pecplas_model_columns).
module pecplas_fe_plate_assembly
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_strings, only: itoa
   use pecplas_model_type, only: model_t
   use pecplas_model_columns, only: rotation_column
   use pecplas_model_plates, only: plate_set_t
   use pecplas_fe_dofs, only: dofs_t
   use pecplas_linalg_sparse, only: coo_t
   use pecplas_structures_beam, only: NGEN, MAX_BEAM_DOFS, beam_point_t, beam_npoint, &
      beam_points, beam_line_load
   use pecplas_structures_section, only: NHIST, section_elastic, section_update
   use pecplas_structures_state, only: plate_state_t, plate_set_state_t
   use pecplas_structures_hinge, only: hinge_gamma, hinge_stiffness, hinge_update
   use pecplas_fe_share, only: share_t
   implicit none (type, external)
   private

   public :: setup_plate_state, add_plate_stiffness, add_plate_forces, add_plate_load
   public :: plate_element_x, plate_element_u, plate_element_equations, plate_points
   public :: scatter_plate_vector, activate_plate, hinged

contains

   !> Zero strains, resultants and history at every point of every plate set, tangents elastic.
   subroutine setup_plate_state(model, pstate)
      type(model_t), intent(in) :: model
      type(plate_state_t), intent(out) :: pstate
      real(wp) :: c(NGEN, NGEN)
      integer :: s, np, nel, e, p
      allocate (pstate%sets(0))
      if (.not. allocated(model%plates)) return
      deallocate (pstate%sets)
      allocate (pstate%sets(size(model%plates)))
      do s = 1, size(model%plates)
         associate (pl => model%plates(s), st => pstate%sets(s))
            np = beam_npoint(pl%nen)
            nel = size(pl%conn, 2)
            st%npoint = np
            allocate (st%e(NGEN, np, nel), st%s(NGEN, np, nel), st%hist(NHIST, np, nel), &
               source=0.0_wp)
            allocate (st%e_trial, st%s_trial, source=st%e)
            allocate (st%hist_trial, source=st%hist)
            allocate (st%tangent(NGEN, NGEN, np, nel))
            call section_elastic(pl%section, model%analysis%kind == 2, c)
            do e = 1, nel
               do p = 1, np
                  st%tangent(:, :, p, e) = c
               end do
               if (hinged(model, pl)) st%tangent(1:3, 1:3, 1, e) = hinge_stiffness(pl%section, &
                  norm2(model%mesh%x(:, pl%conn(2, e)) - model%mesh%x(:, pl%conn(1, e))))
            end do
         end associate
      end do
   end subroutine setup_plate_state

   !> Plate set s becomes active (a phase): free of forces, without history, its strains
   !> counted from the displacements u at activation.
   subroutine activate_plate(model, u, pstate, s, error)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: u(:, :)
      type(plate_state_t), intent(inout) :: pstate
      integer, intent(in) :: s
      type(error_t), allocatable, intent(out) :: error
      type(beam_point_t) :: pts(3)
      real(wp) :: c(NGEN, NGEN), ue(MAX_BEAM_DOFS)
      integer :: e, p, nd, np
      associate (pl => model%plates(s), st => pstate%sets(s))
         st%active = .true.
         nd = 3*pl%nen
         np = beam_npoint(pl%nen)
         call section_elastic(pl%section, model%analysis%kind == 2, c)
         st%s = 0.0_wp
         st%hist = 0.0_wp
         do e = 1, size(pl%conn, 2)
            call plate_points(model, pl, e, pts(1:np), error)
            if (allocated(error)) return
            ue(1:nd) = plate_element_u(model, pl, e, u)
            do p = 1, np
               st%e(:, p, e) = matmul(pts(p)%b(:, 1:nd), ue(1:nd))
               st%tangent(:, :, p, e) = c
            end do
            if (hinged(model, pl)) then
               ! the basic deformations at activation, from which the element counts its own
               st%e(:, :, e) = 0.0_wp
               st%e(1:3, 2, e) = matmul(hinge_gamma(plate_element_x(model, pl, e)), ue(1:6))
               st%tangent(1:3, 1:3, 1, e) = hinge_stiffness(pl%section, &
                  norm2(model%mesh%x(:, pl%conn(2, e)) - model%mesh%x(:, pl%conn(1, e))))
            end if
         end do
         st%e_trial = st%e
         st%s_trial = st%s
         st%hist_trial = st%hist
      end associate
   end subroutine activate_plate

   !> True for a plate whose plasticity is carried by hinges at its elements' ends
   !> (pecplas_structures_hinge): 2-node elements with NP or MP, plane strain. Its point
   !> state holds the element's basic quantities: e(1:3, 1) the basic deformations counted
   !> from activation, e(1:3, 2) those at activation; s(:, p) = (N, Q, M at the point, 0, 0);
   !> hist(1:2, 1) = (plastic elongation, hinge rotation at end 1), hist(2, 3) the hinge
   !> rotation at end 2, hist(3, 1 | 3) the accumulated multipliers; tangent(1:3, 1:3, 1)
   !> the basic tangent dq/dv.
   pure logical function hinged(model, pl)
      type(model_t), intent(in) :: model
      type(plate_set_t), intent(in) :: pl
      hinged = pl%section%plastic() .and. pl%nen == 2 .and. model%analysis%kind /= 2
   end function hinged

   !> Element stiffness Gamma^T Kb Gamma of a hinged element (elastic Kb, or the tangent).
   subroutine hinge_block(model, pl, st, e, tangent, ke)
      type(model_t), intent(in) :: model
      type(plate_set_t), intent(in) :: pl
      type(plate_set_state_t), intent(in) :: st
      integer, intent(in) :: e
      logical, intent(in) :: tangent
      real(wp), intent(out) :: ke(:, :)
      real(wp) :: g(3, 6), kb(3, 3), x(2, 2)
      x = plate_element_x(model, pl, e)
      g = hinge_gamma(x)
      if (tangent) then
         kb = st%tangent(1:3, 1:3, 1, e)
      else
         kb = hinge_stiffness(pl%section, norm2(x(:, 2) - x(:, 1)))
      end if
      ke = matmul(transpose(g), matmul(kb, g))
   end subroutine hinge_block

   !> Forces Gamma^T q of a hinged element at the element dofs ue, its trial state updated.
   subroutine hinge_forces(model, pl, st, e, ue, fe, error)
      type(model_t), intent(in) :: model
      type(plate_set_t), intent(in) :: pl
      type(plate_set_state_t), intent(inout) :: st
      integer, intent(in) :: e
      real(wp), intent(in) :: ue(6)
      real(wp), intent(out) :: fe(6)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: AT(3) = [0.0_wp, 0.5_wp, 1.0_wp]
      real(wp) :: g(3, 6), x(2, 2), h, v(3), vp0(3), q(3), vp(3), dl(2), kalg(3, 3)
      integer :: p
      x = plate_element_x(model, pl, e)
      h = norm2(x(:, 2) - x(:, 1))
      g = hinge_gamma(x)
      v = matmul(g, ue) - st%e(1:3, 2, e)
      vp0 = [st%hist(1, 1, e), st%hist(2, 1, e), st%hist(2, 3, e)]
      call hinge_update(pl%section, hinge_stiffness(pl%section, h), v, vp0, q, vp, dl, kalg, &
         error)
      if (allocated(error)) then
         error%message = error%message//" (element "//itoa(e)//" of plate set '"//pl%name//"')"
         return
      end if
      st%e_trial(:, :, e) = st%e(:, :, e)
      st%e_trial(1:3, 1, e) = v
      do p = 1, 3
         st%s_trial(:, p, e) = [q(1), (q(2) - q(3))/h, (1.0_wp - AT(p))*q(2) + AT(p)*q(3), &
            0.0_wp, 0.0_wp]
      end do
      st%hist_trial(:, :, e) = st%hist(:, :, e)
      st%hist_trial(1, 1, e) = vp(1)
      st%hist_trial(2, 1, e) = vp(2)
      st%hist_trial(2, 3, e) = vp(3)
      st%hist_trial(3, 1, e) = st%hist(3, 1, e) + dl(1)
      st%hist_trial(3, 3, e) = st%hist(3, 3, e) + dl(2)
      st%tangent(1:3, 1:3, 1, e) = kalg
      fe = matmul(q, g)
   end subroutine hinge_forces

   !> Node coordinates x(2, nen) of element e of plate set `pl`.
   pure function plate_element_x(model, pl, e) result(x)
      type(model_t), intent(in) :: model
      type(plate_set_t), intent(in) :: pl
      integer, intent(in) :: e
      real(wp) :: x(2, size(pl%conn, 1))
      x = model%mesh%x(:, pl%conn(:, e))
   end function plate_element_x

   !> Element dof vector (u_x, u_y, theta per node) of element e from the nodal arrays u.
   pure function plate_element_u(model, pl, e, u) result(ue)
      type(model_t), intent(in) :: model
      type(plate_set_t), intent(in) :: pl
      integer, intent(in) :: e
      real(wp), intent(in) :: u(:, :)
      real(wp) :: ue(3*size(pl%conn, 1))
      integer :: k, node
      do k = 1, size(pl%conn, 1)
         node = pl%conn(k, e)
         ue(3*k - 2:3*k - 1) = u(:, node)
         ue(3*k) = u(1, rotation_column(model, node))
      end do
   end function plate_element_u

   !> Equation numbers of the element's dofs (0: constrained).
   pure subroutine plate_element_equations(model, dofs, pl, e, idx)
      type(model_t), intent(in) :: model
      type(dofs_t), intent(in) :: dofs
      type(plate_set_t), intent(in) :: pl
      integer, intent(in) :: e
      integer, intent(out) :: idx(:)
      integer :: k, node
      do k = 1, size(pl%conn, 1)
         node = pl%conn(k, e)
         idx(3*k - 2:3*k - 1) = dofs%eq(:, node)
         idx(3*k) = dofs%eq(1, rotation_column(model, node))
      end do
   end subroutine plate_element_equations

   !> Adds an element vector fe (3 nen) to the nodal arrays f.
   pure subroutine scatter_plate_vector(model, pl, e, fe, f)
      type(model_t), intent(in) :: model
      type(plate_set_t), intent(in) :: pl
      integer, intent(in) :: e
      real(wp), intent(in) :: fe(:)
      real(wp), intent(inout) :: f(:, :)
      integer :: k, node, c
      do k = 1, size(pl%conn, 1)
         node = pl%conn(k, e)
         f(:, node) = f(:, node) + fe(3*k - 2:3*k - 1)
         c = rotation_column(model, node)
         f(1, c) = f(1, c) + fe(3*k)
      end do
   end subroutine scatter_plate_vector

   !> The integration points of element e of plate set `pl`; an error names the element.
   subroutine plate_points(model, pl, e, pts, error)
      type(model_t), intent(in) :: model
      type(plate_set_t), intent(in) :: pl
      integer, intent(in) :: e
      type(beam_point_t), intent(out) :: pts(:)
      type(error_t), allocatable, intent(out) :: error
      call beam_points(plate_element_x(model, pl, e), pl%section, model%analysis%kind == 2, &
         model%analysis%thickness, pts, error)
      if (allocated(error)) error%message = error%message//" (element "//itoa(e)// &
         " of plate set '"//pl%name//"', nodes "//itoa(model%mesh%node_id(pl%conn(1, e)))// &
         '-'//itoa(model%mesh%node_id(pl%conn(2, e)))//')'
   end subroutine plate_points

   !> Adds the plate blocks to `coo`. `tangent`: the consistent tangents of the last update;
   !> otherwise the elastic section. An inactive set adds zero blocks (the pattern stays).
   !> In a partitioned (MPI) assembly rank 0 adds them all.
   subroutine add_plate_stiffness(model, dofs, pstate, tangent, coo, error, share)
      type(model_t), intent(in) :: model
      type(dofs_t), intent(in) :: dofs
      type(plate_state_t), intent(in) :: pstate
      logical, intent(in) :: tangent
      type(coo_t), intent(inout) :: coo
      type(error_t), allocatable, intent(out) :: error
      type(share_t), intent(in), optional :: share
      type(beam_point_t) :: pts(3)
      real(wp) :: c(NGEN, NGEN), ke(MAX_BEAM_DOFS, MAX_BEAM_DOFS)
      integer :: idx(MAX_BEAM_DOFS)
      integer :: s, e, p, nd, np
      if (.not. allocated(model%plates)) return
      if (present(share)) then
         if (share%rank /= 0) return
      end if
      do s = 1, size(model%plates)
         associate (pl => model%plates(s), st => pstate%sets(s))
            nd = 3*pl%nen
            np = beam_npoint(pl%nen)
            call section_elastic(pl%section, model%analysis%kind == 2, c)
            do e = 1, size(pl%conn, 2)
               ke = 0.0_wp
               if (st%active .and. hinged(model, pl)) then
                  call hinge_block(model, pl, st, e, tangent, ke(1:6, 1:6))
               else if (st%active) then
                  call plate_points(model, pl, e, pts(1:np), error)
                  if (allocated(error)) return
                  do p = 1, np
                     if (tangent) c = st%tangent(:, :, p, e)
                     ke(1:nd, 1:nd) = ke(1:nd, 1:nd) + pts(p)%weight* &
                        matmul(transpose(pts(p)%b(:, 1:nd)), matmul(c, pts(p)%b(:, 1:nd)))
                  end do
               end if
               call plate_element_equations(model, dofs, pl, e, idx(1:nd))
               call coo%add_block(idx(1:nd), ke(1:nd, 1:nd))
            end do
         end associate
      end do
   end subroutine add_plate_stiffness

   !> Adds the plate internal forces for the trial displacements u (2, ncolumns) to fint,
   !> updating the trial strains, resultants, history and tangents from the converged state.
   subroutine add_plate_forces(model, u, pstate, fint, error)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: u(:, :)
      type(plate_state_t), intent(inout) :: pstate
      real(wp), intent(inout) :: fint(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(beam_point_t) :: pts(3)
      real(wp) :: ue(MAX_BEAM_DOFS), fe(MAX_BEAM_DOFS), eps(NGEN)
      integer :: s, e, p, nd, np
      if (.not. allocated(model%plates)) return
      do s = 1, size(model%plates)
         if (.not. pstate%sets(s)%active) cycle
         associate (pl => model%plates(s), st => pstate%sets(s))
            nd = 3*pl%nen
            np = beam_npoint(pl%nen)
            do e = 1, size(pl%conn, 2)
               ue(1:nd) = plate_element_u(model, pl, e, u)
               if (hinged(model, pl)) then
                  call hinge_forces(model, pl, st, e, ue(1:6), fe(1:6), error)
                  if (allocated(error)) return
                  call scatter_plate_vector(model, pl, e, fe(1:nd), fint)
                  cycle
               end if
               call plate_points(model, pl, e, pts(1:np), error)
               if (allocated(error)) return
               fe(1:nd) = 0.0_wp
               do p = 1, np
                  eps = matmul(pts(p)%b(:, 1:nd), ue(1:nd))
                  call section_update(pl%section, model%analysis%kind == 2, st%s(:, p, e), &
                     eps - st%e(:, p, e), st%hist(:, p, e), st%s_trial(:, p, e), &
                     st%hist_trial(:, p, e), st%tangent(:, :, p, e), error)
                  if (allocated(error)) then
                     error%message = error%message//" (element "//itoa(e)//" of plate set '"// &
                        pl%name//"')"
                     return
                  end if
                  st%e_trial(:, p, e) = eps
                  fe(1:nd) = fe(1:nd) + pts(p)%weight*matmul(st%s_trial(:, p, e), &
                     pts(p)%b(:, 1:nd))
               end do
               call scatter_plate_vector(model, pl, e, fe(1:nd), fint)
            end do
         end associate
      end do
   end subroutine add_plate_forces

   !> Adds to `force` (2, ncolumns) the consistent nodal loads of a uniform load q(2) per
   !> unit length (x, y) on every element of plate set s; `weight`: q is a unit direction
   !> and the load is the plate's weight w along it.
   subroutine add_plate_load(model, s, q, weight, force)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      real(wp), intent(in) :: q(2)
      logical, intent(in) :: weight
      real(wp), intent(inout) :: force(:, :)
      real(wp) :: fe(MAX_BEAM_DOFS), qe(2)
      integer :: e, nd
      associate (pl => model%plates(s))
         nd = 3*pl%nen
         qe = q
         if (weight) qe = pl%section%w*q
         do e = 1, size(pl%conn, 2)
            call beam_line_load(plate_element_x(model, pl, e), pl%section, &
               model%analysis%kind == 2, model%analysis%thickness, qe, fe(1:nd))
            call scatter_plate_vector(model, pl, e, fe(1:nd), force)
         end do
      end associate
   end subroutine add_plate_load

end module pecplas_fe_plate_assembly
