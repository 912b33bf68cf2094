!> Output of the sensitivity study in the layout of table III.4: one row per parameter with
!> its perturbation, then per curve our normalised Q_p (%) beside the thesis's value, the
!> ranking of the parameters per curve, and a CSV with the raw and normalised Q_p.
module pecplas_studies_sensitivity_report
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_strings, only: upper
   use pecplas_studies_sensitivity_core, only: sensitivity_t
   use pecplas_studies_sensitivity_thesis, only: THESIS_KEYS, THESIS_LABELS, TABLE_III4
   implicit none (type, external)
   private

   public :: print_sensitivity, write_sensitivity_csv, ranking, thesis_value

contains

   !> Table III.4's value for `key` and curve `j` (-1 when the thesis has none).
   pure real(wp) function thesis_value(key, j) result(v)
      character(len=*), intent(in) :: key
      integer, intent(in) :: j
      integer :: k
      v = -1.0_wp
      if (j < 1 .or. j > size(TABLE_III4, 2)) return
      k = findloc(THESIS_KEYS, upper(key), dim=1)
      if (k > 0) v = TABLE_III4(k, j)
   end function thesis_value

   !> Indices of the used parameters by decreasing value of `q` (ties keep the order).
   pure function ranking(q, used) result(order)
      real(wp), intent(in) :: q(:)
      logical, intent(in) :: used(:)
      integer, allocatable :: order(:)
      integer :: i, j, t
      order = pack([(i, i=1, size(q))], used)
      do i = 2, size(order)
         j = i
         do while (j > 1)
            if (.not. q(order(j)) > q(order(j - 1))) exit
            t = order(j)
            order(j) = order(j - 1)
            order(j - 1) = t
            j = j - 1
         end do
      end do
   end function ranking

   !> The table on `unit`; `labels(j)` names curve j (the thesis column j beside it when
   !> `with_thesis`: the law is MODJOIN).
   subroutine print_sensitivity(unit, res, labels, title, with_thesis)
      integer, intent(in) :: unit
      type(sensitivity_t), intent(in) :: res
      character(len=*), intent(in) :: labels(:), title
      logical, intent(in) :: with_thesis
      character(len=:), allocatable :: line
      character(len=16) :: cell
      integer :: i, j
      integer, allocatable :: ours(:), theirs(:)
      real(wp) :: tv(size(res%keys))
      write (unit, '(a)') title
      write (unit, '(a)') '  Q_p = sum (y+ - y-)^2 / sum (y0)^2 (III.21), normalised by the '// &
         'largest of each curve (%); thesis = table III.4'
      line = 'parameter  perturb.'
      do j = 1, size(labels)
         line = line//' | '//adjustl_to(labels(j), 17)
      end do
      write (unit, '(a)') line
      line = repeat(' ', 19)
      do j = 1, size(labels)
         line = line//' |    ours   thesis'
      end do
      write (unit, '(a)') line
      write (unit, '(a)') repeat('-', 19 + 20*size(labels))
      do i = 1, size(res%keys)
         write (cell, '(a,i0,a)') '+/-', nint(100.0_wp*res%fractions(i)), '%'
         line = adjustl_to(label_of(res%keys(i)), 10)//' '//adjustl_to(cell, 8)
         do j = 1, size(labels)
            if (res%used(i)) then
               write (cell, '(f8.2)') res%q_percent(i, j)
               if (res%short(i, j)) cell(9:9) = '*'
            else
               cell = '       -'
            end if
            line = line//' | '//cell(1:9)
            if (with_thesis .and. thesis_value(res%keys(i), j) >= 0.0_wp) then
               write (cell, '(f8.2)') thesis_value(res%keys(i), j)
            else
               cell = '       -'
            end if
            line = line//cell(1:8)
         end do
         write (unit, '(a)') line
      end do
      write (unit, '(a)') repeat('-', 19 + 20*size(labels))
      if (any(res%short)) write (unit, '(a)') '  * a perturbed path stopped early: Q_p '// &
         'over the increments it reached'
      do j = 1, size(labels)
         ours = ranking(res%q(:, j), res%used)
         do i = 1, size(res%keys)
            tv(i) = thesis_value(res%keys(i), j)
         end do
         theirs = ranking(tv, res%used .and. tv >= 0.0_wp)
         line = '  ranking '//adjustl_to(labels(j), 16)//' ours:'//names(res%keys, ours)
         if (with_thesis) line = line//'   thesis:'//names(res%keys, theirs)
         write (unit, '(a)') line
      end do
   end subroutine print_sensitivity

   !> CSV: key, fraction, then per curve q, percent, thesis (empty when none or not
   !> `with_thesis`), short (1 when a perturbed path stopped early).
   subroutine write_sensitivity_csv(path, res, labels, with_thesis, error)
      character(len=*), intent(in) :: path
      type(sensitivity_t), intent(in) :: res
      character(len=*), intent(in) :: labels(:)
      logical, intent(in) :: with_thesis
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: line
      character(len=64) :: buf
      integer :: u, ios, i, j
      open (newunit=u, file=path, status='replace', action='write', iostat=ios)
      if (ios /= 0) then
         call fatal_error(error, 'cannot write '//path//' (does its directory exist?)')
         return
      end if
      line = 'parameter,fraction'
      do j = 1, size(labels)
         line = line//',q_'//slug(labels(j))//',percent_'//slug(labels(j))//',thesis_'// &
            slug(labels(j))//',short_'//slug(labels(j))
      end do
      write (u, '(a)') line
      do i = 1, size(res%keys)
         line = trim(res%keys(i))//','//real_text(res%fractions(i))
         do j = 1, size(labels)
            if (res%used(i)) then
               line = line//','//real_text(res%q(i, j))//','//real_text(res%q_percent(i, j))
            else
               line = line//',,'
            end if
            buf = ''
            if (with_thesis .and. thesis_value(res%keys(i), j) >= 0.0_wp) &
               buf = real_text(thesis_value(res%keys(i), j))
            line = line//','//trim(buf)//','//trim(merge('1', '0', res%short(i, j)))
         end do
         write (u, '(a)') line
      end do
      close (u)
   end subroutine write_sensitivity_csv

   function real_text(x) result(s)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=32) :: buf
      write (buf, '(es23.15e3)') x
      s = trim(adjustl(buf))
   end function real_text

   function names(keys, order) result(s)
      character(len=*), intent(in) :: keys(:)
      integer, intent(in) :: order(:)
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, size(order)
         s = s//' '//label_of(keys(order(i)))
      end do
   end function names

   !> The thesis's spelling of a deck key (phi for PHI, a_g for A_G), else the key.
   function label_of(key) result(s)
      character(len=*), intent(in) :: key
      character(len=:), allocatable :: s
      integer :: k
      k = findloc(THESIS_KEYS, upper(key), dim=1)
      if (k > 0) then
         s = trim(THESIS_LABELS(k))
      else
         s = trim(key)
      end if
   end function label_of

   pure function adjustl_to(s, n) result(t)
      character(len=*), intent(in) :: s
      integer, intent(in) :: n
      character(len=n) :: t
      t = adjustl(s)
   end function adjustl_to

   !> 'CNL eps_t-tau' -> 'cnl_eps_t_tau'.
   pure function slug(s) result(t)
      character(len=*), intent(in) :: s
      character(len=len_trim(s)) :: t
      integer :: i, c
      t = trim(s)
      do i = 1, len(t)
         c = iachar(t(i:i))
         if (c >= 65 .and. c <= 90) t(i:i) = achar(c + 32)
         if (t(i:i) == ' ' .or. t(i:i) == '-') t(i:i) = '_'
      end do
   end function slug

end module pecplas_studies_sensitivity_report
