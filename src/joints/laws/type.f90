!> The PECJOIN dispatch: abstract interface law. Every law maps a relative-displacement
!> increment and its stored state to the interface stress, a tangent and a contact mode.
!>
!> Conventions (soil mechanics, doc/theory.md §6): strain-like vector eps = (eps_n, eps_t) with the
!> normal relative displacement **closure positive** (eps_n = -g_n, g_n the opening of (B.8)
!> row 1) and eps_t = U_t(2) - U_t(1); stress vector sigma = (sigma_n, tau) with sigma_n
!> **compression positive**. So d sigma = C d eps with C = diag(K_n, K_t) in the elastic range.
!> Joint elements (Goodman, thin layer) give eps per unit area (a displacement jump; divided
!> by the thickness for a thin layer), springs give force / tributary measure.
module pecplas_joints_laws_type
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   implicit none (type, external)
   private

   public :: interface_law_t, interface_law_box_t
   public :: MODE_STICK, MODE_SLIP, MODE_OPEN, MODE_NAMES

   !> Contact modes (I.3–I.5): adhesion, slip, separation.
   integer, parameter :: MODE_STICK = 1, MODE_SLIP = 2, MODE_OPEN = 3
   character(len=*), parameter :: MODE_NAMES(3) = [character(len=5) :: 'stick', 'slip', 'open']

   type, abstract :: interface_law_t
      !> Name given in the deck (*INTERFACE_LAW, NAME=...).
      character(len=:), allocatable :: name
   contains
      !> Number of history variables per integration point (may be 0).
      procedure(nstate_ifc), deferred :: nstate
      !> Initialises the history of a point from its initial stress (e.g. MODJOIN's sigma_n0).
      procedure(init_ifc), deferred :: init_state
      !> Elastic (initial) tangent for modified Newton, given the current state.
      procedure(elastic_ifc), deferred :: elastic_tangent
      !> Stress update from the converged stress/state and the increment deps of eps;
      !> tangent = d sigma / d eps consistent with the update; mode after the update.
      procedure(update_ifc), deferred :: update
      !> False when the tangent can be non-symmetric (the solver then uses UMFPACK).
      procedure :: symmetric_tangent => law_symmetric_tangent
      !> Why the law cannot work on strains (jump / thickness) as a thin layer passes them
      !> ('' when it can: stiffnesses alone scale with the thickness).
      procedure :: strain_refusal => law_strain_refusal
      !> Accumulated plastic slip sum |d eps_t^p| of a point with history `state` (for the
      !> results; 0 for a law without one).
      procedure :: plastic_slip => law_plastic_slip
      !> Names of the history variables (for the results file; none by default).
      procedure :: state_names => law_state_names
      !> One line describing the law as built (e.g. unit conversions); '' by default.
      procedure :: describe => law_describe
      !> The law with its strength divided by `msf` (strength reduction, doc/theory.md,
      !> Factor of safety); unallocated for a law whose strength is not a c, tan(phi) pair
      !> (the default).
      procedure :: reduced_strength => law_reduced_strength
   end type interface_law_t

   type :: interface_law_box_t
      class(interface_law_t), allocatable :: law
   end type interface_law_box_t

   abstract interface
      pure integer function nstate_ifc(this)
         import :: interface_law_t
         class(interface_law_t), intent(in) :: this
      end function nstate_ifc

      subroutine init_ifc(this, sigma0, state)
         import :: interface_law_t, wp
         class(interface_law_t), intent(in) :: this
         !> Initial (sigma_n, tau) of the point.
         real(wp), intent(in) :: sigma0(2)
         real(wp), intent(out) :: state(:)
      end subroutine init_ifc

      subroutine elastic_ifc(this, state, tangent)
         import :: interface_law_t, wp
         class(interface_law_t), intent(in) :: this
         real(wp), intent(in) :: state(:)
         real(wp), intent(out) :: tangent(2, 2)
      end subroutine elastic_ifc

      subroutine update_ifc(this, sigma_old, deps, state, sigma, tangent, mode, error)
         import :: interface_law_t, wp, error_t
         class(interface_law_t), intent(in) :: this
         real(wp), intent(in) :: sigma_old(2), deps(2)
         !> History: in = converged values, out = updated values.
         real(wp), intent(inout) :: state(:)
         real(wp), intent(out) :: sigma(2), tangent(2, 2)
         integer, intent(out) :: mode
         type(error_t), allocatable, intent(out) :: error
      end subroutine update_ifc
   end interface

contains

   pure logical function law_symmetric_tangent(this)
      class(interface_law_t), intent(in) :: this
      law_symmetric_tangent = .true.
   end function law_symmetric_tangent

   pure function law_strain_refusal(this) result(why)
      class(interface_law_t), intent(in) :: this
      character(len=:), allocatable :: why
      why = ''
   end function law_strain_refusal

   pure real(wp) function law_plastic_slip(this, state) result(slip)
      class(interface_law_t), intent(in) :: this
      real(wp), intent(in) :: state(:)
      slip = 0.0_wp
   end function law_plastic_slip

   pure subroutine law_state_names(this, names)
      class(interface_law_t), intent(in) :: this
      character(len=16), allocatable, intent(out) :: names(:)
      allocate (names(0))
   end subroutine law_state_names

   function law_describe(this) result(text)
      class(interface_law_t), intent(in) :: this
      character(len=:), allocatable :: text
      text = ''
   end function law_describe

   subroutine law_reduced_strength(this, msf, reduced)
      class(interface_law_t), intent(in) :: this
      real(wp), intent(in) :: msf
      class(interface_law_t), allocatable, intent(out) :: reduced
   end subroutine law_reduced_strength

end module pecplas_joints_laws_type
