!> Words of the command-line texts (pecplas_cmd_args): a word of its own length, and the
!> wrapping of the --help text and of the usage forms to HELP_WIDTH columns.
module pecplas_cmd_words
   implicit none (type, external)
   private

   public :: word_t, split, wrapped, wrapped_form

   !> Width of the --help text.
   integer, parameter :: HELP_WIDTH = 80

   !> A word of its own length.
   type :: word_t
      character(len=:), allocatable :: s
   end type word_t

contains

   !> `text` wrapped to HELP_WIDTH columns, the lines after the first indented by `indent`;
   !> `label` starts the first line and the text column indent + 1 (the next line when the
   !> label leaves less than two blanks before that column).
   function wrapped(text, label, indent) result(out)
      character(len=*), intent(in) :: text, label
      integer, intent(in) :: indent
      character(len=:), allocatable :: out, line
      type(word_t), allocatable :: words(:)
      character(len=1), parameter :: NL = new_line('a')
      logical :: started
      integer :: i
      words = split(text)
      out = ''
      line = ''
      if (len(label) > 0) then
         if (len(label) + 2 > indent) then
            out = label//NL
            line = repeat(' ', indent)
         else
            line = label//repeat(' ', indent - len(label))
         end if
      end if
      started = .false.
      do i = 1, size(words)
         if (started .and. len(line) + 1 + len(words(i)%s) > HELP_WIDTH) then
            out = out//line//NL
            line = repeat(' ', indent)
            started = .false.
         end if
         if (started) then
            line = line//' '//words(i)%s
         else
            line = line//words(i)%s
            started = .true.
         end if
      end do
      out = out//trim(line)
   end function wrapped

   !> A usage form after `prefix`, wrapped to HELP_WIDTH columns between bracketed groups,
   !> the lines after the first aligned after the program name.
   function wrapped_form(prefix, form) result(out)
      character(len=*), intent(in) :: prefix, form
      character(len=:), allocatable :: out, line
      character(len=1), parameter :: NL = new_line('a')
      integer :: i, depth, start, indent
      out = ''
      line = prefix
      indent = -1
      depth = 0
      start = 1
      do i = 1, len(form) + 1
         if (i <= len(form)) then
            if (form(i:i) == '[') depth = depth + 1
            if (form(i:i) == ']') depth = depth - 1
            if (form(i:i) /= ' ' .or. depth > 0) cycle
         end if
         ! form(start:i - 1): a group (a word outside brackets, or a bracketed group)
         if (i > start) then
            if (indent < 0) then
               line = line//form(start:i - 1)
               indent = len(line) + 1
            else if (len(line) + 1 + i - start > HELP_WIDTH .and. len(line) > indent) then
               out = out//line//NL
               line = repeat(' ', indent)//form(start:i - 1)
            else
               line = line//' '//form(start:i - 1)
            end if
         end if
         start = i + 1
      end do
      out = out//line
   end function wrapped_form

   !> The blank-separated words of `text`.
   function split(text) result(words)
      character(len=*), intent(in) :: text
      type(word_t), allocatable :: words(:)
      integer :: i, j
      allocate (words(0))
      i = 1
      do while (i <= len(text))
         if (text(i:i) == ' ') then
            i = i + 1
            cycle
         end if
         j = index(text(i:), ' ')
         if (j == 0) then
            j = len(text) + 1
         else
            j = i + j - 1
         end if
         words = [words, word_t(text(i:j - 1))]
         i = j
      end do
   end function split

end module pecplas_cmd_words
