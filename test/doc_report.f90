!> Values that tests measure and the documentation quotes (doc/validation.md, doc/theory.md):
!> when the environment variable PECPLAS_REPORT names a file, `report(key, values)` appends
!> one line `key v1 v2 ...` to it; otherwise it does nothing. tools/pecplas_py/docs/validation_report.py runs
!> the suites with it set and writes the generated blocks of the docs from the lines.
module doc_report
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private
   public :: report

   interface report
      module procedure report_one, report_many
   end interface report

contains

   !> Appends `key value` to $PECPLAS_REPORT (nothing when it is unset or empty).
   subroutine report_one(key, value)
      character(len=*), intent(in) :: key
      real(wp), intent(in) :: value
      call report_many(key, [value])
   end subroutine report_one

   !> Appends `key v1 v2 ...` (17 significant digits each) to $PECPLAS_REPORT.
   subroutine report_many(key, values)
      character(len=*), intent(in) :: key
      real(wp), intent(in) :: values(:)
      character(len=4096) :: path
      integer :: n, stat, unit
      call get_environment_variable('PECPLAS_REPORT', path, n, stat)
      if (stat /= 0 .or. n == 0) return
      open (newunit=unit, file=path(1:n), position='append', action='write', status='unknown', &
         iostat=stat)
      if (stat /= 0) return
      write (unit, '(a,*(1x,es24.16e3))') key, values
      close (unit)
   end subroutine report_many

end module doc_report
