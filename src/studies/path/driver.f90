!> Point driver (doc/path.md, thesis §III.2.1.6): integrates one interface law, through the
!> abstract interface_law_t (the very code the joint elements call), on a homogeneous path
!> with eps_t imposed and a mixed normal control per increment:
!>
!>     CNL  d sigma_n = 0                 (constant normal load)
!>     CND  d eps_n   = 0                 (constant normal displacement)
!>     CNS  d sigma_n = -KS d eps_n        (constant normal stiffness; dilation raises sigma_n)
!>
!> For CNL and CNS the normal increment d eps_n solves r(d eps_n) = 0 by Newton with the
!> law's tangent, d r / d(d eps_n) = C(1,1) + KS, every iteration re-calling `update` from the
!> converged state of the previous increment, until |r| <= 1e-10 max(|sigma|); one more
!> Newton step then polishes the root (Newton converges quadratically, so the normal
!> condition then holds to round-off and does not drift over thousands of increments).
module pecplas_studies_path_driver
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, run_error
   use pecplas_joints_laws_type, only: interface_law_t, MODE_STICK
   use pecplas_joints_laws_coulomb, only: plastic_slip
   use pecplas_studies_path_deck, only: PATH_CNL, PATH_CND, PATH_CNS, PATH_NAMES
   use pecplas_base_timers, only: wall_time
   use pecplas_base_progress_eta, only: progress_eta_t
   implicit none (type, external)
   private

   public :: path_result_t, run_path, path_increment

   !> Relative tolerance of the normal condition and the iteration limit.
   real(wp), parameter :: TOL = 1.0e-10_wp
   integer, parameter :: MAX_ITER = 50

   !> One row per increment (row 0 = initial state).
   type :: path_result_t
      integer, allocatable :: step(:), mode(:)
      real(wp), allocatable :: eps_t(:), eps_n(:), sigma_n(:), tau(:), slip(:)
      !> Total number of law updates (Newton iterations) over the path.
      integer :: iterations = 0
   end type path_result_t

contains

   !> Runs `law` from sigma0 = (sigma_n0, tau0) to the successive eps_t `targets`, each
   !> segment in `steps` equal increments; eps are measured from the initial state.
   !> With `progress`, a line with the time left is printed every 5 s; with
   !> `max_seconds` > 0 the path stops (a run error) once that wall time is spent.
   subroutine run_path(law, control, sigma0, ks, targets, steps, res, error, progress, &
         max_seconds)
      class(interface_law_t), intent(in) :: law
      integer, intent(in) :: control, steps
      real(wp), intent(in) :: sigma0(2), ks, targets(:)
      type(path_result_t), intent(out) :: res
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: progress
      real(wp), intent(in), optional :: max_seconds
      real(wp), allocatable :: state(:)
      real(wp) :: sigma(2), sigma_new(2), eps(2), deps_t, deps_n, now
      integer :: n, k, seg, i, mode, iters
      type(progress_eta_t) :: eta
      character(len=32) :: buf

      n = steps*size(targets)
      allocate (res%step(0:n), res%mode(0:n), res%eps_t(0:n), res%eps_n(0:n), &
         res%sigma_n(0:n), res%tau(0:n), res%slip(0:n))
      allocate (state(law%nstate()))
      call law%init_state(sigma0, state)
      sigma = sigma0
      eps = 0.0_wp
      k = 0
      call record(res, k, eps, sigma, MODE_STICK, plastic_slip(law, state))
      call eta%start(wall_time(), n)
      do seg = 1, size(targets)
         deps_t = (targets(seg) - eps(2))/steps
         do i = 1, steps
            call path_increment(law, control, ks, sigma, state, deps_t, deps_n, sigma_new, &
               mode, iters, error)
            res%iterations = res%iterations + iters
            if (allocated(error)) then
               call shrink(res, k)
               return
            end if
            k = k + 1
            eps = eps + [deps_n, deps_t]
            ! the last increment of a segment lands on the target exactly (no round-off drift)
            if (i == steps) eps(2) = targets(seg)
            sigma = sigma_new
            call record(res, k, eps, sigma, mode, plastic_slip(law, state))
            now = wall_time()
            if (present(max_seconds)) then
               if (max_seconds > 0.0_wp .and. now - eta%t0 > max_seconds .and. k < n) then
                  write (buf, '(g0.4)') max_seconds
                  call run_error(error, 'time limit of '//trim(buf)//' s reached (--max-'// &
                     'seconds); '//eta%line(k, now))
                  call shrink(res, k)
                  return
               end if
            end if
            if (present(progress)) then
               if (progress .and. eta%due(now)) write (*, '(a)') ' '//eta%line(k, now)
            end if
         end do
      end do
   end subroutine run_path

   !> One increment d eps_t from the converged (sigma_old, state); returns d eps_n, the new
   !> stress and mode, and updates `state` once converged. `iterations` = law updates.
   subroutine path_increment(law, control, ks, sigma_old, state, deps_t, deps_n, sigma, mode, &
         iterations, error)
      class(interface_law_t), intent(in) :: law
      integer, intent(in) :: control
      real(wp), intent(in) :: ks, sigma_old(2), deps_t
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: deps_n, sigma(2)
      integer, intent(out) :: mode, iterations
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: trial_state(size(state)), tangent(2, 2), r, slope, kc, scale
      character(len=16) :: buf
      logical :: polished

      kc = 0.0_wp
      if (control == PATH_CNS) kc = ks
      deps_n = 0.0_wp
      polished = .false.
      do iterations = 1, MAX_ITER
         trial_state = state
         call law%update(sigma_old, [deps_n, deps_t], trial_state, sigma, tangent, mode, error)
         if (allocated(error)) return
         if (control == PATH_CND) exit
         r = sigma(1) - sigma_old(1) + kc*deps_n
         scale = max(abs(sigma_old(1)), abs(sigma(1)), abs(sigma(2)))
         if (abs(r) <= TOL*scale) then
            if (polished .or. abs(r) <= 1.0e-15_wp*scale) exit
            polished = .true.
         end if
         slope = tangent(1, 1) + kc
         if (.not. slope > 0.0_wp) then
            call run_error(error, PATH_NAMES(control)//' path: the normal stiffness of law '// &
               law%name//' vanished (the interface opened), the normal condition cannot '// &
               'be imposed')
            return
         end if
         deps_n = deps_n - r/slope
      end do
      if (iterations > MAX_ITER) then
         write (buf, '(i0)') MAX_ITER
         call run_error(error, PATH_NAMES(control)//' path: the normal condition did not '// &
            'converge in '//trim(buf)//' iterations')
         return
      end if
      state = trial_state
   end subroutine path_increment

   subroutine record(res, k, eps, sigma, mode, slip)
      type(path_result_t), intent(inout) :: res
      integer, intent(in) :: k, mode
      real(wp), intent(in) :: eps(2), sigma(2), slip
      res%step(k) = k
      res%eps_n(k) = eps(1)
      res%eps_t(k) = eps(2)
      res%sigma_n(k) = sigma(1)
      res%tau(k) = sigma(2)
      res%mode(k) = mode
      res%slip(k) = slip
   end subroutine record

   !> Keeps rows 0..k (the converged part of a path that stopped).
   subroutine shrink(res, k)
      type(path_result_t), intent(inout) :: res
      integer, intent(in) :: k
      call cut_int(res%step, k)
      call cut_int(res%mode, k)
      call cut_real(res%eps_t, k)
      call cut_real(res%eps_n, k)
      call cut_real(res%sigma_n, k)
      call cut_real(res%tau, k)
      call cut_real(res%slip, k)
   end subroutine shrink

   subroutine cut_int(a, k)
      integer, allocatable, intent(inout) :: a(:)
      integer, intent(in) :: k
      integer, allocatable :: tmp(:)
      allocate (tmp(0:k))
      tmp = a(0:k)
      call move_alloc(tmp, a)
   end subroutine cut_int

   subroutine cut_real(a, k)
      real(wp), allocatable, intent(inout) :: a(:)
      integer, intent(in) :: k
      real(wp), allocatable :: tmp(:)
      allocate (tmp(0:k))
      tmp = a(0:k)
      call move_alloc(tmp, a)
   end subroutine cut_real

end module pecplas_studies_path_driver
