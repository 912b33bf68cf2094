!> Element-level integrals of a massif element over its integration rule: stiffness,
!> internal force, strains, body force, integration-point coordinates. Nodal vectors use
!> the DOF order u1, v1, u2, v2, ...; point quantities are indexed by the rule's points.
!> Nothing here allocates: the benchmark assembles some 1e5 elements.
module pecplas_massif_element_matrices
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_options, only: AXISYMMETRIC
   use pecplas_massif_kinematics, only: MAX_NODES, massif_rule_t, massif_point_t, &
      massif_gauss_point, massif_gauss_derivs
   use pecplas_massif_point_kernels, only: point_stiffness_add, point_strain, point_force_add
   implicit none (type, external)
   private

   public :: massif_stiffness, massif_internal_force, massif_strains, massif_body_force
   public :: massif_gauss_coordinates

contains

   !> ke(2*nnode, 2*nnode) = sum_g B^T D_g B dvol for tangents d(4, 4, ngauss); D need
   !> not be symmetric (non-associated plasticity), and ke is then not symmetric either.
   subroutine massif_stiffness(rule, analysis_kind, thickness, xe, d, ke, error)
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness
      real(wp), contiguous, intent(in) :: xe(:, :), d(:, :, :)
      real(wp), contiguous, intent(out) :: ke(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: dndx(2, MAX_NODES), hr(MAX_NODES), dvol, dg(4, 4)
      integer :: ig, j, ndof, nn
      logical :: sym
      nn = rule%nnode
      ndof = 2*nn
      call check_shapes(rule, xe, ndof, size(ke, 1), 'massif_stiffness', error)
      if (allocated(error)) return
      if (size(ke, 2) /= ndof .or. any(shape(d) /= [4, 4, rule%ngauss])) then
         call fatal_error(error, 'massif_stiffness: ke must be (ndof, ndof), d (4, 4, ngauss)')
         return
      end if
      ! symmetric point tangents (elastic, associated plasticity) give a symmetric ke: its
      ! upper node blocks are computed and mirrored, half the products
      sym = .true.
      do ig = 1, rule%ngauss
         do j = 1, 3
            sym = sym .and. all(d(j + 1:4, j, ig) == d(j, j + 1:4, ig))
         end do
      end do
      ke = 0.0_wp
      do ig = 1, rule%ngauss
         call massif_gauss_derivs(rule, ig, analysis_kind, thickness, xe, dndx, hr, dvol, &
            error)
         if (allocated(error)) return
         dg = d(:, :, ig)
         call point_stiffness_add(nn, dndx, hr, dvol, dg, &
            analysis_kind == AXISYMMETRIC, sym, ke)
      end do
      if (sym) then
         do j = 1, ndof - 1
            ke(j + 1:ndof, j) = ke(j, j + 1:ndof)
         end do
      end if
   end subroutine massif_stiffness

   !> fe(2*nnode) = sum_g B^T sigma_g dvol for stresses sigma(4, ngauss).
   subroutine massif_internal_force(rule, analysis_kind, thickness, xe, sigma, fe, error)
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness
      real(wp), contiguous, intent(in) :: xe(:, :), sigma(:, :)
      real(wp), contiguous, intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: dndx(2, MAX_NODES), hr(MAX_NODES), dvol
      integer :: ig, ndof, nn
      nn = rule%nnode
      ndof = 2*nn
      call check_shapes(rule, xe, ndof, size(fe), 'massif_internal_force', error)
      if (allocated(error)) return
      if (any(shape(sigma) /= [4, rule%ngauss])) then
         call fatal_error(error, 'massif_internal_force: sigma must be (4, ngauss)')
         return
      end if
      fe = 0.0_wp
      do ig = 1, rule%ngauss
         call massif_gauss_derivs(rule, ig, analysis_kind, thickness, xe, dndx, hr, dvol, &
            error)
         if (allocated(error)) return
         call point_force_add(nn, dndx, hr, dvol, sigma(:, ig), fe)
      end do
   end subroutine massif_internal_force

   !> Strains eps(4, ngauss) = B ue at the integration points for nodal displacements
   !> ue(2*nnode) (or their increments).
   subroutine massif_strains(rule, analysis_kind, thickness, xe, ue, eps, error)
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness
      real(wp), contiguous, intent(in) :: xe(:, :), ue(:)
      real(wp), contiguous, intent(out) :: eps(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: dndx(2, MAX_NODES), hr(MAX_NODES), dvol
      integer :: ig, ndof, nn
      nn = rule%nnode
      ndof = 2*nn
      call check_shapes(rule, xe, ndof, size(ue), 'massif_strains', error)
      if (allocated(error)) return
      if (any(shape(eps) /= [4, rule%ngauss])) then
         call fatal_error(error, 'massif_strains: eps must be (4, ngauss)')
         return
      end if
      do ig = 1, rule%ngauss
         call massif_gauss_derivs(rule, ig, analysis_kind, thickness, xe, dndx, hr, dvol, &
            error)
         if (allocated(error)) return
         call point_strain(nn, dndx, hr, ue, eps(:, ig))
      end do
   end subroutine massif_strains

   !> Consistent nodal forces fe(2*nnode) = sum_g N^T b dvol of a uniform body force
   !> b(2) per unit volume (gravity: b = (0, -gamma)).
   subroutine massif_body_force(rule, analysis_kind, thickness, xe, b, fe, error)
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness, xe(:, :), b(2)
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      type(massif_point_t) :: pt
      integer :: ig, k, ndof
      ndof = 2*rule%nnode
      call check_shapes(rule, xe, ndof, size(fe), 'massif_body_force', error)
      if (allocated(error)) return
      fe = 0.0_wp
      do ig = 1, rule%ngauss
         call massif_gauss_point(rule, ig, analysis_kind, thickness, xe, pt, error)
         if (allocated(error)) return
         do k = 1, rule%nnode
            fe(2*k - 1:2*k) = fe(2*k - 1:2*k) + pt%n(k)*b*pt%dvol
         end do
      end do
   end subroutine massif_body_force

   !> Physical coordinates xg(2, ngauss) of the integration points.
   pure subroutine massif_gauss_coordinates(rule, xe, xg)
      type(massif_rule_t), intent(in) :: rule
      real(wp), intent(in) :: xe(:, :)
      real(wp), intent(out) :: xg(:, :)
      xg = matmul(xe, rule%n)
   end subroutine massif_gauss_coordinates

   subroutine check_shapes(rule, xe, ndof, nvec, where, error)
      type(massif_rule_t), intent(in) :: rule
      real(wp), intent(in) :: xe(:, :)
      integer, intent(in) :: ndof, nvec
      character(len=*), intent(in) :: where
      type(error_t), allocatable, intent(out) :: error
      if (.not. allocated(rule%n)) then
         call fatal_error(error, where//': integration rule not built (new_massif_rule)')
      else if (size(xe, 1) /= 2 .or. size(xe, 2) /= rule%nnode .or. nvec /= ndof) then
         call fatal_error(error, where//': xe must be (2, nnode) and vectors 2*nnode long')
      end if
   end subroutine check_shapes

end module pecplas_massif_element_matrices
