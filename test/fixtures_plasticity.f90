!> Helpers of the plasticity suites: materials built from deck parameters, stress and strain
!> vectors from principal values and axes, principal values computed independently of the
!> code under test, central-difference tangents and a mixed stress/strain point driver.
module fixtures_plasticity
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_params, only: params_t
   use pecplas_massif_materials_type, only: material_t, NCOMP
   use pecplas_massif_materials_mohr_coulomb, only: mohr_coulomb_t, new_mohr_coulomb
   use pecplas_massif_materials_drucker_prager, only: drucker_prager_t, new_drucker_prager
   implicit none (type, external)
   private

   public :: E, NU, COH, mc, dp, soil_params, rotated_stress, rotated_strain, principal2d
   public :: compliance, fd_tangent, rel_diff, drive_point, mc_strength, PI

   !> Elastic constants and cohesion of the point tests (kPa).
   real(wp), parameter :: E = 1.0e4_wp, NU = 0.3_wp, COH = 10.0_wp
   real(wp), parameter :: PI = acos(-1.0_wp)

contains

   !> Deck parameters E, NU, C, PHI, PSI (at a made-up deck position).
   function soil_params(c, phi, psi) result(p)
      real(wp), intent(in) :: c, phi, psi
      type(params_t) :: p
      p%file = 'soil.inp'; p%line = 7; p%keyword = '*MATERIAL'
      call p%add('E', E)
      call p%add('NU', NU)
      call p%add('C', c)
      call p%add('PHI', phi)
      call p%add('PSI', psi)
   end function soil_params

   !> Mohr–Coulomb with cohesion COH, angles in degrees, optional cut-off.
   function mc(phi, psi, tension) result(mat)
      real(wp), intent(in) :: phi, psi
      real(wp), intent(in), optional :: tension
      type(mohr_coulomb_t) :: mat
      type(params_t) :: p
      type(error_t), allocatable :: error
      p = soil_params(COH, phi, psi)
      if (present(tension)) call p%add('TENSION', tension)
      call new_mohr_coulomb(mat, 'mc', p, error)
      if (allocated(error)) error stop 'fixtures_plasticity: bad Mohr-Coulomb parameters'
   end function mc

   !> Drucker–Prager with cohesion COH, angles in degrees and matching `match`.
   function dp(phi, psi, match) result(mat)
      real(wp), intent(in) :: phi, psi
      integer, intent(in) :: match
      type(drucker_prager_t) :: mat
      type(params_t) :: p
      type(error_t), allocatable :: error
      p = soil_params(COH, phi, psi)
      call p%add('MATCH', real(match, wp))
      call new_drucker_prager(mat, 'dp', p, error)
      if (allocated(error)) error stop 'fixtures_plasticity: bad Drucker-Prager parameters'
   end function dp

   !> Stress vector with principal values (a, b, z), n_a at angle theta to x.
   pure function rotated_stress(v, theta) result(s)
      real(wp), intent(in) :: v(3), theta
      real(wp) :: s(NCOMP), c, t
      c = cos(theta); t = sin(theta)
      s = [c*c*v(1) + t*t*v(2), t*t*v(1) + c*c*v(2), v(3), c*t*(v(1) - v(2))]
   end function rotated_stress

   !> Strain vector (engineering shear) with principal values (a, b, z) at angle theta.
   pure function rotated_strain(v, theta) result(s)
      real(wp), intent(in) :: v(3), theta
      real(wp) :: s(NCOMP)
      s = rotated_stress(v, theta)
      s(4) = 2.0_wp*s(4)
   end function rotated_strain

   !> Principal values (larger in-plane, smaller in-plane, zz) by the closed form.
   pure function principal2d(s) result(v)
      real(wp), intent(in) :: s(NCOMP)
      real(wp) :: v(3), r
      r = sqrt(0.25_wp*(s(1) - s(2))**2 + s(4)**2)
      v = [0.5_wp*(s(1) + s(2)) + r, 0.5_wp*(s(1) + s(2)) - r, s(3)]
   end function principal2d

   !> Elastic strain (engineering shear) of a stress vector, E and NU of the fixtures.
   pure function compliance(s) result(eps)
      real(wp), intent(in) :: s(NCOMP)
      real(wp) :: eps(NCOMP)
      eps(1:3) = ((1.0_wp + NU)*s(1:3) - NU*sum(s(1:3)))/E
      eps(4) = 2.0_wp*(1.0_wp + NU)*s(4)/E
   end function compliance

   !> Central differences of `update` with respect to the strain increment, steps h.
   function fd_tangent(mat, sig0, deps, h) result(d)
      class(material_t), intent(in) :: mat
      real(wp), intent(in) :: sig0(NCOMP), deps(NCOMP), h
      real(wp) :: d(NCOMP, NCOMP), sp(NCOMP), sm(NCOMP), t(NCOMP, NCOMP), e(NCOMP)
      real(wp), allocatable :: st(:)
      type(error_t), allocatable :: error
      integer :: j
      do j = 1, NCOMP
         e = 0.0_wp; e(j) = h
         st = spread(0.0_wp, 1, mat%nstate())
         call mat%update(sig0, deps + e, st, sp, t, error)
         st = spread(0.0_wp, 1, mat%nstate())
         call mat%update(sig0, deps - e, st, sm, t, error)
         d(:, j) = (sp - sm)/(2.0_wp*h)
      end do
   end function fd_tangent

   !> Frobenius norm of a - b relative to that of b.
   pure real(wp) function rel_diff(a, b)
      real(wp), intent(in) :: a(:, :), b(:, :)
      rel_diff = norm2(a - b)/norm2(b)
   end function rel_diff

   !> Homogeneous point path in `nsteps` equal steps: the components with `free` true keep
   !> the stress `sig0` (their strains found by Newton with the material's tangent), the
   !> others follow the strain increment `deps_total`. With `tie13`, components 1 and 3
   !> (radial and hoop in axisymmetry) share one strain, found from their mean stress, as
   !> in a triaxial cell. Returns the final stress and state.
   subroutine drive_point(mat, sig0, free, deps_total, nsteps, sig, state, error, tie13)
      class(material_t), intent(in) :: mat
      real(wp), intent(in) :: sig0(NCOMP), deps_total(NCOMP)
      logical, intent(in) :: free(NCOMP)
      integer, intent(in) :: nsteps
      real(wp), intent(out) :: sig(NCOMP)
      real(wp), allocatable, intent(out) :: state(:)
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: tie13
      real(wp) :: sold(NCOMP), deps(NCOMP), d(NCOMP, NCOMP), r(NCOMP), scale, x
      real(wp), allocatable :: st(:)
      integer :: step, it, nf
      integer, allocatable :: idx(:)
      logical :: tied
      tied = .false.
      if (present(tie13)) tied = tie13
      idx = pack([1, 2, 3, 4], free)
      nf = size(idx)
      allocate (state(mat%nstate()), source=0.0_wp)
      sold = sig0
      scale = maxval(abs(sig0)) + COH
      do step = 1, nsteps
         deps = merge(0.0_wp, deps_total/nsteps, free)
         do it = 1, 50
            st = state
            call mat%update(sold, deps, st, sig, d, error)
            if (allocated(error)) return
            r = sig - sig0
            if (nf == 0) exit
            if (tied) then
               x = 0.5_wp*(r(1) + r(3))
               if (abs(x) <= 1.0e-11_wp*scale) exit
               x = x/(0.5_wp*(d(1, 1) + d(1, 3) + d(3, 1) + d(3, 3)))
               deps([1, 3]) = deps([1, 3]) - x
            else
               if (maxval(abs(r(idx))) <= 1.0e-11_wp*scale) exit
               deps(idx) = deps(idx) - solve(d(idx, idx), r(idx))
            end if
         end do
         if (it > 50) then
            call fatal_error(error, 'point driver: no convergence of the stress control')
            return
         end if
         state = st
         sold = sig
      end do
   end subroutine drive_point

   !> Solution of a small system (1 or 2 unknowns here) by Cramer's rule.
   pure function solve(a, b) result(x)
      real(wp), intent(in) :: a(:, :), b(:)
      real(wp) :: x(size(b)), det
      if (size(b) == 1) then
         x = b/a(1, 1)
      else
         det = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
         x = [a(2, 2)*b(1) - a(1, 2)*b(2), a(1, 1)*b(2) - a(2, 1)*b(1)]/det
      end if
   end function solve

   !> Mohr–Coulomb major principal stress at failure (compression positive):
   !> sigma_1 = sigma_3 N + 2 c sqrt(N), N = (1 + sin phi)/(1 - sin phi), phi in degrees.
   pure real(wp) function mc_strength(sigma3, c, phi) result(s1)
      real(wp), intent(in) :: sigma3, c, phi
      real(wp) :: n
      n = (1.0_wp + sin(phi*PI/180.0_wp))/(1.0_wp - sin(phi*PI/180.0_wp))
      s1 = sigma3*n + 2.0_wp*c*sqrt(n)
   end function mc_strength

end module fixtures_plasticity
