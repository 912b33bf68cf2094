!> Integration-point state of the massif elements: converged values (end of the last
!> converged increment) and trial values (current iterate). Kept apart from the model so
!> the model stays intent(in).
module pecplas_fe_state
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_joints_state, only: joint_state_t
   use pecplas_water_state, only: pore_state_t
   use pecplas_structures_anchor_state, only: anchor_state_t
   use pecplas_structures_state, only: plate_state_t
   use pecplas_linalg_threads, only: PARALLEL_MIN_ELEMENTS
   implicit none (type, external)
   private

   public :: set_state_t, fe_state_t, set_material, set_state_allocate

   !> Per element set: arrays (component, gauss point, element).
   type :: set_state_t
      integer :: ngauss = 0
      !> Integration rule of the set (reference coordinates and weights).
      real(wp), allocatable :: xi(:, :), w(:)
      real(wp), allocatable :: stress(:, :, :), strain(:, :, :), hist(:, :, :)
      real(wp), allocatable :: stress_trial(:, :, :), strain_trial(:, :, :), hist_trial(:, :, :)
      !> Consistent tangent at each point from the last trial update (4, 4, ngauss, nel);
      !> not allocated when the set's material has a constant tangent (linear elastic: its
      !> elastic tangent is used, 16 values per point less to store and stream).
      real(wp), allocatable :: tangent(:, :, :, :)
      !> Phases (pecplas_phases_start): whether the set is active (an inactive set adds no
      !> stiffness and no force, and its points are not updated), and the index in
      !> model%materials of a material given by *CHANGE_MATERIAL (0: the *SECTION's).
      logical :: active = .true.
      integer :: material = 0
      !> Pore pressures at the points (a model with water; pecplas_water_state).
      type(pore_state_t) :: pore
   end type set_state_t

   type :: fe_state_t
      !> Converged nodal displacements (2, ncolumns): the nodes, then the plate rotations
      !> (pecplas_model_columns).
      real(wp), allocatable :: u(:, :)
      !> Factors of the load patterns at the converged state.
      real(wp), allocatable :: factors(:)
      type(set_state_t), allocatable :: sets(:)
      !> Joint sets (PECJOIN), committed and rolled back with the massif.
      type(joint_state_t) :: joints
      !> Anchors and struts, committed and rolled back with the massif.
      type(anchor_state_t) :: anchors
      !> Plate sets, committed and rolled back with the massif.
      type(plate_state_t) :: plates
      !> True while the points' tangents (massif and joints) are those of the converged
      !> state's last update: set by commit, cleared by rollback (the tangents are then those
      !> of the discarded attempt's last iterate).
      logical :: converged_tangents = .true.
      !> Free equations of nodes that no active element or joint holds (after a phase
      !> deactivated their sets): the stiffness gets a diagonal entry there so that it stays
      !> regular; nothing loads them, so they do not move. Empty without phases.
      integer, allocatable :: orphan_eq(:)
   contains
      procedure :: commit => state_commit
      procedure :: rollback => state_rollback
   end type fe_state_t

contains

   !> Index in model%materials of the material of element set s whose state is `st`: the
   !> *SECTION's, or the one a phase changed it to.
   pure integer function set_material(model, s, st) result(m)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      type(set_state_t), intent(in) :: st
      m = model%mesh%esets(s)%material_index
      if (st%material > 0) m = st%material
   end function set_material

   !> The point arrays of a set (ncomp stress components, nst history values, ng points,
   !> nel elements), converged and trial, all zero: the initial state. The zeros are
   !> written element by element by the element loops' threads, so that the page faults
   !> of this fresh memory (six arrays of ncomp or nst values per point) are spread over
   !> the team instead of taken by one thread.
   subroutine set_state_allocate(st, ncomp, nst, ng, nel)
      type(set_state_t), intent(inout) :: st
      integer, intent(in) :: ncomp, nst, ng, nel
      integer :: e
      allocate (st%stress(ncomp, ng, nel), st%strain(ncomp, ng, nel), st%hist(nst, ng, nel))
      allocate (st%stress_trial(ncomp, ng, nel), st%strain_trial(ncomp, ng, nel), &
         st%hist_trial(nst, ng, nel))
      !$omp parallel do default(shared) private(e) schedule(static) &
      !$omp if (nel >= PARALLEL_MIN_ELEMENTS)
      do e = 1, nel
         st%stress(:, :, e) = 0.0_wp
         st%strain(:, :, e) = 0.0_wp
         st%hist(:, :, e) = 0.0_wp
         st%stress_trial(:, :, e) = 0.0_wp
         st%strain_trial(:, :, e) = 0.0_wp
         st%hist_trial(:, :, e) = 0.0_wp
      end do
      !$omp end parallel do
   end subroutine set_state_allocate

   !> a = b, element by element on the element loops' threads where a has b's shape
   !> already (the state arrays: a copy, no arithmetic); else an ordinary assignment.
   subroutine copy_points(a, b)
      real(wp), allocatable, intent(inout) :: a(:, :, :)
      real(wp), intent(in) :: b(:, :, :)
      integer :: e
      logical :: same
      same = allocated(a) .and. size(b) > 0
      if (same) same = all(shape(a) == shape(b))
      if (.not. same) then
         a = b
         return
      end if
      !$omp parallel do default(shared) private(e) schedule(static) &
      !$omp if (size(b, 3) >= PARALLEL_MIN_ELEMENTS)
      do e = 1, size(b, 3)
         a(:, :, e) = b(:, :, e)
      end do
      !$omp end parallel do
   end subroutine copy_points

   !> Accepts the trial values of every point (end of a converged increment).
   subroutine state_commit(this)
      class(fe_state_t), intent(inout) :: this
      integer :: s
      do s = 1, size(this%sets)
         associate (st => this%sets(s))
            call copy_points(st%stress, st%stress_trial)
            call copy_points(st%strain, st%strain_trial)
            call copy_points(st%hist, st%hist_trial)
            call st%pore%commit()
         end associate
      end do
      call this%joints%commit()
      call this%anchors%commit()
      call this%plates%commit()
      this%converged_tangents = .true.
   end subroutine state_commit

   !> Discards the trial values (an increment that is cut).
   subroutine state_rollback(this)
      class(fe_state_t), intent(inout) :: this
      integer :: s
      do s = 1, size(this%sets)
         associate (st => this%sets(s))
            st%stress_trial = st%stress
            st%strain_trial = st%strain
            st%hist_trial = st%hist
            call st%pore%rollback()
         end associate
      end do
      call this%joints%rollback()
      call this%anchors%rollback()
      call this%plates%rollback()
      this%converged_tangents = .false.
   end subroutine state_rollback

end module pecplas_fe_state
