!> Deck handlers for *BOUNDARY and *LOAD. Targets (node ids, set names) are kept as
!> written and resolved by pecplas_io_deck_resolve_loads once the mesh is built.
module pecplas_io_deck_reader_loads
   use pecplas_base_kinds, only: wp
   use pecplas_io_deck_caps, only: MAX_LOAD_MAGNITUDE
   use pecplas_base_error, only: error_t
   use pecplas_io_text_fields, only: deck_line_t, field_t, split_fields, field_real, check_count, &
      parse_int, parse_real, same_name, upper, add_name
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, raw_item_t, raw_pattern_t, &
      line_error, where_text, push_item
   use pecplas_io_deck_reader_mesh, only: check_name, no_data_error
   use pecplas_model_loads, only: LOAD_KINDS
   implicit none (type, external)
   private

   public :: read_boundary, read_load, parse_dofs

contains

   !> *BOUNDARY [, NAME=group] -- data: target, dof_first[, dof_last] | target,
   !> X|Y|R|Z|XY|ALL. A named support is one that phases may activate and deactivate.
   subroutine read_boundary(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(field_t), allocatable :: f(:)
      type(raw_item_t) :: item
      character(len=:), allocatable :: group
      logical :: named
      integer :: i
      call block%kw%check_keys(state%lines%get(block%at), [character(len=4) :: 'NAME'], error)
      if (allocated(error)) return
      call block%kw%get('NAME', group, named)
      if (.not. named) group = ''
      if (named) then
         call check_name(state, block%at, group, error)
         if (allocated(error)) return
      end if
      item%group = group
      call no_data_error(state, block, 'target, dof_first[, dof_last]', error)
      if (allocated(error)) return
      do i = block%first, block%last
         call split_fields(state%lines%text(i), f)
         call check_count(state%lines%get(i), f, 2, 3, 'target, dof_first[, dof_last]', error)
         if (allocated(error)) return
         item%target = f(1)%s
         item%at = i
         if (size(f) == 2) then
            call parse_dofs(state, i, f(2)%s, '', item%dof, error)
         else
            call parse_dofs(state, i, f(2)%s, f(3)%s, item%dof, error)
         end if
         if (allocated(error)) return
         call push_item(state%boundary, state%nboundary, item)
      end do
   end subroutine read_boundary

   !> Dof range from `first` [`last`]: 1, 2 or X, Y, R, Z (one dof), 3 or ROT (the rotation
   !> of a plate node), XY (both translations), ALL (both, and the rotation where the node
   !> carries one).
   subroutine parse_dofs(state, at, first, last, dof, error)
      type(deck_state_t), intent(in) :: state
      integer, intent(in) :: at
      character(len=*), intent(in) :: first, last
      integer, intent(out) :: dof(2)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: HINT = ': expected 1 (x, r), 2 (y, z), 3 (rotation) '// &
         'or one of X Y R Z ROT XY ALL'
      integer :: d
      logical :: ok
      select case (upper(first))
      case ('1', 'X', 'R')
         dof = 1
      case ('2', 'Y', 'Z')
         dof = 2
      case ('3', 'ROT')
         dof = 3
      case ('XY')
         dof = [1, 2]
      case ('ALL')
         dof = [1, 3]
      case default
         call line_error(state, at, "bad dof '"//first//"'"//HINT, error)
         return
      end select
      if (len(last) == 0) return
      call parse_int(last, d, ok)
      if (.not. ok .or. d < 1 .or. d > 3 .or. verify(first, '123') /= 0) then
         call line_error(state, at, "bad dof range '"//first//', '//last// &
            "': expected dof_first, dof_last with 1 <= dof_first <= dof_last <= 3", error)
         return
      end if
      if (d < dof(1)) then
         call line_error(state, at, "bad dof range '"//first//', '//last// &
            "': dof_last must not be smaller than dof_first", error)
         return
      end if
      dof(2) = d
   end subroutine parse_dofs

   !> *LOAD, NAME=name, TYPE=FORCE|PRESSURE|BODY_FORCE|GRAVITY|DISPLACEMENT
   subroutine read_load(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      type(raw_pattern_t) :: pat
      type(raw_pattern_t), allocatable :: tmp(:)
      character(len=:), allocatable :: kind, list, form
      integer :: i, n
      kwline = state%lines%get(block%at)
      call block%kw%check_keys(kwline, [character(len=4) :: 'NAME', 'TYPE', 'MIN'], error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'NAME', pat%name, error)
      if (allocated(error)) return
      call block%kw%require(kwline, 'TYPE', kind, error)
      if (allocated(error)) return
      call check_name(state, block%at, pat%name, error)
      if (allocated(error)) return
      pat%kind = upper(kind)
      if (.not. any(LOAD_KINDS == pat%kind)) then
         list = ''
         do i = 1, size(LOAD_KINDS)
            call add_name(list, trim(LOAD_KINDS(i)))
         end do
         call line_error(state, block%at, "unknown load type '"//kind//"'; known types:"// &
            list, error)
         return
      end if
      if (.not. allocated(state%patterns)) allocate (state%patterns(0))
      n = size(state%patterns)
      do i = 1, n
         if (same_name(state%patterns(i)%name, pat%name)) then
            call line_error(state, block%at, "load pattern '"//pat%name// &
               "' is defined twice (first at "//where_text(state, state%patterns(i)%at)//')', error)
            return
         end if
      end do
      pat%at = block%at
      call read_pressure_min(state, block, pat, error)
      if (allocated(error)) return
      select case (pat%kind)
      case ('FORCE', 'DISPLACEMENT')
         form = 'target, dof, value'
      case ('PRESSURE')
         form = 'edge_set, p | edge_set, p_ref, gradient, y_ref'
      case ('BODY_FORCE')
         form = 'element_set|ALL, bx, by'
      case ('PLATE_LOAD')
         form = 'plate_set, qx, qy'
      case default
         form = 'element_set|ALL[, dx, dy]'
      end select
      call no_data_error(state, block, form, error)
      if (allocated(error)) return
      do i = block%first, block%last
         call read_load_line(state, i, pat, form, error)
         if (allocated(error)) return
      end do
      allocate (tmp(n + 1))
      tmp(1:n) = state%patterns
      tmp(n + 1) = pat
      call move_alloc(tmp, state%patterns)
   end subroutine read_load

   subroutine read_load_line(state, at, pat, form, error)
      type(deck_state_t), intent(in) :: state
      integer, intent(in) :: at
      type(raw_pattern_t), intent(inout) :: pat
      character(len=*), intent(in) :: form
      type(error_t), allocatable, intent(out) :: error
      type(field_t), allocatable :: f(:)
      type(raw_item_t) :: item
      real(wp) :: norm
      allocate (f(0)) ! gives the descriptor bounds (silences a gfortran 12 false warning)
      call split_fields(state%lines%text(at), f)
      call check_count(state%lines%get(at), f, 1, 4, form, error)
      if (allocated(error)) return
      item%at = at
      item%target = f(1)%s
      select case (pat%kind)
      case ('FORCE', 'DISPLACEMENT')
         call check_count(state%lines%get(at), f, 3, 3, form, error)
         if (allocated(error)) return
         call parse_dofs(state, at, f(2)%s, '', item%dof, error)
         if (allocated(error)) return
         if (item%dof(1) /= item%dof(2)) then
            call line_error(state, at, "bad dof '"//f(2)%s//"': a "//pat%kind// &
               ' line takes one dof: 1, 2, 3, X, Y, R, Z or ROT', error)
            return
         end if
         call field_real(state%lines%get(at), f, 3, 'value', item%value(1), error)
      case ('PRESSURE')
         call check_count(state%lines%get(at), f, 2, 4, form, error)
         if (allocated(error)) return
         if (size(f) == 3) then
            call line_error(state, at, 'expected "'//form//'" (uniform, or p_ref + '// &
               'gradient (y_ref - y)), found 3 fields', error)
            return
         end if
         call field_real(state%lines%get(at), f, 2, 'pressure', item%value(1), error)
         if (allocated(error)) return
         if (size(f) == 4) then
            call field_real(state%lines%get(at), f, 3, 'gradient', item%gradient, error)
            if (allocated(error)) return
            call field_real(state%lines%get(at), f, 4, 'y_ref', item%y_ref, error)
            if (allocated(error)) return
            if (abs(item%gradient) > MAX_LOAD_MAGNITUDE .or. &
                abs(item%y_ref) > MAX_LOAD_MAGNITUDE) then
               call line_error(state, at, 'load value above 1e100 in magnitude (see '// &
                  'doc/deck.md, Limits)', error)
               return
            end if
         end if
      case ('BODY_FORCE')
         call check_count(state%lines%get(at), f, 3, 3, form, error)
         if (allocated(error)) return
         call field_real(state%lines%get(at), f, 2, 'bx', item%value(1), error)
         if (allocated(error)) return
         call field_real(state%lines%get(at), f, 3, 'by', item%value(2), error)
      case ('PLATE_LOAD')
         call check_count(state%lines%get(at), f, 3, 3, form, error)
         if (allocated(error)) return
         call field_real(state%lines%get(at), f, 2, 'qx', item%value(1), error)
         if (allocated(error)) return
         call field_real(state%lines%get(at), f, 3, 'qy', item%value(2), error)
      case default
         if (size(f) == 1) then
            item%value = [0.0_wp, -1.0_wp]
         else
            call check_count(state%lines%get(at), f, 3, 3, form, error)
            if (allocated(error)) return
            call field_real(state%lines%get(at), f, 2, 'dx', item%value(1), error)
            if (allocated(error)) return
            call field_real(state%lines%get(at), f, 3, 'dy', item%value(2), error)
            if (allocated(error)) return
            norm = norm2(item%value)
            if (.not. (norm > 0.0_wp)) then
               call line_error(state, at, 'GRAVITY direction (dx, dy) must not be zero', error)
               return
            end if
            item%value = item%value/norm
         end if
      end select
      if (allocated(error)) return
      if (any(abs(item%value) > MAX_LOAD_MAGNITUDE)) then
         call line_error(state, at, 'load value above 1e100 in magnitude (see doc/deck.md, '// &
            'Limits)', error)
         return
      end if
      call push_item(pat%items, pat%n, item)
   end subroutine read_load_line

   !> *LOAD, TYPE=PRESSURE, MIN=p_min: the pressure of the pattern is max(p_min, p).
   subroutine read_pressure_min(state, block, pat, error)
      type(deck_state_t), intent(in) :: state
      type(deck_block_t), intent(in) :: block
      type(raw_pattern_t), intent(inout) :: pat
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      logical :: ok
      call block%kw%get('MIN', text, pat%floored)
      if (.not. pat%floored) return
      if (pat%kind /= 'PRESSURE') then
         call line_error(state, block%at, 'MIN= is an option of TYPE=PRESSURE (the least '// &
            'pressure, e.g. MIN=0: no suction above a water table)', error)
         return
      end if
      call parse_real(text, pat%p_min, ok)
      if (.not. ok .or. .not. abs(pat%p_min) <= MAX_LOAD_MAGNITUDE) then
         call line_error(state, block%at, "expected MIN=<number>, found '"//text//"'", error)
         return
      end if
   end subroutine read_pressure_min

end module pecplas_io_deck_reader_loads
