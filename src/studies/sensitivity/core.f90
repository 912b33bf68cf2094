!> Sensitivity of an interface law to its parameters on homogeneous paths (thesis §III.3.2,
!> doc/identify.md): each parameter p is perturbed by +/- a fraction of its value, the paths are run
!> with the reference and both perturbed sets, and for every output curve y(eps_t)
!>
!>     Q_p = sum_i (y_i^+ - y_i^-)^2 / sum_i (y_i^0)^2                     (III.21)
!>
!> then normalised (in %) by its largest value over the parameters, curve by curve (the
!> perturbation fractions differ, so only this normalised ranking compares them: table III.4).
!> The paths run through an abstract `path_runner_t`: `law_path_runner_t` builds a law of
!> the registry from KEY = value parameters and calls the point driver; a test may plug in
!> any other response.
module pecplas_studies_sensitivity_core
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_joints_laws_factory, only: law_registry_t
   use pecplas_studies_path_driver, only: path_result_t, run_path
   implicit none (type, external)
   private

   public :: path_runner_t, law_path_runner_t, curve_spec_t, sensitivity_t, sensitivity_study
   public :: curve_values, OUT_TAU, OUT_EPS_N, OUT_SIGMA_N, OUT_NAMES

   !> Output of a path used as a curve y(eps_t).
   integer, parameter :: OUT_TAU = 1, OUT_EPS_N = 2, OUT_SIGMA_N = 3
   character(len=*), parameter :: OUT_NAMES(3) = [character(len=7) :: 'tau', 'eps_n', 'sigma_n']

   !> Something that runs a homogeneous path for a parameter set.
   type, abstract :: path_runner_t
   contains
      procedure(run_ifc), deferred :: run
   end type path_runner_t

   abstract interface
      !> Runs path `control` (PATH_CNL, ...) from (sigma_n0, 0) to the eps_t `targets` in
      !> `steps` increments per segment; on a run error `res` holds the converged rows.
      subroutine run_ifc(this, params, control, sigma_n0, targets, steps, res, error)
         import :: path_runner_t, params_t, wp, path_result_t, error_t
         class(path_runner_t), intent(in) :: this
         type(params_t), intent(in) :: params
         integer, intent(in) :: control, steps
         real(wp), intent(in) :: sigma_n0, targets(:)
         type(path_result_t), intent(out) :: res
         type(error_t), allocatable, intent(out) :: error
      end subroutine run_ifc
   end interface

   !> The point driver on a law of the registry (`law_type` as in *INTERFACE_LAW, TYPE=).
   type, extends(path_runner_t) :: law_path_runner_t
      character(len=:), allocatable :: law_type
      type(law_registry_t) :: registry
   contains
      procedure :: run => law_runner_run
   end type law_path_runner_t

   !> One curve of the study: output `output` of path `control`.
   type :: curve_spec_t
      integer :: control = 1, output = OUT_TAU
   end type curve_spec_t

   !> Result: per parameter (rows) and curve (columns).
   type :: sensitivity_t
      character(len=32), allocatable :: keys(:)
      real(wp), allocatable :: fractions(:)
      !> False when the parameter is not in the reference set (then Q = 0).
      logical, allocatable :: used(:)
      !> Q_p (III.21) and Q_p normalised by each column's maximum (%).
      real(wp), allocatable :: q(:, :), q_percent(:, :)
      !> A perturbed path stopped early: Q over the rows both reached (flagged in reports).
      logical, allocatable :: short(:, :)
   end type sensitivity_t

contains

   subroutine law_runner_run(this, params, control, sigma_n0, targets, steps, res, error)
      class(law_path_runner_t), intent(in) :: this
      type(params_t), intent(in) :: params
      integer, intent(in) :: control, steps
      real(wp), intent(in) :: sigma_n0, targets(:)
      type(path_result_t), intent(out) :: res
      type(error_t), allocatable, intent(out) :: error
      class(interface_law_t), allocatable :: law
      call this%registry%new_law(this%law_type, 'sensitivity', params, law, error)
      if (allocated(error)) return
      call run_path(law, control, [sigma_n0, 0.0_wp], 0.0_wp, targets, steps, res, error)
   end subroutine law_runner_run

   !> The study: `keys(i)` perturbed by +/- `fractions(i)` (0.3 = 30 %) around `base`, on
   !> the `curves`, every path from sigma_n0 to `targets`. A reference path that fails, or a
   !> perturbed set the law refuses, is an error naming the parameter.
   subroutine sensitivity_study(runner, base, keys, fractions, curves, sigma_n0, targets, &
         steps, res, error)
      class(path_runner_t), intent(in) :: runner
      type(params_t), intent(in) :: base
      character(len=*), intent(in) :: keys(:)
      real(wp), intent(in) :: fractions(:), sigma_n0, targets(:)
      type(curve_spec_t), intent(in) :: curves(:)
      integer, intent(in) :: steps
      type(sensitivity_t), intent(out) :: res
      type(error_t), allocatable, intent(out) :: error
      type(path_result_t), allocatable :: ref(:), plus(:), minus(:)
      type(params_t) :: p
      type(error_t), allocatable :: run_err
      integer, allocatable :: controls(:)
      real(wp) :: v
      integer :: i, j, c

      controls = unique_controls(curves)
      allocate (ref(size(controls)), plus(size(controls)), minus(size(controls)))
      do c = 1, size(controls)
         call runner%run(base, controls(c), sigma_n0, targets, steps, ref(c), error)
         if (allocated(error)) then
            error%message = 'reference path: '//error%message
            return
         end if
      end do
      allocate (res%keys(size(keys)), res%fractions(size(keys)), res%used(size(keys)))
      allocate (res%q(size(keys), size(curves)), res%q_percent(size(keys), size(curves)))
      allocate (res%short(size(keys), size(curves)))
      res%keys = keys
      res%fractions = fractions
      res%q = 0.0_wp
      res%short = .false.
      do i = 1, size(keys)
         res%used(i) = base%has(keys(i))
         if (.not. res%used(i)) cycle
         call base%get(keys(i), v, error)
         if (allocated(error)) return
         do c = 1, size(controls)
            p = base
            call p%add(keys(i), v*(1.0_wp + fractions(i)))
            call runner%run(p, controls(c), sigma_n0, targets, steps, plus(c), run_err)
            if (allocated(run_err)) call refused(run_err, plus(c), keys(i), '+', error)
            if (allocated(error)) return
            p = base
            call p%add(keys(i), v*(1.0_wp - fractions(i)))
            call runner%run(p, controls(c), sigma_n0, targets, steps, minus(c), run_err)
            if (allocated(run_err)) call refused(run_err, minus(c), keys(i), '-', error)
            if (allocated(error)) return
         end do
         do j = 1, size(curves)
            c = findloc(controls, curves(j)%control, dim=1)
            call q_ratio(ref(c), plus(c), minus(c), curves(j)%output, res%q(i, j), &
               res%short(i, j))
         end do
      end do
      do j = 1, size(curves)
         res%q_percent(:, j) = 0.0_wp
         if (maxval(res%q(:, j)) > 0.0_wp) res%q_percent(:, j) = 100.0_wp*res%q(:, j)/ &
            maxval(res%q(:, j))
      end do
   end subroutine sensitivity_study

   !> A perturbed run that produced no row (the law refused the set) is an error; one
   !> that stopped on the way keeps its rows.
   subroutine refused(run_err, res, key, sign, error)
      type(error_t), intent(in) :: run_err
      type(path_result_t), intent(in) :: res
      character(len=*), intent(in) :: key, sign
      type(error_t), allocatable, intent(out) :: error
      if (allocated(res%step)) then
         if (ubound(res%step, 1) >= 1) return
      end if
      allocate (error, source=run_err)
      error%message = 'parameter '//trim(key)//' perturbed '//sign//': '//run_err%message
   end subroutine refused

   !> (III.21) over the rows that the three runs share.
   subroutine q_ratio(ref, plus, minus, output, q, short)
      type(path_result_t), intent(in) :: ref, plus, minus
      integer, intent(in) :: output
      real(wp), intent(out) :: q
      logical, intent(out) :: short
      real(wp), allocatable :: y0(:), yp(:), ym(:)
      integer :: n
      n = min(ubound(ref%step, 1), ubound(plus%step, 1), ubound(minus%step, 1))
      short = n < ubound(ref%step, 1)
      y0 = curve_values(ref, output)
      yp = curve_values(plus, output)
      ym = curve_values(minus, output)
      ! function results start at 1: rows 0..n are elements 1..n+1
      q = 0.0_wp
      if (sum(y0(1:n + 1)**2) > 0.0_wp) q = sum((yp(1:n + 1) - ym(1:n + 1))**2)/ &
         sum(y0(1:n + 1)**2)
   end subroutine q_ratio

   !> The output `output` of a path result (rows 0..n of the result as elements 1..n+1).
   function curve_values(res, output) result(y)
      type(path_result_t), intent(in) :: res
      integer, intent(in) :: output
      real(wp), allocatable :: y(:)
      select case (output)
      case (OUT_TAU)
         y = res%tau
      case (OUT_EPS_N)
         y = res%eps_n
      case default
         y = res%sigma_n
      end select
   end function curve_values

   function unique_controls(curves) result(controls)
      type(curve_spec_t), intent(in) :: curves(:)
      integer, allocatable :: controls(:)
      integer :: j
      allocate (controls(0))
      do j = 1, size(curves)
         if (findloc(controls, curves(j)%control, dim=1) == 0) &
            controls = [controls, curves(j)%control]
      end do
   end function unique_controls

end module pecplas_studies_sensitivity_core
