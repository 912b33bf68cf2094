!> Spring (ressort) law after Herrmann and Frank (thesis §I.2.1.1 2°, (I.9)–(I.10), Annex B
!> (B.13)–(B.18)): penalty springs on a node doublet enforcing two, one or no continuity of
!> displacement, on the Coulomb kernel (pecplas_joints_laws_coulomb):
!>
!> - stick: both springs, lambda_n = K_n dU_n, lambda_t = K_t dU_t (I.9);
!> - slip: normal spring only, the tangential force capped at c + sigma_n tan(phi) (no
!>   dilatancy); a smooth interface (neither PHI nor C given) has tau = 0 whenever it moves;
!> - open (sigma_n would become tensile): no spring, zero force; re-contact when closed again.
!>
!> The law works on force per tributary measure (length in plane strain, area in
!> axisymmetry): the spring element divides its forces by the tributary measure and hands
!> the law dU, so c is a force per tributary measure and K_n, K_t are per tributary measure.
!>
!> Penalty (I.10): K = 1e5 E_RYG R_max with E_RYG <= 1 the ratio of the Young moduli of the
!> two bodies and R_max the largest diagonal term of the massif stiffness. When KN or KT is
!> absent (or 0) the law is built with `needs_penalty = .true.`; the FE setup then computes
!> `default_penalty(r_max)` and calls `set_penalty(kn, kt)`, which fills the stiffnesses not
!> given in the deck. `update` refuses to run before that.
!>
!> Deck: KN, KT (>= 0, 0 or absent = default penalty), E_RYG (0 < E_RYG <= 1, default 1),
!> PHI (degrees, 0 <= PHI < 90, default 0), C (>= 0, default 0).
module pecplas_joints_laws_spring
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_joints_laws_coulomb, only: coulomb_law_t, coulomb_update
   use pecplas_joints_laws_checks, only: get_param, tan_deg
   implicit none (type, external)
   private

   public :: spring_law_t, build_spring_law

   type, extends(coulomb_law_t) :: spring_law_t
      !> Ratio of the Young moduli of the two bodies in (I.10).
      real(wp) :: e_ryg = 1.0_wp
      !> Friction angle (degrees) as given.
      real(wp) :: phi = 0.0_wp
      !> True until set_penalty has supplied the stiffnesses not given in the deck.
      logical :: needs_penalty = .false.
      !> Which stiffnesses the deck gave (set_penalty leaves those alone).
      logical :: kn_given = .false., kt_given = .false.
      !> Neither PHI nor C given: frictionless contact (tau = 0 in slip).
      logical :: smooth = .false.
   contains
      procedure :: update => spring_update
      !> Fills the stiffnesses not given in the deck (the FE setup calls it once).
      procedure :: set_penalty => spring_set_penalty
      !> Frank's default penalty 1e5 E_RYG R_max (I.10).
      procedure :: default_penalty => spring_default_penalty
   end type spring_law_t

contains

   subroutine build_spring_law(name, params, law, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(spring_law_t) :: s
      call params%unknown_keys([character(len=5) :: 'KN', 'KT', 'E_RYG', 'PHI', 'C'], error)
      if (allocated(error)) return
      s%name = name
      call get_param(params, 'KN', s%kn, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'KT', s%kt, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      call get_param(params, 'E_RYG', s%e_ryg, error, default=1.0_wp, gt=0.0_wp, le=1.0_wp)
      if (allocated(error)) return
      call get_param(params, 'PHI', s%phi, error, default=0.0_wp, ge=0.0_wp, lt=90.0_wp)
      if (allocated(error)) return
      call get_param(params, 'C', s%c, error, default=0.0_wp, ge=0.0_wp)
      if (allocated(error)) return
      s%kn_given = s%kn > 0.0_wp
      s%kt_given = s%kt > 0.0_wp
      s%needs_penalty = .not. (s%kn_given .and. s%kt_given)
      s%smooth = .not. (params%has('PHI') .or. params%has('C'))
      s%mu_f = tan_deg(s%phi)
      s%mu_g = 0.0_wp
      s%tension = 0.0_wp
      s%kt_slip = 0.0_wp
      allocate (law, source=s)
   end subroutine build_spring_law

   pure real(wp) function spring_default_penalty(this, r_max) result(k)
      class(spring_law_t), intent(in) :: this
      !> Largest diagonal term of the massif stiffness.
      real(wp), intent(in) :: r_max
      k = 1.0e5_wp*this%e_ryg*r_max
   end function spring_default_penalty

   subroutine spring_set_penalty(this, kn, kt)
      class(spring_law_t), intent(inout) :: this
      real(wp), intent(in) :: kn, kt
      if (.not. this%kn_given) this%kn = kn
      if (.not. this%kt_given) this%kt = kt
      this%needs_penalty = .not. (this%kn > 0.0_wp .and. this%kt > 0.0_wp)
   end subroutine spring_set_penalty

   subroutine spring_update(this, sigma_old, deps, state, sigma, tangent, mode, error)
      class(spring_law_t), intent(in) :: this
      real(wp), intent(in) :: sigma_old(2), deps(2)
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: sigma(2), tangent(2, 2)
      integer, intent(out) :: mode
      type(error_t), allocatable, intent(out) :: error
      if (this%needs_penalty) then
         sigma = sigma_old
         tangent = 0.0_wp
         mode = 0
         call fatal_error(error, "spring law '"//this%name//"': penalty stiffness not set "// &
            '(give KN and KT, or the FE setup must call set_penalty with 1e5 E_RYG R_max)')
         return
      end if
      call coulomb_update(this, sigma_old, deps, state, sigma, tangent, mode, error)
   end subroutine spring_update

end module pecplas_joints_laws_spring
