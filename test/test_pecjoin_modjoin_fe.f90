!> MODJOIN in the finite-element solver: one GOODMAN4 joint between two stiff blocks
!> (test/data/modjoin/) under a constant normal load, sheared monotonically (improved
!> version, table III.2; also with a GOODMAN6 joint and with two spring doublets) and
!> cyclically (cyclic version, table III.6 Dr = 80 %), with the parameters in mm and the
!> model in metres. The joint points must follow the point
!> driver's CNL curve on the same eps_t path within 0.5 % (the blocks deform by ~1e-6 of
!> the joint displacement; the law is step-size independent to ~1e-5), and the full Newton
!> iteration with the law's tangent must converge quadratically (<= 3 iterations).
module test_pecjoin_modjoin_fe
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_io_results_h5, only: increment_group
   use pecplas_testing, only: unittest_t, new_unittest, check
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_studies_path_driver, only: path_result_t
   use pecplas_studies_path_deck, only: PATH_CNL
   use fixtures_modjoin, only: table_law, run_table_path
   use fixtures_bad_decks, only: bad, run_bad_cases
   implicit none (type, external)
   private
   public :: collect_pecjoin_modjoin_fe

   character(len=*), parameter :: DIR = 'build/test_out/modjoin', DATA = 'test/data/modjoin/'
   !> Point-driver increments per mm of eps_t (0.001 mm).
   integer, parameter :: PER_MM = 1000

contains

   subroutine collect_pecjoin_modjoin_fe(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('fe_cnl_equals_point_driver', test_cnl), &
               new_unittest('fe_cnl_goodman6', test_cnl_goodman6), &
               new_unittest('fe_cnl_spring', test_cnl_spring), &
               new_unittest('fe_cyclic_equals_point_driver', test_cyclic), &
               new_unittest('fe_cnl_force_arc_length', test_force_arc), &
               new_unittest('fe_model_unit_required', test_model_unit), &
               new_unittest('fe_thin_layer_refused', test_thin_layer)]
   end subroutine collect_pecjoin_modjoin_fe

   subroutine test_cnl(error)
      type(error_t), allocatable, intent(out) :: error
      call compare('fe_cnl', 'III.2', 56.0_wp, [6.0_wp], error)
   end subroutine test_cnl

   !> The same path under force control: the slider is pulled by a force above the peak of
   !> tau with arc-length control, which follows tau through the peak and down the softening
   !> branch to 6 mm of slip; the run ends as a limit load (the load fell after its maximum)
   !> and every increment lies on the point driver's CNL curve (within 0.5 %).
   subroutine test_force_arc(error)
      type(error_t), allocatable, intent(out) :: error
      call compare('fe_cnl_force_arc', 'III.2', 56.0_wp, [6.0_wp], error, 'limit load')
   end subroutine test_force_arc

   !> The same with Q8 blocks and a GOODMAN6 joint (3 Gauss points).
   subroutine test_cnl_goodman6(error)
      type(error_t), allocatable, intent(out) :: error
      call compare('fe_cnl_goodman6', 'III.2', 56.0_wp, [6.0_wp], error)
   end subroutine test_cnl_goodman6

   !> The same with two spring doublets (the law works on force per tributary length).
   subroutine test_cnl_spring(error)
      type(error_t), allocatable, intent(out) :: error
      call compare('fe_cnl_spring', 'III.2', 56.0_wp, [6.0_wp], error)
   end subroutine test_cnl_spring

   subroutine test_cyclic(error)
      type(error_t), allocatable, intent(out) :: error
      call compare('fe_cyclic', 'III.6D', 100.0_wp, [2.0_wp, -2.0_wp, 2.0_wp, -2.0_wp, 2.0_wp], &
         error)
   end subroutine test_cyclic

   !> LENGTH_UNIT without MODEL_UNIT in a model deck: input error, no results file.
   subroutine test_model_unit(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      integer :: code
      logical :: exists
      call make_directories(DIR)
      code = run_deck(DATA//'bad_no_model_unit.inp', DIR//'/bad_no_model_unit.h5', .true., &
         model, problem)
      inquire (file=DIR//'/bad_no_model_unit.h5', exist=exists)
      call check(error, code == 2 .and. .not. exists, 'exit code 2 and no results file')
   end subroutine test_model_unit

   !> MODJOIN on a THIN_LAYER joint: the layer hands its law strains (jump / THICKNESS),
   !> MODJOIN's parameters are per length of relative displacement, so the deck is refused
   !> (input error at the *JOINTS line, naming both and the joint types that work).
   subroutine test_thin_layer(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DATA, [bad('thin_layer', 13, '*JOINTS', 'THIN_LAYER', 'MODJOIN', &
         'GOODMAN4')], error)
   end subroutine test_thin_layer

   !> Runs deck `name`, reads (eps, sigma) of both joint points at every increment and
   !> compares them with the point driver on the targets (mm) at the same eps_t.
   !> `status`: the status the run must end with ('completed' when absent).
   subroutine compare(name, table, sigma_n0, targets, error, status)
      character(len=*), intent(in) :: name, table
      real(wp), intent(in) :: sigma_n0, targets(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in), optional :: status
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: rd
      class(interface_law_t), allocatable :: law
      type(path_result_t) :: pd
      real(wp), allocatable :: eps(:, :, :), sig(:, :, :)
      real(wp) :: e_t, tau_ref, en_ref, dtau, den, dsn, prev
      integer :: code, n, k, ip, e, seg, nseg
      character(len=:), allocatable :: ended
      call make_directories(DIR)
      code = run_deck(DATA//name//'.inp', DIR//'/'//name//'.h5', .true., model, problem)
      if (present(status)) then
         call rd%open(DIR//'/'//name//'.h5', error)
         if (allocated(error)) return
         call rd%attribute('/', 'status', ended, error)
         call rd%close()
         if (allocated(error)) return
         call check(error, ended == status, name//': the run ends as '//status//', not '//ended)
      else
         call check(error, code == 0, name//': the run completes')
      end if
      if (allocated(error)) return
      call check(error, problem%stats%iterations <= 3*problem%stats%increments, name// &
         ': full Newton with the law tangent, at most 3 iterations per increment on average')
      if (allocated(error)) return
      ! every segment gets the increments of the longest one (0.001 mm there)
      nseg = nint(max(abs(targets(1)), maxval(abs(targets(2:) - targets(:size(targets) - 1)), &
         mask=size(targets) > 1))*PER_MM)
      call table_law(table, law, error)
      if (.not. allocated(error)) call run_table_path(law, PATH_CNL, sigma_n0, targets, nseg, &
         pd, error)
      if (allocated(error)) return
      call rd%open(DIR//'/'//name//'.h5', error)
      if (allocated(error)) return
      call rd%history_length(n, error)
      if (allocated(error)) return
      dtau = 0.0_wp
      den = 0.0_wp
      dsn = 0.0_wp
      seg = 1
      prev = 0.0_wp
      do k = 1, n
         ! the segment of the FE row: the next target once the previous row reached one
         if (seg < size(targets)) then
            if (abs(prev - targets(seg)) < 1.0e-3_wp) seg = seg + 1
         end if
         call rd%dataset(increment_group(k)//'/joints/joint/relative_displacement', eps, error)
         if (.not. allocated(error)) call rd%dataset(increment_group(k)// &
            '/joints/joint/stress', sig, error)
         if (allocated(error)) return
         do e = 1, size(eps, 3)
            do ip = 1, size(eps, 2)
               e_t = 1.0e3_wp*eps(2, ip, e)
               call driver_at(pd, targets, nseg, seg, e_t, tau_ref, en_ref)
               dtau = max(dtau, abs(sig(2, ip, e) - tau_ref))
               den = max(den, abs(1.0e3_wp*eps(1, ip, e) - en_ref))
               dsn = max(dsn, abs(sig(1, ip, e) - sigma_n0))
            end do
         end do
         prev = 1.0e3_wp*eps(2, 1, 1)
      end do
      call rd%close()
      call check(error, dtau <= 5.0e-3_wp*maxval(abs(pd%tau)), name// &
         ': tau = point driver within 0.5 %')
      if (allocated(error)) return
      call check(error, den <= 5.0e-3_wp*maxval(abs(pd%eps_n)), name// &
         ': eps_n = point driver within 0.5 %')
      if (allocated(error)) return
      call check(error, dsn <= 5.0e-3_wp*sigma_n0, name//': sigma_n = sigma_n0 within 0.5 %')
   end subroutine compare

   !> tau and eps_n of the point driver at eps_t = e on segment `seg` (linear between rows;
   !> the first segment has nseg rows per |targets(2) - targets(1)| scaled to its length).
   subroutine driver_at(pd, targets, nseg, seg, e, tau, en)
      type(path_result_t), intent(in) :: pd
      real(wp), intent(in) :: targets(:), e
      integer, intent(in) :: nseg, seg
      real(wp), intent(out) :: tau, en
      real(wp) :: start, x, t
      integer :: row0, i
      start = 0.0_wp
      if (seg > 1) start = targets(seg - 1)
      row0 = (seg - 1)*nseg
      ! rows of a segment are equally spaced between its start and its target
      x = (e - start)/(targets(seg) - start)*nseg
      x = min(max(x, 0.0_wp), real(nseg, wp))
      i = min(int(x), nseg - 1)
      t = x - i
      tau = (1.0_wp - t)*pd%tau(row0 + i) + t*pd%tau(row0 + i + 1)
      en = (1.0_wp - t)*pd%eps_n(row0 + i) + t*pd%eps_n(row0 + i + 1)
   end subroutine driver_at

end module test_pecjoin_modjoin_fe
