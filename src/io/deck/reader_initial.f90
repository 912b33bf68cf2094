!> Deck handler for *INITIAL_STRESS (set names are resolved once the mesh is built).
!>   *INITIAL_STRESS, TYPE=HOMOGENEOUS   data: set|ALL, sxx, syy, szz, sxy (tension +)
!>   *INITIAL_STRESS, TYPE=GEOSTATIC     data: set|ALL, y_surface, K0 [, q_surface]
module pecplas_io_deck_reader_initial
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_io_text_fields, only: deck_line_t, &
      field_t, split_fields, field_real, check_count, upper
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, line_error
   use pecplas_io_deck_reader_mesh, only: no_data_error
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_set_names, only: eset_names
   use pecplas_model_initial, only: initial_stress_t
   implicit none (type, external)
   private

   public :: read_initial_stress, resolve_initial_stress

contains

   subroutine read_initial_stress(state, model, block, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: kwline
      type(field_t), allocatable :: f(:)
      type(initial_stress_t) :: init
      type(initial_stress_t), allocatable :: tmp(:)
      character(len=:), allocatable :: kind, form
      integer :: i, k, n
      kwline = state%lines%get(block%at)
      associate (kw => block%kw)
         call kw%check_keys(kwline, [character(len=4) :: 'TYPE'], error)
         if (allocated(error)) return
         call kw%require(kwline, 'TYPE', kind, error)
         if (allocated(error)) return
         select case (upper(kind))
         case ('HOMOGENEOUS')
            form = 'set, sxx, syy, szz, sxy'
         case ('GEOSTATIC')
            form = 'set, y_surface, K0[, q_surface]'
         case default
            call line_error(state, block%at, "unknown initial stress type '"//kind// &
               "'; known types: HOMOGENEOUS GEOSTATIC", error)
            return
         end select
      end associate
      call no_data_error(state, block, form, error)
      if (allocated(error)) return
      if (.not. allocated(model%initial_stresses)) allocate (model%initial_stresses(0))
      do i = block%first, block%last
         call split_fields(state%lines%text(i), f)
         init = initial_stress_t()
         init%kind = upper(kind)
         init%file = state%lines%file(i)
         init%line = state%lines%line(i)
         if (init%kind == 'HOMOGENEOUS') then
            call check_count(state%lines%get(i), f, 5, 5, form, error)
            if (allocated(error)) return
            do k = 1, 4
               call field_real(state%lines%get(i), f, k + 1, 'stress component', &
                  init%stress(k), error)
               if (allocated(error)) return
            end do
         else
            call check_count(state%lines%get(i), f, 3, 4, form, error)
            if (allocated(error)) return
            call field_real(state%lines%get(i), f, 2, 'y_surface', init%surface, error)
            if (allocated(error)) return
            call field_real(state%lines%get(i), f, 3, 'K0', init%k0, error)
            if (allocated(error)) return
            if (size(f) == 4) then
               call field_real(state%lines%get(i), f, 4, 'q_surface', init%surcharge, error)
               if (allocated(error)) return
            end if
            if (init%k0 < 0.0_wp) then
               call line_error(state, i, 'K0 must not be negative', error)
               return
            end if
         end if
         init%set = f(1)%s
         ! explicit copies: gfortran 12 loses deferred-length components in array constructors
         n = size(model%initial_stresses)
         allocate (tmp(n + 1))
         tmp(1:n) = model%initial_stresses
         tmp(n + 1) = init
         call move_alloc(tmp, model%initial_stresses)
      end do
   end subroutine read_initial_stress

   !> Element set names -> indices (ALL -> 0); a Gmsh group of several element types gives
   !> one entry per part, in place (so later lines still overwrite earlier ones); an unknown
   !> name lists the known sets.
   subroutine resolve_initial_stress(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      type(initial_stress_t), allocatable :: out(:)
      integer, allocatable :: nparts(:), parts(:)
      integer :: i, k, n
      if (.not. allocated(model%initial_stresses)) return
      ! the parts of each line (one: a set or ALL), then one entry per part, element by
      ! element (no array constructor of the type: its allocatable components)
      allocate (nparts(size(model%initial_stresses)), source=1)
      do i = 1, size(model%initial_stresses)
         associate (init => model%initial_stresses(i))
            if (upper(init%set) == 'ALL') cycle
            nparts(i) = size(model%mesh%find_esets(init%set))
            if (nparts(i) == 0) then
               call line_error(state, find_line(state, init%file, init%line), &
                  "undefined element set '"//init%set//"'; known element sets: ALL"// &
                  eset_names(model%mesh), error)
               return
            end if
         end associate
      end do
      allocate (out(sum(nparts)))
      n = 0
      do i = 1, size(model%initial_stresses)
         associate (init => model%initial_stresses(i))
            if (upper(init%set) == 'ALL') then
               n = n + 1
               out(n) = init
               out(n)%eset = 0
               cycle
            end if
            parts = model%mesh%find_esets(init%set)
            do k = 1, size(parts)
               n = n + 1
               out(n) = init
               out(n)%eset = parts(k)
               out(n)%set = model%mesh%esets(parts(k))%name
            end do
         end associate
      end do
      call move_alloc(out, model%initial_stresses)
   end subroutine resolve_initial_stress

   !> Index of the deck line (file, line) in state%lines.
   integer function find_line(state, file, line) result(k)
      type(deck_state_t), intent(in) :: state
      character(len=*), intent(in) :: file
      integer, intent(in) :: line
      do k = 1, state%lines%n
         if (state%lines%line(k) == line .and. state%lines%file(k) == file) return
      end do
      k = 1
   end function find_line

end module pecplas_io_deck_reader_initial
