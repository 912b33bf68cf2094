!> Output of the point driver: a CSV table (one row per increment, full precision) and an
!> HDF5 file with the same columns as 1-D datasets at the root, described by attributes
!> (program, deck text, law name/type/parameters, path type and its data). Each real
!> dataset has a text attribute `units` (from the deck's *UNITS: length for eps_t, eps_n,
!> plastic_slip and targets, stress for sigma_n and tau; "(not stated)" without *UNITS) and
!> the root has length_unit, force_unit and stress_unit.
module pecplas_studies_path_writers
   use hdf5, only: hid_t, h5fcreate_f, h5fclose_f, H5F_ACC_TRUNC_F
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_run_status, only: RUN_COMPLETED, status_name
   use pecplas_io_results_h5, only: h5_init, h5_write, h5_attr, h5_group, h5_close_group, &
      h5_describe
   use pecplas_joints_laws_type, only: MODE_NAMES
   use pecplas_studies_path_deck, only: path_deck_t, PATH_NAMES, PATH_CNS
   use pecplas_studies_path_driver, only: path_result_t
   implicit none (type, external)
   private

   public :: write_path_csv, write_path_h5, CSV_HEADER

   character(len=*), parameter :: CSV_HEADER = 'step,eps_t,eps_n,sigma_n,tau,mode,plastic_slip'

contains

   !> Writes `res` as CSV (mode as its name: stick, slip, open).
   subroutine write_path_csv(path, res, error)
      character(len=*), intent(in) :: path
      type(path_result_t), intent(in) :: res
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios, i
      open (newunit=u, file=path, status='replace', action='write', iostat=ios)
      if (ios /= 0) then
         call fatal_error(error, 'cannot write '//path//' (does its directory exist?)')
         return
      end if
      write (u, '(a)') CSV_HEADER
      do i = lbound(res%step, 1), ubound(res%step, 1)
         write (u, '(i0,4(",",es24.16e3),",",a,",",es24.16e3)', iostat=ios) res%step(i), &
            res%eps_t(i), res%eps_n(i), res%sigma_n(i), res%tau(i), &
            trim(mode_name(res%mode(i))), res%slip(i)
         if (ios /= 0) exit
      end do
      close (u)
      if (ios /= 0) call fatal_error(error, 'error writing '//path)
   end subroutine write_path_csv

   !> Writes `res` and the run's description to the HDF5 file `path`.
   !> Root attributes status (RUN_COMPLETED, the default, or RUN_STOPPED, written as their
   !> words), complete (1 or 0) and status_message say whether the path reached its last target.
   subroutine write_path_h5(path, deck, res, version, error, status, message)
      character(len=*), intent(in) :: path, version
      type(path_deck_t), intent(in) :: deck
      type(path_result_t), intent(in) :: res
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: status
      character(len=*), intent(in), optional :: message
      integer(hid_t) :: file, law
      integer :: err, i, ended
      call h5_init(error)
      if (allocated(error)) return
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, file, err)
      if (err /= 0) then
         call fatal_error(error, 'cannot create '//path//' (does its directory exist?)')
         return
      end if
      ended = RUN_COMPLETED
      if (present(status)) ended = status
      law = -1
      body: block
         call h5_attr(file, 'program', 'pecplas-path '//version, error)
         if (allocated(error)) exit body
         call h5_attr(file, 'deck_file', deck%file, error)
         if (allocated(error)) exit body
         call h5_attr(file, 'status', status_name(ended), error)
         if (allocated(error)) exit body
         call h5_attr(file, 'complete', merge(1, 0, ended == RUN_COMPLETED), error)
         if (allocated(error)) exit body
         call h5_attr(file, 'status_message', optval_text(message, ''), error)
         if (allocated(error)) exit body
         call h5_attr(file, 'deck_text', deck%raw, error)
         if (allocated(error)) exit body
         call h5_attr(file, 'path_type', PATH_NAMES(deck%control), error)
         if (allocated(error)) exit body
         call h5_attr(file, 'sigma_n0', deck%sigma_n0, error)
         if (allocated(error)) exit body
         call h5_attr(file, 'tau0', deck%tau0, error)
         if (allocated(error)) exit body
         if (deck%control == PATH_CNS) call h5_attr(file, 'ks', deck%ks, error)
         if (allocated(error)) exit body
         call h5_attr(file, 'steps_per_segment', deck%steps, error)
         if (allocated(error)) exit body
         call h5_attr(file, 'mode_names', MODE_NAMES, error)
         if (allocated(error)) exit body
         call h5_attr(file, 'iterations', res%iterations, error)
         if (allocated(error)) exit body
         call h5_write(file, 'targets', deck%targets, error)
         if (allocated(error)) exit body
         call h5_write(file, 'step', res%step, error)
         if (allocated(error)) exit body
         call h5_write(file, 'eps_t', res%eps_t, error)
         if (allocated(error)) exit body
         call h5_write(file, 'eps_n', res%eps_n, error)
         if (allocated(error)) exit body
         call h5_write(file, 'sigma_n', res%sigma_n, error)
         if (allocated(error)) exit body
         call h5_write(file, 'tau', res%tau, error)
         if (allocated(error)) exit body
         call h5_write(file, 'mode', res%mode, error)
         if (allocated(error)) exit body
         call h5_write(file, 'plastic_slip', res%slip, error)
         if (allocated(error)) exit body
         call write_units(file, deck, error)
         if (allocated(error)) exit body
         ! the law: group /law with its name and type, one real attribute per parameter
         call h5_group(file, 'law', law, error)
         if (allocated(error)) exit body
         call h5_attr(law, 'name', deck%law%name, error)
         if (allocated(error)) exit body
         call h5_attr(law, 'type', deck%law_type, error)
         if (allocated(error)) exit body
         ! what the law made of its parameters (e.g. MODJOIN's unit conversion)
         if (len(deck%law%describe()) > 0) call h5_attr(law, 'description', &
            deck%law%describe(), error)
         if (allocated(error)) exit body
         do i = 1, size(deck%params%keys)
            call h5_attr(law, trim(deck%params%keys(i)), deck%params%values(i), error)
            if (allocated(error)) exit
         end do
      end block body
      call h5_close_group(law)
      call h5fclose_f(file, err)
      if (err /= 0 .and. .not. allocated(error)) call fatal_error(error, 'cannot close '//path)
   end subroutine write_path_h5

   !> Root length_unit, force_unit, stress_unit and the `units` of each real dataset.
   subroutine write_units(file, deck, error)
      integer(hid_t), intent(in) :: file
      type(path_deck_t), intent(in) :: deck
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: LENGTHS(4) = [character(len=12) :: 'targets', 'eps_t', &
         'eps_n', 'plastic_slip']
      integer :: i
      associate (u => deck%units)
         call h5_attr(file, 'length_unit', u%of('length'), error)
         if (.not. allocated(error)) call h5_attr(file, 'force_unit', u%of('force'), error)
         if (.not. allocated(error)) call h5_attr(file, 'stress_unit', u%of('stress'), error)
         do i = 1, size(LENGTHS)
            if (.not. allocated(error)) call h5_describe(file, trim(LENGTHS(i)), &
               u%of('length'), error)
         end do
         if (.not. allocated(error)) call h5_describe(file, 'sigma_n', u%of('stress'), error)
         if (.not. allocated(error)) call h5_describe(file, 'tau', u%of('stress'), error)
      end associate
   end subroutine write_units

   pure function mode_name(mode) result(name)
      integer, intent(in) :: mode
      character(len=5) :: name
      name = '?'
      if (mode >= 1 .and. mode <= size(MODE_NAMES)) name = MODE_NAMES(mode)
   end function mode_name

   function optval_text(x, default) result(s)
      character(len=*), intent(in), optional :: x
      character(len=*), intent(in) :: default
      character(len=:), allocatable :: s
      s = default
      if (present(x)) s = x
   end function optval_text

end module pecplas_studies_path_writers
