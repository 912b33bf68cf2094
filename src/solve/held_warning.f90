!> Warnings about the out-of-balance of the initial (K0) state of a phased deck (doc/deck.md,
!> Phases, "Initial state as a phase"): it is held with the load until the first nil step
!> without changes (no pattern line, no change) releases it, so a deck whose steps all change
!> something never lets it act, nor the water standing on its plates from the start
!> (*PLATE_WATER). One warning after reading (plate water held and no nil step in the deck),
!> one at the end of a run that never released a held out-of-balance larger than round-off.
module pecplas_solve_held_warning
   use pecplas_base_kinds, only: wp
   use pecplas_base_strings, only: itoa
   use pecplas_model_type, only: model_t
   use pecplas_model_columns, only: nodal_columns
   use pecplas_model_phases, only: TARGET_PLATES
   use pecplas_model_phase_plan, only: target_activity
   use pecplas_model_plate_water_sides, only: planned_activity
   use pecplas_model_loads, only: LOAD_GRAVITY
   use pecplas_fe_water_faces, only: add_plate_water
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_progress, only: force_unit
   implicit none (type, external)
   private

   public :: first_nil_step, initial_plate_water, held_start_warning, held_end_warning

   character(len=*), parameter :: ADVICE = 'put a nil step without changes first (a *STEP '// &
      'with no pattern line and no change; doc/deck.md, Phases, "Initial state as a phase")'

contains

   !> The first nil step without changes (no pattern line, no change), which releases the
   !> held out-of-balance (pecplas_phases_start's start_phase), before any safety step (which
   !> releases nothing); 0 when the deck has none.
   integer function first_nil_step(model) result(k)
      type(model_t), intent(in) :: model
      integer :: i
      k = 0
      if (.not. allocated(model%steps)) return
      do i = 1, size(model%steps)
         if (model%steps(i)%safety%on) return
         if (allocated(model%steps(i)%pattern)) then
            if (size(model%steps(i)%pattern) > 0) cycle
         end if
         if (allocated(model%steps(i)%changes)) then
            if (size(model%steps(i)%changes) > 0) cycle
         end if
         k = i
         return
      end do
   end function first_nil_step

   !> The nodal forces (2, nodal_columns) of the water standing on the plates in the K0
   !> state's out-of-balance (pecplas_phases_start's k0_unbalance: the *PLATE_WATER modes
   !> before the first step, every element set active, the joint and plate sets active at
   !> the start, the level of the first step); zero under gravity loading with water, whose
   !> held load holds no water on the plates (the water comes with the gravity pattern).
   function initial_plate_water(model) result(w)
      type(model_t), intent(in) :: model
      real(wp), allocatable :: w(:, :)
      logical, allocatable :: pon(:), eon(:), jon(:)
      allocate (w(2, nodal_columns(model)), source=0.0_wp)
      if (.not. allocated(model%plates) .or. .not. model%water%used()) return
      if (gravity_water(model)) return
      pon = target_activity(model, TARGET_PLATES, 0)
      call planned_activity(model, 0, eon, jon)
      eon = .true.
      call add_plate_water(model, pon, eon, jon, model%water%level_at(1), 0, w)
   end function initial_plate_water

   !> After reading: a phased deck with water standing on its plates from the start and no
   !> nil step without changes: the water is held for the whole run and never loads the
   !> plates ('' otherwise).
   function held_start_warning(model, problem) result(text)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      character(len=:), allocatable :: text
      real(wp) :: wnorm
      text = ''
      if (.not. problem%phase%phased) return
      if (first_nil_step(model) > 0) return
      wnorm = force_norm(model, initial_plate_water(model))
      ! the water's nodal forces are exactly zero where no water stands (p = 0 above the
      ! level, no face): any other value is water
      if (wnorm <= 0.0_wp) return
      text = 'the water standing on plates at the start (*PLATE_WATER LEFT or RIGHT, or FREE '// &
         'on a face free from the start; its nodal forces have the norm '//num(wnorm)// &
         funit(model)// &
         ') is held with the out-of-balance of the initial (K0) state until the first nil '// &
         'step without changes, and this deck has none: the water will never load the '// &
         'plates; '//ADVICE
   end function held_start_warning

   !> At the end of a phased run (any status) whose held out-of-balance of the initial state
   !> was never released and is larger than round-off: larger than the convergence tolerance
   !> times the held load of the initial state (its weight, the water on its faces and plates),
   !> the accuracy every converged state has against its loads; an initial state balanced to
   !> it would move by no more than the solver's own error when released ('' otherwise).
   !> The norms are of the force entries on the free equations (not the plates' moments).
   function held_end_warning(model, problem) result(text)
      type(model_t), intent(in) :: model
      type(problem_t), intent(in) :: problem
      character(len=:), allocatable :: text
      real(wp) :: enorm, wnorm
      integer :: k
      text = ''
      if (.not. problem%phase%phased) return
      if (.not. allocated(problem%phase%unbalanced)) return
      enorm = force_norm(model, problem%phase%unbalanced)
      if (problem%phase%released) return
      if (enorm <= model%solver%tolerance*problem%phase%held0_norm) return
      text = 'the out-of-balance of the initial (K0) state (a sloping surface, a surcharge '// &
         'no pattern holds, the joints'' tractions, water standing on plates) was held to '// &
         'the end of the run and never acted: '
      k = first_nil_step(model)
      if (k == 0) then
         text = text//'no nil step without changes released it (the deck has none)'
      else
         text = text//'the run ended before step '//itoa(k)//" ('"//trim(model%steps(k)%name)// &
            "'), the first nil step without changes, which releases it"
      end if
      text = text//'; the held forces have the norm '//num(enorm)//funit(model)
      if (problem%phase%held0_norm > 0.0_wp) text = text//' ('// &
         num(enorm/problem%phase%held0_norm)//' times that of the held load of the initial state)'
      wnorm = force_norm(model, initial_plate_water(model))
      if (wnorm > 0.0_wp) text = text//', the water standing on plates alone '//num(wnorm)// &
         funit(model)
      if (k > 0) then
         text = text//'; continue the run (--restart) to release it, or '//ADVICE
      else
         text = text//'; '//ADVICE
      end if
   end function held_end_warning

   !> Under gravity loading with groundwater the water comes with the first GRAVITY pattern
   !> (pecplas_phases_start's gravity_pattern: no *INITIAL_STRESS).
   logical function gravity_water(model)
      type(model_t), intent(in) :: model
      integer :: i
      gravity_water = .false.
      if (allocated(model%initial_stresses)) then
         if (size(model%initial_stresses) > 0) return
      end if
      if (.not. allocated(model%patterns)) return
      do i = 1, size(model%patterns)
         if (model%patterns(i)%kind == LOAD_GRAVITY) gravity_water = .true.
      end do
   end function gravity_water

   !> norm2 of the force entries (the node columns; not the plates' rotation columns).
   real(wp) function force_norm(model, f) result(v)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: f(:, :)
      v = norm2(f(:, 1:model%mesh%nnode()))
   end function force_norm

   !> The unit of a nodal force (pecplas_solve_progress's force_unit), or a word on it.
   function funit(model) result(s)
      type(model_t), intent(in) :: model
      character(len=:), allocatable :: s
      s = force_unit(model)
      if (len(s) == 0) s = ' (the deck''s force unit)'
   end function funit

   !> A number with 4 significant digits.
   function num(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=32) :: buf
      write (buf, '(es11.4)') x
      s = trim(adjustl(buf))
   end function num

end module pecplas_solve_held_warning
