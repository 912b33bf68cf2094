!> The K0 state with Lobatto (Newton–Cotes) joints (doc/theory.md, "Lobatto joints and the
!> initial state"): a Lobatto joint lumps its forces on the doublets, so a linear initial
!> stress along it would get nodal forces other than the consistent ones the massif beside
!> it takes (Gauss rule); the joint adds the difference, so the K0 state is at rest and its
!> points keep K0 sigma'_v. Registered in the water suite (test_water).
module test_joint_k0_lobatto
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_testing, only: check
   use fixtures_runs, only: run_completes
   use fixtures_held_wall, only: write_held_wall
   implicit none (type, external)
   private
   public :: test_k0_lobatto_at_rest

   character(len=*), parameter :: OUT = 'build/test_out/water/'
   !> Surface, level (on a node), K0, gamma_unsat, gamma_sat, gamma_w, joint stiffness KN.
   real(wp), parameter :: H = 10.0_wp, LEVEL = 6.0_wp, K0 = 0.5_wp, GU = 18.0_wp, &
      GS = 20.0_wp, GW = 10.0_wp, KN = 1.0e6_wp
   integer, parameter :: NE = 5

contains

   !> A wall at x = 0 (a plate held at every node), one column of five 2 m Q4 on its right,
   !> base held, right side on rollers, joined by five GOODMAN4 joints with
   !> INTEGRATION=LOBATTO; the K0 procedure (K0 = 0.5), a nil step; with the level y = 6 on a
   !> node and without water. Before the consistent forces, the top joint's lumped force
   !> missed L (sigma_2 - sigma_1) / 6 = 6 kN/m at the surface node: the nil step moved the
   !> soil by about 6e-6 m and the top point took 5.9 kPa. Now the state is in discrete
   !> equilibrium, to the round-off of its forces (eps |f| ~ 1e-13 kN against the soil's
   !> stiffness ~ 1e4 kN/m, ~1e-17 m): the bound max |u| < 1e-12 m, and each joint point's
   !> sigma'_n = K0 sigma'_v(y) and tau = 0 to KN x 1e-12 = 1e-6 kPa.
   subroutine test_k0_lobatto_at_rest(error)
      type(error_t), allocatable, intent(out) :: error
      call one_case(.true., error)
      if (allocated(error)) return
      call one_case(.false., error)
   end subroutine test_k0_lobatto_at_rest

   subroutine one_case(water, error)
      logical, intent(in) :: water
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: file
      real(wp), allocatable :: st(:, :, :), xy(:, :, :)
      character(len=:), allocatable :: deck, name
      character(len=80) :: msg
      real(wp) :: y, sv, worst, l
      integer :: e, ip
      call make_directories(OUT)
      name = 'k0_lobatto_dry'
      if (water) name = 'k0_lobatto_wet'
      deck = OUT//name//'.inp'
      l = H/NE
      if (water) then
         call write_held_wall(deck, NE, l, 2.0_wp, GS, K0, 'LOBATTO', LEVEL)
      else
         call write_held_wall(deck, NE, l, 2.0_wp, GS, K0, 'LOBATTO')
      end if
      call run_completes(error, deck, OUT//name//'.h5', model, problem, 'K0, Lobatto joints')
      if (allocated(error)) return
      call check(error, maxval(abs(problem%state%u)) < 1.0e-12_wp, &
         name//': the K0 state stays at rest under a nil step (max |u| < 1e-12 m)')
      if (allocated(error)) return
      call file%open(OUT//name//'.h5', error)
      if (allocated(error)) return
      call file%dataset('/increments/000001/joints/wif/stress', st, error)
      if (allocated(error)) return
      call file%dataset('/mesh/joint_sets/wif/point_coordinates', xy, error)
      if (allocated(error)) return
      call file%close()
      worst = 0.0_wp
      do e = 1, size(st, 3)
         do ip = 1, size(st, 2)
            y = xy(2, ip, e)
            sv = GU*(H - y)
            if (water .and. y < LEVEL) sv = GU*(H - LEVEL) + (GS - GW)*(LEVEL - y)
            worst = max(worst, abs(st(1, ip, e) - K0*sv), abs(st(2, ip, e)))
         end do
      end do
      write (msg, '(a,es10.3,a)') ': max |joint stress - (K0 sigma''_v, 0)| = ', worst, &
         ' kPa, expected < 1e-6'
      call check(error, worst < KN*1.0e-12_wp, name//trim(msg))
   end subroutine one_case

end module test_joint_k0_lobatto
