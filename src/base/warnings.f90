!> The warnings channel: suspicious but runnable input (an angle that looks like radians, a
!> tensile initial stress, a load no step uses...). A warning never changes the exit code;
!> it is printed on standard error as "file:line: warning: text" and stored in the results
!> file (root attribute `warnings`, doc/results.md). `pecplas --strict` turns the first
!> one into an input error (exit 2, no results file).
module pecplas_base_warnings
   use pecplas_base_error, only: error_t, deck_error, input_error
   implicit none (type, external)
   private

   public :: warnings_t, warning_t

   !> One warning: its text and, when known, the deck position it is about.
   type :: warning_t
      character(len=:), allocatable :: text, file
      integer :: line = 0
   end type warning_t

   type :: warnings_t
      integer :: n = 0
      type(warning_t), allocatable :: items(:)
   contains
      procedure :: add => warnings_add
      procedure :: count => warnings_count
      procedure :: line => warnings_line
      procedure :: lines => warnings_lines
      procedure :: print => warnings_print
      procedure :: as_error => warnings_as_error
      procedure :: merge => warnings_merge
   end type warnings_t

contains

   !> Adds `text` (about deck line `line` of `file`, when given). The same text at the
   !> same place is kept once.
   subroutine warnings_add(this, text, file, line)
      class(warnings_t), intent(inout) :: this
      character(len=*), intent(in) :: text
      character(len=*), intent(in), optional :: file
      integer, intent(in), optional :: line
      type(warning_t) :: w
      type(warning_t), allocatable :: tmp(:)
      integer :: i
      w%text = text
      w%file = ''
      if (present(file)) w%file = file
      if (present(line)) w%line = line
      do i = 1, this%n
         if (this%items(i)%text == w%text .and. this%items(i)%file == w%file .and. &
             this%items(i)%line == w%line) return
      end do
      if (.not. allocated(this%items)) allocate (this%items(4))
      if (this%n == size(this%items)) then
         allocate (tmp(2*this%n))
         tmp(1:this%n) = this%items(1:this%n)
         call move_alloc(tmp, this%items)
      end if
      this%n = this%n + 1
      this%items(this%n) = w
   end subroutine warnings_add

   pure integer function warnings_count(this) result(n)
      class(warnings_t), intent(in) :: this
      n = this%n
   end function warnings_count

   !> Warning i as "file:line: warning: text" (without the position when unknown).
   function warnings_line(this, i) result(s)
      class(warnings_t), intent(in) :: this
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=16) :: buf
      s = ''
      associate (w => this%items(i))
         if (len(w%file) > 0) then
            s = w%file
            if (w%line > 0) then
               write (buf, '(i0)') w%line
               s = s//':'//trim(buf)
            end if
            s = s//': '
         end if
         s = s//'warning: '//w%text
      end associate
   end function warnings_line

   !> All warnings as lines of one fixed length (for a string-list attribute); (0) if none.
   function warnings_lines(this) result(list)
      class(warnings_t), intent(in) :: this
      character(len=:), allocatable :: list(:)
      integer :: i, width
      width = 1
      do i = 1, this%n
         width = max(width, len(this%line(i)))
      end do
      allocate (character(len=width) :: list(this%n))
      do i = 1, this%n
         list(i) = this%line(i)
      end do
   end function warnings_lines

   !> Prints every warning on `unit` (standard error: 0).
   subroutine warnings_print(this, unit)
      class(warnings_t), intent(in) :: this
      integer, intent(in) :: unit
      integer :: i
      do i = 1, this%n
         write (unit, '(a)') this%line(i)
      end do
   end subroutine warnings_print

   !> --strict: the first warning as an input error at its line (nothing when none).
   subroutine warnings_as_error(this, error)
      class(warnings_t), intent(in) :: this
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: more
      character(len=16) :: buf
      if (this%n == 0) return
      more = ''
      if (this%n > 1) then
         write (buf, '(i0)') this%n - 1
         more = ' (and '//trim(buf)//' more warning(s))'
      end if
      associate (w => this%items(1))
         if (len(w%file) > 0) then
            call deck_error(error, w%file, w%line, '', 'warning treated as an error '// &
               '(--strict): '//w%text//more)
         else
            call input_error(error, 'warning treated as an error (--strict): '//w%text//more)
         end if
      end associate
   end subroutine warnings_as_error

   !> Appends the warnings of `other` (e.g. the run's to the deck's).
   subroutine warnings_merge(this, other)
      class(warnings_t), intent(inout) :: this
      type(warnings_t), intent(in) :: other
      integer :: i
      do i = 1, other%n
         call this%add(other%items(i)%text, other%items(i)%file, other%items(i)%line)
      end do
   end subroutine warnings_merge

end module pecplas_base_warnings
