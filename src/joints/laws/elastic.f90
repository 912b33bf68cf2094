!> Linear elastic interface: sigma_n = K_n eps_n, tau = K_t eps_t (bonded, never slips).
module pecplas_joints_laws_elastic
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_type, only: interface_law_t, MODE_STICK
   implicit none (type, external)
   private

   public :: elastic_law_t, build_elastic_law

   type, extends(interface_law_t) :: elastic_law_t
      real(wp) :: kn = 0.0_wp, kt = 0.0_wp
   contains
      procedure :: nstate => elastic_nstate
      procedure :: init_state => elastic_init_state
      procedure :: elastic_tangent => elastic_elastic_tangent
      procedure :: update => elastic_update
   end type elastic_law_t

contains

   !> Deck parameters KN, KT (both > 0).
   subroutine build_elastic_law(name, params, law, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(elastic_law_t) :: e
      call params%unknown_keys([character(len=2) :: 'KN', 'KT'], error)
      if (allocated(error)) return
      e%name = name
      call params%get('KN', e%kn, error)
      if (allocated(error)) return
      call params%get('KT', e%kt, error)
      if (allocated(error)) return
      if (.not. (e%kn > 0.0_wp .and. e%kt > 0.0_wp)) then
         call deck_error(error, params%file, params%line, params%keyword, &
            'interface stiffnesses KN and KT must be positive')
         return
      end if
      allocate (law, source=e)
   end subroutine build_elastic_law

   pure integer function elastic_nstate(this) result(n)
      class(elastic_law_t), intent(in) :: this
      n = 0
   end function elastic_nstate

   subroutine elastic_init_state(this, sigma0, state)
      class(elastic_law_t), intent(in) :: this
      real(wp), intent(in) :: sigma0(2)
      real(wp), intent(out) :: state(:)
      state = 0.0_wp
   end subroutine elastic_init_state

   subroutine elastic_elastic_tangent(this, state, tangent)
      class(elastic_law_t), intent(in) :: this
      real(wp), intent(in) :: state(:)
      real(wp), intent(out) :: tangent(2, 2)
      tangent = reshape([this%kn, 0.0_wp, 0.0_wp, this%kt], [2, 2])
   end subroutine elastic_elastic_tangent

   subroutine elastic_update(this, sigma_old, deps, state, sigma, tangent, mode, error)
      class(elastic_law_t), intent(in) :: this
      real(wp), intent(in) :: sigma_old(2), deps(2)
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: sigma(2), tangent(2, 2)
      integer, intent(out) :: mode
      type(error_t), allocatable, intent(out) :: error
      call this%elastic_tangent(state, tangent)
      sigma = sigma_old + matmul(tangent, deps)
      mode = MODE_STICK
   end subroutine elastic_update

end module pecplas_joints_laws_elastic
