!> The safety step of the deck (doc/deck.md, Safety): `*STEP, CONTROL=SAFETY` (options read
!> by pecplas_io_deck_reader_options) and its `*REDUCE` lines, names of the materials and
!> interface laws whose strength the step reduces. Checked once the deck is read: a safety
!> step is neither the first step (it starts from the state of a step before it) nor followed
!> by another, drives no pattern and changes nothing else; a name that is no material or law,
!> or one without a c, tan(phi) strength, is an error at its line.
module pecplas_io_deck_reader_safety
   use pecplas_base_error, only: error_t
   use pecplas_base_kinds, only: wp
   use pecplas_io_text_fields, only: field_t, split_fields, same_name, add_name
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, raw_item_t, line_error, &
      push_item
   use pecplas_model_type, only: model_t
   use pecplas_massif_materials_type, only: material_t
   use pecplas_joints_laws_type, only: interface_law_t
   implicit none (type, external)
   private

   public :: read_reduce, resolve_safety

contains

   !> *REDUCE after a safety step's *STEP line: data lines of material or law names.
   subroutine read_reduce(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(field_t), allocatable :: f(:)
      type(raw_item_t) :: item
      integer :: i, k
      call block%kw%check_keys(state%lines%get(block%at), [character(len=1) ::], error)
      if (allocated(error)) return
      if (state%open_step == 0) then
         call line_error(state, block%at, '*REDUCE names what a safety step reduces: put '// &
            'it after a "*STEP, CONTROL=SAFETY" line', error)
         return
      end if
      if (.not. state%steps(state%open_step)%safety) then
         call line_error(state, block%at, "*REDUCE belongs to a safety step; step '"// &
            state%steps(state%open_step)%name//"' is not one (CONTROL=SAFETY)", error)
         return
      end if
      if (block%last < block%first) then
         call line_error(state, block%at, '*REDUCE needs data lines: the names of '// &
            'materials and interface laws whose strength the step reduces', error)
         return
      end if
      associate (step => state%steps(state%open_step))
         if (step%reduce_at == 0) step%reduce_at = block%at
         do i = block%first, block%last
            call split_fields(state%lines%text(i), f)
            do k = 1, size(f)
               if (f(k)%s == '=') then
                  call line_error(state, i, "expected material or law names, found '='", error)
                  return
               end if
               item%target = f(k)%s
               item%at = i
               call push_item(step%reduce, step%nreduce, item)
            end do
         end do
      end associate
   end subroutine read_reduce

   !> The safety plan of each safety step (model%steps(:)%safety), checked (module header).
   subroutine resolve_safety(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: msg
      integer :: s, nm, nl, i
      nm = size(model%materials)
      nl = 0
      if (allocated(model%laws)) nl = size(model%laws)
      do s = 1, size(state%steps)
         associate (raw => state%steps(s), step => model%steps(s))
            if (.not. raw%safety) cycle
            if (s == 1) then
               call line_error(state, raw%at, "safety step '"//raw%name//"' is the first "// &
                  'step: strength reduction starts from the state a step before it reached '// &
                  '(put the construction or loading steps first)', error)
               return
            end if
            if (s < size(state%steps)) then
               call line_error(state, raw%at, "safety step '"//raw%name//"' must be the last "// &
                  "step (its displacements are not physical: no step can start from them); "// &
                  "step '"//state%steps(s + 1)%name//"' follows it", error)
               return
            end if
            if (raw%n > 0) then
               call line_error(state, raw%items(1)%at, "safety step '"//raw%name//"' drives "// &
                  'no load pattern (the loads keep the factors of the step before): remove '// &
                  'the "pattern, target_factor" lines', error)
               return
            end if
            if (allocated(raw%changes)) then
               if (size(raw%changes) > 0) then
                  call line_error(state, raw%changes(1)%at, "safety step '"//raw%name// &
                     "' changes nothing but strengths: put the phase changes in a step "// &
                     'before it', error)
                  return
               end if
            end if
            if (allocated(state%water%changes)) then
               do i = 1, size(state%water%changes)
                  if (state%water%changes(i)%step /= s) cycle
                  call line_error(state, state%water%changes(i)%at, "safety step '"// &
                     raw%name//"' changes nothing but strengths: put *CHANGE_WATER in a "// &
                     'step before it', error)
                  return
               end do
            end if
            if (raw%reset_displacements) then
               call line_error(state, raw%at, 'RESET_DISPLACEMENTS is no option of a safety '// &
                  'step (its displacements are those of the reduction from the state before)', &
                  error)
               return
            end if
            step%safety%on = .true.
            step%safety%msf_step = raw%msf_step
            step%safety%resolution = raw%resolution
            step%safety%max_increments = raw%max_increments
            step%safety%dof = raw%dof
            if (len(raw%node) > 0) then
               call model%mesh%node_of(raw%node, step%safety%node, msg)
               if (step%safety%node == 0) then
                  call line_error(state, raw%at, 'NODE='//raw%node//': '//msg, error)
                  return
               end if
            end if
            allocate (step%safety%materials(nm), step%safety%laws(nl), source=.false.)
            if (raw%nreduce == 0) then
               call reduce_all(model, step%safety%materials, step%safety%laws)
               if (.not. (any(step%safety%materials) .or. any(step%safety%laws))) then
                  call line_error(state, raw%at, "safety step '"//raw%name//"': no material "// &
                     'or interface law has a c, tan(phi) strength to reduce (MOHR_COULOMB, '// &
                     'DRUCKER_PRAGER; the Coulomb interface laws)', error)
                  return
               end if
            else
               call reduce_named(state, model, raw%reduce(1:raw%nreduce), &
                  step%safety%materials, step%safety%laws, error)
               if (allocated(error)) return
            end if
         end associate
      end do
   end subroutine resolve_safety

   !> Every material and law with a c, tan(phi) strength.
   subroutine reduce_all(model, materials, laws)
      type(model_t), intent(in) :: model
      logical, intent(inout) :: materials(:), laws(:)
      class(material_t), allocatable :: m
      class(interface_law_t), allocatable :: l
      integer :: k
      do k = 1, size(materials)
         call model%materials(k)%m%reduced_strength(1.0_wp, m)
         materials(k) = allocated(m)
      end do
      do k = 1, size(laws)
         call model%laws(k)%law%reduced_strength(1.0_wp, l)
         laws(k) = allocated(l)
      end do
   end subroutine reduce_all

   !> The named materials and laws; each must exist and have a c, tan(phi) strength.
   subroutine reduce_named(state, model, names, materials, laws, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(in) :: model
      type(raw_item_t), intent(in) :: names(:)
      logical, intent(inout) :: materials(:), laws(:)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: m
      class(interface_law_t), allocatable :: l
      character(len=:), allocatable :: list
      integer :: i, k, found
      do i = 1, size(names)
         found = 0
         do k = 1, size(materials)
            if (.not. same_name(model%materials(k)%m%name, names(i)%target)) cycle
            found = 1
            call model%materials(k)%m%reduced_strength(1.0_wp, m)
            if (.not. allocated(m)) then
               call line_error(state, names(i)%at, "material '"//names(i)%target//"' has no "// &
                  'strength parameters to reduce (C, PHI: TYPE=MOHR_COULOMB or '// &
                  'DRUCKER_PRAGER)', error)
               return
            end if
            materials(k) = .true.
         end do
         do k = 1, size(laws)
            if (.not. same_name(model%laws(k)%law%name, names(i)%target)) cycle
            found = 1
            call model%laws(k)%law%reduced_strength(1.0_wp, l)
            if (.not. allocated(l)) then
               call line_error(state, names(i)%at, "interface law '"//names(i)%target// &
                  "' has no c, tan(phi) strength to reduce (the Coulomb laws GOODMAN, "// &
                  'SPRING, GHABOUSSI, MOHR_COULOMB have one; ELASTIC and MODJOIN are not '// &
                  'reduced)', error)
               return
            end if
            laws(k) = .true.
         end do
         if (found == 0) then
            list = ''
            do k = 1, size(materials)
               call add_name(list, model%materials(k)%m%name)
            end do
            do k = 1, size(laws)
               call add_name(list, model%laws(k)%law%name)
            end do
            call line_error(state, names(i)%at, "no material or interface law '"// &
               names(i)%target//"'; known:"//list, error)
            return
         end if
      end do
   end subroutine reduce_named

end module pecplas_io_deck_reader_safety
