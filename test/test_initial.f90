!> Initial stresses (*INITIAL_STRESS): a geostatic state is in equilibrium by itself (no
!> displacement, stresses unchanged) and superposes with the response to later loads; a
!> joint along layered soil starts, point by point, from the stress of its own layer
!> whatever the order of its edges.
module test_initial
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_massif_element_matrices, only: massif_gauss_coordinates
   use pecplas_solve_prepare, only: prepare_run
   use pecplas_io_results_increment, only: joint_points_t
   use pecplas_joints_points, only: joint_point_geometry
   use pecplas_base_strings, only: itoa
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_initial

contains

   subroutine collect_initial(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('geostatic_column_superposition', test_column), &
               new_unittest('undefined_set_names_line', test_bad_set), &
               new_unittest('joint_start_stress_two_layers', test_two_layers), &
               new_unittest('joint_start_stress_three_layers', test_three_layers)]
   end subroutine collect_initial

   subroutine test_column(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      real(wp), parameter :: gamma = 20.0_wp, k0 = 0.5_wp, q = 100.0_wp, e = 3.0e4_wp, &
         nu = 0.25_wp
      real(wp) :: m, xg(2, 4), sv, expect(4), worst
      integer :: code, el, g
      call make_directories('build/test_out/initial')
      code = run_deck('test/data/initial/geostatic_column.inp', &
         'build/test_out/initial/column.h5', .true., model, problem)
      call check(error, code == 0, 'geostatic column runs')
      if (allocated(error)) return
      m = e*(1.0_wp - nu)/((1.0_wp + nu)*(1.0_wp - 2.0_wp*nu))
      ! the weight is in the initial state: only the surcharge moves the column
      call check_close(error, problem%state%u(2, 10), -q*4.0_wp/m, 1.0e-10_wp, &
         'top settlement = -q H / M (surcharge only)')
      if (allocated(error)) return
      worst = 0.0_wp
      do el = 1, 4
         call massif_gauss_coordinates(problem%system%rules(1), &
            model%mesh%x(:, model%mesh%esets(1)%conn(:, el)), xg)
         do g = 1, 4
            sv = gamma*(0.0_wp - xg(2, g))
            expect = [-k0*sv - nu/(1.0_wp - nu)*q, -sv - q, -k0*sv - nu/(1.0_wp - nu)*q, 0.0_wp]
            worst = max(worst, maxval(abs(problem%state%sets(1)%stress(:, g, el) - expect)))
         end do
      end do
      ! exact: geostatic at the Gauss point + uniform oedometric response to q
      call check_close(error, worst, 0.0_wp, 0.0_wp, 'stresses = geostatic + surcharge', &
         atol=1.0e-9_wp*q)
      if (allocated(error)) return
      call check(error, problem%stats%iterations == 2, 'the rest step needs no iteration, the '// &
         'surcharge one per increment')
   end subroutine test_column

   subroutine test_bad_set(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(model_t) :: model
      call read_deck('test/data/initial/bad_set.inp', model, e)
      call check(error, allocated(e), 'undefined set must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'bad_set.inp:36') > 0 .and. &
         index(e%text(), '*INITIAL_STRESS') > 0 .and. index(e%text(), "'clay'") > 0 .and. &
         index(e%text(), 'SOIL') + index(e%text(), 'soil') > 0, 'message: '//e%text())
   end subroutine test_bad_set

   !> Two layers (clay 0 to -4 m, sand -4 to -10 m, two element rows each) beside a wall:
   !> GOODMAN4 joints and springs generated along the wall from the four edges listed in
   !> each of their 24 orders.
   subroutine test_two_layers(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: rows(5) = [0.0_wp, -2.0_wp, -4.0_wp, -7.0_wp, -10.0_wp]
      integer, parameter :: layer(4) = [1, 1, 2, 2]
      call every_order(rows, layer, 'Q4', 'GOODMAN4', error)
      if (allocated(error)) return
      call every_order(rows, layer, 'Q4', 'SPRING', error)
   end subroutine test_two_layers

   !> Three layers (one, two and one Q8 rows) beside a wall: GOODMAN6 joints from the four
   !> edges in each of their 24 orders.
   subroutine test_three_layers(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: rows(5) = [0.0_wp, -3.0_wp, -5.0_wp, -7.0_wp, -10.0_wp]
      integer, parameter :: layer(4) = [1, 2, 2, 3]
      call every_order(rows, layer, 'Q8', 'GOODMAN6', error)
   end subroutine test_three_layers

   !> For each order of the interface edges: every joint point starts at sigma_n0 = K0 sigma_v'
   !> of the layer it lies in (the interface is vertical: sigma_n = sigma_xx), tau0 = 0; a
   !> spring at a layer boundary at the mean of the two layers' K0 sigma_v (sigma_v is
   !> continuous there). Tolerance 1e-12 relative: the expected value is the same geostatic
   !> formula at the same point, so only the rounding of a few operations separates them
   !> (and the mean of two terms for a spring).
   subroutine every_order(rows, layer, etype, jtype, error)
      real(wp), intent(in) :: rows(:)
      integer, intent(in) :: layer(:)
      character(len=*), intent(in) :: etype, jtype
      type(error_t), allocatable, intent(out) :: error
      integer :: perm(size(layer)), count, i
      logical :: more
      perm = [(i, i=1, size(layer))]
      count = 0
      more = .true.
      do while (more)
         count = count + 1
         call check_order(rows, layer, etype, jtype, perm, error)
         if (allocated(error)) return
         call next_permutation(perm, more)
      end do
      call check(error, count == product([(i, i=1, size(layer))]), 'every order tried')
   end subroutine every_order

   subroutine check_order(rows, layer, etype, jtype, perm, error)
      real(wp), intent(in) :: rows(:)
      integer, intent(in) :: layer(:), perm(:)
      character(len=*), intent(in) :: etype, jtype
      type(error_t), allocatable, intent(out) :: error
      ! layers: unit weight, K0 (then top and overburden at the top); the wall has its own
      real(wp), parameter :: gam(3) = [17.0_wp, 19.0_wp, 21.0_wp], k0(3) = [0.6_wp, 0.4_wp, &
         0.8_wp]
      type(model_t) :: model
      type(problem_t) :: problem
      type(joint_points_t), allocatable :: jpoints(:)
      type(error_t), allocatable :: e
      real(wp), allocatable :: xy(:, :, :), t(:, :, :)
      real(wp) :: top(3), q(3), expect, worst, y
      integer :: nflipped, el, ip, l, lb
      character(len=:), allocatable :: path, where
      ! a surcharge of 10 on the surface, so that sigma_v > 0 at every point (relative error)
      top = 0.0_wp
      q = 10.0_wp
      do l = 2, maxval(layer)
         top(l) = rows(findloc(layer, l, dim=1))
         q(l) = q(l - 1) + gam(l - 1)*(top(l - 1) - top(l))
      end do
      path = 'build/test_out/initial/layers_'//etype//'_'//jtype//'.inp'
      call make_directories('build/test_out/initial')
      call write_column(path, rows, layer, etype, jtype, perm, gam, k0, top, q)
      where = jtype//' along '//itoa(maxval(layer))//' layers, edges in the order '// &
         order_text(perm)
      call read_deck(path, model, e)
      if (allocated(e)) then
         call fatal_error(error, where//': '//e%text())
         return
      end if
      call prepare_run(model, problem, nflipped, jpoints, e)
      if (allocated(e)) then
         call fatal_error(error, where//': '//e%text())
         return
      end if
      call joint_point_geometry(model, 1, xy, t, e)
      if (allocated(e)) then
         call fatal_error(error, where//': '//e%text())
         return
      end if
      worst = 0.0_wp
      associate (sigma => problem%state%joints%sets(1)%sigma)
         do el = 1, size(xy, 3)
            do ip = 1, size(xy, 2)
               y = xy(2, ip, el)
               l = layer_at(y, .false.)
               lb = layer_at(y, .true.)
               expect = 0.5_wp*(k0(l)*(q(l) + gam(l)*(top(l) - y)) + &
                  k0(lb)*(q(lb) + gam(lb)*(top(lb) - y)))
               worst = max(worst, abs(sigma(1, ip, el) - expect)/expect, &
                  abs(sigma(2, ip, el))/expect)
            end do
         end do
      end associate
      call check_close(error, worst, 0.0_wp, 0.0_wp, where//': sigma_n0 = K0 sigma_v of '// &
         'the layer at each point, tau0 = 0', atol=1.0e-12_wp)
   contains
      !> The layer of height y: the one whose rows hold y inside; at a row boundary the
      !> one above (below = .false.) or below it (top and bottom: the only one).
      integer function layer_at(yy, below) result(lay)
         real(wp), intent(in) :: yy
         logical, intent(in) :: below
         integer :: r
         lay = layer(size(layer))
         do r = 1, size(layer)
            if (yy > rows(r + 1) .or. (.not. below .and. yy >= rows(r + 1))) then
               lay = layer(r)
               return
            end if
         end do
      end function layer_at
   end subroutine check_order

   !> A soil column x in [0, 1] (one element per row, set layer<k> per layer) beside a wall
   !> column x in [-0.5, 0] (the joints' SIDE: the soil is on face 1), rows between the
   !> heights `rows`; the interface edges (x = 0, top down) listed in the order `perm`.
   subroutine write_column(path, rows, layer, etype, jtype, perm, gam, k0, top, q)
      character(len=*), intent(in) :: path, etype, jtype
      real(wp), intent(in) :: rows(:), gam(:), k0(:), top(:), q(:)
      integer, intent(in) :: layer(:), perm(:)
      real(wp), parameter :: xs(5) = [-0.5_wp, -0.25_wp, 0.0_wp, 0.5_wp, 1.0_wp]
      integer :: u, r, c, l, nrow
      logical :: quad
      character(len=128) :: line
      quad = etype == 'Q8'
      nrow = size(layer)
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'joint beside layered soil', '*NODES'
      ! node (j, c): j = 0 .. 2 nrow along the heights (odd: mid-rows), c = 1 .. 5 along x
      do r = 0, 2*nrow
         do c = 1, 5
            if (.not. quad .and. (mod(r, 2) == 1 .or. mod(c, 2) == 0)) cycle
            if (mod(r, 2) == 1 .and. mod(c, 2) == 0) cycle
            write (line, '(i0,2(a,es24.16e3))') id(r, c), ', ', xs(c), ', ', height(r)
            write (u, '(a)') trim(line)
         end do
      end do
      call elements('wall', 1, [(r, r=1, nrow)])
      do l = 1, maxval(layer)
         call elements('layer'//itoa(l), 3, pack([(r, r=1, nrow)], layer == l))
      end do
      do l = 1, maxval(layer)
         write (u, '(a)') '*MATERIAL, NAME=m'//itoa(l)
         write (line, '(a,es24.16e3)') 'E = 2e4, NU = 0.3, GAMMA = ', gam(l)
         write (u, '(a)') trim(line), '*SECTION, SET=layer'//itoa(l)//', MATERIAL=m'//itoa(l)
      end do
      write (u, '(a)') '*MATERIAL, NAME=concrete', 'E = 2e7, NU = 0.2, GAMMA = 25', &
         '*SECTION, SET=wall, MATERIAL=concrete', '*EDGES, NAME=shaft'
      do r = 1, nrow
         if (quad) then
            write (u, '(a)') itoa(id(2*perm(r) - 2, 3))//', '//itoa(id(2*perm(r), 3))// &
               ', '//itoa(id(2*perm(r) - 1, 3))
         else
            write (u, '(a)') itoa(id(2*perm(r) - 2, 3))//', '//itoa(id(2*perm(r), 3))
         end if
      end do
      write (u, '(a)') '*INTERFACE_LAW, NAME=iface, TYPE=MOHR_COULOMB', &
         'KN = 1e6, KT = 1e5, PHI = 25, C = 0', '*JOINTS, TYPE='//jtype// &
         ', SET=shaft_joints, LAW=iface, EDGES=shaft, SIDE=wall', '*NSET, NAME=base'
      write (u, '(a)') itoa(id(2*nrow, 1))//', '//itoa(id(2*nrow, 3))//', '// &
         itoa(id(2*nrow, 5)), '*BOUNDARY', 'base, XY', '*INITIAL_STRESS, TYPE=GEOSTATIC', &
         'wall, 0.0, 1.0'
      do l = 1, maxval(layer)
         write (line, '(3(a,es24.16e3))') ', ', top(l), ', ', k0(l), ', ', q(l)
         write (u, '(a)') 'layer'//itoa(l)//trim(line)
      end do
      if (quad) then
         write (u, '(a)') '*EDGES, NAME=surface', itoa(id(0, 5))//', '//itoa(id(0, 3))// &
            ', '//itoa(id(0, 4))
      else
         write (u, '(a)') '*EDGES, NAME=surface', itoa(id(0, 5))//', '//itoa(id(0, 3))
      end if
      write (u, '(a)') '*LOAD, NAME=q, TYPE=PRESSURE', 'surface, 10', &
         '*STEP, NAME=surcharge, INCREMENTS=1', 'q, 1'
      close (u)
   contains
      integer function id(j, cc)
         integer, intent(in) :: j, cc
         id = 5*j + cc
      end function id
      real(wp) function height(j)
         integer, intent(in) :: j
         height = rows(j/2 + 1)
         if (mod(j, 2) == 1) height = 0.5_wp*(rows(j/2 + 1) + rows(j/2 + 2))
      end function height
      !> Elements of rows `rr` in the column whose left node column is c0 (1: wall, 3: soil).
      subroutine elements(name, c0, rr)
         character(len=*), intent(in) :: name
         integer, intent(in) :: c0, rr(:)
         integer :: k, j
         write (u, '(a)') '*ELEMENTS, TYPE='//etype//', SET='//name
         do k = 1, size(rr)
            j = 2*rr(k)
            ! counterclockwise from the bottom left (rows go down: row r spans j - 2 .. j)
            if (quad) then
               write (u, '(a)') itoa(100*c0 + rr(k))//', '//itoa(id(j, c0))//', '// &
                  itoa(id(j, c0 + 2))//', '//itoa(id(j - 2, c0 + 2))//', '// &
                  itoa(id(j - 2, c0))//', '//itoa(id(j, c0 + 1))//', '// &
                  itoa(id(j - 1, c0 + 2))//', '//itoa(id(j - 2, c0 + 1))//', '// &
                  itoa(id(j - 1, c0))
            else
               write (u, '(a)') itoa(100*c0 + rr(k))//', '//itoa(id(j, c0))//', '// &
                  itoa(id(j, c0 + 2))//', '//itoa(id(j - 2, c0 + 2))//', '//itoa(id(j - 2, c0))
            end if
         end do
      end subroutine elements
   end subroutine write_column

   !> The next permutation in lexicographic order; more = .false. after the last.
   pure subroutine next_permutation(p, more)
      integer, intent(inout) :: p(:)
      logical, intent(out) :: more
      integer :: i, j, tmp
      more = .false.
      do i = size(p) - 1, 1, -1
         if (p(i) < p(i + 1)) then
            more = .true.
            exit
         end if
      end do
      if (.not. more) return
      do j = size(p), i + 1, -1
         if (p(j) > p(i)) exit
      end do
      tmp = p(i); p(i) = p(j); p(j) = tmp
      p(i + 1:) = p(size(p):i + 1:-1)
   end subroutine next_permutation

   function order_text(p) result(text)
      integer, intent(in) :: p(:)
      character(len=:), allocatable :: text
      integer :: i
      text = itoa(p(1))
      do i = 2, size(p)
         text = text//' '//itoa(p(i))
      end do
   end function order_text

end module test_initial
