!> Massif material factory: maps a deck type name (*MATERIAL, TYPE=...) to a builder.
!> Builders live in a registry object owned by the caller (no global state): start from
!> `default_material_registry()`, which holds the built-in materials, and add user
!> materials with `register_material` (the Abaqus UMAT habit) without editing this file.
!> Adding a built-in material is one `register` line in `default_material_registry`,
!> given a builder with the interface `material_builder_ifc` in the material's module.
module pecplas_massif_materials_factory
   use pecplas_base_error, only: error_t, deck_error, fatal_error
   use pecplas_base_params, only: params_t
   use pecplas_massif_materials_type, only: material_t
   use pecplas_massif_materials_elastic, only: elastic_t, new_elastic
   use pecplas_base_strings, only: upper
   use pecplas_massif_materials_mohr_coulomb, only: mohr_coulomb_t, new_mohr_coulomb
   use pecplas_massif_materials_drucker_prager, only: drucker_prager_t, new_drucker_prager
   implicit none (type, external)
   private

   public :: material_builder_ifc, material_registry_t, default_material_registry
   public :: register_material, new_material, KNOWN_MATERIALS

   !> Built-in material type names, as in the deck; the default registry holds exactly these.
   character(len=*), parameter :: KNOWN_MATERIALS(3) = [character(len=16) :: 'ELASTIC', &
      'MOHR_COULOMB', 'DRUCKER_PRAGER']

   abstract interface
      !> Builds material `name` from its deck parameters (checking them).
      subroutine material_builder_ifc(name, params, mat, error)
         import :: params_t, material_t, error_t
         character(len=*), intent(in) :: name
         type(params_t), intent(in) :: params
         class(material_t), allocatable, intent(out) :: mat
         type(error_t), allocatable, intent(out) :: error
      end subroutine material_builder_ifc
   end interface

   type :: registry_entry_t
      !> Upper-case type name.
      character(len=:), allocatable :: name
      procedure(material_builder_ifc), pointer, nopass :: build => null()
   end type registry_entry_t

   !> Known material types and their builders.
   type :: material_registry_t
      type(registry_entry_t), allocatable :: entries(:)
   contains
      procedure :: register => registry_register
      procedure :: new_material => registry_new_material
      procedure :: names => registry_names
      procedure :: has => registry_has
   end type material_registry_t

contains

   !> Registry of the built-in materials (KNOWN_MATERIALS).
   function default_material_registry() result(registry)
      type(material_registry_t) :: registry
      allocate (registry%entries(0))
      call registry%register('ELASTIC', build_elastic)
      call registry%register('MOHR_COULOMB', build_mohr_coulomb)
      call registry%register('DRUCKER_PRAGER', build_drucker_prager)
   end function default_material_registry

   !> Adds (or replaces) the builder of type `name` (case-insensitive).
   subroutine register_material(registry, name, builder)
      type(material_registry_t), intent(inout) :: registry
      character(len=*), intent(in) :: name
      procedure(material_builder_ifc) :: builder
      call registry%register(name, builder)
   end subroutine register_material

   subroutine registry_register(this, name, builder)
      class(material_registry_t), intent(inout) :: this
      character(len=*), intent(in) :: name
      procedure(material_builder_ifc) :: builder
      type(registry_entry_t), allocatable :: tmp(:)
      integer :: k, n
      if (.not. allocated(this%entries)) allocate (this%entries(0))
      k = find(this, name)
      if (k == 0) then
         n = size(this%entries)
         allocate (tmp(n + 1))
         tmp(1:n) = this%entries
         call move_alloc(tmp, this%entries)
         k = n + 1
         this%entries(k)%name = upper(name)
      end if
      this%entries(k)%build => builder
   end subroutine registry_register

   !> Builds a material of type `type_name`; an unknown type is a deck error at the
   !> position held by `params`, listing the known types.
   subroutine registry_new_material(this, type_name, name, params, mat, error)
      class(material_registry_t), intent(in) :: this
      character(len=*), intent(in) :: type_name, name
      type(params_t), intent(in) :: params
      class(material_t), allocatable, intent(out) :: mat
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      k = find(this, type_name)
      if (k == 0) then
         call deck_error(error, params%file, params%line, params%keyword, &
            "unknown material type '"//trim(type_name)//"'; known types:"//this%names())
         return
      end if
      call this%entries(k)%build(name, params, mat, error)
      if (allocated(error)) return
      if (.not. allocated(mat)) call fatal_error(error, 'material builder for '// &
         this%entries(k)%name//' returned no material')
   end subroutine registry_new_material

   !> True if type `name` is registered (case-insensitive).
   logical function registry_has(this, name)
      class(material_registry_t), intent(in) :: this
      character(len=*), intent(in) :: name
      registry_has = find(this, name) > 0
   end function registry_has

   !> Blank-separated list of the registered type names (leading blank).
   function registry_names(this) result(list)
      class(material_registry_t), intent(in) :: this
      character(len=:), allocatable :: list
      integer :: i
      list = ''
      if (.not. allocated(this%entries)) return
      do i = 1, size(this%entries)
         list = list//' '//this%entries(i)%name
      end do
   end function registry_names

   !> Builds a built-in material (default registry).
   subroutine new_material(type_name, name, params, mat, error)
      character(len=*), intent(in) :: type_name, name
      type(params_t), intent(in) :: params
      class(material_t), allocatable, intent(out) :: mat
      type(error_t), allocatable, intent(out) :: error
      type(material_registry_t) :: registry
      registry = default_material_registry()
      call registry%new_material(type_name, name, params, mat, error)
   end subroutine new_material

   subroutine build_elastic(name, params, mat, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(material_t), allocatable, intent(out) :: mat
      type(error_t), allocatable, intent(out) :: error
      type(elastic_t), allocatable :: elastic
      allocate (elastic)
      call new_elastic(elastic, name, params, error)
      if (allocated(error)) return
      call move_alloc(elastic, mat)
   end subroutine build_elastic

   subroutine build_mohr_coulomb(name, params, mat, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(material_t), allocatable, intent(out) :: mat
      type(error_t), allocatable, intent(out) :: error
      type(mohr_coulomb_t), allocatable :: mc
      allocate (mc)
      call new_mohr_coulomb(mc, name, params, error)
      if (allocated(error)) return
      call move_alloc(mc, mat)
   end subroutine build_mohr_coulomb

   subroutine build_drucker_prager(name, params, mat, error)
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      class(material_t), allocatable, intent(out) :: mat
      type(error_t), allocatable, intent(out) :: error
      type(drucker_prager_t), allocatable :: dp
      allocate (dp)
      call new_drucker_prager(dp, name, params, error)
      if (allocated(error)) return
      call move_alloc(dp, mat)
   end subroutine build_drucker_prager

   integer function find(registry, name) result(k)
      type(material_registry_t), intent(in) :: registry
      character(len=*), intent(in) :: name
      integer :: i
      k = 0
      if (.not. allocated(registry%entries)) return
      do i = 1, size(registry%entries)
         if (registry%entries(i)%name == upper(name)) k = i
      end do
   end function find

end module pecplas_massif_materials_factory
