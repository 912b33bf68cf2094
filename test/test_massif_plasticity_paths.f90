!> Strain-driven homogeneous point paths to failure against the closed-form Mohr–Coulomb
!> strength sigma_1 = sigma_3 N + 2 c sqrt(N) (compression positive), from a hydrostatic
!> confining stress p = 100 (c = 10, phi = 30 deg: N = 3, sigma_1 = 334.64): plane strain
!> compression, axisymmetric triaxial compression and extension, Tresca; and the deck
!> errors of the parameter checks.
module test_massif_plasticity_paths
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error, ERR_INPUT
   use pecplas_base_params, only: params_t
   use pecplas_massif_materials_type, only: material_t, NCOMP
   use pecplas_massif_materials_mohr_coulomb, only: mohr_coulomb_t, new_mohr_coulomb
   use pecplas_massif_materials_drucker_prager, only: drucker_prager_t, new_drucker_prager
   use pecplas_massif_materials_soil, only: RETURN_SMOOTH, RETURN_EDGE
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_plasticity, only: COH, mc, dp, soil_params, drive_point, mc_strength
   implicit none (type, external)
   private
   public :: collect_massif_plasticity_paths

   real(wp), parameter :: P = 100.0_wp
   real(wp), parameter :: SIG0(NCOMP) = [-P, -P, -P, 0.0_wp]
   !> Plane strain: sigma_xx held, eps_yy imposed, eps_zz = gamma = 0.
   logical, parameter :: BIAXIAL(NCOMP) = [.true., .false., .false., .false.]
   !> Axisymmetric triaxial: sigma_rr and sigma_tt held, axial eps_yy imposed.
   logical, parameter :: TRIAXIAL(NCOMP) = [.true., .false., .true., .false.]
   real(wp), parameter :: SHORTEN(NCOMP) = [0.0_wp, -0.05_wp, 0.0_wp, 0.0_wp]
   !> Dilatancy angles (degrees) of the plane strain paths.
   real(wp), parameter :: PSIS(3) = [0.0_wp, 10.0_wp, 30.0_wp]

contains

   subroutine collect_massif_plasticity_paths(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('mc_plane_strain_compression', test_mc_biaxial), &
               new_unittest('mc_triaxial_compression_edge', test_mc_triaxial), &
               new_unittest('mc_triaxial_extension_edge', test_mc_extension), &
               new_unittest('tresca_plane_strain', test_tresca), &
               new_unittest('dp_plane_strain_match', test_dp_biaxial), &
               new_unittest('dp_outer_inner_triaxial', test_dp_triaxial), &
               new_unittest('parameter_errors', test_errors)]
   end subroutine collect_massif_plasticity_paths

   !> Final stress of a path (stress control on `free`, radial and hoop strains tied in
   !> the triaxial paths, `n` steps, default 50) and the kind of the last return.
   subroutine path(mat, free, deps, sig, kind, error, n)
      class(material_t), intent(in) :: mat
      logical, intent(in) :: free(NCOMP)
      real(wp), intent(in) :: deps(NCOMP)
      real(wp), intent(out) :: sig(NCOMP)
      integer, intent(out) :: kind
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: n
      real(wp), allocatable :: state(:)
      integer :: nsteps
      nsteps = 50
      if (present(n)) nsteps = n
      call drive_point(mat, SIG0, free, deps, nsteps, sig, state, error, &
         tie13=free(1) .and. free(3))
      if (allocated(error)) return
      kind = nint(state(6))
   end subroutine path

   !> Plane strain, psi = 0, 10, 30: main plane (sigma_zz intermediate), sigma_yy reaches
   !> -(p N + 2 c sqrt N) to 1e-10 (perfect plasticity: the stress stops on the plane).
   subroutine test_mc_biaxial(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: sig(NCOMP)
      integer :: k, kind
      do k = 1, 3
         call path(mc(30.0_wp, PSIS(k)), BIAXIAL, SHORTEN, sig, kind, error)
         if (allocated(error)) return
         call check_close(error, -sig(2), mc_strength(P, COH, 30.0_wp), 1.0e-10_wp, &
            'plane strain compression strength')
         if (allocated(error)) return
         call check(error, kind == RETURN_SMOOTH .and. sig(3) < -P .and. sig(3) > sig(2), &
            'main plane with sigma_zz intermediate')
         if (allocated(error)) return
      end do
   end subroutine test_mc_biaxial

   !> Triaxial compression (sigma_rr = sigma_tt = -p): the edge sigma_1 = sigma_2, same
   !> strength.
   subroutine test_mc_triaxial(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: sig(NCOMP)
      integer :: kind
      call path(mc(30.0_wp, 10.0_wp), TRIAXIAL, SHORTEN, sig, kind, error)
      if (allocated(error)) return
      call check_close(error, -sig(2), mc_strength(P, COH, 30.0_wp), 1.0e-10_wp, &
         'triaxial compression strength')
      if (allocated(error)) return
      call check(error, kind == RETURN_EDGE, 'triaxial compression ends on an edge')
   end subroutine test_mc_triaxial

   !> Triaxial extension (axial stress unloaded under sigma_rr = sigma_tt = -p): the axial
   !> stress is the minor compression, -(p - 2 c sqrt N)/N, on the edge sigma_2 = sigma_3.
   subroutine test_mc_extension(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: sig(NCOMP)
      integer :: kind
      call path(mc(30.0_wp, 10.0_wp), TRIAXIAL, -0.6_wp*SHORTEN, sig, kind, error)
      if (allocated(error)) return
      call check_close(error, -sig(2), (P - 2.0_wp*COH*sqrt(3.0_wp))/3.0_wp, 1.0e-10_wp, &
         'triaxial extension strength')
      if (allocated(error)) return
      call check(error, kind == RETURN_EDGE, 'triaxial extension ends on an edge')
   end subroutine test_mc_extension

   !> phi = psi = 0 (Tresca): sigma_xx - sigma_yy = 2 c in plane strain.
   subroutine test_tresca(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: sig(NCOMP)
      integer :: kind
      call path(mc(0.0_wp, 0.0_wp), BIAXIAL, SHORTEN, sig, kind, error)
      if (allocated(error)) return
      call check_close(error, sig(1) - sig(2), 2.0_wp*COH, 1.0e-10_wp, 'Tresca: 2 c')
   end subroutine test_tresca

   !> MATCH = 3 (plane strain) gives Mohr–Coulomb's plane strain strength for psi = 0, 10,
   !> 30 (the matching depends on psi). The limit is approached as the plastic eps_zz rate
   !> dies out: to 1e-9 after an axial strain of 0.4 (measured 7e-10 for psi = 0).
   subroutine test_dp_biaxial(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: sig(NCOMP)
      integer :: k, kind
      do k = 1, 3
         call path(dp(30.0_wp, PSIS(k), 3), BIAXIAL, 8.0_wp*SHORTEN, sig, kind, error, n=400)
         if (allocated(error)) return
         call check_close(error, -sig(2), mc_strength(P, COH, 30.0_wp), 3.0e-9_wp, &
            'Drucker-Prager plane strain match')
         if (allocated(error)) return
      end do
   end subroutine test_dp_biaxial

   !> MATCH = 1 (outer cone) in triaxial compression and MATCH = 2 (inner cone) in triaxial
   !> extension give Mohr–Coulomb's strengths (to 1e-10).
   subroutine test_dp_triaxial(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: sig(NCOMP)
      integer :: kind
      call path(dp(30.0_wp, 10.0_wp, 1), TRIAXIAL, SHORTEN, sig, kind, error)
      if (allocated(error)) return
      call check_close(error, -sig(2), mc_strength(P, COH, 30.0_wp), 1.0e-10_wp, &
         'outer cone, triaxial compression')
      if (allocated(error)) return
      call path(dp(30.0_wp, 10.0_wp, 2), TRIAXIAL, -0.6_wp*SHORTEN, sig, kind, error)
      if (allocated(error)) return
      call check_close(error, -sig(2), (P - 2.0_wp*COH*sqrt(3.0_wp))/3.0_wp, 1.0e-10_wp, &
         'inner cone, triaxial extension')
   end subroutine test_dp_triaxial

   !> Each bad value is a deck error at the material's line naming the parameter.
   subroutine test_errors(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: keys(9) = [character(len=7) :: 'E', 'NU', 'NU', 'C', &
         'PHI', 'PSI', 'PSI', 'TENSION', 'MATCH']
      real(wp), parameter :: values(9) = [0.0_wp, 0.5_wp, -1.0_wp, -1.0_wp, 90.0_wp, &
         35.0_wp, -1.0_wp, -1.0_wp, 4.0_wp]
      type(params_t) :: prm
      type(mohr_coulomb_t) :: m
      type(drucker_prager_t) :: d
      type(error_t), allocatable :: e
      integer :: i
      do i = 1, size(keys) + 1
         prm = soil_params(COH, 30.0_wp, 10.0_wp)
         if (i <= size(keys)) then
            call prm%add(trim(keys(i)), values(i))
         else
            prm = soil_params(0.0_wp, 0.0_wp, 0.0_wp) ! no strength at all
         end if
         if (i == 9) then
            call new_drucker_prager(d, 'dp', prm, e)
         else
            call new_mohr_coulomb(m, 'mc', prm, e)
         end if
         if (.not. allocated(e)) then
            call fatal_error(error, 'no error for bad '//trim(keys(min(i, 9))))
            return
         end if
         if (e%kind /= ERR_INPUT .or. e%line /= 7 .or. e%keyword /= '*MATERIAL' .or. &
             (i <= size(keys) .and. index(e%message, trim(keys(min(i, 9)))) == 0)) then
            call fatal_error(error, 'bad error for '//trim(keys(min(i, 9)))//': '//e%text())
            return
         end if
         deallocate (e)
      end do
   end subroutine test_errors

end module test_massif_plasticity_paths
