!> The structured point kernels (pecplas_massif_point_kernels, behind massif_stiffness,
!> massif_internal_force and massif_strains) against the generic dense formulas
!> ke = sum B^T D B dvol, fe = sum B^T sigma dvol, eps = B ue built from the full strain
!> matrix of massif_gauss_point, on randomly distorted elements of every type, in plane
!> strain and axisymmetry, with symmetric and non-symmetric D.
module test_massif_kernels
   use, intrinsic :: iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC
   use pecplas_massif_elements_type, only: massif_element_t
   use pecplas_massif_elements_factory, only: new_massif_element, KNOWN_MASSIF_ELEMENTS
   use pecplas_massif_kinematics, only: massif_point_t, massif_rule_t, new_massif_rule, &
      massif_gauss_point
   use pecplas_massif_element_matrices, only: massif_stiffness, massif_internal_force, &
      massif_strains
   use pecplas_testing, only: unittest_t, new_unittest, check
   use fixtures_massif, only: sample_xe, hooke
   implicit none (type, external)
   private
   public :: collect_massif_kernels

   character(len=*), parameter :: NAMES(*) = KNOWN_MASSIF_ELEMENTS
   !> The kernels sum the same nonzero products as the dense formulas in another order
   !> (and skip the zero ones): the difference is a few ulps of the largest term.
   real(wp), parameter :: RTOL = 1.0e-13_wp
   !> Random distortions per element type and case.
   integer, parameter :: NDRAW = 4

contains

   subroutine collect_massif_kernels(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('plane_symmetric_d', test_plane_sym), &
               new_unittest('plane_nonsymmetric_d', test_plane_nonsym), &
               new_unittest('axi_symmetric_d', test_axi_sym), &
               new_unittest('axi_nonsymmetric_d', test_axi_nonsym)]
   end subroutine collect_massif_kernels

   subroutine test_plane_sym(error)
      type(error_t), allocatable, intent(out) :: error
      call check_all(PLANE_STRAIN, .true., 11, error)
   end subroutine test_plane_sym

   subroutine test_plane_nonsym(error)
      type(error_t), allocatable, intent(out) :: error
      call check_all(PLANE_STRAIN, .false., 23, error)
   end subroutine test_plane_nonsym

   subroutine test_axi_sym(error)
      type(error_t), allocatable, intent(out) :: error
      call check_all(AXISYMMETRIC, .true., 37, error)
   end subroutine test_axi_sym

   subroutine test_axi_nonsym(error)
      type(error_t), allocatable, intent(out) :: error
      call check_all(AXISYMMETRIC, .false., 41, error)
   end subroutine test_axi_nonsym

   !> Every element type, NDRAW random distortions of its sample element, random point
   !> tangents (Hooke plus a symmetric or non-symmetric perturbation), stresses and
   !> nodal displacements.
   subroutine check_all(kind, symmetric, seed, error)
      integer, intent(in) :: kind, seed
      logical, intent(in) :: symmetric
      type(error_t), allocatable, intent(out) :: error
      class(massif_element_t), allocatable :: elem
      type(massif_rule_t) :: rule
      real(wp), allocatable :: xe(:, :), d(:, :, :), sigma(:, :), ue(:)
      real(wp), allocatable :: ke(:, :), ke_ref(:, :), fe(:), fe_ref(:), eps(:, :), eps_ref(:, :)
      integer :: it, idraw, ig, nd, state
      character(len=64) :: label
      state = seed
      do it = 1, size(NAMES)
         call new_massif_element(trim(NAMES(it)), elem, error)
         if (allocated(error)) return
         call new_massif_rule(rule, elem)
         nd = 2*rule%nnode
         if (allocated(ke)) deallocate (xe, d, sigma, ue, ke, ke_ref, fe, fe_ref, eps, eps_ref)
         allocate (d(4, 4, rule%ngauss), sigma(4, rule%ngauss), ue(nd), ke(nd, nd), &
            ke_ref(nd, nd), fe(nd), fe_ref(nd), eps(4, rule%ngauss), eps_ref(4, rule%ngauss))
         do idraw = 1, NDRAW
            write (label, '(a,a,i0,a,l1)') trim(NAMES(it)), ' draw ', idraw, ' symmetric D ', &
               symmetric
            xe = sample_xe(trim(NAMES(it)))
            ! nodes moved by up to 0.06 (elements ~1 across: still valid, r > 1 stays > 0)
            xe = xe + 0.12_wp*(reshape(uniform(state, shape(xe)), shape(xe)) - 0.5_wp)
            do ig = 1, rule%ngauss
               d(:, :, ig) = hooke(3.0e4_wp, 0.3_wp) &
                             + 2.0e3_wp*reshape(uniform(state, [16]), [4, 4])
               if (symmetric) d(:, :, ig) = 0.5_wp*(d(:, :, ig) + transpose(d(:, :, ig)))
               sigma(:, ig) = 100.0_wp*(uniform(state, [4]) - 0.5_wp)
            end do
            ue = 1.0e-3_wp*(uniform(state, [nd]) - 0.5_wp)
            call dense_reference(rule, kind, xe, d, sigma, ue, ke_ref, fe_ref, eps_ref, error)
            if (allocated(error)) return
            call massif_stiffness(rule, kind, 0.7_wp, xe, d, ke, error)
            if (allocated(error)) return
            call massif_internal_force(rule, kind, 0.7_wp, xe, sigma, fe, error)
            if (allocated(error)) return
            call massif_strains(rule, kind, 0.7_wp, xe, ue, eps, error)
            if (allocated(error)) return
            call check(error, maxval(abs(ke - ke_ref)) <= RTOL*maxval(abs(ke_ref)), &
               'ke differs from sum B^T D B dvol: '//trim(label))
            if (allocated(error)) return
            call check(error, maxval(abs(fe - fe_ref)) <= RTOL*maxval(abs(fe_ref)), &
               'fe differs from sum B^T sigma dvol: '//trim(label))
            if (allocated(error)) return
            call check(error, maxval(abs(eps - eps_ref)) <= RTOL*maxval(abs(eps_ref)), &
               'eps differs from B ue: '//trim(label))
            if (allocated(error)) return
            ! a symmetric D gives an exactly symmetric ke (upper blocks mirrored)
            if (symmetric) then
               call check(error, all(ke == transpose(ke)), 'ke not exactly symmetric: ' &
                  //trim(label))
               if (allocated(error)) return
            else
               ! and a non-symmetric D a non-symmetric ke (no triangle was mirrored)
               call check(error, maxval(abs(ke - transpose(ke))) > 1.0e-3_wp*maxval(abs(ke)), &
                  'ke symmetric for a non-symmetric D: '//trim(label))
               if (allocated(error)) return
            end if
         end do
      end do
   end subroutine check_all

   !> The generic formulas with the dense B(4, 2*nnode) of massif_gauss_point.
   subroutine dense_reference(rule, kind, xe, d, sigma, ue, ke, fe, eps, error)
      type(massif_rule_t), intent(in) :: rule
      integer, intent(in) :: kind
      real(wp), intent(in) :: xe(:, :), d(:, :, :), sigma(:, :), ue(:)
      real(wp), intent(out) :: ke(:, :), fe(:), eps(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(massif_point_t) :: pt
      integer :: ig, nd
      nd = 2*rule%nnode
      ke = 0.0_wp
      fe = 0.0_wp
      do ig = 1, rule%ngauss
         call massif_gauss_point(rule, ig, kind, 0.7_wp, xe, pt, error)
         if (allocated(error)) return
         ke = ke + matmul(transpose(pt%b(:, 1:nd)), matmul(d(:, :, ig), pt%b(:, 1:nd)))*pt%dvol
         fe = fe + matmul(transpose(pt%b(:, 1:nd)), sigma(:, ig))*pt%dvol
         eps(:, ig) = matmul(pt%b(:, 1:nd), ue)
      end do
   end subroutine dense_reference

   !> Uniform numbers in [0, 1) from a small linear congruential generator (reproducible
   !> across compilers, unlike random_number's default seed).
   function uniform(state, shp) result(r)
      integer, intent(inout) :: state
      integer, intent(in) :: shp(:)
      real(wp), allocatable :: r(:)
      integer :: i
      allocate (r(product(shp)))
      do i = 1, size(r)
         state = int(modulo(16807_int64*state, 2147483647_int64))
         r(i) = real(state, wp)/2147483647.0_wp
      end do
   end function uniform

end module test_massif_kernels
