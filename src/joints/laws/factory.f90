!> Interface-law factory (PECJOIN dispatch): maps a deck type name
!> (*INTERFACE_LAW, TYPE=...) to a builder. The registry is an object owned by the caller
!> (no global state): start from `default_law_registry()` and add user laws with
!> `register_law` (the Abaqus UINTER habit) without editing this file. A built-in law is
!> one `register` line in `default_law_registry`, with a builder in the law's own module.
module pecplas_joints_laws_factory
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_joints_laws_elastic, only: build_elastic_law
   use pecplas_base_strings, only: upper
   use pecplas_joints_laws_goodman, only: build_goodman_law
   use pecplas_joints_laws_spring, only: build_spring_law
   use pecplas_joints_laws_ghaboussi, only: build_ghaboussi_law
   use pecplas_joints_laws_mohr_coulomb, only: build_mohr_coulomb_law
   use pecplas_joints_laws_modjoin_build, only: build_modjoin_initial_law, build_modjoin_law, &
      build_modjoin_cyclic_law
   implicit none (type, external)
   private

   public :: law_builder_ifc, law_registry_t, default_law_registry, register_law

   abstract interface
      !> Builds law `name` from its deck parameters (checking them).
      subroutine law_builder_ifc(name, params, law, error)
         import :: params_t, interface_law_t, error_t
         character(len=*), intent(in) :: name
         type(params_t), intent(in) :: params
         class(interface_law_t), allocatable, intent(out) :: law
         type(error_t), allocatable, intent(out) :: error
      end subroutine law_builder_ifc
   end interface

   type :: law_entry_t
      character(len=:), allocatable :: name
      procedure(law_builder_ifc), pointer, nopass :: build => null()
   end type law_entry_t

   type :: law_registry_t
      type(law_entry_t), allocatable :: entries(:)
   contains
      procedure :: register => registry_register
      procedure :: new_law => registry_new_law
      procedure :: names => registry_names
   end type law_registry_t

contains

   !> Registry of the built-in interface laws.
   function default_law_registry() result(registry)
      type(law_registry_t) :: registry
      allocate (registry%entries(0))
      call registry%register('ELASTIC', build_elastic_law)
      call registry%register('GOODMAN', build_goodman_law)
      call registry%register('SPRING', build_spring_law)
      call registry%register('GHABOUSSI', build_ghaboussi_law)
      call registry%register('MOHR_COULOMB', build_mohr_coulomb_law)
      call registry%register('MODJOIN_INITIAL', build_modjoin_initial_law)
      call registry%register('MODJOIN', build_modjoin_law)
      call registry%register('MODJOIN_CYCLIC', build_modjoin_cyclic_law)
   end function default_law_registry

   subroutine register_law(registry, name, builder)
      type(law_registry_t), intent(inout) :: registry
      character(len=*), intent(in) :: name
      procedure(law_builder_ifc) :: builder
      call registry%register(name, builder)
   end subroutine register_law

   !> Adds (or replaces) the builder of type `name` (case-insensitive).
   subroutine registry_register(this, name, builder)
      class(law_registry_t), intent(inout) :: this
      character(len=*), intent(in) :: name
      procedure(law_builder_ifc) :: builder
      type(law_entry_t), allocatable :: tmp(:)
      integer :: i, n
      if (.not. allocated(this%entries)) allocate (this%entries(0))
      do i = 1, size(this%entries)
         if (this%entries(i)%name == upper(name)) then
            this%entries(i)%build => builder
            return
         end if
      end do
      n = size(this%entries)
      allocate (tmp(n + 1))
      do i = 1, n
         tmp(i)%name = this%entries(i)%name
         tmp(i)%build => this%entries(i)%build
      end do
      tmp(n + 1)%name = upper(name)
      tmp(n + 1)%build => builder
      call move_alloc(tmp, this%entries)
   end subroutine registry_register

   !> Builds a law of type `type_name`; an unknown type lists the known ones.
   subroutine registry_new_law(this, type_name, name, params, law, error)
      class(law_registry_t), intent(in) :: this
      character(len=*), intent(in) :: type_name, name
      type(params_t), intent(in) :: params
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      do i = 1, size(this%entries)
         if (this%entries(i)%name == upper(type_name)) then
            call this%entries(i)%build(name, params, law, error)
            return
         end if
      end do
      call deck_error(error, params%file, params%line, params%keyword, "unknown interface law '"// &
         trim(type_name)//"'; known laws:"//this%names())
   end subroutine registry_new_law

   !> ' ELASTIC GOODMAN ...' (for messages).
   function registry_names(this) result(list)
      class(law_registry_t), intent(in) :: this
      character(len=:), allocatable :: list
      integer :: i
      list = ''
      do i = 1, size(this%entries)
         list = list//' '//this%entries(i)%name
      end do
   end function registry_names

end module pecplas_joints_laws_factory
