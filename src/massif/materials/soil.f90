!> What the elastoplastic soil materials (Mohr–Coulomb, Drucker–Prager) share: the deck
!> parameters E, NU, C, PHI, PSI, GAMMA with their checks, isotropic elasticity (stiffness and
!> compliance) and the history layout of a point.
!>
!> History of a point (`state(:)`, NSTATE_SOIL values): 1-4 plastic strain (xx, yy, zz, xy,
!> engineering shear), 5 accumulated equivalent plastic strain sum sqrt(2/3 dep:dep),
!> 6 kind of the last return (RETURN_ELASTIC, RETURN_SMOOTH, RETURN_EDGE, RETURN_APEX).
module pecplas_massif_materials_soil
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_base_params, only: params_t
   use pecplas_massif_materials_type, only: NCOMP
   implicit none (type, external)
   private

   public :: soil_params_t, read_soil_params, soil_hooke, soil_plastic_state, reduce_soil
   public :: NSTATE_SOIL, SOIL_STATE_NAMES, RETURN_ELASTIC, RETURN_SMOOTH, RETURN_EDGE, RETURN_APEX

   !> Number of history values of a soil point.
   integer, parameter :: NSTATE_SOIL = 6
   !> Names of the history values (results file `state_names`), in the order above.
   character(len=*), parameter :: SOIL_STATE_NAMES(NSTATE_SOIL) = [character(len=11) :: &
      'eps_p_xx', 'eps_p_yy', 'eps_p_zz', 'eps_p_xy', 'eps_p_eq', 'return_kind']
   !> Kinds of return, stored in state(6): elastic, one active surface (smooth part of the
   !> cone, Mohr–Coulomb main plane or tension plane), two (edge), three or the apex.
   integer, parameter :: RETURN_ELASTIC = 0, RETURN_SMOOTH = 1, RETURN_EDGE = 2, RETURN_APEX = 3

   !> Elastic constants and strength of a perfectly plastic soil; angles in radians.
   type :: soil_params_t
      real(wp) :: young = 0.0_wp, poisson = 0.0_wp
      !> Lamé's lambda, shear modulus G and bulk modulus K.
      real(wp) :: lambda = 0.0_wp, shear = 0.0_wp, bulk = 0.0_wp
      !> Cohesion c, friction angle phi, dilatancy angle psi.
      real(wp) :: cohesion = 0.0_wp, phi = 0.0_wp, psi = 0.0_wp
      real(wp) :: unit_weight = 0.0_wp
   end type soil_params_t

contains

   !> Reads E, NU, C, PHI, PSI (degrees) and optional GAMMA from `params`, which may hold
   !> only those and the material's own `extra` keys. Checks E > 0, -1 < NU < 0.5, C >= 0,
   !> 0 <= PHI < 90, 0 <= PSI <= PHI and C > 0 or PHI > 0 (a soil with some strength).
   subroutine read_soil_params(params, extra, soil, error)
      type(params_t), intent(in) :: params
      character(len=*), intent(in) :: extra(:)
      type(soil_params_t), intent(out) :: soil
      type(error_t), allocatable, intent(out) :: error
      character(len=16), allocatable :: known(:)
      real(wp) :: phi_deg, psi_deg
      real(wp), parameter :: DEG = acos(-1.0_wp)/180.0_wp
      integer :: i

      known = [character(len=16) :: 'E', 'NU', 'C', 'PHI', 'PSI', 'GAMMA']
      do i = 1, size(extra)
         known = [character(len=16) :: known, extra(i)]
      end do
      call params%unknown_keys(known, error)
      if (allocated(error)) return
      call params%get('E', soil%young, error)
      if (allocated(error)) return
      call params%get('NU', soil%poisson, error)
      if (allocated(error)) return
      call params%get('C', soil%cohesion, error)
      if (allocated(error)) return
      call params%get('PHI', phi_deg, error)
      if (allocated(error)) return
      call params%get('PSI', psi_deg, error)
      if (allocated(error)) return
      call params%get('GAMMA', soil%unit_weight, error, default=0.0_wp)
      if (allocated(error)) return

      if (.not. (soil%young > 0.0_wp)) then
         call bad('Young modulus E must be positive, got '//num(soil%young))
      else if (.not. (soil%poisson > -1.0_wp .and. soil%poisson < 0.5_wp)) then
         call bad('Poisson ratio NU must satisfy -1 < NU < 0.5, got '//num(soil%poisson))
      else if (.not. (soil%cohesion >= 0.0_wp)) then
         call bad('cohesion C must not be negative, got '//num(soil%cohesion))
      else if (.not. (phi_deg >= 0.0_wp .and. phi_deg < 90.0_wp)) then
         call bad('friction angle PHI (degrees) must satisfy 0 <= PHI < 90, got '//num(phi_deg))
      else if (.not. (psi_deg >= 0.0_wp .and. psi_deg <= phi_deg)) then
         call bad('dilatancy angle PSI (degrees) must satisfy 0 <= PSI <= PHI, got '// &
            num(psi_deg)//' with PHI = '//num(phi_deg))
      else if (.not. (soil%cohesion > 0.0_wp .or. phi_deg > 0.0_wp)) then
         call bad('a soil needs some strength: C > 0 or PHI > 0 (both are 0)')
      else if (.not. (soil%unit_weight >= 0.0_wp)) then
         call bad('unit weight GAMMA must not be negative')
      end if
      if (allocated(error)) return
      soil%phi = phi_deg*DEG
      soil%psi = psi_deg*DEG
      soil%shear = soil%young/(2.0_wp*(1.0_wp + soil%poisson))
      soil%lambda = soil%young*soil%poisson/((1.0_wp + soil%poisson)*(1.0_wp - 2.0_wp*soil%poisson))
      soil%bulk = soil%lambda + 2.0_wp*soil%shear/3.0_wp
   contains
      subroutine bad(message)
         character(len=*), intent(in) :: message
         call deck_error(error, params%file, params%line, params%keyword, message)
      end subroutine bad
   end subroutine read_soil_params

   !> Strength reduction by msf (doc/theory.md, Factor of safety): c / msf, tan(phi) / msf, and the
   !> dilatancy angle kept unless the reduced friction angle falls below it, where it follows
   !> it (psi_r = min(psi, phi_r), as PLAXIS does).
   pure function reduce_soil(soil, msf) result(r)
      type(soil_params_t), intent(in) :: soil
      real(wp), intent(in) :: msf
      type(soil_params_t) :: r
      r = soil
      r%cohesion = soil%cohesion/msf
      r%phi = atan(tan(soil%phi)/msf)
      r%psi = min(soil%psi, r%phi)
   end function reduce_soil

   !> Hooke matrix for (xx, yy, zz, xy) with engineering shear strain.
   pure function soil_hooke(soil) result(d)
      type(soil_params_t), intent(in) :: soil
      real(wp) :: d(NCOMP, NCOMP)
      integer :: i
      d = 0.0_wp
      d(1:3, 1:3) = soil%lambda
      do i = 1, 3
         d(i, i) = soil%lambda + 2.0_wp*soil%shear
      end do
      d(4, 4) = soil%shear
   end function soil_hooke

   !> Adds the plastic strain of a return from `trial` to `stress` to the history:
   !> dep = C^-1 (trial - stress) (exact for any return, since stress = trial - C dep),
   !> its equivalent measure sqrt(2/3 dep:dep) and the kind of return.
   pure subroutine soil_plastic_state(soil, trial, stress, kind, state)
      type(soil_params_t), intent(in) :: soil
      real(wp), intent(in) :: trial(NCOMP), stress(NCOMP)
      integer, intent(in) :: kind
      real(wp), intent(inout) :: state(:)
      real(wp) :: ds(NCOMP), dep(NCOMP), tr
      ds = trial - stress
      tr = sum(ds(1:3))
      dep(1:3) = ((1.0_wp + soil%poisson)*ds(1:3) - soil%poisson*tr)/soil%young
      dep(4) = ds(4)/soil%shear
      state(1:4) = state(1:4) + dep
      ! tensor norm: the engineering shear counts as twice the tensor component
      state(5) = state(5) + sqrt(2.0_wp/3.0_wp*(sum(dep(1:3)**2) + 0.5_wp*dep(4)**2))
      state(6) = real(kind, wp)
   end subroutine soil_plastic_state

   !> Short text of a number for messages.
   function num(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=24) :: buf
      write (buf, '(g12.5)') x
      s = trim(adjustl(buf))
   end function num

end module pecplas_massif_materials_soil
