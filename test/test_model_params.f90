!> Deck parameter lists: lookup, defaults, and errors that name the missing or unknown key.
module test_model_params
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_params, only: params_t
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_model_params

contains

   subroutine collect_model_params(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('lookup', test_lookup), &
               new_unittest('missing_names_key', test_missing), &
               new_unittest('unknown_lists_known', test_unknown)]
   end subroutine collect_model_params

   function sample() result(p)
      type(params_t) :: p
      p%file = 'deck.inp'; p%line = 7; p%keyword = '*MATERIAL'
      call p%add('e', 2.0e4_wp)
      call p%add('Nu', 0.3_wp)
   end function sample

   subroutine test_lookup(error)
      type(error_t), allocatable, intent(out) :: error
      type(params_t) :: p
      real(wp) :: v
      p = sample()
      call p%get('NU', v, error)
      if (allocated(error)) return
      ! keys are case-insensitive; the stored value comes back bit for bit
      call check_close(error, v, 0.3_wp, 0.0_wp, 'NU read back')
      if (allocated(error)) return
      call p%get('GAMMA', v, error, default=18.0_wp)
      if (allocated(error)) return
      call check_close(error, v, 18.0_wp, 0.0_wp, 'default used when absent')
   end subroutine test_lookup

   subroutine test_missing(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(params_t) :: p
      real(wp) :: v
      p = sample()
      call p%get('GAMMA', v, e)
      call check(error, allocated(e), 'missing key must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'deck.inp:7') > 0 .and. index(e%text(), 'GAMMA') > 0, &
         'message names file:line and key: '//e%text())
   end subroutine test_missing

   subroutine test_unknown(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(params_t) :: p
      p = sample()
      call p%add('NUU', 0.2_wp)
      call p%unknown_keys([character(len=2) :: 'E', 'NU'], e)
      call check(error, allocated(e), 'typo NUU must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'NUU') > 0 .and. index(e%text(), 'known parameters: E NU') > 0, &
         'message lists known keys: '//e%text())
   end subroutine test_unknown

end module test_model_params
