!> The uniform refiner (pecplas_model_refine_refine): counts, area, ids and node-set growth on the
!> GOODMAN4 joint patch deck and on a T3 square; a refined patch under uniform pressure still
!> gives the exact uniform stress in the massif and in the joints (plane, and axisymmetric
!> with generated joints); Q8 and springs refine; point forces on an edge are refused with
!> their reason.
module test_refine
   use pecplas_base_run_status, only: RUN_COMPLETED, status_name
   use pecplas_model_loads, only: LOAD_FORCE, load_pattern_t
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_model_mesh, only: mesh_t
   use pecplas_model_refine_refine, only: refine_model
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_base_files, only: make_directories
   use pecplas_base_version, only: VERSION
   use pecplas_problem_type, only: problem_t
   use pecplas_solve_prepare, only: prepare_run
   use pecplas_solve_increments, only: run_increments
   use pecplas_solve_gauss, only: gauss_coordinates
   use pecplas_io_results_increment, only: joint_points_t
   use pecplas_io_results_file, only: results_file_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_refine, run_model, total_area

   character(len=*), parameter :: DATA = 'test/data/joints/'
   character(len=*), parameter :: DIR = 'build/test_out/refine'
   !> The patch decks' pressure on the top [kPa].
   real(wp), parameter :: P = 100.0_wp

contains

   subroutine collect_refine(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('q4_joint_patch_counts', test_counts), &
               new_unittest('t3_square', test_t3), &
               new_unittest('refined_patch_exact', test_patch), &
               new_unittest('quadratic_springs_refused_forces', test_refused)]
   end subroutine collect_refine

   !> patch_goodman4_plane: 12 nodes, 2 + 2 Q4 (two 2 x 1 bodies), 2 GOODMAN4 joints between
   !> them. Unique edges: 7 per body, so 12 + 14 midpoints + 4 centres = 30 nodes, 16 Q4,
   !> 4 joints; area 4 m2 kept; ids 1..12 kept, new ones 13..30; node set base (y = 0) grows
   !> from 3 to the 5 nodes at y = 0; supports 4 -> 6 (Y on the two base midpoints); every
   !> refined joint still joins coincident doublets (1-4 and 2-3).
   subroutine test_counts(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model, fine
      character(len=:), allocatable :: reason
      integer :: k, ib
      call read_refine(DATA//'patch_goodman4_plane.inp', model, fine, reason, error)
      if (allocated(error)) return
      call check(error, fine%mesh%nnode() == 30 .and. fine%mesh%nelem() == 16 .and. &
         size(fine%joint_sets(1)%conn, 2) == 4, 'nodes 30, Q4 16, joints 4')
      if (allocated(error)) return
      call check(error, abs(total_area(fine%mesh) - total_area(model%mesh)) < 1.0e-12_wp .and. &
         abs(total_area(model%mesh) - 4.0_wp) < 1.0e-12_wp, 'area 4 preserved (1e-12)')
      if (allocated(error)) return
      call check(error, all(fine%mesh%node_id(1:12) == model%mesh%node_id) .and. &
         all(fine%mesh%x(:, 1:12) == model%mesh%x) .and. &
         all(fine%mesh%node_id(13:) == [(k, k=13, 30)]), 'original ids kept, new ones above')
      if (allocated(error)) return
      ib = fine%mesh%find_nset('base')
      call check(error, size(fine%mesh%nsets(ib)%nodes) == 5 .and. &
         all(fine%mesh%x(2, fine%mesh%nsets(ib)%nodes) == 0.0_wp) .and. &
         count(fine%mesh%x(2, :) == 0.0_wp) == 5, 'base grows to the 5 nodes at y = 0')
      if (allocated(error)) return
      call check(error, size(fine%supports%node) == 6, 'supports 4 -> 6')
      if (allocated(error)) return
      associate (c => fine%joint_sets(1)%conn, x => fine%mesh%x)
         do k = 1, size(c, 2)
            call check(error, all(x(:, c(1, k)) == x(:, c(4, k))) .and. &
               all(x(:, c(2, k)) == x(:, c(3, k))) .and. c(2, k) /= c(3, k), &
               'refined joints join coincident doublets')
            if (allocated(error)) return
         end do
      end associate
   end subroutine test_counts

   !> A unit square of 2 T3 (4 nodes, 5 edges): 9 nodes, 8 T3, area 1; a node set on the
   !> bottom gains its midpoint, one across the diagonal (an interior edge) does not.
   subroutine test_t3(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model, fine
      character(len=:), allocatable :: reason
      model%mesh%x = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, 0.0_wp, 1.0_wp], &
         [2, 4])
      model%mesh%node_id = [10, 20, 30, 40]
      allocate (model%mesh%esets(1), model%mesh%nsets(2), model%mesh%edge_sets(0))
      model%mesh%esets(1)%name = 'sq'
      model%mesh%esets(1)%etype = 'T3'
      model%mesh%esets(1)%conn = reshape([1, 2, 3, 1, 3, 4], [3, 2])
      model%mesh%esets(1)%ids = [1, 2]
      model%mesh%nsets(1)%name = 'bottom'
      model%mesh%nsets(1)%nodes = [1, 2]
      model%mesh%nsets(2)%name = 'diagonal'
      model%mesh%nsets(2)%nodes = [1, 3]
      allocate (model%joint_sets(0), model%patterns(0), model%supports%node(0), &
         model%supports%dof(0))
      call refine_model(model, fine, reason)
      call check(error, .not. allocated(reason), 'a T3 square refines')
      if (allocated(error)) return
      call check(error, fine%mesh%nnode() == 9 .and. fine%mesh%nelem() == 8 .and. &
         abs(total_area(fine%mesh) - 1.0_wp) < 1.0e-12_wp, 'T3: 9 nodes, 8 elements, area 1')
      if (allocated(error)) return
      call check(error, size(fine%mesh%nsets(1)%nodes) == 3 .and. &
         size(fine%mesh%nsets(2)%nodes) == 2 .and. all(fine%mesh%node_id(5:) > 40), &
         'bottom gains its midpoint, the diagonal (interior) does not; new ids above 40')
   end subroutine test_t3

   !> Uniform pressure P through a GOODMAN4 joint: on the refined mesh sigma_yy = -P,
   !> sigma_xx = sigma_xy = 0 at every massif Gauss point and sigma_n = P, tau = 0 at every
   !> joint point (1e-10 P), as on the deck's mesh; the joint has twice its points.
   subroutine test_patch(error)
      type(error_t), allocatable, intent(out) :: error
      call patch_case('patch_goodman4_plane.inp', error)
      if (allocated(error)) return
      call patch_case('patch_goodman4_axi_gen.inp', error)
   end subroutine test_patch

   subroutine patch_case(deck, error)
      character(len=*), intent(in) :: deck
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model, fine
      type(problem_t) :: coarse_problem, problem
      character(len=:), allocatable :: reason
      real(wp) :: worst
      integer :: s
      character(len=80) :: buf
      call read_refine(DATA//deck, model, fine, reason, error)
      if (allocated(error)) return
      call run_model(model, coarse_problem, error)
      if (allocated(error)) return
      call run_model(fine, problem, error)
      if (allocated(error)) return
      worst = 0.0_wp
      do s = 1, size(problem%state%sets)
         associate (st => problem%state%sets(s)%stress)
            worst = max(worst, maxval(abs(st(2, :, :) + P)), maxval(abs(st(1, :, :))), &
               maxval(abs(st(4, :, :))))
         end associate
      end do
      write (buf, '(a,es9.2)') ': refined massif stress error ', worst
      call check(error, worst <= 1.0e-10_wp*P, deck//trim(buf))
      if (allocated(error)) return
      associate (js => problem%state%joints%sets(1)%sigma, &
                 jc => coarse_problem%state%joints%sets(1)%sigma)
         worst = max(maxval(abs(js(1, :, :) - P)), maxval(abs(js(2, :, :))))
         write (buf, '(a,es9.2)') ': refined joint stress error ', worst
         call check(error, worst <= 1.0e-10_wp*P .and. size(js) == 2*size(jc), deck//trim(buf))
      end associate
   end subroutine patch_case

   !> Quadratic elements and springs refine (the strip footing: 8 Q8 -> 32 Q8, area kept; the
   !> spring patch: 3 springs on 2 face edges -> 5); point forces on both ends of an edge are
   !> refused.
   subroutine test_refused(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model, fine
      character(len=:), allocatable :: reason
      integer :: n
      type(load_pattern_t), allocatable :: pats(:)
      call read_refine('input/examples/strip_footing.inp', model, fine, reason, error)
      if (allocated(error)) return
      call check(error, .not. allocated(reason), 'strip footing (Q8) refines')
      if (allocated(error)) return
      call check(error, fine%mesh%nelem() == 4*model%mesh%nelem() .and. &
         abs(total_area(fine%mesh) - total_area(model%mesh)) < 1.0e-12_wp* &
         total_area(model%mesh), 'Q8: four children each, area kept (1e-12)')
      if (allocated(error)) return
      call read_refine(DATA//'patch_spring_plane.inp', model, fine, reason, error)
      if (allocated(error)) return
      call check(error, .not. allocated(reason), 'springs refine')
      if (allocated(error)) return
      call check(error, size(fine%joint_sets(1)%conn, 2) == 5 .and. &
         abs(sum(fine%joint_sets(1)%tributary) - sum(model%joint_sets(1)%tributary)) < &
         1.0e-12_wp*sum(model%joint_sets(1)%tributary), &
         'springs 3 -> 5, total tributary length kept (1e-12)')
      if (allocated(error)) return
      ! two point forces on the top nodes 10 and 11 (one edge): the total would grow
      call read_deck(DATA//'patch_goodman4_plane.inp', model, error)
      if (allocated(error)) return
      n = size(model%patterns)
      ! (not an array constructor: gfortran 12 frees the components of such a copy twice)
      allocate (pats(n + 1))
      pats(1:n) = model%patterns
      pats(n + 1) = model%patterns(n)
      call move_alloc(pats, model%patterns)
      model%patterns(n + 1)%name = 'f'
      model%patterns(n + 1)%kind = LOAD_FORCE
      model%patterns(n + 1)%node = [findloc(model%mesh%node_id, 10, 1), &
         findloc(model%mesh%node_id, 11, 1)]
      model%patterns(n + 1)%dof = [2, 2]
      model%patterns(n + 1)%value = [-1.0_wp, -1.0_wp]
      call refine_model(model, fine, reason)
      call check(error, allocated(reason), 'point forces on an edge refused')
      if (allocated(error)) return
      call check(error, index(reason, 'nodal loads on a refined set') == 1, &
         'reason: nodal loads on a refined set')
   end subroutine test_refused

   subroutine read_refine(deck, model, fine, reason, error)
      character(len=*), intent(in) :: deck
      type(model_t), intent(out) :: model, fine
      character(len=:), allocatable, intent(out) :: reason
      type(error_t), allocatable, intent(out) :: error
      call read_deck(deck, model, error)
      if (allocated(error)) return
      call refine_model(model, fine, reason)
   end subroutine read_refine

   !> Runs a model in memory to a scratch results file (as the advice mode does).
   subroutine run_model(model, problem, error)
      type(model_t), intent(inout) :: model
      type(problem_t), intent(out) :: problem
      type(error_t), allocatable, intent(out) :: error
      type(results_file_t) :: results
      type(joint_points_t), allocatable :: jpoints(:)
      character(len=:), allocatable :: message
      integer :: status
      integer :: nflipped
      call make_directories(DIR)
      call prepare_run(model, problem, nflipped, jpoints, error)
      if (allocated(error)) return
      call results%create(DIR//'/run.h5', model, VERSION, gauss_coordinates(model, problem), &
         error, jpoints)
      if (allocated(error)) return
      call run_increments(model, problem, results, .true., status, message, error)
      call results%free()
      if (allocated(error)) return
      if (status /= RUN_COMPLETED) call fatal_error(error, 'run did not complete: '//status_name(status))
   end subroutine run_model

   !> Sum of the element areas (shoelace over the corners).
   real(wp) function total_area(mesh) result(a)
      type(mesh_t), intent(in) :: mesh
      integer :: s, k, i, nc
      real(wp) :: x(2, 4)
      a = 0.0_wp
      do s = 1, size(mesh%esets)
         nc = merge(4, 3, mesh%esets(s)%etype(1:1) == 'Q')
         do k = 1, size(mesh%esets(s)%conn, 2)
            x(:, 1:nc) = mesh%x(:, mesh%esets(s)%conn(1:nc, k))
            do i = 1, nc
               a = a + 0.5_wp*(x(1, i)*x(2, mod(i, nc) + 1) - x(1, mod(i, nc) + 1)*x(2, i))
            end do
         end do
      end do
   end function total_area

end module test_refine
