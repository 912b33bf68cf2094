!> Test curves for the identification: one CNL test = (eps_t, tau, eps_n) at an initial
!> normal stress sigma_n0, in mm and kPa, eps_n closure positive (doc/theory.md §6: dilation < 0).
!> Read from CSV: a header row naming the columns (any order, case-insensitive; others are
!> ignored, so the point driver's `step,eps_t,eps_n,sigma_n,tau,mode,plastic_slip` is read
!> as it is), then one row per point. sigma_n0 is the first row's `sigma_n` when that column
!> exists, else a comment line `# sigma_n0 = 56` (lines starting with '#' are comments).
module pecplas_studies_identify_curves
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error
   use pecplas_base_strings, only: upper
   use pecplas_io_text_lines, only: read_text_file
   use pecplas_io_text_parse, only: parse_real, itoa
   implicit none (type, external)
   private

   public :: test_curve_t, read_test_curve

   !> One CNL test curve.
   type :: test_curve_t
      !> Where it came from (file name or a label).
      character(len=:), allocatable :: file
      !> Initial (constant) normal stress, kPa.
      real(wp) :: sigma_n0 = 0.0_wp
      !> Tangential displacement (mm), shear stress (kPa), normal displacement (mm, closure +).
      real(wp), allocatable :: eps_t(:), tau(:), eps_n(:)
   end type test_curve_t

   type :: cell_t
      character(len=:), allocatable :: s
   end type cell_t

contains

   !> Reads the CSV file `path` into `curve`; errors name the file and line.
   subroutine read_test_curve(path, curve, error)
      character(len=*), intent(in) :: path
      type(test_curve_t), intent(out) :: curve
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text, line
      type(cell_t), allocatable :: cells(:)
      integer :: col(4), start, stop_at, lineno, n, k
      real(wp) :: value(4), comment_sigma
      logical :: found, header_seen, ok, have_comment

      call read_text_file(path, text, found)
      if (.not. found) then
         call input_error(error, 'cannot read the test curve '//path)
         return
      end if
      curve%file = path
      allocate (curve%eps_t(0), curve%tau(0), curve%eps_n(0))
      header_seen = .false.
      have_comment = .false.
      col = 0
      lineno = 0
      start = 1
      n = 0
      do while (start <= len(text))
         stop_at = index(text(start:), new_line('a'))
         if (stop_at == 0) then
            stop_at = len(text) + 1
         else
            stop_at = start + stop_at - 1
         end if
         line = trim(adjustl(strip_cr(text(start:stop_at - 1))))
         start = stop_at + 1
         lineno = lineno + 1
         if (len(line) == 0) cycle
         if (line(1:1) == '#') then
            call sigma_comment(line, comment_sigma, ok)
            if (ok) have_comment = .true.
            cycle
         end if
         call split_csv(line, cells)
         if (.not. header_seen) then
            header_seen = .true.
            do k = 1, size(cells)
               select case (upper(cells(k)%s))
               case ('EPS_T'); col(1) = k
               case ('TAU'); col(2) = k
               case ('EPS_N'); col(3) = k
               case ('SIGMA_N'); col(4) = k
               end select
            end do
            if (any(col(1:3) == 0)) then
               call input_error(error, path//':'//itoa(lineno)//': the header must name the '// &
                  "columns eps_t, tau and eps_n (found '"//line//"')")
               return
            end if
            cycle
         end if
         do k = 1, 4
            value(k) = 0.0_wp
            if (col(k) == 0) cycle
            ok = col(k) <= size(cells)
            if (ok) call parse_real(cells(col(k))%s, value(k), ok)
            if (.not. ok) then
               call input_error(error, path//':'//itoa(lineno)//': expected a number in '// &
                  "column "//itoa(col(k))//" ('"//line//"')")
               return
            end if
         end do
         n = n + 1
         if (n == 1 .and. col(4) > 0) curve%sigma_n0 = value(4)
         curve%eps_t = [curve%eps_t, value(1)]
         curve%tau = [curve%tau, value(2)]
         curve%eps_n = [curve%eps_n, value(3)]
      end do
      if (col(4) == 0) then
         if (.not. have_comment) then
            call input_error(error, path//': no sigma_n column and no "# sigma_n0 = value" '// &
               'comment line: the initial normal stress of the test is unknown')
            return
         end if
         curve%sigma_n0 = comment_sigma
      end if
      if (n < 5) then
         call input_error(error, path//': a test curve needs at least 5 points, found '// &
            itoa(n))
      else if (.not. curve%sigma_n0 > 0.0_wp) then
         call input_error(error, path//': sigma_n0 must be > 0 (compression positive)')
      end if
   end subroutine read_test_curve

   !> '# sigma_n0 = 56' (case-insensitive, blanks free) -> 56.
   subroutine sigma_comment(line, value, ok)
      character(len=*), intent(in) :: line
      real(wp), intent(out) :: value
      logical, intent(out) :: ok
      character(len=:), allocatable :: u
      integer :: k
      value = 0.0_wp
      ok = .false.
      u = upper(line(2:))
      k = index(u, '=')
      if (k == 0) return
      if (upper(u(1:k - 1)) /= 'SIGMA_N0') return
      call parse_real(trim(adjustl(u(k + 1:))), value, ok)
   end subroutine sigma_comment

   !> Splits on commas, keeping empty cells (their position matters in a CSV).
   subroutine split_csv(line, cells)
      character(len=*), intent(in) :: line
      type(cell_t), allocatable, intent(out) :: cells(:)
      integer :: start, k, n
      n = count([(line(k:k) == ',', k=1, len(line))]) + 1
      allocate (cells(n))
      start = 1
      do k = 1, n
         if (k < n) then
            cells(k)%s = trim(adjustl(line(start:start + index(line(start:), ',') - 2)))
            start = start + index(line(start:), ',')
         else
            cells(k)%s = trim(adjustl(line(start:)))
         end if
      end do
   end subroutine split_csv

   pure function strip_cr(s) result(t)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: t
      t = s
      if (len(t) > 0) then
         if (t(len(t):len(t)) == achar(13)) t = t(1:len(t) - 1)
      end if
   end function strip_cr

end module pecplas_studies_identify_curves
