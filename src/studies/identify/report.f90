!> Output of the identification: a table on a unit (per test, then the averaged set beside
!> the thesis's tables), a CSV file (one row per test plus `mean`) and the identified set as
!> an *INTERFACE_LAW data line.
module pecplas_studies_identify_report
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_studies_identify_method, only: identification_t, VERSION_NAMES, VERSION_IMPROVED
   implicit none (type, external)
   private

   public :: print_identification, write_identification_csv, CSV_COLUMNS

   !> Columns of the CSV (k0_modulus = K0 = 2 G0; k0 = start of the hardening variable).
   character(len=*), parameter :: CSV_COLUMNS = 'test,sigma_n0,g_secant,g0,k0_modulus,'// &
      'eps_peak,tau_peak,phi,c,tau_lim,alpha,beta,r0,k0,gamma,a,b,eps_turn,tau_turn,psi,'// &
      'a_g,a_g_rms'

contains

   !> The table: one row per test, then the averaged (regressed) set.
   subroutine print_identification(unit, res)
      integer, intent(in) :: unit
      type(identification_t), intent(in) :: res
      character(len=160) :: line
      character(len=32) :: tail
      integer :: i
      write (unit, '(a,i0,a)') 'MODJOIN identification ('//trim(VERSION_NAMES(res%version))// &
         ' version) from ', size(res%tests), ' CNL test(s); kPa, mm, degrees'
      write (unit, '(a)') '  (thesis III.17-III.20; gamma = hardening variable at the peak; '// &
         'psi at the turn of eps_n)'
      write (unit, '(a)') repeat('-', 132)
      write (unit, '(a)') ' sigma_n0  G_sec     G0  eps_pk  tau_pk  phi_i  tau_lim  alpha'// &
         '   beta     R0     k0  gamma       A      B  eps_tn  tau_tn  psi_i    a_g  rms(eps_n)'
      do i = 1, size(res%tests)
         associate (t => res%tests(i))
            write (line, '(f9.2,f7.2,f7.2,f8.3,f8.2,f7.2,f9.2,f7.3,f7.3,f7.3,f7.3,f7.3,f8.4,'// &
               'f7.3)') t%sigma_n0, t%g_secant, t%g0, t%eps_peak, t%tau_peak, t%phi, t%tau_lim, &
               t%alpha, t%beta, t%r0, t%k0, t%gamma, t%a, t%b
            if (t%turns) then
               write (tail, '(f8.3,f8.2,f7.2)') t%eps_turn, t%tau_turn, t%psi
            else
               tail = '       -       -      -'
            end if
            write (unit, '(a,f7.3,es11.2)') trim(line)//tail(1:23), t%a_g, t%ag_rms
            if (t%asymptote) then
               write (unit, '(a)') '          ('//t%file//'; no peak: tau_pk = asymptote '// &
                  'of the fitted hyperbola, beta = its beta)'
            else
               write (unit, '(a)') '          ('//t%file//')'
            end if
         end associate
      end do
      write (unit, '(a)') repeat('-', 132)
      write (unit, '(a)') 'Identified set (phi, c: regression of tau_peak on sigma_n0; psi: '// &
         'regression through the origin; the rest averaged; K0 = 2 G0 as the thesis):'
      write (unit, '(a)') '  K0 = '//num(res%k0_modulus, 2)//'  G0 = '//num(res%g0, 3)// &
         '  phi = '//num(res%phi, 3)//'  c = '//num(res%c, 3)//'  R0 = '//num(res%r0, 3)// &
         '  beta = '//num(res%beta, 3)//'  alpha = '//num(res%alpha, 4)//'  A = '// &
         num(res%a, 4)//'  B = '//num(res%b, 3)//'  psi = '//num(res%psi, 3)//'  a_g = '// &
         num(res%a_g, 3)
      if (res%version == VERSION_IMPROVED) then
         write (unit, '(a)') '  thesis table III.2 (dense, improved): K0 = 80  G0 = 40  '// &
            'phi = 41  c = 0  R0 = 0.3  beta = 1.5  alpha = 0.7  A = 0.6  B = 0.96  '// &
            'psi = 27  a_g = 0.4'
         write (unit, '(a)') '  thesis table III.5 (medium, improved): K0 = 70  G0 = 35  '// &
            'phi = 37  c = 0  R0 = 0.2  beta = 1.8  alpha = 0.84  A = 0.15  B = 0.7  '// &
            'psi = 30  a_g = 0.4'
      else
         write (unit, '(a)') '  thesis table III.1 (dense, initial): K = 80  G = 40  '// &
            'phi = 41  c = 0  R0 = 0.3  beta = 9.0  psi = 27  a_g = 0.5'
      end if
   end subroutine print_identification

   !> CSV: one row per test, then a row `mean` with the identified set (cells that belong
   !> to a single test left empty there).
   subroutine write_identification_csv(path, res, error)
      character(len=*), intent(in) :: path
      type(identification_t), intent(in) :: res
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: turn
      integer :: u, ios, i
      open (newunit=u, file=path, status='replace', action='write', iostat=ios)
      if (ios /= 0) then
         call fatal_error(error, 'cannot write '//path//' (does its directory exist?)')
         return
      end if
      write (u, '(a)') CSV_COLUMNS
      do i = 1, size(res%tests)
         associate (t => res%tests(i))
            if (t%turns) then
               turn = cells([t%eps_turn, t%tau_turn, t%psi])
            else
               turn = ',,,'
            end if
            write (u, '(a)') csv_name(t%file)//cells([t%sigma_n0, t%g_secant, t%g0, &
               2.0_wp*t%g0, t%eps_peak, t%tau_peak, t%phi, res%c, t%tau_lim, t%alpha, t%beta, &
               t%r0, t%k0, t%gamma, t%a, t%b])//turn//cells([t%a_g, t%ag_rms])
         end associate
      end do
      write (u, '(a)') 'mean,,'//cells([res%g0, res%k0_modulus])//',,'// &
         cells([res%phi, res%c])//','//cells([res%alpha, res%beta, res%r0])//',,'// &
         cells([res%a, res%b])//',,'//cells([res%psi, res%a_g])//','
      close (u)
   end subroutine write_identification_csv

   !> x with d decimals, no blanks (0.313, not .313).
   pure function num(x, d) result(s)
      real(wp), intent(in) :: x
      integer, intent(in) :: d
      character(len=:), allocatable :: s
      character(len=32) :: buf
      character(len=12) :: f
      write (f, '(a,i0,a)') '(f24.', d, ')'
      ! no '-0.000' for a value that rounds to zero
      write (buf, f) merge(0.0_wp, x, abs(x) < 0.5_wp*10.0_wp**(-d))
      s = trim(adjustl(buf))
   end function num

   !> ',v1,v2,...' with full precision.
   pure function cells(v) result(s)
      real(wp), intent(in) :: v(:)
      character(len=:), allocatable :: s
      character(len=32) :: buf
      integer :: i
      s = ''
      do i = 1, size(v)
         write (buf, '(es23.15e3)') v(i)
         s = s//','//trim(adjustl(buf))
      end do
   end function cells

   !> A file name as one CSV cell (commas would split it).
   pure function csv_name(s) result(t)
      character(len=*), intent(in) :: s
      character(len=len(s)) :: t
      integer :: i
      t = s
      do i = 1, len(t)
         if (t(i:i) == ',') t(i:i) = ';'
      end do
   end function csv_name

end module pecplas_studies_identify_report
