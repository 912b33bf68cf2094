!> Mohr–Coulomb return map at one point (c = 10, phi = 30 deg, psi = 10 or 30 deg, E = 1e4,
!> NU = 0.3), principal axes turned by 0.3 rad from x: elastic range, returned stress on the
!> yield surface, plastic strain along the flow directions, apex and tension cut-off,
!> consistent tangent against central differences of `update`, symmetry for psi = phi.
module test_massif_plasticity
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_params, only: params_t
   use pecplas_massif_materials_type, only: NCOMP
   use pecplas_massif_materials_elastic, only: elastic_t, new_elastic
   use pecplas_massif_materials_mohr_coulomb, only: mohr_coulomb_t
   use pecplas_massif_materials_soil, only: RETURN_SMOOTH, RETURN_EDGE, RETURN_APEX
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   use fixtures_plasticity, only: E, NU, COH, mc, rotated_stress, rotated_strain, &
      compliance, fd_tangent, rel_diff, principal2d, PI
   implicit none (type, external)
   private
   public :: collect_massif_plasticity

   real(wp), parameter :: THETA = 0.3_wp
   !> Converged stress before the increment: hydrostatic, inside the cone.
   real(wp), parameter :: SIG0(NCOMP) = [-50.0_wp, -50.0_wp, -50.0_wp, 0.0_wp]
   !> Trial principal values (a, b, z) of each kind of return: main plane, edge a = z,
   !> edge b = z, edge a = b, equal in-plane trial values (ends on the edge a = b).
   real(wp), parameter :: TRIALS(3, 5) = reshape([0.0_wp, -150.0_wp, -70.0_wp, &
      -30.0_wp, -200.0_wp, -32.0_wp, 0.0_wp, -150.0_wp, -148.0_wp, &
      -30.0_wp, -32.0_wp, -200.0_wp, -150.0_wp, -150.0_wp, -20.0_wp], [3, 5])
   integer, parameter :: KINDS(5) = [RETURN_SMOOTH, RETURN_EDGE, RETURN_EDGE, RETURN_EDGE, &
      RETURN_EDGE]

contains

   subroutine collect_massif_plasticity(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('elastic_range_is_elastic', test_elastic), &
               new_unittest('returns_on_yield_surface', test_on_surface), &
               new_unittest('main_plane_flow_direction', test_flow_main), &
               new_unittest('edge_flow_in_cone', test_flow_edge), &
               new_unittest('apex_return', test_apex), &
               new_unittest('tension_cutoff', test_tension), &
               new_unittest('tangent_central_differences', test_tangent), &
               new_unittest('tangent_symmetric_iff_associated', test_symmetry)]
   end subroutine collect_massif_plasticity

   !> Strain increment that takes SIG0 to the trial stress with principal values v.
   pure function increment_to(v) result(deps)
      real(wp), intent(in) :: v(3)
      real(wp) :: deps(NCOMP)
      deps = compliance(rotated_stress(v, THETA) - SIG0)
   end function increment_to

   !> Inside the cone the update is the elastic material's, stress and tangent.
   subroutine test_elastic(error)
      type(error_t), allocatable, intent(out) :: error
      type(mohr_coulomb_t) :: mat
      type(elastic_t) :: el
      real(wp) :: deps(NCOMP), s1(NCOMP), s2(NCOMP), d1(NCOMP, NCOMP), d2(NCOMP, NCOMP)
      real(wp) :: st(6), none(0)
      type(params_t) :: p
      mat = mc(30.0_wp, 10.0_wp)
      p%file = 'soil.inp'; p%line = 3; p%keyword = '*MATERIAL'
      call p%add('E', E)
      call p%add('NU', NU)
      call new_elastic(el, 'el', p, error)
      if (allocated(error)) return
      deps = increment_to([-40.0_wp, -70.0_wp, -55.0_wp])
      st = 0.0_wp
      call mat%update(SIG0, deps, st, s1, d1, error)
      if (allocated(error)) return
      call el%update(SIG0, deps, none, s2, d2, error)
      if (allocated(error)) return
      ! same formulas evaluated in the same order: equal to rounding
      call check(error, maxval(abs(s1 - s2)) <= 1.0e-13_wp*maxval(abs(s2)) .and. &
         maxval(abs(d1 - d2)) <= 1.0e-13_wp*maxval(abs(d2)) .and. all(st == 0.0_wp), &
         'elastic range: stress and tangent of the elastic material, no plastic strain')
   end subroutine test_elastic

   !> Every return ends on the yield surface (f = 0 to 1e-10 of the stress scale) with the
   !> expected kind, for psi = 10 and 30 degrees.
   subroutine test_on_surface(error)
      type(error_t), allocatable, intent(out) :: error
      type(mohr_coulomb_t) :: mat
      real(wp) :: s(NCOMP), d(NCOMP, NCOMP), st(6), psi
      integer :: i, k
      character(len=80) :: buf
      do k = 1, 2
         psi = merge(10.0_wp, 30.0_wp, k == 1)
         mat = mc(30.0_wp, psi)
         do i = 1, size(KINDS)
            st = 0.0_wp
            call mat%update(SIG0, increment_to(TRIALS(:, i)), st, s, d, error)
            if (allocated(error)) return
            write (buf, '(a,i0,a,f4.0)') 'case ', i, ', psi = ', psi
            call check(error, nint(st(6)) == KINDS(i), trim(buf)//': kind of return')
            if (allocated(error)) return
            call check_close(error, mat%yield(s), 0.0_wp, 0.0_wp, trim(buf)//': f = 0', &
               atol=1.0e-10_wp*maxval(abs(s)))
            if (allocated(error)) return
         end do
      end do
   end subroutine test_on_surface

   !> Main plane (sigma_1 = a, sigma_3 = b): the plastic strain increment is parallel to
   !> dg/dsigma = (1 + sin psi) n_a n_a - (1 - sin psi) n_b n_b, not to df/dsigma.
   subroutine test_flow_main(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: sq
      sq = sin(10.0_wp*PI/180.0_wp)
      call check_flow(mc(30.0_wp, 10.0_wp), TRIALS(:, 1), &
         reshape([1.0_wp + sq, -(1.0_wp - sq), 0.0_wp], [3, 1]), 'main plane', error)
   end subroutine test_flow_main

   !> Edges: the plastic strain increment is a non-negative combination of the flow
   !> directions of the two active planes.
   subroutine test_flow_edge(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: p, m
      p = 1.0_wp + sin(10.0_wp*PI/180.0_wp); m = -(1.0_wp - sin(10.0_wp*PI/180.0_wp))
      ! a = z: planes (a, b) and (z, b)
      call check_flow(mc(30.0_wp, 10.0_wp), TRIALS(:, 2), &
         reshape([p, m, 0.0_wp, 0.0_wp, m, p], [3, 2]), 'edge a = z', error)
      if (allocated(error)) return
      ! b = z: planes (a, b) and (a, z)
      call check_flow(mc(30.0_wp, 10.0_wp), TRIALS(:, 3), &
         reshape([p, m, 0.0_wp, p, 0.0_wp, m], [3, 2]), 'edge b = z', error)
   end subroutine test_flow_edge

   !> Plastic strain of the return from TRIALS-like `v` against the principal flow
   !> vectors `dirs` (a, b, z): least-squares weights >= 0 and a residual below 1e-10.
   subroutine check_flow(mat, v, dirs, what, error)
      type(mohr_coulomb_t), intent(in) :: mat
      real(wp), intent(in) :: v(3), dirs(:, :)
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: s(NCOMP), d(NCOMP, NCOMP), st(6), vec(NCOMP, size(dirs, 2))
      real(wp) :: n(size(dirs, 2), size(dirs, 2)), rhs(size(dirs, 2)), x(size(dirs, 2)), det
      integer :: j
      st = 0.0_wp
      call mat%update(SIG0, increment_to(v), st, s, d, error)
      if (allocated(error)) return
      do j = 1, size(dirs, 2)
         vec(:, j) = rotated_strain(dirs(:, j), THETA)
      end do
      n = matmul(transpose(vec), vec)
      rhs = matmul(st(1:4), vec)
      if (size(x) == 1) then
         x = rhs/n(1, 1)
      else
         det = n(1, 1)*n(2, 2) - n(1, 2)*n(2, 1)
         x = [n(2, 2)*rhs(1) - n(1, 2)*rhs(2), n(1, 1)*rhs(2) - n(2, 1)*rhs(1)]/det
      end if
      call check(error, all(x >= 0.0_wp) .and. norm2(st(1:4)) > 0.0_wp .and. &
         norm2(st(1:4) - matmul(vec, x)) <= 1.0e-10_wp*norm2(st(1:4)), &
         what//': plastic strain along the flow direction(s)')
   end subroutine check_flow

   !> Beyond the apex c cot(phi) the stress is the apex and the tangent is 0 (and so are
   !> central differences), for psi = 10 and 30 degrees.
   subroutine test_apex(error)
      type(error_t), allocatable, intent(out) :: error
      type(mohr_coulomb_t) :: mat
      real(wp) :: s(NCOMP), d(NCOMP, NCOMP), st(6), deps(NCOMP), apex
      integer :: k
      apex = COH/tan(PI/6.0_wp)
      deps = increment_to([30.0_wp, 25.0_wp, 28.0_wp])
      do k = 1, 2
         mat = mc(30.0_wp, merge(10.0_wp, 30.0_wp, k == 1))
         st = 0.0_wp
         call mat%update(SIG0, deps, st, s, d, error)
         if (allocated(error)) return
         call check(error, maxval(abs(s - [apex, apex, apex, 0.0_wp])) <= 1.0e-12_wp*apex &
            .and. nint(st(6)) == RETURN_APEX .and. all(d == 0.0_wp) .and. &
            maxval(abs(fd_tangent(mat, SIG0, deps, 1.0e-6_wp))) <= 1.0e-6_wp, &
            'apex: stress c cot(phi), kind apex, tangent and its differences 0')
         if (allocated(error)) return
      end do
   end subroutine test_apex

   !> Tension cut-off t = 5: one plane (sigma_a = t, plastic strain along n_a n_a) and the
   !> edge sigma_a = sigma_b = t; tangents against central differences.
   subroutine test_tension(error)
      type(error_t), allocatable, intent(out) :: error
      type(mohr_coulomb_t) :: mat
      real(wp) :: s(NCOMP), d(NCOMP, NCOMP), st(6), deps(NCOMP), v(3)
      integer :: k
      mat = mc(30.0_wp, 10.0_wp, tension=5.0_wp)
      call check_flow(mat, [8.0_wp, -10.0_wp, -5.0_wp], reshape([1.0_wp, 0.0_wp, 0.0_wp], &
         [3, 1]), 'tension plane', error)
      if (allocated(error)) return
      do k = 1, 2
         v = [8.0_wp, -10.0_wp, -5.0_wp]
         if (k == 2) v = [8.0_wp, 7.0_wp, -5.0_wp]
         deps = increment_to(v)
         st = 0.0_wp
         call mat%update(SIG0, deps, st, s, d, error)
         if (allocated(error)) return
         call check(error, nint(st(6)) == k .and. abs(maxval(principal2d(s)) - 5.0_wp) <= 1.0e-12_wp &
            .and. abs(mat%yield(s)) <= 1.0e-12_wp*maxval(abs(s)), 'cut-off: sigma_max = t')
         if (allocated(error)) return
         call check(error, rel_diff(d, fd_tangent(mat, SIG0, deps, 1.0e-6_wp)) < 1.0e-6_wp, &
            'cut-off: tangent = central differences')
         if (allocated(error)) return
      end do
   end subroutine test_tension

   !> Consistent tangent = central differences of update (step 1e-6 on strains of ~1e-2;
   !> relative Frobenius error < 1e-6) for every kind of return, psi = 10 and 30 degrees.
   subroutine test_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      type(mohr_coulomb_t) :: mat
      real(wp) :: s(NCOMP), d(NCOMP, NCOMP), st(6), deps(NCOMP), err
      integer :: i, k
      character(len=80) :: buf
      do k = 1, 2
         mat = mc(30.0_wp, merge(10.0_wp, 30.0_wp, k == 1))
         do i = 1, size(KINDS)
            deps = increment_to(TRIALS(:, i))
            st = 0.0_wp
            call mat%update(SIG0, deps, st, s, d, error)
            if (allocated(error)) return
            err = rel_diff(d, fd_tangent(mat, SIG0, deps, 1.0e-6_wp))
            write (buf, '(a,i0,a,i0,a,es9.2)') 'case ', i, ' psi set ', k, ': error ', err
            call check(error, err < 1.0e-6_wp, trim(buf))
            if (allocated(error)) return
         end do
      end do
   end subroutine test_tangent

   !> psi = phi: the tangent is symmetric (to 1e-12); psi < phi: it is not (> 1e-3).
   subroutine test_symmetry(error)
      type(error_t), allocatable, intent(out) :: error
      type(mohr_coulomb_t) :: mat
      real(wp) :: s(NCOMP), d(NCOMP, NCOMP), st(6), asym
      integer :: i, k
      do k = 1, 2
         mat = mc(30.0_wp, merge(30.0_wp, 10.0_wp, k == 1))
         do i = 1, size(KINDS)
            st = 0.0_wp
            call mat%update(SIG0, increment_to(TRIALS(:, i)), st, s, d, error)
            if (allocated(error)) return
            asym = rel_diff(d, transpose(d))
            if (k == 1 .and. .not. asym < 1.0e-12_wp) then
               call fatal_error(error, 'associated flow: tangent not symmetric')
               return
            end if
            if (k == 2 .and. .not. asym > 1.0e-3_wp) then
               call fatal_error(error, 'non-associated flow: tangent unexpectedly symmetric')
               return
            end if
         end do
         call check(error, mat%symmetric_tangent() .eqv. (k == 1), 'symmetric_tangent()')
         if (allocated(error)) return
      end do
   end subroutine test_symmetry

end module test_massif_plasticity
