!> Decks that used to crash, hang, exhaust memory or be accepted silently
!> (test/data/trust/): each bad one must fail with file:line and keyword; resource caps are
!> checked against the file's own content before anything is allocated.
module test_io_deck_trust
   use pecplas_base_error, only: error_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_model_type, only: model_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use fixtures_bad_decks, only: bad, run_bad_cases
   use pecplas_base_kinds, only: wp
   use pecplas_io_results_fields, only: stress_mean
   use pecplas_base_progress_eta, only: progress_eta_t
   use pecplas_base_warnings, only: warnings_t
   use pecplas_model_geometry, only: corner_jacobian_ratio
   implicit none (type, external)
   private
   public :: collect_io_deck_trust

   character(len=*), parameter :: DIR = 'test/data/trust/'

contains

   subroutine collect_io_deck_trust(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('resource_caps', test_caps), &
               new_unittest('utf8_bom', test_bom), &
               new_unittest('stress_mean_no_overflow', test_stress_mean), &
               new_unittest('progress_eta', test_eta), &
               new_unittest('warnings_channel', test_warnings), &
               new_unittest('jacobian_ratio', test_jacobian_ratio), &
               new_unittest('geometry_errors', test_geometry)]
   end subroutine collect_io_deck_trust

   !> Reproducers: a 1e8-id GENERATE range, INCREMENTS=1000015, a Gmsh header announcing
   !> 1e6 elements with 8 given. Each is refused at its line (and fast: nothing allocated).
   subroutine test_caps(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DIR, [ &
         bad('generate_huge', 10, '*NSET', 'lists 100000000 ids', 'more than the 4 nodes'), &
         bad('increments_huge', 18, '*STEP', 'INCREMENTS must be <= 100000', 'Limits'), &
         bad('gmsh_count', 50, '$Elements', '1000000 elements announced', &
         'cannot hold them', file='header_count.msh'), &
         bad('mesh_directory', 3, '*MESH', 'cannot read', 'Is a directory'), &
         bad('load_huge', 17, '*LOAD', 'load value above 1e100')], error)
   end subroutine test_caps

   !> A UTF-8 byte order mark before the first keyword is skipped, not "a data line before
   !> the first keyword"; the deck reads like the same deck without it (4 nodes, 1 element).
   subroutine test_bom(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(model_t) :: model
      call read_deck(DIR//'good_bom.inp', model, e)
      call check(error, .not. allocated(e), 'BOM deck refused')
      if (allocated(error)) return
      call check(error, model%mesh%nnode() == 4 .and. model%mesh%nelem() == 1, &
         'BOM deck: expected 4 nodes and 1 element')
   end subroutine test_bom

   !> Four Gauss points at 0.9 huge(): the sum overflows, the mean (0.9 huge()) must not.
   subroutine test_stress_mean(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: stress(4, 4, 2)
      real(wp), allocatable :: mean(:, :)
      stress = 0.9_wp*huge(1.0_wp)
      stress(:, :, 2) = -1.0_wp
      mean = stress_mean(stress)
      call check(error, all(abs(mean(:, 1)/(0.9_wp*huge(1.0_wp)) - 1.0_wp) < &
         8*epsilon(1.0_wp)), 'mean of 0.9 huge() should be 0.9 huge() (no overflow)')
      if (allocated(error)) return
      call check(error, all(abs(mean(:, 2) + 1.0_wp) < 8*epsilon(1.0_wp)), 'mean of -1')
   end subroutine test_stress_mean

   !> Clock given by the test: 10 of 100 increments in 20 s leave 180 s at the same rate;
   !> lines are due every 5 s, not at every increment.
   subroutine test_eta(error)
      type(error_t), allocatable, intent(out) :: error
      type(progress_eta_t) :: eta
      character(len=:), allocatable :: line
      call eta%start(100.0_wp, 100)
      call check(error, eta%remaining(0, 100.0_wp) < 0.0_wp, 'no estimate before an increment')
      if (allocated(error)) return
      call check(error, abs(eta%remaining(10, 120.0_wp) - 180.0_wp) < 1.0e-9_wp, &
         'linear estimate: 10/100 done in 20 s -> 180 s left')
      if (allocated(error)) return
      call check(error, .not. eta%due(103.0_wp), 'not due after 3 s')
      if (allocated(error)) return
      call check(error, eta%due(105.5_wp), 'due after 5.5 s')
      if (allocated(error)) return
      call check(error, .not. eta%due(107.0_wp), 'interval counts from the last line')
      if (allocated(error)) return
      line = eta%line(10, 120.0_wp)
      call check(error, line == 'increment 10/100 (10 %), 20 s elapsed, about 3.0 min left', &
         'line: '//line)
      if (allocated(error)) return
      call check(error, abs(eta%remaining(100, 500.0_wp)) < 1.0e-12_wp, 'nothing left at end')
   end subroutine test_eta

   !> Warnings keep their order, drop exact repeats, and --strict reports the first at its
   !> line with the count of the others.
   subroutine test_warnings(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(warnings_t) :: w
      character(len=:), allocatable :: lines(:)
      call w%as_error(e)
      call check(error, .not. allocated(e), 'no warning, no error')
      if (allocated(error)) return
      call w%add('first', 'a.inp', 3)
      call w%add('second')
      call w%add('first', 'a.inp', 3)
      call check(error, w%count() == 2, 'a repeated warning is kept once')
      if (allocated(error)) return
      lines = w%lines()
      call check(error, lines(1) == 'a.inp:3: warning: first' .and. &
         trim(lines(2)) == 'warning: second', 'lines: '//lines(1)//' | '//lines(2))
      if (allocated(error)) return
      call w%as_error(e)
      call check(error, allocated(e), '--strict: an error')
      if (allocated(error)) return
      call check(error, e%exit_code() == 2 .and. e%text() == 'a.inp:3: warning treated '// &
         'as an error (--strict): first (and 1 more warning(s))', 'strict text: '//e%text())
   end subroutine test_warnings

   !> Square: ratio 1; a quadrilateral with one corner pushed towards the opposite side
   !> by 98 % of the way: ratio 0.02 (corner Jacobians 0.02 and 1 for unit edges).
   subroutine test_jacobian_ratio(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: sq(2, 4), thin(2, 4)
      sq = reshape([0, 0, 1, 0, 1, 1, 0, 1]*1.0_wp, [2, 4])
      thin = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 0.02_wp, 0.0_wp, 1.0_wp], [2, 4])
      call check(error, abs(corner_jacobian_ratio(sq) - 1.0_wp) < 1.0e-14_wp, 'square')
      if (allocated(error)) return
      call check(error, abs(corner_jacobian_ratio(thin) - 0.02_wp) < 1.0e-12_wp, &
         'corner at 2 % of the height: ratio 0.02')
   end subroutine test_jacobian_ratio

   !> Geometry errors found after reading name the element's deck line (the deck reader
   !> and prepare_run are exercised through the command in test/python/test_deck_trust.py);
   !> here: the element lines recorded by the reader point at the *ELEMENTS data lines.
   subroutine test_geometry(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(model_t) :: model
      call read_deck(DIR//'bad_not_convex.inp', model, e)
      call check(error, .not. allocated(e), 'the concave element is refused later, not read')
      if (allocated(error)) return
      call check(error, model%provenance%text(model%provenance%esets(1)%at(2)) == &
         DIR//'bad_not_convex.inp:13', 'element 2 line: '// &
         model%provenance%text(model%provenance%esets(1)%at(2)))
      if (allocated(error)) return
      call check(error, model%provenance%text(model%provenance%node(4)) == &
         DIR//'bad_not_convex.inp:6', 'node 4 line')
   end subroutine test_geometry

end module test_io_deck_trust
