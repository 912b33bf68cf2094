!> Perfectly plastic Drucker–Prager soil with non-associated flow:
!>   f = sqrt(J2) + eta p - xi c,   g = sqrt(J2) + etabar p   (p = tr(sigma)/3, tension +),
!> with eta, xi, etabar matched to Mohr–Coulomb's c, phi, psi (MATCH = 1 outer cone,
!> 2 inner cone, 3 plane strain, the default). Implicit return to the cone, closed form for
!> perfect plasticity, or to the apex, with the consistent tangent (de Souza Neto et al.,
!> 2008, ch. 8; doc/theory.md, "Elastoplastic soil").
module pecplas_massif_materials_drucker_prager
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_base_params, only: params_t
   use pecplas_massif_materials_type, only: material_t, NCOMP
   use pecplas_massif_materials_soil, only: soil_params_t, read_soil_params, soil_hooke, &
      soil_plastic_state, NSTATE_SOIL, SOIL_STATE_NAMES, RETURN_ELASTIC, RETURN_SMOOTH, &
      RETURN_APEX, reduce_soil
   implicit none (type, external)
   private

   public :: drucker_prager_t, new_drucker_prager, drucker_prager_constants

   type, extends(material_t) :: drucker_prager_t
      type(soil_params_t) :: soil
      !> Matching of the cone to Mohr–Coulomb: 1 outer, 2 inner, 3 plane strain.
      integer :: match = 3
      !> Friction and cohesion factors of f, dilatancy factor of g.
      real(wp) :: eta = 0.0_wp, xi = 0.0_wp, etabar = 0.0_wp
   contains
      procedure :: nstate => drucker_prager_nstate
      procedure :: state_names => drucker_prager_state_names
      procedure :: elastic_tangent => drucker_prager_elastic_tangent
      procedure :: update => drucker_prager_update
      procedure :: with_cohesion => drucker_prager_with_cohesion
      procedure :: symmetric_tangent => drucker_prager_symmetric_tangent
      !> Yield function at a stress vector (<= 0 admissible; stress units).
      procedure :: yield => drucker_prager_yield
      !> The Mohr-Coulomb c, tan(phi) divided by msf (psi_r = min(psi, phi_r)), the cone
      !> fitted again to them with the same MATCH.
      procedure :: reduced_strength => drucker_prager_reduced_strength
   end type drucker_prager_t

contains

   !> Builds from E, NU, C, PHI, PSI (degrees), optional GAMMA and MATCH (1, 2 or 3).
   subroutine new_drucker_prager(mat, name, params, error)
      type(drucker_prager_t), intent(out) :: mat
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: match
      mat%name = name
      call read_soil_params(params, [character(len=8) :: 'MATCH'], mat%soil, error)
      if (allocated(error)) return
      mat%unit_weight = mat%soil%unit_weight
      call params%get('MATCH', match, error, default=3.0_wp)
      if (allocated(error)) return
      if (.not. any(match == [1.0_wp, 2.0_wp, 3.0_wp])) then
         call deck_error(error, params%file, params%line, params%keyword, &
            'MATCH must be 1 (outer cone), 2 (inner cone) or 3 (plane strain)')
         return
      end if
      mat%match = nint(match)
      call drucker_prager_constants(mat%match, mat%soil%phi, mat%soil%psi, mat%eta, mat%xi, &
         mat%etabar)
   end subroutine new_drucker_prager

   !> eta, xi, etabar of the cone matched to Mohr–Coulomb (phi, psi in radians):
   !> 1 outer cone through the triaxial compression meridians, 2 inner cone through the
   !> extension meridians, 3 plane strain: the plane-strain limit state (plastic
   !> eps_zz = 0) and dilatancy ratio are Mohr–Coulomb's for this phi and psi.
   pure subroutine drucker_prager_constants(match, phi, psi, eta, xi, etabar)
      integer, intent(in) :: match
      real(wp), intent(in) :: phi, psi
      real(wp), intent(out) :: eta, xi, etabar
      real(wp) :: root
      select case (match)
      case (1, 2)
         root = 3.0_wp - sin(phi)
         if (match == 2) root = 3.0_wp + sin(phi)
         eta = 6.0_wp*sin(phi)/(sqrt(3.0_wp)*root)
         xi = 6.0_wp*cos(phi)/(sqrt(3.0_wp)*root)
         root = 3.0_wp - sin(psi)
         if (match == 2) root = 3.0_wp + sin(psi)
         etabar = 6.0_wp*sin(psi)/(sqrt(3.0_wp)*root)
      case default
         etabar = 3.0_wp*sin(psi)/sqrt(9.0_wp + 3.0_wp*sin(psi)**2)
         root = sqrt(1.0_wp - etabar**2/3.0_wp)
         eta = sin(phi)/(root + etabar*sin(phi)/3.0_wp)
         xi = cos(phi)*(1.0_wp - eta*etabar/3.0_wp)/root
      end select
      ! equal in exact arithmetic; made equal in floating point for a symmetric tangent
      if (psi == phi) etabar = eta
   end subroutine drucker_prager_constants

   pure integer function drucker_prager_nstate(this) result(n)
      class(drucker_prager_t), intent(in) :: this
      n = NSTATE_SOIL
   end function drucker_prager_nstate

   pure subroutine drucker_prager_state_names(this, names)
      class(drucker_prager_t), intent(in) :: this
      character(len=16), allocatable, intent(out) :: names(:)
      allocate (names(NSTATE_SOIL))
      names = SOIL_STATE_NAMES
   end subroutine drucker_prager_state_names

   pure subroutine drucker_prager_elastic_tangent(this, tangent)
      class(drucker_prager_t), intent(in) :: this
      real(wp), intent(out) :: tangent(NCOMP, NCOMP)
      tangent = soil_hooke(this%soil)
   end subroutine drucker_prager_elastic_tangent

   !> Symmetric for associated flow (psi = phi).
   pure logical function drucker_prager_symmetric_tangent(this)
      class(drucker_prager_t), intent(in) :: this
      drucker_prager_symmetric_tangent = this%eta == this%etabar
   end function drucker_prager_symmetric_tangent

   pure real(wp) function drucker_prager_yield(this, stress) result(f)
      class(drucker_prager_t), intent(in) :: this
      real(wp), intent(in) :: stress(NCOMP)
      real(wp) :: p, dev(NCOMP)
      p = sum(stress(1:3))/3.0_wp
      dev = stress - p*[1.0_wp, 1.0_wp, 1.0_wp, 0.0_wp]
      f = sqrt(0.5_wp*(sum(dev(1:3)**2) + 2.0_wp*dev(4)**2)) + this%eta*p &
         - this%xi*this%soil%cohesion
   end function drucker_prager_yield

   !> Perfect plasticity makes the cone return linear in dgamma:
   !> sqrt(J2) = sqrt(J2_trial) - G dgamma, p = p_trial - K etabar dgamma, f = 0 gives
   !> dgamma = f_trial / (G + K eta etabar); if sqrt(J2) would be negative the stress goes
   !> to the apex p = xi c / eta (tangent 0).
   subroutine drucker_prager_update(this, stress_old, dstrain, state, stress, tangent, error)
      class(drucker_prager_t), intent(in) :: this
      real(wp), intent(in) :: stress_old(NCOMP), dstrain(NCOMP)
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: stress(NCOMP), tangent(NCOMP, NCOMP)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: m(NCOMP) = [1.0_wp, 1.0_wp, 1.0_wp, 0.0_wp]
      real(wp) :: de(NCOMP, NCOMP), dd(NCOMP, NCOMP), trial(NCOMP), dev(NCOMP), n(NCOMP)
      real(wp) :: p, j2, f, dgam, g, k, u(NCOMP), v(NCOMP), snorm
      integer :: i

      de = soil_hooke(this%soil)
      trial = stress_old + matmul(de, dstrain)
      f = this%yield(trial)
      if (.not. (f > 0.0_wp)) then
         stress = trial
         tangent = de
         state(6) = real(RETURN_ELASTIC, wp)
         return
      end if
      g = this%soil%shear; k = this%soil%bulk
      p = sum(trial(1:3))/3.0_wp
      dev = trial - p*m
      snorm = sqrt(sum(dev(1:3)**2) + 2.0_wp*dev(4)**2)
      j2 = snorm/sqrt(2.0_wp)
      dgam = f/(g + k*this%eta*this%etabar)
      if (j2 - g*dgam >= 0.0_wp) then
         stress = dev*(1.0_wp - g*dgam/j2) + (p - k*this%etabar*dgam)*m
         n = dev/snorm
         ! deviatoric elasticity 2G I_dev (engineering shear: G on the shear term)
         dd = 0.0_wp
         dd(1:3, 1:3) = -2.0_wp*g/3.0_wp
         do i = 1, 3
            dd(i, i) = 4.0_wp*g/3.0_wp
         end do
         dd(4, 4) = g
         u = sqrt(2.0_wp)*g*n + k*this%etabar*m
         v = sqrt(2.0_wp)*g*n + k*this%eta*m
         tangent = (1.0_wp - g*dgam/j2)*dd + 2.0_wp*g*g*dgam/j2*outer(n, n) &
            + k*outer(m, m) - outer(u, v)/(g + k*this%eta*this%etabar)
         call soil_plastic_state(this%soil, trial, stress, RETURN_SMOOTH, state)
      else
         stress = this%xi*this%soil%cohesion/this%eta*m
         tangent = 0.0_wp
         call soil_plastic_state(this%soil, trial, stress, RETURN_APEX, state)
      end if
   end subroutine drucker_prager_update

   pure function outer(x, y) result(a)
      real(wp), intent(in) :: x(:), y(:)
      real(wp) :: a(size(x), size(y))
      a = spread(x, 2, size(y))*spread(y, 1, size(x))
   end function outer

   subroutine drucker_prager_reduced_strength(this, msf, reduced)
      class(drucker_prager_t), intent(in) :: this
      real(wp), intent(in) :: msf
      class(material_t), allocatable, intent(out) :: reduced
      allocate (reduced, source=this)
      select type (r => reduced)
      class is (drucker_prager_t)
         r%soil = reduce_soil(this%soil, msf)
         call drucker_prager_constants(r%match, r%soil%phi, r%soil%psi, r%eta, r%xi, r%etabar)
      end select
   end subroutine drucker_prager_reduced_strength

   !> A copy with the cohesion c (the soil's other parameters kept).
   subroutine drucker_prager_with_cohesion(this, cohesion, copy, error)
      class(drucker_prager_t), intent(in) :: this
      real(wp), intent(in) :: cohesion
      class(material_t), allocatable, intent(out) :: copy
      type(error_t), allocatable, intent(out) :: error
      allocate (copy, source=this)
      select type (copy)
      class is (drucker_prager_t)
         copy%soil%cohesion = cohesion
      end select
   end subroutine drucker_prager_with_cohesion

end module pecplas_massif_materials_drucker_prager
