!> Nodes a phase leaves to no element (doc/deck.md, Phases: "nothing loads them"): a layer dug
!> away through a phreatic level, whose K0 stress bends inside its elements, leaves a share of
!> the K0 out-of-balance at the nodes of its top; that share must leave with them, or their
!> residual keeps it and no iteration converges (the excavation of a Gmsh mesh under water
!> diverged at 0.6 % of its first step). Deck test/data/phases/orphan_k0.inp.
module test_phases_orphans
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_base_strings, only: itoa
   use pecplas_base_files, only: make_directories
   use pecplas_model_type, only: model_t
   use pecplas_problem_type, only: problem_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_phases_orphans

   character(len=*), parameter :: OUT = 'build/test_out/phases_orphans/'

contains

   subroutine collect_phases_orphans(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('dig_through_level', test_dig)]
   end subroutine collect_phases_orphans

   !> Elastic soil, E = 3e4, nu = 0.3, sides on rollers: digging the top metre ('exc', 17
   !> kN/m3 above the level at y = -0.5, 20 below, gamma_w = 10) completes; its top nodes
   !> (ids 1-3), left to no element, do not move; the 2 m of soil below heave as an oedometer
   !> unloaded by the layer's weight less the water now standing on the floor,
   !> (17 x 0.5 + 20 x 0.5 - 10 x 0.5) x 2 / M with M = E (1 - nu)/((1 + nu)(1 - 2 nu)),
   !> 6.686e-4 m. Tolerance 2 %: the forces the dug layer releases are its K0 stress
   !> integrated by the 2 x 2 rule of its one element layer, in which the stress bends at the
   !> level (the Gauss mean of sigma_v, 8.93 kPa, against the exact 8.875: about 1 %).
   subroutine test_dig(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: E = 3.0e4_wp, NU = 0.3_wp
      real(wp) :: m, heave
      integer :: code, n
      call make_directories(OUT)
      code = run_deck('test/data/phases/orphan_k0.inp', OUT//'orphan_k0.h5', .true., model, &
         problem)
      call check(error, code == 0, 'the dig through the level completes (exit '//itoa(code)// &
         ')')
      if (allocated(error)) return
      do n = 1, 3
         ! nothing loads a node left alone: its displacement stays exactly what it was (0)
         call check(error, all(problem%state%u(:, n) == 0.0_wp), 'node '//itoa(n)// &
            ' of the dug layer does not move')
         if (allocated(error)) return
      end do
      m = E*(1.0_wp - NU)/((1.0_wp + NU)*(1.0_wp - 2.0_wp*NU))
      heave = (17.0_wp*0.5_wp + 20.0_wp*0.5_wp - 10.0_wp*0.5_wp)*2.0_wp/m
      do n = 4, 6
         call check_close(error, problem%state%u(2, n), heave, 0.02_wp, 'heave of node '// &
            itoa(n)//' (the floor)')
         if (allocated(error)) return
      end do
   end subroutine test_dig

end module test_phases_orphans
