!> Gmsh 4.1 import: files in test/data (hand-written or made by the .geo scripts there),
!> error messages for bad files, and a ~2e5-node performance smoke test.
module test_io_gmsh
   use iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_mesh, only: mesh_t
   use pecplas_model_mesh_tools, only: orient_edge_sets, check_elements
   use pecplas_io_mesh_gmsh, only: read_gmsh
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_io_gmsh

   character(len=*), parameter :: data = 'test/data/'

contains

   subroutine collect_io_gmsh(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('q4_hand_written', test_q4), &
               new_unittest('q4_orient', test_q4_orient), &
               new_unittest('t6', test_t6), &
               new_unittest('q8_clockwise', test_q8), &
               new_unittest('mixed_split', test_mixed), &
               new_unittest('no_physical_groups', test_nophys), &
               new_unittest('errors_data_files', test_errors_data), &
               new_unittest('errors_generated', test_errors_generated), &
               new_unittest('large_grid_2e5_nodes', test_large_grid)]
   end subroutine collect_io_gmsh

   !> Bit-for-bit equality, for values that are exactly representable (0.25, 1.0, ...).
   pure logical function exact(a, b)
      real(wp), intent(in) :: a(:), b(:)
      exact = maxval(abs(a - b)) <= 0.0_wp
   end function exact

   !> User ids of an internal node list.
   pure function uid(m, nodes) result(ids)
      type(mesh_t), intent(in) :: m
      integer, intent(in) :: nodes(:)
      integer :: ids(size(nodes))
      ids = m%node_id(nodes)
   end function uid

   !> Signed area of the corner polygon of element j of set s.
   pure real(wp) function area(m, s, j)
      type(mesh_t), intent(in) :: m
      integer, intent(in) :: s, j
      integer :: i, k, nc
      nc = merge(3, 4, m%esets(s)%etype(1:1) == 'T')
      area = 0.0_wp
      do i = 1, nc
         k = modulo(i, nc) + 1
         associate (a => m%x(:, m%esets(s)%conn(i, j)), b => m%x(:, m%esets(s)%conn(k, j)))
            area = area + 0.5_wp*(a(1)*b(2) - b(1)*a(2))
         end associate
      end do
   end function area

   !> Largest distance of a midside node from the middle of its corners, over all sets.
   pure real(wp) function midside_gap(m) result(gap)
      type(mesh_t), intent(in) :: m
      integer :: s, j, k, nc
      gap = 0.0_wp
      do s = 1, size(m%esets)
         nc = merge(3, 4, m%esets(s)%etype(1:1) == 'T')
         if (size(m%esets(s)%conn, 1) == nc) cycle
         do j = 1, size(m%esets(s)%conn, 2)
            do k = 1, nc
               associate (c => m%esets(s)%conn(:, j))
                  gap = max(gap, norm2(m%x(:, c(nc + k)) - 0.5_wp*(m%x(:, c(k)) + &
                                                               m%x(:, c(modulo(k, nc) + 1)))))
               end associate
            end do
         end do
      end do
   end function midside_gap

   !> Smallest cross product (x2 - x1) x (centroid - x1) over all edges of all edge sets:
   !> positive when the body is on the left (convex domain, boundary edges).
   pure real(wp) function min_left(m) result(cmin)
      type(mesh_t), intent(in) :: m
      real(wp) :: c(2), d(2), r(2)
      integer :: s, k
      c = sum(m%x, dim=2)/size(m%x, 2)
      cmin = huge(1.0_wp)
      do s = 1, size(m%edge_sets)
         do k = 1, size(m%edge_sets(s)%nodes, 2)
            associate (n => m%edge_sets(s)%nodes(:, k))
               d = m%x(:, n(2)) - m%x(:, n(1))
               r = c - m%x(:, n(1))
               cmin = min(cmin, d(1)*r(2) - d(2)*r(1))
            end associate
         end do
      end do
   end function min_left

   subroutine test_q4(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: m
      integer :: s
      call read_gmsh(data//'soil_q4.msh', m, error)
      if (allocated(error)) return
      ! internal numbers follow the file order of the node blocks
      call check(error, m%nnode() == 6 .and. all(m%node_id == [11, 13, 23, 21, 12, 22]), &
         'six nodes, Gmsh tags kept as user ids in file order')
      if (allocated(error)) return
      ! node 12 had a parametric coordinate; node 22 was written "1.0 1.0e0 0"
      call check(error, exact(m%x(:, 5), [1.0_wp, 0.0_wp]) .and. exact(m%x(:, 6), [1.0_wp, 1.0_wp]), &
         'coordinates read exactly')
      if (allocated(error)) return
      call check(error, size(m%esets) == 1 .and. size(m%edge_sets) == 3 .and. size(m%nsets) == 4, &
         '1 element set, 3 edge sets (bottom, top, PHYS7), 4 node sets (+ anchor)')
      if (allocated(error)) return
      s = m%find_eset('soil')
      call check(error, s == 1, 'element set soil')
      if (allocated(error)) return
      call check(error, m%esets(1)%etype == 'Q4' .and. all(m%esets(1)%ids == [7, 8]) .and. &
         all(uid(m, m%esets(1)%conn(:, 1)) == [11, 12, 22, 21]) .and. &
         all(uid(m, m%esets(1)%conn(:, 2)) == [12, 13, 23, 22]), 'Q4 connectivity via internal numbers')
      if (allocated(error)) return
      s = m%find_edge_set('top')
      call check(error, s > 0, 'edge set top')
      if (allocated(error)) return
      call check(error, all(uid(m, m%edge_sets(s)%nodes(:, 1)) == [21, 22]) .and. &
         all(uid(m, m%edge_sets(s)%nodes(:, 2)) == [22, 23]), 'top edges as written')
      if (allocated(error)) return
      s = m%find_edge_set('PHYS7')
      call check(error, s > 0, 'unnamed physical curve 7 named PHYS7')
      if (allocated(error)) return
      call check(error, all(uid(m, m%nsets(m%find_nset('bottom'))%nodes) == [11, 12, 13]) .and. &
         all(uid(m, m%nsets(m%find_nset('PHYS7'))%nodes) == [13, 23]) .and. &
         all(uid(m, m%nsets(m%find_nset('anchor'))%nodes) == [11]), &
         'node sets: curve nodes once each, point group')
   end subroutine test_q4

   subroutine test_q4_orient(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: m
      integer :: nflip, s
      call read_gmsh(data//'soil_q4.msh', m, error)
      if (allocated(error)) return
      call check(error, min_left(m) < 0.0_wp, 'top is written with the body on its right')
      if (allocated(error)) return
      call check_elements(m, nflip, error)
      if (allocated(error)) return
      call check(error, nflip == 0, 'hand-written elements are counter-clockwise')
      if (allocated(error)) return
      call orient_edge_sets(m, error)
      if (allocated(error)) return
      ! unit edges, centroid at distance 0.5 from every boundary: cross product = 0.5
      call check_close(error, min_left(m), 0.5_wp, 1.0e-14_wp, 'body on the left of every edge')
      if (allocated(error)) return
      s = m%find_edge_set('top')
      call check(error, all(uid(m, m%edge_sets(s)%nodes(:, 1)) == [22, 21]), 'top edge reversed')
   end subroutine test_q4_orient

   subroutine test_t6(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: m
      logical, allocatable :: used(:)
      integer :: j, s, nflip
      real(wp) :: a, len
      call read_gmsh(data//'t6.msh', m, error)
      if (allocated(error)) return
      call check(error, size(m%esets) == 1 .and. m%esets(1)%etype == 'T6' .and. &
         size(m%esets(1)%conn, 1) == 6, 'one T6 set')
      if (allocated(error)) return
      allocate (used(m%nnode()))
      used = .false.
      used(pack(m%esets(1)%conn, .true.)) = .true.
      call check(error, all(used), 'every node belongs to a triangle (surface-only model)')
      if (allocated(error)) return
      a = 0.0_wp
      do j = 1, size(m%esets(1)%conn, 2)
         a = a + area(m, 1, j)
      end do
      ! Gmsh places nodes to ~1e-12 relative; straight sides: the midsides are midpoints
      call check_close(error, a, 2.0_wp, 1.0e-10_wp, 'triangles tile the 2 x 1 block')
      if (allocated(error)) return
      call check_close(error, midside_gap(m), 0.0_wp, 0.0_wp, 'T6 midside order', atol=1.0e-10_wp)
      if (allocated(error)) return
      s = m%find_edge_set('bottom')
      call check(error, size(m%edge_sets(s)%nodes, 1) == 3, '3-node edges')
      if (allocated(error)) return
      len = 0.0_wp
      do j = 1, size(m%edge_sets(s)%nodes, 2)
         associate (n => m%edge_sets(s)%nodes(:, j))
            len = len + abs(m%x(1, n(2)) - m%x(1, n(1)))
            ! Gmsh line3 order is end, end, mid
            call check_close(error, m%x(1, n(3)), 0.5_wp*(m%x(1, n(1)) + m%x(1, n(2))), 0.0_wp, &
               'line3 midside third', atol=1.0e-10_wp)
            if (allocated(error)) return
         end associate
      end do
      call check_close(error, len, 2.0_wp, 1.0e-10_wp, 'bottom edges cover y = 0')
      if (allocated(error)) return
      call check(error, all(abs(m%x(2, m%nsets(m%find_nset('bottom'))%nodes)) < 1.0e-12_wp) .and. &
         size(m%nsets(m%find_nset('bottom'))%nodes) == 2*size(m%edge_sets(s)%nodes, 2) + 1, &
         'bottom node set: the 2n+1 nodes of n quadratic edges on y = 0')
      if (allocated(error)) return
      s = m%find_nset('sides')
      call check(error, all(abs(m%x(1, m%nsets(s)%nodes) - 1.0_wp) > 1.0_wp - 1.0e-12_wp), &
         'sides (two curves in one group) only at x = 0 and x = 2')
      if (allocated(error)) return
      call check_elements(m, nflip, error)
      if (allocated(error)) return
      call orient_edge_sets(m, error)
      if (allocated(error)) return
      call check(error, min_left(m) > 0.0_wp, 'body on the left after orientation')
   end subroutine test_t6

   subroutine test_q8(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: m
      integer :: nflip, s
      call read_gmsh(data//'q8.msh', m, error)
      if (allocated(error)) return
      call check(error, size(m%esets) == 1 .and. m%esets(1)%etype == 'Q8' .and. &
         size(m%esets(1)%conn, 2) == 2 .and. m%find_eset('wall') == 1, 'two Q8 in set wall')
      if (allocated(error)) return
      call check(error, area(m, 1, 1) < 0.0_wp .and. area(m, 1, 2) < 0.0_wp, &
         'clockwise curve loop gives clockwise elements')
      if (allocated(error)) return
      call check_elements(m, nflip, error)
      if (allocated(error)) return
      call check(error, nflip == 2, 'both elements renumbered')
      if (allocated(error)) return
      call check_close(error, area(m, 1, 1) + area(m, 1, 2), 2.0_wp, 1.0e-10_wp, 'positive areas')
      if (allocated(error)) return
      call check_close(error, midside_gap(m), 0.0_wp, 0.0_wp, 'midsides follow', atol=1.0e-10_wp)
      if (allocated(error)) return
      call orient_edge_sets(m, error)
      if (allocated(error)) return
      ! unit edges, centroid 0.5 from top and base
      call check_close(error, min_left(m), 0.5_wp, 1.0e-10_wp, 'base and top: body on the left')
      if (allocated(error)) return
      s = m%find_edge_set('base')
      call check(error, size(m%edge_sets(s)%nodes, 1) == 3, 'base has 3-node edges')
   end subroutine test_q8

   subroutine test_mixed(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: m
      integer :: q, t, j, s, nflip
      real(wp) :: aq, at
      integer, allocatable :: before(:, :)
      call read_gmsh(data//'mixed.msh', m, error)
      if (allocated(error)) return
      q = m%find_eset('soil_Q4'); t = m%find_eset('soil_T3')
      call check(error, q > 0 .and. t > 0 .and. m%find_eset('soil') == 0 .and. size(m%esets) == 2, &
         'group soil split into soil_Q4 and soil_T3')
      if (allocated(error)) return
      call check(error, size(m%esets(q)%conn, 2) == 4 .and. m%esets(t)%etype == 'T3', &
         '2 x 2 transfinite quadrangles')
      if (allocated(error)) return
      aq = 0.0_wp; at = 0.0_wp
      do j = 1, size(m%esets(q)%conn, 2)
         aq = aq + area(m, q, j)
      end do
      do j = 1, size(m%esets(t)%conn, 2)
         at = at + area(m, t, j)
      end do
      call check_close(error, aq, 1.0_wp, 1.0e-10_wp, 'quads tile the left square')
      if (allocated(error)) return
      call check_close(error, at, 1.0_wp, 1.0e-10_wp, 'triangles tile the right square')
      if (allocated(error)) return
      s = m%find_nset('origin')
      call check(error, size(m%nsets(s)%nodes) == 1 .and. exact(m%x(:, m%nsets(s)%nodes(1)), [0.0_wp, 0.0_wp]), &
         'physical point origin')
      if (allocated(error)) return
      call check_elements(m, nflip, error)
      if (allocated(error)) return
      s = m%find_edge_set('interface')
      before = m%edge_sets(s)%nodes
      call orient_edge_sets(m, error)
      if (allocated(error)) return
      ! an interior edge has an element on each side: its direction is kept
      call check(error, size(before, 2) == 2 .and. all(m%edge_sets(s)%nodes == before) .and. &
         all(abs(m%x(1, pack(before(1:2, :), .true.)) - 1.0_wp) < 1.0e-12_wp), 'interface x = 1 kept as written')
   end subroutine test_mixed

   subroutine test_nophys(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: m
      call read_gmsh(data//'nophys.msh', m, error)
      if (allocated(error)) return
      call check(error, size(m%esets) == 1 .and. m%esets(1)%name == 'ALL_T3' .and. &
         size(m%esets(1)%conn, 2) == 2 .and. size(m%edge_sets) == 0 .and. size(m%nsets) == 0, &
         'no physical group: all triangles in ALL_T3, lines and points ignored')
      if (allocated(error)) return
      call check_close(error, abs(area(m, 1, 1)) + abs(area(m, 1, 2)), 1.0_wp, 1.0e-14_wp, &
         'two triangles tile the unit square')
   end subroutine test_nophys

   !> Reads `path` expecting an error whose text contains every string of `parts`.
   subroutine expect_error(path, parts, error)
      character(len=*), intent(in) :: path, parts(:)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(mesh_t) :: m
      integer :: i
      call read_gmsh(path, m, e)
      call check(error, allocated(e), path//' must be refused')
      if (allocated(error)) return
      do i = 1, size(parts)
         call check(error, index(e%text(), trim(parts(i))) > 0, 'message has "'//trim(parts(i))// &
            '": '//e%text())
         if (allocated(error)) return
      end do
   end subroutine expect_error

   subroutine test_errors_data(error)
      type(error_t), allocatable, intent(out) :: error
      call expect_error(data//'v22.msh', [character(40) :: 'v22.msh:2:', 'version 2.2', '4.1'], error)
      if (allocated(error)) return
      ! the file stops after the tag of node 21 (line 40), before its coordinates
      call expect_error(data//'truncated.msh', [character(40) :: 'truncated.msh:40:', '[$Nodes]', &
         'end of file'], error)
      if (allocated(error)) return
      call expect_error(data//'q9.msh', [character(40) :: 'q9.msh:', 'type 10', '[$Elements]'], error)
      if (allocated(error)) return
      call expect_error(data//'no_such_file.msh', [character(40) :: 'no_such_file.msh'], error)
   end subroutine test_errors_data

   !> Writes `lines` to `path`, one per line.
   subroutine write_lines(path, lines)
      character(len=*), intent(in) :: path, lines(:)
      integer :: u, i
      open (newunit=u, file=path, status='replace', action='write')
      do i = 1, size(lines)
         write (u, '(a)') trim(lines(i))
      end do
      close (u)
   end subroutine write_lines

   subroutine test_errors_generated(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: f = 'build/test_io_gmsh_bad.msh'
      character(len=24), parameter :: head(3) = [character(24) :: '$MeshFormat', '4.1 0 8', &
                                                 '$EndMeshFormat']
      character(len=24), parameter :: tail(6) = [character(24) :: '$EndNodes', '$Elements', &
                                                 '1 1 1 1', '2 1 2 1', '1 1 2 3', '$EndElements']
      call write_lines(f, [character(24) :: '$MeshFormat', '4.1 1 8', '$EndMeshFormat'])
      call expect_error(f, [character(40) :: 'bad.msh:2:', 'binary'], error)
      if (allocated(error)) return
      ! node 3 sits at z = 1e-6 in a model of size 1
      call write_lines(f, [head, [character(24) :: '$Nodes', '1 3 1 3', '2 1 0 3', '1', '2', '3', &
                                  '0 0 0', '1 0 0', '0 1 1e-6'], tail])
      call expect_error(f, [character(40) :: 'bad.msh:12:', 'node 3', 'z = 0'], error)
      if (allocated(error)) return
      ! the same within 1e-12 of the model size is accepted
      call write_lines(f, [head, [character(24) :: '$Nodes', '1 3 1 3', '2 1 0 3', '1', '2', '3', &
                                  '0 0 0', '1 0 0', '0 1 1e-14'], tail])
      block
         type(mesh_t) :: m
         call read_gmsh(f, m, error)
         if (allocated(error)) return
         call check(error, m%nelem() == 1 .and. m%esets(1)%name == 'ALL_T3', 'tiny z accepted')
         if (allocated(error)) return
      end block
      call write_lines(f, [head, [character(24) :: '$Nodes', '1 3 1 3', '2 1 0 3', '1', '2', '3', &
                                  '0 0 0', '1 0 0', '0 1 0', '$EndNodes', '$Elements', '1 1 1 1', &
                                  '2 1 2 1', '1 1 2 4', '$EndElements']])
      call expect_error(f, [character(40) :: 'bad.msh:17:', 'node 4'], error)
      if (allocated(error)) return
      call write_lines(f, [head, [character(24) :: '$Nodes', '1 3 1 3', '2 1 0 3', '1', '2', '1', &
                                  '0 0 0', '1 0 0', '0 1 0'], tail])
      call expect_error(f, [character(40) :: 'bad.msh:4:', 'Gmsh node tag 1 is defined twice'], error)
      if (allocated(error)) return
      ! surface 1 in physical surfaces 1 and 2: its elements would be in two sets
      call write_lines(f, [head, [character(24) :: '$Entities', '0 0 1 0', &
                                  '1 0 0 0 1 1 0 2 1 2 0', '$EndEntities']])
      call expect_error(f, [character(40) :: 'bad.msh:6:', 'surface 1', 'several physical'], error)
      if (allocated(error)) return
      ! one node fewer than announced: the section end is not where the counts say
      call write_lines(f, [head, [character(24) :: '$Nodes', '1 3 1 3', '2 1 0 2', '1', '2', &
                                  '0 0 0', '1 0 0'], tail])
      call expect_error(f, [character(40) :: 'bad.msh:', '3 nodes announced, 2 found'], error)
   end subroutine test_errors_generated

   !> Appends s to buf(1:p).
   subroutine put(buf, p, s)
      character(len=*), intent(inout) :: buf
      integer(int64), intent(inout) :: p
      character(len=*), intent(in) :: s
      buf(p + 1:p + len(s)) = s
      p = p + len(s)
   end subroutine put

   !> Decimal digits of a non-negative integer (formatted I/O would dominate the test time).
   pure function itoa(i) result(s)
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=12) :: b
      integer :: k, v
      k = 12; v = i
      do
         b(k:k) = achar(48 + modulo(v, 10))
         v = v/10
         if (v == 0) exit
         k = k - 1
      end do
      s = b(k:12)
   end function itoa

   !> i/4 written exactly in decimal.
   pure function quarter(i) result(s)
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=3), parameter :: frac(0:3) = ['   ', '.25', '.5 ', '.75']
      s = itoa(i/4)//trim(frac(modulo(i, 4)))
   end function quarter

   !> nx x ny Q4 grid of quarter-metre squares: physical surface "soil" and curve "bottom".
   subroutine write_grid(path, nx, ny)
      character(len=*), intent(in) :: path
      integer, intent(in) :: nx, ny
      character(len=1), parameter :: nl = achar(10)
      character(len=:), allocatable :: buf
      integer(int64) :: p
      integer :: i, j, nn, ne, u
      nn = (nx + 1)*(ny + 1); ne = nx*ny
      allocate (character(len=24_int64*nn + 48_int64*(ne + nx) + 1000) :: buf)
      p = 0
      call put(buf, p, '$MeshFormat'//nl//'4.1 0 8'//nl//'$EndMeshFormat'//nl)
      call put(buf, p, '$PhysicalNames'//nl//'2'//nl//'1 2 "bottom"'//nl//'2 1 "soil"'//nl// &
               '$EndPhysicalNames'//nl)
      call put(buf, p, '$Entities'//nl//'0 1 1 0'//nl//'1 0 0 0 '//quarter(nx)//' 0 0 1 2 0'//nl// &
               '1 0 0 0 '//quarter(nx)//' '//quarter(ny)//' 0 1 1 0'//nl//'$EndEntities'//nl)
      call put(buf, p, '$Nodes'//nl//'1 '//itoa(nn)//' 1 '//itoa(nn)//nl//'2 1 0 '//itoa(nn)//nl)
      do i = 1, nn
         call put(buf, p, itoa(i)//nl)
      end do
      do j = 0, ny
         do i = 0, nx
            call put(buf, p, quarter(i)//' '//quarter(j)//' 0'//nl)
         end do
      end do
      call put(buf, p, '$EndNodes'//nl//'$Elements'//nl//'2 '//itoa(ne + nx)//' 1 '// &
               itoa(ne + nx)//nl//'1 1 1 '//itoa(nx)//nl)
      do i = 0, nx - 1
         call put(buf, p, itoa(ne + i + 1)//' '//itoa(i + 1)//' '//itoa(i + 2)//nl)
      end do
      call put(buf, p, '2 1 3 '//itoa(ne)//nl)
      do j = 0, ny - 1
         do i = 0, nx - 1
            call put(buf, p, itoa(j*nx + i + 1)//' '//itoa(node(i, j))//' '//itoa(node(i + 1, j)) &
                     //' '//itoa(node(i + 1, j + 1))//' '//itoa(node(i, j + 1))//nl)
         end do
      end do
      call put(buf, p, '$EndElements'//nl)
      open (newunit=u, file=path, access='stream', form='unformatted', status='replace', &
            action='write')
      write (u) buf(1:p)
      close (u)
   contains
      pure integer function node(i, j)
         integer, intent(in) :: i, j
         node = j*(nx + 1) + i + 1
      end function node
   end subroutine write_grid

   subroutine test_large_grid(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: f = 'build/test_io_gmsh_perf.msh'
      integer, parameter :: nx = 450, ny = 450
      type(mesh_t) :: m
      integer(int64) :: t0, t1, t2, rate
      integer :: nflip, u
      real(wp) :: tread, ttools
      character(len=80) :: buf
      call write_grid(f, nx, ny)
      call system_clock(t0, rate)
      call read_gmsh(f, m, error)
      if (allocated(error)) return
      call system_clock(t1)
      call check_elements(m, nflip, error)
      if (allocated(error)) return
      call orient_edge_sets(m, error)
      if (allocated(error)) return
      call system_clock(t2)
      open (newunit=u, file=f)
      close (u, status='delete')
      tread = real(t1 - t0, wp)/rate; ttools = real(t2 - t1, wp)/rate
      write (buf, '(a,f0.2,a,f0.2,a)') ' (read ', tread, ' s, checks ', ttools, ' s)'
      call check(error, m%nnode() == (nx + 1)*(ny + 1) .and. m%nelem() == nx*ny .and. &
         size(m%edge_sets(1)%nodes, 2) == nx .and. size(m%nsets(1)%nodes) == nx + 1 .and. &
         nflip == 0, 'counts of the generated grid'//trim(buf))
      if (allocated(error)) return
      ! last node is the far corner (nx/4, ny/4), exactly representable
      call check(error, exact(m%x(:, m%nnode()), [nx, ny]*0.25_wp) .and. &
         exact(m%x(:, nx + 2), [0.0_wp, 0.25_wp]), 'grid coordinates read exactly')
   end subroutine test_large_grid

end module test_io_gmsh
