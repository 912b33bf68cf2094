!> The pore pressure of a joint element that the phreatic level crosses (doc/theory.md,
!> Groundwater, "Joints"): the joint takes p at its integration points, so the water force of
!> the cut element is its Gauss rule's, within the bound the theory states; the soil's
!> ∫ Bᵀ m p dV samples p at the same heights along the joint, so the K0 state stays in
!> discrete equilibrium. Registered in the water suite (test_water).
module test_water_joint_level
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_io_results_reader, only: results_reader_t
   use pecplas_testing, only: check, check_close
   use fixtures_runs, only: run_completes
   use fixtures_held_wall, only: write_held_wall
   implicit none (type, external)
   private
   public :: test_joint_level_bound

   character(len=*), parameter :: OUT = 'build/test_out/water/'
   !> The wall's height, the elements along it, gamma_w, the soil's unit weight (GAMMA_SAT =
   !> GAMMA_UNSAT: the weight does not change at the level, so only p has a kink there) and
   !> the level, at 0.2 of the joint element [4, 5]: both its Gauss points (at 0.211 and
   !> 0.789 of it) lie above the level.
   real(wp), parameter :: H = 10.0_wp, GW = 10.0_wp, GAMMA = 18.0_wp, LEVEL = 4.2_wp
   integer, parameter :: NE = 10

contains

   !> A wall at x = 0, 0 <= y <= 10 (a plate held at every node), one column of ten 1 m Q4
   !> (x from 0 to 1) on its right, base held, right side on rollers, joined to the wall by
   !> ten GOODMAN4 joints (Gauss points, ELASTIC); the K0 procedure with K0 = 0 (the joints
   !> carry the pore pressure only), the level y = 4.2, a nil step. The wall's horizontal
   !> reactions are then the water force of the joints: their resultant F and moment M about
   !> the base against gamma_w h^2 / 2 = 88.2 and gamma_w h^3 / 6 = 123.48 (h = 4.2). The
   !> bound of theory §14 for one cut 2-node joint element of length L under a Gauss rule,
   !> |dF| <= gamma_w d^2 / 2 with d = (3 - sqrt 3) L / 6 (0.2233 here) and |dM| <=
   !> |dF|max (y0 + L) with y0 + L = 5 the top of the cut element over the base, holds; the
   !> value itself is that of the two points, both dry: dF = -gamma_w 0.2^2 / 2 = -0.2 and
   !> dM = -gamma_w ∫ (4.2 - y) y dy over [4, 4.2] = -0.81333, to 1e-10 of F (the statically
   !> determinate sum of the joint forces on a held wall; the solve's residual n eps |K||u|
   !> is far below). The soil does not move (max |u| < 1e-12 m against gamma H^2 / E =
   !> 6e-2 m): the soil's and the joints' pore pressure terms sample p at the same heights,
   !> so the K0 state is in discrete equilibrium with the level inside an element. The
   !> reactions balance the weight and the water: sum R_x = gamma_w h^2 / 2 (the water on
   !> the held right side), sum R_y = the buoyant weight 18 (10 - h) + 8 h = 138, to 1e-10.
   subroutine test_joint_level_bound(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(results_reader_t) :: file
      real(wp), allocatable :: reac(:, :), x(:, :)
      integer, allocatable :: ids(:)
      character(len=*), parameter :: deck = OUT//'joint_level.inp'
      real(wp) :: f, m, fexact, mexact, d, dfmax, hw
      integer :: k
      call make_directories(OUT)
      hw = LEVEL
      call write_held_wall(deck, NE, 1.0_wp, 1.0_wp, GAMMA, 0.0_wp, '', LEVEL)
      call run_completes(error, deck, OUT//'joint_level.h5', model, problem, &
         'wall with joints crossed by the level')
      if (allocated(error)) return
      call file%open(OUT//'joint_level.h5', error)
      if (allocated(error)) return
      call file%dataset('/increments/000001/reaction', reac, error)
      if (allocated(error)) return
      call file%dataset('/mesh/coordinates', x, error)
      if (allocated(error)) return
      call file%dataset('/mesh/node_ids', ids, error)
      if (allocated(error)) return
      call file%close()
      f = 0.0_wp
      m = 0.0_wp
      do k = 1, size(x, 2)
         if (ids(k) < 100) cycle
         f = f + reac(1, k)
         m = m + reac(1, k)*x(2, k)
      end do
      fexact = 0.5_wp*GW*hw**2
      mexact = GW*hw**3/6.0_wp
      d = (3.0_wp - sqrt(3.0_wp))/6.0_wp
      dfmax = 0.5_wp*GW*d**2
      call check(error, abs(f - fexact) <= dfmax, 'water force of the joints within the '// &
         'bound gamma_w d^2 / 2 of a cut element')
      if (allocated(error)) return
      call check(error, abs(m - mexact) <= dfmax*5.0_wp, 'their moment within the bound '// &
         '(y0 + L) gamma_w d^2 / 2')
      if (allocated(error)) return
      call check_close(error, f, fexact - 0.5_wp*GW*0.2_wp**2, 1.0e-10_wp, &
         'water force of the joints = the 2-point Gauss rule''s (both points of the cut '// &
         'element dry)')
      if (allocated(error)) return
      call check_close(error, m, mexact - GW*(LEVEL*(LEVEL**2 - 16.0_wp)/2.0_wp - &
         (LEVEL**3 - 64.0_wp)/3.0_wp), 1.0e-10_wp, 'their moment = the Gauss rule''s')
      if (allocated(error)) return
      call check(error, maxval(abs(problem%state%u)) < 1.0e-12_wp, &
         'the soil stays at rest: its pore pressure term and the joints'' balance')
      if (allocated(error)) return
      call check_close(error, sum(reac(1, :)), fexact, 1.0e-10_wp, &
         'sum of the horizontal reactions = the water on the held right side')
      if (allocated(error)) return
      call check_close(error, sum(reac(2, :)), GAMMA*(H - hw) + (GAMMA - GW)*hw, 1.0e-10_wp, &
         'sum of the vertical reactions = the buoyant weight')
   end subroutine test_joint_level_bound

end module test_water_joint_level
