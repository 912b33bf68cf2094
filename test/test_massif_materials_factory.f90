!> Material factory and registry: built-in types, unknown types listed in the error, and a
!> user type registered by the caller, used from a deck.
module test_massif_materials_factory
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, ERR_INPUT
   use pecplas_base_params, only: params_t
   use pecplas_model_type, only: model_t
   use pecplas_massif_materials_type, only: material_t
   use pecplas_massif_materials_elastic, only: elastic_t, new_elastic
   use pecplas_massif_materials_factory, only: material_registry_t, default_material_registry, &
      register_material, new_material, KNOWN_MATERIALS
   use pecplas_io_deck_reader, only: read_deck, read_deck_with
   use pecplas_testing, only: unittest_t, new_unittest, check, near
   use test_io_deck, only: DECKS
   implicit none (type, external)
   private
   public :: collect_massif_materials_factory

contains

   subroutine collect_massif_materials_factory(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('known_materials', test_known), &
               new_unittest('build_elastic', test_build), &
               new_unittest('unknown_type', test_unknown), &
               new_unittest('user_material', test_user), &
               new_unittest('user_material_in_deck', test_user_deck)]
   end subroutine collect_massif_materials_factory

   function sample() result(p)
      type(params_t) :: p
      p%file = 'deck.inp'; p%line = 4; p%keyword = '*MATERIAL'
      call p%add('E', 3.0e4_wp)
      call p%add('NU', 0.25_wp)
   end function sample

   !> A user material: elastic with NU fixed at 0.2 and E given as STIFFNESS.
   subroutine build_user_linear(name, params, mat, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(material_t), allocatable, intent(out) :: mat
      type(error_t), allocatable, intent(out) :: error
      type(params_t) :: p
      real(wp) :: stiffness
      call params%unknown_keys([character(len=9) :: 'STIFFNESS'], error)
      if (allocated(error)) return
      call params%get('STIFFNESS', stiffness, error)
      if (allocated(error)) return
      p = params
      deallocate (p%keys, p%values)
      call p%add('E', stiffness)
      call p%add('NU', 0.2_wp)
      allocate (elastic_t :: mat)
      select type (mat)
      type is (elastic_t)
         call new_elastic(mat, name, p, error)
      end select
   end subroutine build_user_linear

   subroutine test_known(error)
      type(error_t), allocatable, intent(out) :: error
      type(material_registry_t) :: registry
      integer :: i
      character(len=:), allocatable :: expected
      registry = default_material_registry()
      expected = ''
      do i = 1, size(KNOWN_MATERIALS)
         expected = expected//' '//trim(KNOWN_MATERIALS(i))
      end do
      ! KNOWN_MATERIALS documents the default registry: both must list the same types
      call check(error, registry%names() == expected, 'registry '//registry%names()// &
         ' vs KNOWN_MATERIALS'//expected)
   end subroutine test_known

   subroutine test_build(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: mat
      call new_material('Elastic', 'sand', sample(), mat, error)
      if (allocated(error)) return
      select type (mat)
      type is (elastic_t)
         call check(error, mat%name == 'sand' .and. near(mat%young, 3.0e4_wp) .and. &
            near(mat%poisson, 0.25_wp), 'parameters passed through')
      class default
         call check(error, .false., 'ELASTIC must build an elastic_t')
      end select
   end subroutine test_build

   subroutine test_unknown(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      class(material_t), allocatable :: mat
      call new_material('MOHR', 'x', sample(), mat, e)
      call check(error, allocated(e), 'unknown type is an error')
      if (allocated(error)) return
      call check(error, e%kind == ERR_INPUT .and. index(e%text(), 'deck.inp:4') > 0 .and. &
         index(e%message, "'MOHR'") > 0 .and. index(e%message, 'known types: ELASTIC') > 0, &
         'message names the position and lists the types: '//e%text())
   end subroutine test_unknown

   subroutine test_user(error)
      type(error_t), allocatable, intent(out) :: error
      type(material_registry_t) :: registry
      class(material_t), allocatable :: mat
      type(params_t) :: p
      character(len=:), allocatable :: expected
      integer :: i
      registry = default_material_registry()
      call register_material(registry, 'user_linear', build_user_linear)
      expected = ''
      do i = 1, size(KNOWN_MATERIALS)
         expected = expected//' '//trim(KNOWN_MATERIALS(i))
      end do
      call check(error, registry%names() == expected//' USER_LINEAR', 'registered: '// &
         registry%names())
      if (allocated(error)) return
      p%file = 'deck.inp'; p%line = 1; p%keyword = '*MATERIAL'
      call p%add('STIFFNESS', 5.0e3_wp)
      call registry%new_material('USER_LINEAR', 'mine', p, mat, error)
      if (allocated(error)) return
      select type (mat)
      type is (elastic_t)
         call check(error, near(mat%young, 5.0e3_wp) .and. near(mat%poisson, 0.2_wp), &
            'user builder')
      class default
         call check(error, .false., 'elastic_t expected')
      end select
   end subroutine test_user

   subroutine test_user_deck(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(material_registry_t) :: registry
      type(model_t) :: model
      ! without the registration the type is unknown at the *MATERIAL line
      call read_deck(DECKS//'good_user_material.inp', model, e)
      call check(error, allocated(e), 'USER_LINEAR unknown to the default registry')
      if (allocated(error)) return
      call check(error, e%line == 10 .and. index(e%message, 'USER_LINEAR') > 0, e%text())
      if (allocated(error)) return
      registry = default_material_registry()
      call registry%register('USER_LINEAR', build_user_linear)
      call read_deck_with(DECKS//'good_user_material.inp', registry, model, e)
      call check(error, .not. allocated(e), 'deck with a user material')
      if (allocated(error)) then
         error%message = error%message//': '//e%text()
         return
      end if
      select type (m => model%materials(1)%m)
      type is (elastic_t)
         call check(error, near(m%young, 7.5e3_wp) .and. near(m%poisson, 0.2_wp), 'STIFFNESS read')
      class default
         call check(error, .false., 'elastic_t expected')
      end select
   end subroutine test_user_deck

end module test_massif_materials_factory
