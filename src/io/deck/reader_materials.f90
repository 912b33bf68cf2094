!> Deck handlers for *MATERIAL and *SECTION, and the resolution of sections (element set
!> -> material) once the whole deck is read.
module pecplas_io_deck_reader_materials
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_deck_element_aliases, only: element_alias_hint
   use pecplas_io_text_fields, only: deck_line_t, &
      field_t, split_fields, parse_real, same_name, upper, &
      add_name
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, raw_section_t, line_error, &
      where_text
   use pecplas_io_deck_reader_mesh, only: check_name
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_set_names, only: eset_names
   use pecplas_base_params, only: params_t
   use pecplas_base_warnings, only: warnings_t
   use pecplas_io_deck_plausible, only: check_plausible
   use pecplas_base_strings, only: decimal_text
   use pecplas_massif_materials_type, only: material_t, material_box_t
   use pecplas_io_deck_reader_water, only: material_water, finish_material_water
   use pecplas_water_drainage, only: water_material_t
   implicit none (type, external)
   private

   public :: read_material, read_section, resolve_sections, read_pairs

contains

   !> *MATERIAL, NAME=name [, TYPE=ELASTIC] -- data: KEY = value pairs over any lines.
   !> Parameter errors are reported at the first data line (the keyword line if none).
   subroutine read_material(state, model, block, error)
      type(deck_state_t), intent(inout) :: state
      type(model_t), intent(inout) :: model
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      character(len=:), allocatable :: name, mtype
      type(params_t) :: params
      class(material_t), allocatable :: mat
      type(material_box_t), allocatable :: tmp(:)
      type(water_material_t) :: wmat
      character(len=:), allocatable :: drainage
      logical :: found
      integer :: i, n, at, k, k0
      kwline = state%lines%get(block%at)
      call block%kw%check_keys(kwline, [character(len=8) :: 'NAME', 'TYPE', 'DRAINAGE'], error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'NAME', name, error)
      if (allocated(error)) return
      call block%kw%get('TYPE', mtype, found)
      if (.not. found) mtype = 'ELASTIC'
      call check_name(state, block%at, name, error)
      if (allocated(error)) return
      if (.not. state%registry%has(mtype)) then
         call line_error(state, block%at, "unknown material type '"//upper(mtype)// &
            "'; known types:"//state%registry%names(), error)
         return
      end if
      if (.not. allocated(model%materials)) allocate (model%materials(0), state%material_at(0))
      n = size(model%materials)
      do i = 1, n
         if (same_name(model%materials(i)%m%name, name)) then
            call line_error(state, block%at, "material '"//name//"' is defined twice (first at " &
               //where_text(state, state%material_at(i))//')', error)
            return
         end if
      end do

      at = block%at
      if (block%last >= block%first) at = block%first
      params%file = state%lines%file(at)
      params%line = state%lines%line(at)
      params%keyword = '*MATERIAL'
      allocate (params%keys(0), params%values(0))
      do i = block%first, block%last
         k0 = size(params%keys)
         call read_pairs(state, i, params, error, model%warnings)
         if (allocated(error)) return
         ! a value far outside its range in the deck's units (typed in another unit?)
         do k = k0 + 1, size(params%keys)
            call check_plausible(model%unit_system, name, upper(trim(params%keys(k))), &
               params%values(k), state%lines%file(i), state%lines%line(i), model%warnings)
         end do
      end do
      ! the water's part (doc/deck.md, Groundwater) is taken out before the soil model
      call block%kw%get('DRAINAGE', drainage, found)
      if (.not. found) drainage = ''
      call material_water(state, at, mtype, drainage, params, wmat, error)
      if (allocated(error)) return
      call state%registry%new_material(upper(mtype), name, params, mat, error)
      if (allocated(error)) return
      call finish_material_water(mat, wmat)
      if (.not. allocated(model%water%mats)) allocate (model%water%mats(0))
      model%water%mats = [model%water%mats, wmat]

      allocate (tmp(n + 1))
      do i = 1, n
         call move_alloc(model%materials(i)%m, tmp(i)%m)
      end do
      call move_alloc(mat, tmp(n + 1)%m)
      call move_alloc(tmp, model%materials)
      state%material_at = [state%material_at, block%at]
   end subroutine read_material

   !> One data line of `KEY = value` pairs (also used by *INTERFACE_LAW).
   subroutine read_pairs(state, at, params, error, warnings)
      type(deck_state_t), intent(in) :: state
      integer, intent(in) :: at
      type(params_t), intent(inout) :: params
      type(error_t), allocatable, intent(out) :: error
      !> Receives suspicious values (an angle in (0, 1) degree: radians by mistake?).
      type(warnings_t), intent(inout), optional :: warnings
      type(field_t), allocatable :: f(:)
      real(wp) :: value
      logical :: ok
      integer :: j
      allocate (f(0)) ! gives the descriptor bounds (silences a gfortran 12 false warning)
      call split_fields(state%lines%text(at), f)
      j = 1
      do while (j <= size(f))
         if (f(j)%s == '=') then
            call line_error(state, at, "expected KEY = value, found '=' without a key", error)
            return
         end if
         ok = j + 1 <= size(f)
         if (ok) ok = f(j + 1)%s == '='
         if (.not. ok) then
            call line_error(state, at, 'expected KEY = value, found '''//f(j)%s// &
               ''' not followed by =', error)
            return
         end if
         if (j + 2 > size(f)) then
            call line_error(state, at, 'missing value for '//upper(f(j)%s)// &
               ' (expected '//upper(f(j)%s)//' = <number>)', error)
            return
         end if
         call parse_real(f(j + 2)%s, value, ok)
         if (.not. ok) then
            call line_error(state, at, 'expected '//upper(f(j)%s)//" as a number, found '"// &
               f(j + 2)%s//"'", error)
            return
         end if
         if (params%has(f(j)%s)) then
            call line_error(state, at, 'parameter '//upper(f(j)%s)//' given twice', error)
            return
         end if
         call params%add(f(j)%s, value)
         if (present(warnings)) call check_angle(state, at, upper(f(j)%s), value, warnings)
         j = j + 3
      end do
   end subroutine read_pairs

   !> PHI and PSI are in degrees: a value in (0, 1) is most likely radians.
   subroutine check_angle(state, at, key, value, warnings)
      type(deck_state_t), intent(in) :: state
      integer, intent(in) :: at
      character(len=*), intent(in) :: key
      real(wp), intent(in) :: value
      type(warnings_t), intent(inout) :: warnings
      if (key /= 'PHI' .and. key /= 'PSI') return
      if (.not. (value > 0.0_wp .and. value < 1.0_wp)) return
      call warnings%add(key//' = '//decimal_text(value, 6)//' degree is below 1 degree: '// &
         'angles are in degrees (radians by mistake? '//decimal_text(value, 6)//' rad = '// &
         decimal_text(value*180.0_wp/acos(-1.0_wp), 2)//' degrees)', state%lines%file(at), &
         state%lines%line(at))
   end subroutine check_angle

   !> *SECTION, SET=eset, MATERIAL=name [, ELEMENT=Q8R|Q8] -- no data lines; resolved at the
   !> end.
   subroutine read_section(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      type(raw_section_t) :: sec
      type(raw_section_t), allocatable :: tmp(:)
      integer :: n
      logical :: found
      kwline = state%lines%get(block%at)
      call block%kw%check_keys(kwline, [character(len=8) :: 'SET', 'MATERIAL', 'ELEMENT'], error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'SET', sec%set, error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'MATERIAL', sec%material, error)
      if (allocated(error)) return
      call block%kw%get('ELEMENT', sec%element, found)
      if (.not. found) sec%element = ''
      sec%element = upper(sec%element)
      if (found .and. sec%element /= 'Q8' .and. sec%element /= 'Q8R') then
         call line_error(state, block%at, "bad value ELEMENT="//sec%element// &
            element_alias_hint(sec%element)//'; expected '// &
            'Q8R (8-node quadrilaterals with 2 x 2 Gauss points) or Q8 (3 x 3)', error)
         return
      end if
      sec%at = block%at
      if (.not. allocated(state%sections)) allocate (state%sections(0))
      n = size(state%sections)
      allocate (tmp(n + 1))
      tmp(1:n) = state%sections
      tmp(n + 1) = sec
      call move_alloc(tmp, state%sections)
   end subroutine read_section

   !> Gives every element set its material (and ELEMENT= its 8-node quadrilateral kind); each
   !> set needs exactly one section. SET= a Gmsh group of several element types gives all its
   !> parts the section.
   subroutine resolve_sections(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: given_at(:), parts(:)
      character(len=:), allocatable :: list
      integer :: i, j, k, m, quads
      allocate (given_at(size(model%mesh%esets)))
      given_at = 0
      if (.not. allocated(model%materials)) allocate (model%materials(0))
      if (allocated(state%sections)) then
         do i = 1, size(state%sections)
            associate (sec => state%sections(i))
               parts = model%mesh%find_esets(sec%set)
               if (size(parts) == 0) then
                  call line_error(state, sec%at, "undefined element set '"//sec%set// &
                     "'; known element sets:"//eset_names(model%mesh), error)
                  return
               end if
               m = 0
               do k = 1, size(model%materials)
                  if (same_name(model%materials(k)%m%name, sec%material)) m = k
               end do
               if (m == 0) then
                  list = ''
                  do k = 1, size(model%materials)
                     call add_name(list, model%materials(k)%m%name)
                  end do
                  if (len(list) == 0) list = ' (none)'
                  call line_error(state, sec%at, "undefined material '"//sec%material// &
                     "'; known materials:"//list, error)
                  return
               end if
               do j = 1, size(parts)
                  k = parts(j)
                  if (given_at(k) > 0) then
                     call line_error(state, sec%at, "element set '"// &
                        model%mesh%esets(k)%name//"' already has a section (at "// &
                        where_text(state, given_at(k))//')', error)
                     return
                  end if
                  given_at(k) = sec%at
                  model%mesh%esets(k)%material = model%materials(m)%m%name
                  model%mesh%esets(k)%material_index = m
                  ! ELEMENT=: the integration of the 8-node quadrilaterals among the parts
                  if (len(sec%element) > 0 .and. (model%mesh%esets(k)%etype == 'Q8' .or. &
                      model%mesh%esets(k)%etype == 'Q8R')) model%mesh%esets(k)%etype = sec%element
               end do
               quads = 0
               do j = 1, size(parts)
                  if (model%mesh%esets(parts(j))%etype == sec%element) quads = quads + 1
               end do
               if (len(sec%element) > 0 .and. quads == 0) then
                  call line_error(state, sec%at, 'ELEMENT='//sec%element//' is for 8-node '// &
                     "quadrilaterals; element set '"//sec%set//"' has none (type "// &
                     model%mesh%esets(parts(1))%etype//')', error)
                  return
               end if
            end associate
         end do
      end if
      do k = 1, size(model%mesh%esets)
         if (given_at(k) > 0) cycle
         call line_error(state, state%mesh_eset_at(k), "element set '"// &
            model%mesh%esets(k)%name//"' has no material: add *SECTION, SET="// &
            model%mesh%esets(k)%name//', MATERIAL=<name>', error)
         return
      end do
   end subroutine resolve_sections

end module pecplas_io_deck_reader_materials
