!> Bad-deck cases shared by the deck-error suites: each case names a deck, the file, line
!> and keyword its error must name, and up to three words of the message; and the check
!> that a bad deck is refused by the reader and by a run (exit 2, no results file).
module fixtures_bad_decks
   use pecplas_base_error, only: error_t, ERR_INPUT
   use pecplas_base_strings, only: itoa
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_model_type, only: model_t
   use pecplas_problem_type, only: problem_t
   use pecplas_testing, only: check
   implicit none (type, external)
   private
   public :: bad_case_t, bad, run_bad_cases, check_refused, last_line

   type :: bad_case_t
      character(len=40) :: deck = '', file = '', keyword = ''
      integer :: line = 0
      character(len=48) :: words(3) = ''
   end type bad_case_t

contains

   pure function bad(deck, line, keyword, w1, w2, w3, file) result(c)
      character(len=*), intent(in) :: deck, keyword, w1
      integer, intent(in) :: line
      character(len=*), intent(in), optional :: w2, w3, file
      type(bad_case_t) :: c
      c%deck = 'bad_'//deck//'.inp'
      c%file = c%deck
      if (present(file)) c%file = file
      c%line = line
      c%keyword = keyword
      c%words(1) = w1
      if (present(w2)) c%words(2) = w2
      if (present(w3)) c%words(3) = w3
   end function bad

   !> Reads each deck of `dir` and checks kind, file, line, keyword and every word.
   subroutine run_bad_cases(dir, cases, error)
      character(len=*), intent(in) :: dir
      type(bad_case_t), intent(in) :: cases(:)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(model_t) :: model
      character(len=16) :: buf
      integer :: i, j
      do i = 1, size(cases)
         associate (c => cases(i), what => trim(cases(i)%deck)//': ')
            call read_deck(dir//trim(c%deck), model, e)
            call check(error, allocated(e), what//'no error reported')
            if (allocated(error)) return
            call check(error, e%kind == ERR_INPUT, what//'not an input error: '//e%text())
            if (allocated(error)) return
            call check(error, allocated(e%file), what//'no file in: '//e%text())
            if (allocated(error)) return
            call check(error, ends_with(e%file, '/'//trim(c%file)), what//'file should be '// &
               trim(c%file)//': '//e%text())
            if (allocated(error)) return
            write (buf, '(i0)') c%line
            call check(error, e%line == c%line, what//'line should be '//trim(buf)//': '// &
               e%text())
            if (allocated(error)) return
            if (c%line > 0) then
               call check(error, index(e%text(), trim(c%file)//':'//trim(buf)//': ') > 0, &
                  what//'text should name file:line: '//e%text())
               if (allocated(error)) return
            end if
            call check(error, e%keyword == trim(c%keyword), what//'keyword should be '// &
               trim(c%keyword)//': '//e%text())
            if (allocated(error)) return
            do j = 1, size(c%words)
               if (len_trim(c%words(j)) == 0) cycle
               call check(error, index(e%text(), trim(c%words(j))) > 0, what//'message '// &
                  'lacks "'//trim(c%words(j))//'": '//e%text())
               if (allocated(error)) return
            end do
         end associate
      end do
   end subroutine run_bad_cases

   !> Checks that bad deck `deck` is refused: read_deck reports an error whose text names
   !> `deck:N`, N the last line of the deck that reads `marker`, and holds `expect`; run_deck
   !> exits 2 and leaves no results file `results` (removed before the run). Failure messages
   !> start with `label`.
   subroutine check_refused(error, deck, marker, expect, results, label)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: deck, marker, expect, results, label
      type(model_t) :: model
      type(problem_t) :: problem
      type(error_t), allocatable :: e
      integer :: code, u
      logical :: exists
      call read_deck(deck, model, e)
      call check(error, allocated(e), label//' is refused')
      if (allocated(error)) return
      call check(error, index(e%text(), deck//':'//itoa(last_line(deck, marker))) > 0 &
         .and. index(e%text(), expect) > 0, label//': '//e%text())
      if (allocated(error)) return
      open (newunit=u, file=results, status='replace')
      close (u, status='delete')
      code = run_deck(deck, results, .true., model, problem)
      inquire (file=results, exist=exists)
      call check(error, code == 2 .and. .not. exists, label//': exit '// &
         itoa(code)//', results file written: '//merge('yes', 'no ', exists))
   end subroutine check_refused

   !> Number of the last line of file `path` that reads `text`.
   integer function last_line(path, text) result(n)
      character(len=*), intent(in) :: path, text
      character(len=256) :: buf
      integer :: u, i, ios
      n = 0
      open (newunit=u, file=path, status='old', action='read')
      i = 0
      do
         read (u, '(a)', iostat=ios) buf
         if (ios /= 0) exit
         i = i + 1
         if (trim(buf) == text) n = i
      end do
      close (u)
   end function last_line

   pure logical function ends_with(s, tail)
      character(len=*), intent(in) :: s, tail
      ends_with = .false.
      if (len(s) >= len(tail)) ends_with = s(len(s) - len(tail) + 1:) == tail
   end function ends_with

end module fixtures_bad_decks
