!> Zienkiewicz–Zhu error estimate on the Lamé thick cylinder (exact solution): effectivity
!> eta / ||e|| in [0.8, 1.25] on the finest of three meshes and convergence of eta at the
!> element's energy-norm rate (1 for T3/Q4, 2 for T6/Q8), plane strain and axisymmetric;
!> and a finite estimate after plastic flow.
module test_estimator
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_estimate_estimator, only: error_estimate_t, estimate_error, set_compliance
   use pecplas_massif_materials_type, only: NCOMP
   use pecplas_massif_kinematics, only: massif_point_t, massif_gauss_point
   use doc_report, only: report
   use pecplas_testing, only: unittest_t, new_unittest, check
   use lame_mesh, only: write_lame_deck, A, B, P, NU
   implicit none (type, external)
   private
   public :: collect_estimator

   character(len=*), parameter :: DIR = 'build/test_out'

contains

   subroutine collect_estimator(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('lame_q4_plane', test_q4_plane), &
               new_unittest('lame_q4_axi', test_q4_axi), &
               new_unittest('lame_t3_plane', test_t3_plane), &
               new_unittest('lame_t3_axi', test_t3_axi), &
               new_unittest('lame_q8_plane', test_q8_plane), &
               new_unittest('lame_q8_axi', test_q8_axi), &
               new_unittest('lame_t6_plane', test_t6_plane), &
               new_unittest('lame_t6_axi', test_t6_axi), &
               new_unittest('plastic_footing_finite', test_plastic), &
               new_unittest('joint_uniform_traction', test_joint_uniform)]
   end subroutine collect_estimator

   !> Exact Lamé stresses at x in the analysis' components (xx, yy, zz, xy) or (rr, zz,
   !> hoop, rz); u_z = 0 in both, so sigma_zz = 2 nu c.
   pure function lame_stress(x, axi) result(s)
      real(wp), intent(in) :: x(2)
      logical, intent(in) :: axi
      real(wp) :: s(NCOMP), c, r, sr, st, cs, sn
      c = P*A**2/(B**2 - A**2)
      r = merge(x(1), norm2(x), axi)
      sr = c*(1.0_wp - B**2/r**2)
      st = c*(1.0_wp + B**2/r**2)
      if (axi) then
         s = [sr, 2.0_wp*NU*c, st, 0.0_wp]
      else
         cs = x(1)/r; sn = x(2)/r
         s = [sr*cs**2 + st*sn**2, sr*sn**2 + st*cs**2, 2.0_wp*NU*c, (sr - st)*sn*cs]
      end if
   end function lame_stress

   !> Solves the n x n mesh; returns the estimate and the exact energy-norm error
   !> sqrt(int (sigma_ex - sigma_h) : C^-1 : (sigma_ex - sigma_h) dV) at the Gauss points.
   subroutine solve_and_estimate(etype, axi, n, eta, exact, error)
      character(len=*), intent(in) :: etype
      logical, intent(in) :: axi
      integer, intent(in) :: n
      real(wp), intent(out) :: eta, exact
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(error_estimate_t) :: est
      type(massif_point_t) :: pt
      character(len=:), allocatable :: deck
      character(len=16) :: tag
      real(wp) :: cinv(NCOMP, NCOMP), d(NCOMP)
      integer :: code, e, g

      write (tag, '(a,a,i0)') etype, merge('_axi', '_pla', axi), n
      call make_directories(DIR)
      deck = DIR//'/est_'//trim(tag)//'.inp'
      call write_lame_deck(deck, etype, axi, n, n)
      code = run_deck(deck, DIR//'/est_'//trim(tag)//'.h5', .true., model, problem)
      if (code /= 0) then
         call fatal_error(error, 'run of '//deck//' failed')
         return
      end if
      call estimate_error(model, problem, est, error)
      if (allocated(error)) return
      eta = est%eta
      call set_compliance(model, 1, model%mesh%esets(1)%material_index, cinv, error)
      if (allocated(error)) return
      exact = 0.0_wp
      associate (set => model%mesh%esets(1), st => problem%state%sets(1))
         do e = 1, size(set%conn, 2)
            do g = 1, st%ngauss
               call massif_gauss_point(problem%system%rules(1), g, model%analysis%kind, &
                  model%analysis%thickness, model%mesh%x(:, set%conn(:, e)), pt, error)
               if (allocated(error)) return
               d = lame_stress(pt%x, axi) - st%stress(:, g, e)
               exact = exact + dot_product(d, matmul(cinv, d))*pt%dvol
            end do
         end do
      end associate
      exact = sqrt(exact)
   end subroutine solve_and_estimate

   !> Meshes n0, 2 n0, 4 n0 (n0 = 2 unless given): effectivity on the finest in [0.8, 1.25]
   !> (Zienkiewicz–Zhu's asymptotic exactness on a smooth solution) and the observed order
   !> of eta between the two finer meshes within 0.3 of the energy-norm rate p of the
   !> element (the coarser pair may be pre-asymptotic: it is printed, not checked).
   subroutine check_estimator(etype, axi, p, error, n0)
      character(len=*), intent(in) :: etype
      logical, intent(in) :: axi
      real(wp), intent(in) :: p
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: n0
      real(wp) :: eta(3), exact(3), rate(2), theta
      character(len=160) :: buf
      integer :: k, n
      n = 2
      if (present(n0)) n = n0
      do k = 1, 3
         call solve_and_estimate(etype, axi, n*2**(k - 1), eta(k), exact(k), error)
         if (allocated(error)) return
      end do
      rate = log(eta(1:2)/eta(2:3))/log(2.0_wp)
      theta = eta(3)/exact(3)
      write (buf, '(a,3es10.3,a,3f6.3,a,2f6.3)') ' eta', eta, ' effectivity', eta/exact, &
         ' orders', rate
      write (*, '(a)') '        '//etype//merge(' axi  ', ' plane', axi)//trim(buf)
      call report('estimator/'//etype//trim(merge('_axi  ', '_plane', axi))//'/eta', eta)
      call report('estimator/'//etype//trim(merge('_axi  ', '_plane', axi))//'/exact', exact)
      call check(error, theta >= 0.8_wp .and. theta <= 1.25_wp, etype// &
         ' effectivity on the finest mesh outside [0.8, 1.25]:'//trim(buf))
      if (allocated(error)) return
      call check(error, abs(rate(2) - p) <= 0.3_wp, etype// &
         ' order of eta not within 0.3 of the element rate:'//trim(buf))
   end subroutine check_estimator

   subroutine test_q4_plane(error)
      type(error_t), allocatable, intent(out) :: error
      call check_estimator('Q4', .false., 1.0_wp, error)
   end subroutine test_q4_plane

   subroutine test_q4_axi(error)
      type(error_t), allocatable, intent(out) :: error
      call check_estimator('Q4', .true., 1.0_wp, error)
   end subroutine test_q4_axi

   subroutine test_t3_plane(error)
      type(error_t), allocatable, intent(out) :: error
      call check_estimator('T3', .false., 1.0_wp, error)
   end subroutine test_t3_plane

   subroutine test_t3_axi(error)
      type(error_t), allocatable, intent(out) :: error
      call check_estimator('T3', .true., 1.0_wp, error)
   end subroutine test_t3_axi

   subroutine test_q8_plane(error)
      type(error_t), allocatable, intent(out) :: error
      ! coarse quarter rings are pre-asymptotic in the plane: effectivity 8.0, 3.5, 1.8 and
      ! order of eta 3.1, 2.9, 2.6 from 2 x 2 to 8 x 8 (Q8; T6 alike), so start at 8 x 8
      call check_estimator('Q8', .false., 2.0_wp, error, n0=8)
   end subroutine test_q8_plane

   subroutine test_q8_axi(error)
      type(error_t), allocatable, intent(out) :: error
      call check_estimator('Q8', .true., 2.0_wp, error)
   end subroutine test_q8_axi

   subroutine test_t6_plane(error)
      type(error_t), allocatable, intent(out) :: error
      ! coarse quarter rings are pre-asymptotic in the plane: effectivity 8.0, 3.5, 1.8 and
      ! order of eta 3.1, 2.9, 2.6 from 2 x 2 to 8 x 8 (Q8; T6 alike), so start at 8 x 8
      call check_estimator('T6', .false., 2.0_wp, error, n0=8)
   end subroutine test_t6_plane

   subroutine test_t6_axi(error)
      type(error_t), allocatable, intent(out) :: error
      call check_estimator('T6', .true., 2.0_wp, error)
   end subroutine test_t6_axi

   !> After plastic flow (Mohr–Coulomb footing): the estimate runs, is finite and positive,
   !> and the global value is the root sum of squares of the element indicators (to the
   !> rounding bound of a sum of n positive terms). The geostatic state of the same deck (linear stresses) is checked in
   !> test/python/test_estimator.py.
   subroutine test_plastic(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(error_estimate_t) :: est
      character(len=80) :: buf
      call make_directories(DIR)
      if (run_deck('test/data/estimator/footing_mc.inp', DIR//'/est_footing_mc.h5', .true., &
         model, problem) /= 0) then
         call fatal_error(error, 'run of test/data/estimator/footing_mc.inp failed')
         return
      end if
      call check(error, any(problem%state%sets(1)%hist /= 0.0_wp), 'no plastic flow in the deck')
      if (allocated(error)) return
      call estimate_error(model, problem, est, error)
      if (allocated(error)) return
      write (buf, '(a,2es11.3)') ' eta, energy norm', est%eta, est%energy
      write (*, '(a)') '        plastic footing'//trim(buf)
      call check(error, est%eta > 0.0_wp .and. est%eta <= huge(1.0_wp) .and. &
         all(est%sets(1)%eta >= 0.0_wp), 'estimate not finite and positive:'//trim(buf))
      if (allocated(error)) return
      ! a sum of n positive terms is exact to (n - 1) eps relative (Higham thm 4.1 bound for
      ! recursive summation; the estimator may add them in another order), the root halves it
      call check(error, abs(sqrt(sum(est%sets(1)%eta**2)) - est%eta) <= &
         size(est%sets(1)%eta)*epsilon(1.0_wp)*est%eta, &
         'global estimate is not the root sum of squares of the indicators')
   end subroutine test_plastic

   !> Joint patch test (uniform contact pressure 100 at every joint point): a traction
   !> field linear along the joint is recovered exactly, so every joint indicator vanishes
   !> (1e-8 against a joint traction energy of order sqrt(100^2 / 1e5 * area) ~ 1).
   subroutine test_joint_uniform(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      type(error_estimate_t) :: est
      character(len=*), parameter :: DECK = 'test/data/joints/patch_goodman6_axi_gen.inp'
      call make_directories(DIR)
      if (run_deck(DECK, DIR//'/est_joint_patch.h5', .true., model, problem) /= 0) then
         call fatal_error(error, 'run of '//DECK//' failed')
         return
      end if
      call estimate_error(model, problem, est, error)
      if (allocated(error)) return
      call check(error, size(est%joints) == 1, 'one joint set expected')
      if (allocated(error)) return
      call check(error, size(est%joints(1)%eta) == size(model%joint_sets(1)%conn, 2) .and. &
         maxval(est%joints(1)%eta) <= 1.0e-8_wp, 'joint indicator of a uniform traction not 0')
   end subroutine test_joint_uniform

end module test_estimator
