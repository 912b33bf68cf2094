!> The small deck of the point driver `pecplas-path` (doc/path.md), read with the main reader's
!> line and field tools (includes, comments, strict numbers, file:line errors):
!>
!>     *INTERFACE_LAW, NAME=j, TYPE=MOHR_COULOMB
!>     KN = 1e4, KT = 5e3, PHI = 30, PSI = 10
!>     *PATH, TYPE=CNL|CND|CNS, SIGMA_N0=100 [, KS=k (CNS only)] [, STEPS=n] [, TAU0=t]
!>     2, -2, 2          ! successive eps_t targets (one = monotonic, several = cycles)
!>     *OUTPUT, FILE=output/paths/name     ! -> name.csv and name.h5
!>     *UNITS                                ! optional: length and stress (doc/path.md)
!>     mm, kPa
!>
!> Everything that can be checked (law parameters, initial stress inside the strength) is
!> checked here, before any output exists.
module pecplas_studies_path_deck
   use iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_base_params, only: params_t
   use pecplas_io_text_lines, only: deck_line_t, read_deck_lines
   use pecplas_io_text_fields, only: keyword_line_t, field_t, parse_keyword_line, keyword_name, &
      split_fields, field_real, parse_real, parse_int, upper, itoa
   use pecplas_joints_laws_type, only: interface_law_t, MODE_OPEN
   use pecplas_joints_laws_factory, only: law_registry_t, default_law_registry
   use pecplas_joints_laws_checks, only: length_unit_metres, LENGTH_UNIT_KEYS
   use pecplas_base_units, only: units_t, parse_units
   implicit none (type, external)
   private

   public :: path_deck_t, read_path_deck
   public :: PATH_CNL, PATH_CND, PATH_CNS, PATH_NAMES

   !> Normal control of a path: constant normal load, displacement or stiffness.
   integer, parameter :: PATH_CNL = 1, PATH_CND = 2, PATH_CNS = 3
   !> Increments of one path (STEPS x number of targets), doc/deck.md "Limits".
   integer, parameter, public :: MAX_PATH_INCREMENTS = 1000000
   character(len=*), parameter :: PATH_NAMES(3) = [character(len=3) :: 'CNL', 'CND', 'CNS']

   type :: path_deck_t
      !> Deck file and the raw text of every file read (provenance for the HDF5 file).
      character(len=:), allocatable :: file, raw
      !> The law, its deck name, type and parameters.
      class(interface_law_t), allocatable :: law
      character(len=:), allocatable :: law_type
      type(params_t) :: params
      !> PATH_CNL, PATH_CND or PATH_CNS; initial stress; CNS stiffness; increments per segment.
      integer :: control = PATH_CNL
      real(wp) :: sigma_n0 = 0.0_wp, tau0 = 0.0_wp, ks = 0.0_wp
      integer :: steps = 100
      !> Successive targets of eps_t.
      real(wp), allocatable :: targets(:)
      !> Output path without extension ('' when not given).
      character(len=:), allocatable :: output
      !> *UNITS (not stated when the deck has none): written next to the results.
      type(units_t) :: units
   end type path_deck_t

contains

   !> Reads and checks the path deck `path`; `registry` adds user laws (default: built-ins).
   subroutine read_path_deck(path, deck, error, registry)
      character(len=*), intent(in) :: path
      type(path_deck_t), intent(out) :: deck
      type(error_t), allocatable, intent(out) :: error
      type(law_registry_t), intent(in), optional :: registry
      type(deck_line_t), allocatable :: lines(:)
      type(keyword_line_t) :: kw
      integer :: i, first, last, law_at, path_at
      character(len=:), allocatable :: name

      call read_deck_lines(path, lines, deck%raw, error)
      if (allocated(error)) return
      deck%file = path
      deck%output = ''
      law_at = 0
      path_at = 0
      i = 1
      do while (i <= size(lines))
         name = keyword_name(lines(i)%text)
         if (len(name) == 0) then
            call deck_error(error, lines(i)%file, lines(i)%line, '', 'data line before any '// &
               "keyword: '"//lines(i)%text//"'")
            return
         end if
         call parse_keyword_line(lines(i), kw, error)
         if (allocated(error)) return
         first = i + 1
         last = i
         do while (last + 1 <= size(lines))
            if (len(keyword_name(lines(last + 1)%text)) > 0) exit
            last = last + 1
         end do
         select case (name)
         case ('*INTERFACE_LAW')
            call once(lines(i), law_at, error)
            if (allocated(error)) return
            law_at = i
            call read_law(lines, i, first, last, kw, deck, error, registry)
         case ('*PATH')
            call once(lines(i), path_at, error)
            if (allocated(error)) return
            path_at = i
            call read_path(lines, i, first, last, kw, deck, error)
         case ('*OUTPUT')
            call kw%check_keys(lines(i), [character(len=4) :: 'FILE'], error)
            if (.not. allocated(error)) call no_data(lines, first, last, error)
            if (.not. allocated(error)) call kw%require(lines(i), 'FILE', deck%output, error)
            if (.not. allocated(error)) call strip_extension(deck%output)
         case ('*UNITS')
            call read_units(lines, i, first, last, deck, error)
         case default
            call deck_error(error, lines(i)%file, lines(i)%line, name, 'unknown keyword '// &
               name//' in a path deck; known keywords: *INTERFACE_LAW *PATH *OUTPUT *UNITS')
         end select
         if (allocated(error)) return
         i = last + 1
      end do
      if (law_at == 0 .or. path_at == 0) then
         call deck_error(error, path, 0, '', 'a path deck needs one *INTERFACE_LAW and one '// &
            '*PATH (missing: '//trim(merge('*INTERFACE_LAW ', '               ', law_at == 0)// &
            merge('*PATH', '     ', path_at == 0))//')')
         return
      end if
      call check_initial_stress(deck, lines(path_at), error)
   end subroutine read_path_deck

   !> *UNITS: one data line naming a length and a stress unit (pecplas_base_units; a point
   !> has no force).
   subroutine read_units(lines, at, first, last, deck, error)
      type(deck_line_t), intent(in) :: lines(:)
      integer, intent(in) :: at, first, last
      type(path_deck_t), intent(inout) :: deck
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: message
      if (last /= first) then
         call deck_error(error, lines(at)%file, lines(at)%line, '*UNITS', 'expected exactly '// &
            'one data line after *UNITS, found '//itoa(last - first + 1))
         return
      end if
      call parse_units(lines(first)%text, deck%units, message, no_force=.true.)
      if (len(message) > 0) call deck_error(error, lines(first)%file, lines(first)%line, &
         '*UNITS', message)
   end subroutine read_units

   subroutine once(line, seen_at, error)
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: seen_at
      type(error_t), allocatable, intent(out) :: error
      if (seen_at > 0) call deck_error(error, line%file, line%line, line%keyword, &
         line%keyword//' given twice (a path deck runs one law on one path)')
   end subroutine once

   subroutine no_data(lines, first, last, error)
      type(deck_line_t), intent(in) :: lines(:)
      integer, intent(in) :: first, last
      type(error_t), allocatable, intent(out) :: error
      if (last >= first) call deck_error(error, lines(first)%file, lines(first)%line, &
         lines(first)%keyword, "unexpected data line '"//lines(first)%text//"'")
   end subroutine no_data

   !> *INTERFACE_LAW, NAME=, TYPE= -- data: KEY = value pairs, built through the registry.
   subroutine read_law(lines, at, first, last, kw, deck, error, registry)
      type(deck_line_t), intent(in) :: lines(:)
      integer, intent(in) :: at, first, last
      type(keyword_line_t), intent(in) :: kw
      type(path_deck_t), intent(inout) :: deck
      type(error_t), allocatable, intent(out) :: error
      type(law_registry_t), intent(in), optional :: registry
      character(len=:), allocatable :: name, text
      integer :: i, pos
      real(wp) :: metres
      logical :: found, ok
      call kw%check_keys(lines(at), [character(len=11) :: 'NAME', 'TYPE', LENGTH_UNIT_KEYS], &
         error)
      if (allocated(error)) return
      call kw%require(lines(at), 'NAME', name, error)
      if (allocated(error)) return
      call kw%require(lines(at), 'TYPE', deck%law_type, error)
      if (allocated(error)) return
      deck%law_type = upper(deck%law_type)
      pos = at
      if (last >= first) pos = first
      deck%params%file = lines(pos)%file
      deck%params%line = lines(pos)%line
      deck%params%keyword = '*INTERFACE_LAW'
      allocate (deck%params%keys(0), deck%params%values(0))
      ! LENGTH_UNIT=MM|M, MODEL_UNIT=MM|M: passed to the law as the unit's size in metres
      do i = 1, size(LENGTH_UNIT_KEYS)
         call kw%get(trim(LENGTH_UNIT_KEYS(i)), text, found)
         if (.not. found) cycle
         call length_unit_metres(upper(text), metres, ok)
         if (.not. ok) then
            call deck_error(error, lines(at)%file, lines(at)%line, lines(at)%keyword, &
               trim(LENGTH_UNIT_KEYS(i))//"='"//text//"' is not a length unit: use MM or M")
            return
         end if
         call deck%params%add(trim(LENGTH_UNIT_KEYS(i)), metres)
      end do
      do i = first, last
         call read_pairs(lines(i), deck%params, error)
         if (allocated(error)) return
      end do
      if (present(registry)) then
         call registry%new_law(deck%law_type, name, deck%params, deck%law, error)
      else
         block
            type(law_registry_t) :: builtin
            builtin = default_law_registry()
            call builtin%new_law(deck%law_type, name, deck%params, deck%law, error)
         end block
      end if
   end subroutine read_law

   !> One data line of `KEY = value` pairs.
   subroutine read_pairs(line, params, error)
      type(deck_line_t), intent(in) :: line
      type(params_t), intent(inout) :: params
      type(error_t), allocatable, intent(out) :: error
      type(field_t), allocatable :: f(:)
      real(wp) :: value
      logical :: ok
      integer :: j
      allocate (f(0))
      call split_fields(line%text, f)
      j = 1
      do while (j <= size(f))
         ok = j + 2 <= size(f) .and. f(j)%s /= '='
         if (ok) ok = f(j + 1)%s == '='
         if (.not. ok) then
            call deck_error(error, line%file, line%line, line%keyword, "expected KEY = value, "// &
               "found '"//line%text//"'")
            return
         end if
         call parse_real(f(j + 2)%s, value, ok)
         if (.not. ok) then
            call deck_error(error, line%file, line%line, line%keyword, 'expected '// &
               upper(f(j)%s)//" as a number, found '"//f(j + 2)%s//"'")
            return
         end if
         if (params%has(f(j)%s)) then
            call deck_error(error, line%file, line%line, line%keyword, 'parameter '// &
               upper(f(j)%s)//' given twice')
            return
         end if
         call params%add(f(j)%s, value)
         j = j + 3
      end do
   end subroutine read_pairs

   !> *PATH, TYPE=, SIGMA_N0= [, KS=] [, STEPS=] [, TAU0=] -- data: eps_t targets.
   subroutine read_path(lines, at, first, last, kw, deck, error)
      type(deck_line_t), intent(in) :: lines(:)
      integer, intent(in) :: at, first, last
      type(keyword_line_t), intent(in) :: kw
      type(path_deck_t), intent(inout) :: deck
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      type(field_t), allocatable :: f(:)
      logical :: found, ok
      real(wp) :: value
      integer :: i, k
      associate (line => lines(at))
         call kw%check_keys(line, [character(len=8) :: 'TYPE', 'SIGMA_N0', 'KS', 'STEPS', &
            'TAU0'], error)
         if (allocated(error)) return
         call kw%require(line, 'TYPE', text, error)
         if (allocated(error)) return
         deck%control = findloc(PATH_NAMES, upper(text), dim=1)
         if (deck%control == 0) then
            call deck_error(error, line%file, line%line, line%keyword, "unknown path TYPE='"// &
               text//"'; known types: CNL (constant normal load), CND (constant normal "// &
               'displacement), CNS (constant normal stiffness)')
            return
         end if
         call real_param(line, kw, 'SIGMA_N0', .true., deck%sigma_n0, error)
         if (allocated(error)) return
         call real_param(line, kw, 'TAU0', .false., deck%tau0, error)
         if (allocated(error)) return
         call real_param(line, kw, 'KS', deck%control == PATH_CNS, deck%ks, error)
         if (allocated(error)) return
         if (kw%has('KS') .and. deck%control /= PATH_CNS) then
            call deck_error(error, line%file, line%line, line%keyword, 'KS is the normal '// &
               'stiffness of a CNS path; remove it or use TYPE=CNS')
            return
         end if
         if (deck%control == PATH_CNS .and. .not. deck%ks > 0.0_wp) then
            call deck_error(error, line%file, line%line, line%keyword, 'KS must be > 0 '// &
               '(CNS: d sigma_n = -KS d eps_n)')
            return
         end if
         call kw%get('STEPS', text, found)
         if (found) then
            call parse_int(text, deck%steps, ok)
            if (.not. ok .or. deck%steps < 1) then
               call deck_error(error, line%file, line%line, line%keyword, 'STEPS must be a '// &
                  "positive integer, found '"//text//"'")
               return
            end if
         end if
      end associate
      allocate (deck%targets(0))
      do i = first, last
         allocate (f(0))
         call split_fields(lines(i)%text, f)
         do k = 1, size(f)
            call field_real(lines(i), f, k, 'a target value of eps_t', value, error)
            if (allocated(error)) return
            deck%targets = [deck%targets, value]
         end do
         deallocate (f)
      end do
      if (size(deck%targets) == 0) call deck_error(error, lines(at)%file, lines(at)%line, &
         '*PATH', 'no target of eps_t: add a data line such as "2.0" (monotonic) or '// &
         '"2, -2, 2" (cycles)')
      if (allocated(error)) return
      ! one row of 7 columns per increment is kept in memory: a cap against typos
      if (int(deck%steps, int64)*size(deck%targets) > MAX_PATH_INCREMENTS) &
         call deck_error(error, lines(at)%file, lines(at)%line, '*PATH', 'STEPS x targets '// &
         'must be <= '//itoa(MAX_PATH_INCREMENTS)//' increments, found '//itoa(deck%steps)// &
         ' x '//itoa(size(deck%targets))//' (see doc/deck.md, Limits)')
   end subroutine read_path

   subroutine real_param(line, kw, key, required, value, error)
      type(deck_line_t), intent(in) :: line
      type(keyword_line_t), intent(in) :: kw
      character(len=*), intent(in) :: key
      logical, intent(in) :: required
      real(wp), intent(inout) :: value
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      logical :: found, ok
      if (required) then
         call kw%require(line, key, text, error)
         if (allocated(error)) return
      else
         call kw%get(key, text, found)
         if (.not. found) return
      end if
      call parse_real(text, value, ok)
      if (.not. ok) call deck_error(error, line%file, line%line, line%keyword, 'expected '// &
         key//" as a number, found '"//text//"'")
   end subroutine real_param

   !> The initial stress must be inside the law's strength: a zero increment from it must
   !> leave it unchanged and in contact. A law that cannot run at all (a spring without its
   !> penalty: the point driver has no massif to take R_max from) is reported at the law.
   subroutine check_initial_stress(deck, line, error)
      type(path_deck_t), intent(in) :: deck
      type(deck_line_t), intent(in) :: line
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: state(:)
      real(wp) :: sigma(2), tangent(2, 2), s0(2)
      character(len=:), allocatable :: message
      integer :: mode
      s0 = [deck%sigma_n0, deck%tau0]
      allocate (state(deck%law%nstate()))
      call deck%law%init_state(s0, state)
      call deck%law%update(s0, [0.0_wp, 0.0_wp], state, sigma, tangent, mode, error)
      if (allocated(error)) then
         message = error%message
         call deck_error(error, deck%params%file, deck%params%line, deck%params%keyword, message)
         return
      end if
      if (mode == MODE_OPEN .or. any(abs(sigma - s0) > 1.0e-12_wp*maxval(abs(s0)))) &
         call deck_error(error, line%file, line%line, line%keyword, 'the initial stress '// &
         '(SIGMA_N0, TAU0) is outside the strength of law '//deck%law%name// &
         ' (tension beyond the cut-off, or |TAU0| above c + SIGMA_N0 tan(phi))')
   end subroutine check_initial_stress

   !> 'out/a.csv' -> 'out/a' (also .h5); other names are kept.
   subroutine strip_extension(name)
      character(len=:), allocatable, intent(inout) :: name
      integer :: n
      n = len(name)
      if (n > 4) then
         if (name(n - 3:n) == '.csv') name = name(1:n - 4)
      end if
      n = len(name)
      if (n > 3) then
         if (name(n - 2:n) == '.h5') name = name(1:n - 3)
      end if
   end subroutine strip_extension

end module pecplas_studies_path_deck
