!> Deck handlers for groundwater (doc/deck.md, Groundwater):
!>   *WATER, NAME=name, GAMMA_W=value [, LEVEL=y]   a phreatic level: LEVEL= horizontal, or
!>                                                  data lines "x, y" (a polyline, x rising)
!>   *DRY                                           data: element sets that ignore the water
!>   *CHANGE_WATER [, LEVEL=name|NONE] [, RESET_EXCESS=YES|NO]   in a step: from its start
!> and the water part of *MATERIAL (DRAINAGE= on the keyword line; GAMMA_UNSAT, GAMMA_SAT,
!> KW_N, CU among its parameters). Resolved once the whole deck is read.
module pecplas_io_deck_reader_water
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_params, only: params_t
   use pecplas_base_strings, only: decimal_text
   use pecplas_io_text_fields, only: field_t, split_fields, check_count, field_real, &
      parse_real, same_name, upper, add_name
   use pecplas_io_deck_state, only: deck_state_t, deck_block_t, line_error, where_text
   use pecplas_io_deck_raw_water, only: raw_name_t, raw_water_change_t
   use pecplas_model_type, only: model_t
   use pecplas_massif_materials_type, only: material_t, NCOMP
   use pecplas_water_phreatic, only: phreatic_t
   use pecplas_water_drainage, only: water_material_t, default_water_stiffness, &
      DRAINAGE_NAMES, DRAINED, UNDRAINED_A, UNDRAINED_B, NON_POROUS
   use pecplas_water_type, only: LEVEL_KEEP, LEVEL_NONE, PLATE_KEEP, PLATE_FREE
   implicit none (type, external)
   private

   public :: read_water, read_dry, read_change_water, material_water, finish_material_water
   public :: read_plate_water
   public :: resolve_water, WATER_PARAMS

   !> *MATERIAL parameters that belong to the water, not to the soil model.
   character(len=*), parameter :: WATER_PARAMS(6) = [character(len=11) :: 'GAMMA_UNSAT', &
      'GAMMA_SAT', 'KW_N', 'CU', 'CU_INC', 'CU_YREF']

contains

   !> *WATER, NAME=, GAMMA_W= [, LEVEL=]: one phreatic level.
   subroutine read_water(state, model, block, error)
      type(deck_state_t), intent(inout) :: state
      type(model_t), intent(inout) :: model
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(phreatic_t) :: lvl
      type(phreatic_t), allocatable :: tmp(:)
      type(field_t), allocatable :: f(:)
      character(len=:), allocatable :: text
      real(wp) :: v
      logical :: found, ok
      integer :: i, n
      call block%kw%check_keys(state%lines%get(block%at), [character(len=7) :: 'NAME', &
         'GAMMA_W', 'LEVEL'], error)
      if (allocated(error)) return
      call block%kw%require(state%lines%get(block%at), 'NAME', lvl%name, error)
      if (allocated(error)) return
      call block%kw%require(state%lines%get(block%at), 'GAMMA_W', text, error)
      if (allocated(error)) return
      call parse_real(text, lvl%gamma_w, ok)
      if (.not. ok .or. .not. (lvl%gamma_w > 0.0_wp)) then
         call line_error(state, block%at, "GAMMA_W="//text//': expected the unit weight '// &
            'of water, a positive number (10 kN/m3, 9.81 kN/m3 ...)', error)
         return
      end if
      if (.not. allocated(model%water%levels)) allocate (model%water%levels(0), &
         state%water%level_at(0))
      do i = 1, size(model%water%levels)
         if (same_name(model%water%levels(i)%name, lvl%name)) then
            call line_error(state, block%at, "phreatic level '"//lvl%name//"' is defined "// &
               'twice (first at '//where_text(state, state%water%level_at(i))//')', error)
            return
         end if
      end do
      if (upper(lvl%name) == 'NONE') then
         call line_error(state, block%at, "NAME=NONE is reserved (*CHANGE_WATER, "// &
            "LEVEL=NONE: no water)", error)
         return
      end if
      call block%kw%get('LEVEL', text, found)
      if (found .eqv. (block%last >= block%first)) then
         call line_error(state, block%at, '*WATER needs either LEVEL=y (a horizontal '// &
            'level) or data lines "x, y" (a polyline), not both', error)
         return
      end if
      if (found) then
         call parse_real(text, v, ok)
         if (.not. ok) then
            call line_error(state, block%at, 'LEVEL='//text//': expected a number', error)
            return
         end if
         lvl%x = [0.0_wp]
         lvl%y = [v]
      else
         allocate (lvl%x(0), lvl%y(0))
         do i = block%first, block%last
            call split_fields(state%lines%text(i), f)
            call check_count(state%lines%get(i), f, 2, 2, 'x, y', error)
            if (allocated(error)) return
            call field_real(state%lines%get(i), f, 1, 'x', v, error)
            if (allocated(error)) return
            lvl%x = [lvl%x, v]
            call field_real(state%lines%get(i), f, 2, 'y', v, error)
            if (allocated(error)) return
            lvl%y = [lvl%y, v]
            n = size(lvl%x)
            if (n > 1) then
               if (.not. (lvl%x(n) > lvl%x(n - 1))) then
                  call line_error(state, i, 'the points of a phreatic polyline must have '// &
                     'increasing x', error)
                  return
               end if
            end if
         end do
         if (size(lvl%x) < 2) then
            call line_error(state, block%first, 'a phreatic polyline needs at least two '// &
               'points (or LEVEL=y on the keyword line for a horizontal level)', error)
            return
         end if
      end if
      lvl%file = state%lines%file(block%at)
      lvl%line = state%lines%line(block%at)
      n = size(model%water%levels)
      allocate (tmp(n + 1))
      tmp(1:n) = model%water%levels
      tmp(n + 1) = lvl
      call move_alloc(tmp, model%water%levels)
      state%water%level_at = [state%water%level_at, block%at]
   end subroutine read_water

   !> *DRY: data lines of element set names.
   subroutine read_dry(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(field_t), allocatable :: f(:)
      type(raw_name_t) :: item
      integer :: i, k
      call block%kw%check_keys(state%lines%get(block%at), [character(len=1) ::], error)
      if (allocated(error)) return
      if (block%last < block%first) then
         call line_error(state, block%at, '*DRY needs data lines: the names of element '// &
            'sets that ignore the water', error)
         return
      end if
      if (.not. allocated(state%water%dry)) allocate (state%water%dry(0))
      do i = block%first, block%last
         call split_fields(state%lines%text(i), f)
         do k = 1, size(f)
            item%name = f(k)%s
            item%at = i
            state%water%dry = [state%water%dry, item]
         end do
      end do
   end subroutine read_dry

   !> *PLATE_WATER: data lines `plate_set, LEFT|RIGHT|FREE|NONE`: the water stands on that
   !> side of the plate (walked from its first node to its last), or on its free faces
   !> (FREE), and presses on it below the level. Before the steps: from the start; inside a
   !> step: from that step on (NONE: no more). A plate set no line names has FREE.
   subroutine read_plate_water(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(field_t), allocatable :: f(:)
      type(raw_name_t) :: item, side
      integer :: i
      call block%kw%check_keys(state%lines%get(block%at), [character(len=1) ::], error)
      if (allocated(error)) return
      if (block%last < block%first) then
         call line_error(state, block%at, '*PLATE_WATER needs data lines "plate_set, '// &
            'LEFT|RIGHT|FREE|NONE"', error)
         return
      end if
      if (.not. allocated(state%water%plate)) allocate (state%water%plate(0), &
         state%water%plate_side(0), state%water%plate_step(0))
      do i = block%first, block%last
         call split_fields(state%lines%text(i), f)
         call check_count(state%lines%get(i), f, 2, 2, 'plate_set, LEFT|RIGHT|FREE|NONE', &
            error)
         if (allocated(error)) return
         if (upper(f(2)%s) /= 'LEFT' .and. upper(f(2)%s) /= 'RIGHT' .and. &
             upper(f(2)%s) /= 'FREE' .and. upper(f(2)%s) /= 'NONE') then
            call line_error(state, i, "side '"//f(2)%s//"': expected LEFT or RIGHT (of the "// &
               'plate walked from its first node to its last), FREE (every face no active '// &
               'element or joint lies against) or NONE (no water)', error)
            return
         end if
         item%name = f(1)%s
         item%at = i
         side%name = upper(f(2)%s)
         side%at = i
         state%water%plate = [state%water%plate, item]
         state%water%plate_side = [state%water%plate_side, side]
         state%water%plate_step = [state%water%plate_step, state%open_step]
      end do
   end subroutine read_plate_water

   !> *CHANGE_WATER [, LEVEL=name|NONE] [, RESET_EXCESS=YES|NO] inside a step.
   subroutine read_change_water(state, block, error)
      type(deck_state_t), intent(inout) :: state
      type(deck_block_t), intent(in) :: block
      type(error_t), allocatable, intent(out) :: error
      type(raw_water_change_t) :: ch
      character(len=:), allocatable :: text
      logical :: found
      call block%kw%check_keys(state%lines%get(block%at), [character(len=12) :: 'LEVEL', &
         'RESET_EXCESS'], error)
      if (allocated(error)) return
      if (state%open_step == 0) then
         call line_error(state, block%at, '*CHANGE_WATER changes the water at the start '// &
            'of a step: put it after a *STEP line (and before that step''s *END STEP)', error)
         return
      end if
      if (block%last >= block%first) then
         call line_error(state, block%first, '*CHANGE_WATER takes no data lines', error)
         return
      end if
      ch%step = state%open_step
      ch%at = block%at
      call block%kw%get('LEVEL', text, found)
      ch%level = ''
      if (found) ch%level = text
      call block%kw%get('RESET_EXCESS', text, found)
      if (found) then
         select case (upper(text))
         case ('YES')
            ch%reset = .true.
         case ('NO')
            ch%reset = .false.
         case default
            call line_error(state, block%at, 'RESET_EXCESS='//text//': expected YES or NO', &
               error)
            return
         end select
      end if
      if (len(ch%level) == 0 .and. .not. ch%reset) then
         call line_error(state, block%at, '*CHANGE_WATER changes nothing: give LEVEL=name '// &
            '(or NONE) and/or RESET_EXCESS=YES', error)
         return
      end if
      if (.not. allocated(state%water%changes)) allocate (state%water%changes(0))
      state%water%changes = [state%water%changes, ch]
   end subroutine read_change_water

   !> The water part of a *MATERIAL: DRAINAGE= (keyword line, `drainage`, '' if absent) and
   !> the water parameters, taken out of `params` (what is left goes to the soil model).
   !> UNDRAINED_B puts C = CU, PHI = 0, PSI = 0 for the soil model.
   subroutine material_water(state, at, mtype, drainage, params, wmat, error)
      type(deck_state_t), intent(in) :: state
      integer, intent(in) :: at
      character(len=*), intent(in) :: mtype, drainage
      type(params_t), intent(inout) :: params
      type(water_material_t), intent(out) :: wmat
      type(error_t), allocatable, intent(out) :: error
      type(params_t) :: soil
      integer :: i, k
      wmat%drainage = DRAINED
      if (len(drainage) > 0) then
         wmat%drainage = 0
         do k = 1, size(DRAINAGE_NAMES)
            if (upper(drainage) == trim(DRAINAGE_NAMES(k))) wmat%drainage = k
         end do
         if (wmat%drainage == 0) then
            call line_error(state, at, 'DRAINAGE='//drainage//': expected DRAINED, '// &
               'UNDRAINED_A, UNDRAINED_B or NON_POROUS', error)
            return
         end if
      end if
      soil%file = params%file
      soil%line = params%line
      soil%keyword = params%keyword
      ! a typo's message lists the water keys too (they never reach the soil model)
      soil%other_keys = WATER_PARAMS
      soil%other_what = 'water parameters'
      allocate (soil%keys(0), soil%values(0))
      do i = 1, size(params%keys)
         if (any(WATER_PARAMS == params%keys(i))) cycle
         call soil%add(params%keys(i), params%values(i))
      end do
      if (params%has('GAMMA_UNSAT') .and. params%has('GAMMA')) then
         call line_error(state, at, 'give the unit weight above the phreatic level as '// &
            'GAMMA or as GAMMA_UNSAT, not both', error)
         return
      end if
      if (params%has('GAMMA_UNSAT')) then
         call params%get('GAMMA_UNSAT', wmat%gamma_unsat, error)
         if (allocated(error)) return
         call soil%add('GAMMA', wmat%gamma_unsat)
      else if (params%has('GAMMA')) then
         call params%get('GAMMA', wmat%gamma_unsat, error)
         if (allocated(error)) return
      end if
      wmat%gamma_sat = wmat%gamma_unsat
      if (params%has('GAMMA_SAT')) then
         call params%get('GAMMA_SAT', wmat%gamma_sat, error)
         if (allocated(error)) return
         if (.not. (wmat%gamma_sat >= wmat%gamma_unsat)) then
            call line_error(state, at, 'GAMMA_SAT = '//decimal_text(wmat%gamma_sat, 6)// &
               ' is below the unit weight above the level, '// &
               decimal_text(wmat%gamma_unsat, 6)//' (GAMMA or GAMMA_UNSAT): a saturated '// &
               'soil is not lighter', error)
            return
         end if
         if (wmat%drainage == NON_POROUS) then
            call line_error(state, at, 'GAMMA_SAT is for porous materials: a NON_POROUS '// &
               'material weighs GAMMA everywhere', error)
            return
         end if
      end if
      if (params%has('KW_N')) then
         if (.not. wmat%undrained()) then
            call line_error(state, at, 'KW_N (the pore water stiffness K_w/n) is for '// &
               'DRAINAGE=UNDRAINED_A or UNDRAINED_B', error)
            return
         end if
         call params%get('KW_N', wmat%kwn, error)
         if (allocated(error)) return
         if (.not. (wmat%kwn > 0.0_wp)) then
            call line_error(state, at, 'KW_N must be positive', error)
            return
         end if
      end if
      if (params%has('CU_INC') .or. params%has('CU_YREF')) then
         if (wmat%drainage /= UNDRAINED_B) then
            call line_error(state, at, 'CU_INC and CU_YREF (c_u rising with depth) are for '// &
               'DRAINAGE=UNDRAINED_B', error)
            return
         end if
         if (.not. (params%has('CU_INC') .and. params%has('CU_YREF'))) then
            call line_error(state, at, 'c_u rising with depth needs both CU_INC (its rise '// &
               'per unit depth) and CU_YREF (the level where c_u = CU)', error)
            return
         end if
         call params%get('CU_INC', wmat%cu_inc, error)
         if (allocated(error)) return
         call params%get('CU_YREF', wmat%cu_yref, error)
         if (allocated(error)) return
         if (.not. (wmat%cu_inc >= 0.0_wp)) then
            call line_error(state, at, 'CU_INC must not be negative', error)
            return
         end if
      end if
      if (wmat%drainage == UNDRAINED_B) then
         if (upper(mtype) == 'ELASTIC') then
            call line_error(state, at, 'DRAINAGE=UNDRAINED_B gives the undrained strength '// &
               'CU: it needs a plastic model (TYPE=MOHR_COULOMB or DRUCKER_PRAGER)', error)
            return
         end if
         if (params%has('C') .or. params%has('PHI')) then
            call line_error(state, at, 'DRAINAGE=UNDRAINED_B takes its strength from CU '// &
               '(phi = 0): do not give C or PHI', error)
            return
         end if
         call params%get('CU', wmat%cu, error)
         if (allocated(error)) return
         if (.not. (wmat%cu > 0.0_wp)) then
            call line_error(state, at, 'CU must be positive', error)
            return
         end if
         call soil%add('C', wmat%cu)
         call soil%add('PHI', 0.0_wp)
         if (.not. soil%has('PSI')) call soil%add('PSI', 0.0_wp)
      else if (params%has('CU')) then
         call line_error(state, at, 'CU (the undrained shear strength) is for '// &
            'DRAINAGE=UNDRAINED_B', error)
         return
      end if
      params = soil
   end subroutine material_water

   !> After the soil model is built: the default K_w/n of an undrained material from its
   !> elastic tangent (bulk K' = sum D(1:3, 1:3) / 9, shear G = D(4, 4)).
   subroutine finish_material_water(mat, wmat)
      class(material_t), intent(in) :: mat
      type(water_material_t), intent(inout) :: wmat
      real(wp) :: d(NCOMP, NCOMP)
      if (.not. wmat%undrained() .or. wmat%kwn > 0.0_wp) return
      call mat%elastic_tangent(d)
      wmat%kwn = default_water_stiffness(sum(d(1:3, 1:3))/9.0_wp, d(4, 4))
   end subroutine finish_material_water

   !> The groundwater resolved: water properties for every material, the dry sets, the
   !> level changes of the steps; a polyline must span the model's width.
   subroutine resolve_water(state, model, error)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: list
      integer, allocatable :: parts(:)
      real(wp) :: xmin, xmax
      integer :: i, i2, k, nstep
      if (.not. allocated(model%water%levels)) allocate (model%water%levels(0))
      if (.not. allocated(model%water%mats)) allocate (model%water%mats(0))
      allocate (model%water%dry(size(model%mesh%esets)), source=.false.)
      nstep = size(model%steps)
      allocate (model%water%step_level(nstep), source=LEVEL_KEEP)
      allocate (model%water%step_reset(nstep), source=.false.)
      if (size(model%water%levels) > 0) then
         xmin = minval(model%mesh%x(1, :))
         xmax = maxval(model%mesh%x(1, :))
         do i = 1, size(model%water%levels)
            if (.not. model%water%levels(i)%covers(xmin, xmax)) then
               associate (lv => model%water%levels(i))
                  call line_error(state, state%water%level_at(i), "phreatic polyline '"// &
                     lv%name//"' does not cross the model: its x runs from "// &
                     decimal_text(lv%x(1), 6)//' to '//decimal_text(lv%x(size(lv%x)), 6)// &
                     ', the model from '//decimal_text(xmin, 6)//' to '// &
                     decimal_text(xmax, 6), error)
               end associate
               return
            end if
         end do
      end if
      if (allocated(state%water%dry)) then
         do i = 1, size(state%water%dry)
            parts = model%mesh%find_esets(state%water%dry(i)%name)
            if (size(parts) == 0) then
               list = ''
               do k = 1, size(model%mesh%esets)
                  call add_name(list, model%mesh%esets(k)%name)
               end do
               call line_error(state, state%water%dry(i)%at, "undefined element set '"// &
                  state%water%dry(i)%name//"'; known element sets:"//list, error)
               return
            end if
            model%water%dry(parts) = .true.
         end do
      end if
      k = 0
      if (allocated(model%plates)) k = size(model%plates)
      ! a plate set *PLATE_WATER does not name takes the water on its free faces
      allocate (model%water%plate_side(k), source=PLATE_FREE)
      allocate (model%water%step_plate(k, nstep), source=PLATE_KEEP)
      if (allocated(state%water%plate)) then
         do i = 1, size(state%water%plate)
            k = 0
            list = ''
            do i2 = 1, size(model%water%plate_side)
               if (same_name(model%plates(i2)%name, state%water%plate(i)%name)) k = i2
               call add_name(list, model%plates(i2)%name)
            end do
            if (k == 0) then
               if (len(list) == 0) list = ' (none)'
               call line_error(state, state%water%plate(i)%at, "undefined plate set '"// &
                  state%water%plate(i)%name//"'; known plate sets (*PLATE):"//list, error)
               return
            end if
            i2 = 0
            if (state%water%plate_side(i)%name == 'LEFT') i2 = 1
            if (state%water%plate_side(i)%name == 'RIGHT') i2 = -1
            if (state%water%plate_side(i)%name == 'FREE') i2 = PLATE_FREE
            if (state%water%plate_step(i) == 0) then
               model%water%plate_side(k) = i2
            else
               model%water%step_plate(k, state%water%plate_step(i)) = i2
            end if
         end do
      end if
      if (allocated(state%water%changes)) then
         do i = 1, size(state%water%changes)
            associate (ch => state%water%changes(i))
               if (ch%reset) model%water%step_reset(ch%step) = .true.
               if (len(ch%level) == 0) cycle
               if (upper(ch%level) == 'NONE') then
                  model%water%step_level(ch%step) = LEVEL_NONE
                  cycle
               end if
               k = 0
               list = ''
               do i2 = 1, size(model%water%levels)
                  if (same_name(model%water%levels(i2)%name, ch%level)) k = i2
                  call add_name(list, model%water%levels(i2)%name)
               end do
               if (k == 0) then
                  if (len(list) == 0) list = ' (none)'
                  call line_error(state, ch%at, "undefined phreatic level '"//ch%level// &
                     "'; known levels (*WATER):"//list//' and NONE', error)
                  return
               end if
               model%water%step_level(ch%step) = k
            end associate
         end do
      end if
   end subroutine resolve_water

end module pecplas_io_deck_reader_water
