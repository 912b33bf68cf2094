!> "Did you mean ...?" for an unknown name in an input error: the known names closest to a
!> misspelt keyword, parameter, type or set name (`*MATERAL` -> `*MATERIAL`, `PHY` -> `PHI`,
!> `GOODMAN` -> `GOODMAN4`, `MOHR-COULOMB` -> `MOHR_COULOMB`). Letter case is ignored and
!> `-` counts as `_`; the distance is the optimal string alignment distance (insertions,
!> deletions, substitutions and swaps of two neighbours, each 1), and a name of which the word
!> is the beginning or the end (or the reverse), both of 3 characters or more, counts as
!> distance 1. A known name is suggested when its distance
!> is at most 1 for words of up to 4 characters, 2 beyond: close enough that the word is a
!> typo of it, not another word.
module pecplas_base_suggest
   use pecplas_base_strings, only: upper
   implicit none (type, external)
   private

   public :: did_you_mean, name_distance, with_suggestion

   !> Most names a suggestion lists (the closest, in the order of the list).
   integer, parameter :: MAX_SUGGESTIONS = 3

contains

   !> `message` with the suggestion of `did_you_mean` inserted before its "; known ...:" (or
   !> "; known:") list, when it has one: the unknown word is the first one quoted '...' before
   !> the list, or the word after "unknown parameter "; the names are those of `names_of`.
   !> Other messages are returned as they are.
   function with_suggestion(message) result(text)
      character(len=*), intent(in) :: message
      character(len=:), allocatable :: text
      character(len=:), allocatable :: word, list
      integer :: k, colon, q1, q2, cut
      text = message
      if (index(message, '(did you mean ') > 0) return
      k = index(message, '; known')
      if (k == 0) return
      if (k + 7 > len(message)) return
      if (message(k + 7:k + 7) /= ' ' .and. message(k + 7:k + 7) /= ':') return
      colon = index(message(k:), ':')
      if (colon == 0) return
      ! a message that already gives a hint in parentheses (an Abaqus element name) keeps it
      if (index(message(1:k - 1), ' (') > 0) return
      list = names_of(message(k + colon:))
      q1 = index(message(1:k - 1), "'")
      word = ''
      if (q1 > 0) then
         q2 = index(message(q1 + 1:k - 1), "'")
         if (q2 > 1) word = message(q1 + 1:q1 + q2 - 1)
      else if (index(message(1:k - 1), 'unknown parameter ') > 0) then
         word = message(index(message(1:k - 1), 'unknown parameter ') + 18:k - 1)
         cut = index(word, ' ')
         if (cut > 0) word = word(1:cut - 1)
      end if
      if (len(word) == 0) return
      text = message(1:k - 1)//did_you_mean(word, list)//message(k:)
   end function with_suggestion

   !> The names of a "known ...:" list: up to a remark in parentheses, and with those of the
   !> lists that follow it as "; label: names" (the water parameters after the soil model's).
   function names_of(text) result(list)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: list
      character(len=:), allocatable :: rest, part
      integer :: cut, colon
      list = ''
      rest = text
      do
         cut = index(rest, ';')
         if (cut > 0) then
            part = rest(1:cut - 1)
         else
            part = rest
         end if
         colon = index(part, ':')
         if (len(list) > 0 .and. colon > 0) part = part(colon + 1:)
         if (index(part, ' (') > 0) part = part(1:index(part, ' (') - 1)
         list = list//' '//part
         if (cut == 0) exit
         rest = rest(cut + 1:)
      end do
   end function names_of

   !> ' (did you mean X?)', ' (did you mean X or Y?)', or '' when no name of `known` is close
   !> to `word`. `known`: the names separated by blanks (as the "known ...:" lists of the
   !> messages are written); nothing when the word is one of them (letter case aside).
   function did_you_mean(word, known) result(text)
      character(len=*), intent(in) :: word, known
      character(len=:), allocatable :: text
      character(len=:), allocatable :: w, names(:)
      integer, allocatable :: d(:)
      integer :: i, best, limit, n
      text = ''
      w = key(word)
      if (len(w) == 0) return
      call split_names(known, names)
      if (size(names) == 0) return
      allocate (d(size(names)))
      do i = 1, size(names)
         ! a known name (letter case aside): nothing to suggest (MOHR-COULOMB for MOHR_COULOMB
         ! is not the name itself, and gets one)
         if (upper(names(i)) == upper(word)) return
         d(i) = distance_within(w, key(names(i)), 2)
      end do
      limit = 1
      if (len(w) > 4) limit = 2
      best = minval(d)
      if (best > limit) return
      n = 0
      do i = 1, size(names)
         if (d(i) /= best) cycle
         n = n + 1
         if (n > MAX_SUGGESTIONS) exit
         if (n == 1) then
            text = ' (did you mean '//trim(names(i))
         else
            text = text//' or '//trim(names(i))
         end if
      end do
      text = text//'?)'
   end function did_you_mean

   !> Distance between two names already in comparison form (`key`): 1 when one begins or
   !> ends the other (GOODMAN/GOODMAN4, COULOMB/MOHR_COULOMB; 3 characters or more), else the
   !> optimal string alignment distance.
   pure integer function name_distance(a, b) result(dist)
      character(len=*), intent(in) :: a, b
      integer :: v(0:len(a), 0:len(b))
      integer :: i, j, cost
      if (a == b) then
         dist = 0
         return
      end if
      if (min(len(a), len(b)) >= 3) then
         ! one begins or ends the other: GOODMAN/GOODMAN4, COULOMB/MOHR_COULOMB
         if (ends_with(b, a) .or. ends_with(a, b)) then
            dist = 1
            return
         end if
      end if
      do i = 0, len(a)
         v(i, 0) = i
      end do
      do j = 0, len(b)
         v(0, j) = j
      end do
      do i = 1, len(a)
         do j = 1, len(b)
            cost = merge(0, 1, a(i:i) == b(j:j))
            v(i, j) = min(v(i - 1, j) + 1, v(i, j - 1) + 1, v(i - 1, j - 1) + cost)
            if (i > 1 .and. j > 1) then
               if (a(i:i) == b(j - 1:j - 1) .and. a(i - 1:i - 1) == b(j:j)) &
                  v(i, j) = min(v(i, j), v(i - 2, j - 2) + 1)
            end if
         end do
      end do
      dist = v(len(a), len(b))
   end function name_distance

   !> name_distance(a, b) when the lengths of a and b differ by at most `bound`; otherwise
   !> that difference, a lower bound of the alignment distance (each insertion or deletion
   !> changes the length by 1), or 1 when one name begins or ends the other, as name_distance
   !> says. Which names did_you_mean suggests is the same (its limit is at most `bound`),
   !> without the table of len(a) x len(b) entries: a word of megabytes in a bad deck took
   !> seconds and a gigabyte of memory per known name.
   pure integer function distance_within(a, b, bound) result(dist)
      character(len=*), intent(in) :: a, b
      integer, intent(in) :: bound
      dist = abs(len(a) - len(b))
      if (dist <= bound) then
         dist = name_distance(a, b)
      else if (min(len(a), len(b)) >= 3) then
         if (ends_with(b, a) .or. ends_with(a, b)) dist = 1
      end if
   end function distance_within

   !> True when `part` is the beginning or the end of `whole` (and shorter).
   pure logical function ends_with(whole, part)
      character(len=*), intent(in) :: whole, part
      ends_with = .false.
      if (len(part) >= len(whole)) return
      ends_with = whole(1:len(part)) == part .or. whole(len(whole) - len(part) + 1:) == part
   end function ends_with

   !> Comparison form of a name: upper case, '-' as '_', blanks trimmed.
   function key(s) result(k)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: k
      integer :: i
      k = upper(s)
      do i = 1, len(k)
         if (k(i:i) == '-') k(i:i) = '_'
      end do
   end function key

   !> The blank-separated words of `list`, in order (a word in parentheses, such as the
   !> "(none)" of an empty list, is no name).
   subroutine split_names(list, names)
      character(len=*), intent(in) :: list
      character(len=:), allocatable, intent(out) :: names(:)
      integer :: i, j, n, longest
      n = 0
      longest = 1
      i = 1
      do while (next_word(list, i, j))
         if (list(i:i) /= '(') then
            n = n + 1
            longest = max(longest, j - i + 1)
         end if
         i = j + 1
      end do
      allocate (character(len=longest) :: names(n))
      n = 0
      i = 1
      do while (next_word(list, i, j))
         if (list(i:i) /= '(') then
            n = n + 1
            names(n) = list(i:j)
         end if
         i = j + 1
      end do
   end subroutine split_names

   !> The next blank-separated word of `list` from position i on: list(i:j) (i moved to its
   !> first character); false when only blanks are left.
   logical function next_word(list, i, j) result(found)
      character(len=*), intent(in) :: list
      integer, intent(inout) :: i
      integer, intent(out) :: j
      do while (i <= len(list))
         if (list(i:i) /= ' ') exit
         i = i + 1
      end do
      found = i <= len(list)
      j = i
      if (.not. found) return
      do while (j < len(list))
         if (list(j + 1:j + 1) == ' ') exit
         j = j + 1
      end do
   end function next_word

end module pecplas_base_suggest
