!> Shared fixtures of the PECJOIN law tests: building a law from KEY = value pairs through
!> the factory (as a deck would), a deterministic random generator, central differences of
!> `update`, and a monotonic tangential loading at fixed normal displacement.
module fixtures_pecjoin
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_joints_laws_factory, only: law_registry_t, default_law_registry
   implicit none (type, external)
   private

   public :: law_params, make_law, lcg_uniform, fd_tangent, max_rel_diff, DECK_FILE, DECK_LINE

   !> Where the test "deck" gives the law parameters (errors must name them).
   character(len=*), parameter :: DECK_FILE = 'laws_test.inp'
   integer, parameter :: DECK_LINE = 7

contains

   !> params_t from parallel key/value lists, positioned at DECK_FILE:DECK_LINE.
   function law_params(keys, values) result(p)
      character(len=*), intent(in) :: keys(:)
      real(wp), intent(in) :: values(:)
      type(params_t) :: p
      integer :: i
      p%file = DECK_FILE
      p%line = DECK_LINE
      p%keyword = '*INTERFACE_LAW'
      allocate (p%keys(0), p%values(0))
      do i = 1, size(keys)
         call p%add(trim(keys(i)), values(i))
      end do
   end function law_params

   !> Law `type_name` built by the default registry from the pairs keys = values.
   subroutine make_law(type_name, keys, values, law, error)
      character(len=*), intent(in) :: type_name, keys(:)
      real(wp), intent(in) :: values(:)
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(law_registry_t) :: registry
      registry = default_law_registry()
      call registry%new_law(type_name, 'j', law_params(keys, values), law, error)
   end subroutine make_law

   !> Uniform number in (0, 1) from the Park–Miller minimal standard generator (no integer
   !> overflow in 64 bits): the same sequence on every machine, unlike random_number.
   real(wp) function lcg_uniform(seed) result(u)
      integer(kind=selected_int_kind(18)), intent(inout) :: seed
      integer(kind=selected_int_kind(18)), parameter :: M = 2147483647
      seed = mod(16807*seed, M)
      u = real(seed, wp)/real(M, wp)
   end function lcg_uniform

   !> Central differences of sigma(deps) = update(sigma_old, deps, state) with step h.
   subroutine fd_tangent(law, sigma_old, state, deps, h, fd, error)
      class(interface_law_t), intent(in) :: law
      real(wp), intent(in) :: sigma_old(2), state(:), deps(2), h
      real(wp), intent(out) :: fd(2, 2)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: sp(2), sm(2), st(size(state)), t(2, 2), e(2)
      integer :: j, mode
      do j = 1, 2
         e = 0.0_wp
         e(j) = h
         st = state
         call law%update(sigma_old, deps + e, st, sp, t, mode, error)
         if (allocated(error)) return
         st = state
         call law%update(sigma_old, deps - e, st, sm, t, mode, error)
         if (allocated(error)) return
         fd(:, j) = (sp - sm)/(2.0_wp*h)
      end do
   end subroutine fd_tangent

   !> max |a - b| / max |b| (entrywise, relative to the largest entry of b).
   pure real(wp) function max_rel_diff(a, b) result(r)
      real(wp), intent(in) :: a(2, 2), b(2, 2)
      r = maxval(abs(a - b))/max(maxval(abs(b)), tiny(1.0_wp))
   end function max_rel_diff

end module fixtures_pecjoin
