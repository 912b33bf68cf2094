!> Speed of the MODJOIN law (make bench; not part of make test). For each version (tables
!> III.1 initial, III.2 improved, III.6 Dr 80 % cyclic, kPa and mm):
!> - law updates per second, one call = stress + consistent tangent + history, on a CND
!>   path of 0.001 mm increments (one substep each, mostly plastic), cycled +-2 mm for the
!>   cyclic version; and on 0.1 mm increments (100 substeps per call);
!> - wall time of an 8000-increment CNL path 0 -> 8 mm with the point driver (normal
!>   condition by Newton, several updates per increment).
!> Single thread; times from system_clock.
program bench_laws
   use, intrinsic :: iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_params, only: params_t
   use pecplas_joints_laws_type, only: interface_law_t
   use pecplas_joints_laws_factory, only: law_registry_t, default_law_registry
   use pecplas_studies_path_driver, only: path_result_t, run_path
   implicit none (type, external)
   character(len=*), parameter :: TYPES(3) = [character(len=15) :: 'MODJOIN_INITIAL', &
      'MODJOIN', 'MODJOIN_CYCLIC']
   class(interface_law_t), allocatable :: law
   type(error_t), allocatable :: error
   type(path_result_t) :: res
   real(wp) :: rate1, rate100, wall, sink
   integer :: v
   write (*, '(a)') 'MODJOIN law speed (single core): updates/s incl. tangent'
   write (*, '(a16,3a16)') 'version', 'upd/s 0.001mm', 'upd/s 0.1mm', 'CNL 8000 [s]'
   do v = 1, size(TYPES)
      call build(v, law, error)
      if (allocated(error)) then
         write (*, '(a)') error%message
         error stop 1
      end if
      sink = 0.0_wp
      rate1 = update_rate(law, 1.0e-3_wp, sink)
      rate100 = update_rate(law, 0.1_wp, sink)
      wall = now()
      call run_path(law, 1, [56.0_wp, 0.0_wp], 0.0_wp, [8.0_wp], 8000, res, error)
      wall = now() - wall
      if (allocated(error)) error stop 1
      write (*, '(a16,2es16.3,f16.4,a,es10.2)') trim(TYPES(v)), rate1, rate100, wall, &
         '   (check ', sink + res%tau(8000)
   end do

contains

   real(wp) function now() result(t)
      integer(int64) :: c, r
      call system_clock(c, r)
      t = real(c, wp)/real(r, wp)
   end function now

   !> Updates per second along a CND path of increments `d` (mm), +-2 mm cycles, for at
   !> least 0.5 s; `sink` accumulates results so that nothing is optimised away.
   real(wp) function update_rate(law, d, sink) result(rate)
      class(interface_law_t), intent(in) :: law
      real(wp), intent(in) :: d
      real(wp), intent(inout) :: sink
      real(wp), allocatable :: state(:)
      real(wp) :: sigma(2), s_new(2), t(2, 2), t0, dir, eps
      integer :: mode, i, calls
      type(error_t), allocatable :: err
      allocate (state(law%nstate()))
      calls = 0
      t0 = now()
      do
         sigma = [56.0_wp, 0.0_wp]
         call law%init_state(sigma, state)
         dir = 1.0_wp
         eps = 0.0_wp
         do i = 1, nint(16.0_wp/d)
            if (eps >= 2.0_wp - 0.5_wp*d) dir = -1.0_wp
            if (eps <= -2.0_wp + 0.5_wp*d) dir = 1.0_wp
            call law%update(sigma, [0.0_wp, dir*d], state, s_new, t, mode, err)
            if (allocated(err)) error stop 2
            sigma = s_new
            eps = eps + dir*d
            sink = sink + 1.0e-12_wp*t(1, 2)
         end do
         calls = calls + nint(16.0_wp/d)
         if (now() - t0 > 0.5_wp) exit
      end do
      rate = calls/(now() - t0)
   end function update_rate

   subroutine build(v, law, error)
      integer, intent(in) :: v
      class(interface_law_t), allocatable, intent(out) :: law
      type(error_t), allocatable, intent(out) :: error
      type(law_registry_t) :: reg
      type(params_t) :: p
      allocate (p%keys(0), p%values(0))
      call p%add('LENGTH_UNIT', 1.0e-3_wp)
      call p%add('K0', 80.0_wp)
      call p%add('G0', 40.0_wp)
      call p%add('PHI', 41.0_wp)
      call p%add('R0', 0.3_wp)
      call p%add('PSI', 27.0_wp)
      if (v == 1) then
         call p%add('BETA', 9.0_wp)
         call p%add('A_G', 0.5_wp)
      else
         call p%add('BETA', 1.5_wp)
         call p%add('A_G', 0.4_wp)
         call p%add('ALPHA', 0.7_wp)
         call p%add('A', 0.6_wp)
         call p%add('B', 0.96_wp)
      end if
      if (v == 3) then
         ! table III.6 Dr = 80 %
         call p%add('K0', 90.0_wp)
         call p%add('G0', 45.0_wp)
         call p%add('PHI', 37.0_wp)
         call p%add('BETA', 1.2_wp)
         call p%add('ALPHA', 0.75_wp)
         call p%add('A', 0.25_wp)
         call p%add('B', 0.73_wp)
         call p%add('B_CYC', 0.9_wp)
      end if
      reg = default_law_registry()
      call reg%new_law(trim(TYPES(v)), 'bench', p, law, error)
   end subroutine build

end program bench_laws
