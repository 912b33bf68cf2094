!> Named numeric parameters read from a deck (e.g. `E = 2e4, NU = 0.3`), with the deck
!> position so that a missing or invalid value is reported where it was (not) given.
module pecplas_base_params
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_base_strings, only: upper
   implicit none (type, external)
   private

   public :: params_t

   type :: params_t
      character(len=32), allocatable :: keys(:)
      real(wp), allocatable :: values(:)
      !> Where the parameters were given.
      character(len=:), allocatable :: file, keyword
      integer :: line = 0
      !> Keys another part of the reader takes before these parameters reach their model
      !> (the water keys of *MATERIAL): the unknown-key message lists them too, under `other_what`.
      character(len=32), allocatable :: other_keys(:)
      character(len=:), allocatable :: other_what
   contains
      procedure :: add => params_add
      procedure :: has => params_has
      procedure :: get => params_get
      procedure :: unknown_keys => params_unknown_keys
   end type params_t

contains

   !> Appends (or overwrites) `key = value`; keys are stored upper-case.
   subroutine params_add(this, key, value)
      class(params_t), intent(inout) :: this
      character(len=*), intent(in) :: key
      real(wp), intent(in) :: value
      integer :: k
      if (.not. allocated(this%keys)) then
         allocate (this%keys(0), this%values(0))
      end if
      k = find(this, key)
      if (k > 0) then
         this%values(k) = value
      else
         this%keys = [character(len=32) :: this%keys, upper(key)]
         this%values = [this%values, value]
      end if
   end subroutine params_add

   logical function params_has(this, key)
      class(params_t), intent(in) :: this
      character(len=*), intent(in) :: key
      params_has = find(this, key) > 0
   end function params_has

   !> Value of `key`; `default` when absent, else a deck error naming the key.
   subroutine params_get(this, key, value, error, default)
      class(params_t), intent(in) :: this
      character(len=*), intent(in) :: key
      real(wp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: default
      integer :: k
      k = find(this, key)
      if (k > 0) then
         value = this%values(k)
      else if (present(default)) then
         value = default
      else
         value = 0.0_wp
         call deck_error(error, this%file, this%line, this%keyword, &
            'missing parameter '//upper(key)//' (expected '//upper(key)//' = <number>)')
      end if
   end subroutine params_get

   !> Error if a key is not in `known` (catches typos such as `NUU = 0.3`); the message lists
   !> `known` and, when set, the keys taken by another part of the reader (`other_keys`).
   subroutine params_unknown_keys(this, known, error)
      class(params_t), intent(in) :: this
      character(len=*), intent(in) :: known(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: i, j
      character(len=:), allocatable :: list
      logical :: ok
      if (.not. allocated(this%keys)) return
      do i = 1, size(this%keys)
         ok = .false.
         do j = 1, size(known)
            if (trim(this%keys(i)) == upper(known(j))) ok = .true.
         end do
         if (.not. ok) then
            list = ''
            do j = 1, size(known)
               list = list//' '//upper(trim(known(j)))
            end do
            if (allocated(this%other_keys) .and. allocated(this%other_what)) then
               list = list//'; '//this%other_what//':'
               do j = 1, size(this%other_keys)
                  list = list//' '//upper(trim(this%other_keys(j)))
               end do
            end if
            call deck_error(error, this%file, this%line, this%keyword, 'unknown parameter '// &
               trim(this%keys(i))//'; known parameters:'//list)
            return
         end if
      end do
   end subroutine params_unknown_keys

   integer function find(this, key) result(k)
      class(params_t), intent(in) :: this
      character(len=*), intent(in) :: key
      integer :: i
      k = 0
      if (.not. allocated(this%keys)) return
      do i = 1, size(this%keys)
         if (trim(this%keys(i)) == upper(key)) k = i
      end do
   end function find

end module pecplas_base_params
