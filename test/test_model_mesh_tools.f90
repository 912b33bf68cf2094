!> Mesh utilities: id lookup, appending meshes, element checks and edge-set orientation.
module test_model_mesh_tools
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_mesh, only: mesh_t, element_set_t, node_set_t, edge_set_t
   use pecplas_model_mesh_tools, only: node_lookup_t, append_mesh, orient_edge_sets, check_elements
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_model_mesh_tools

contains

   subroutine collect_model_mesh_tools(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('lookup_dense', test_lookup_dense), &
               new_unittest('lookup_sparse', test_lookup_sparse), &
               new_unittest('lookup_duplicate', test_lookup_duplicate), &
               new_unittest('append', test_append), &
               new_unittest('append_collisions', test_append_collisions), &
               new_unittest('check_flips_cw', test_check_flip), &
               new_unittest('check_errors', test_check_errors), &
               new_unittest('orient', test_orient), &
               new_unittest('orient_errors', test_orient_errors)]
   end subroutine collect_model_mesh_tools

   !> Unit square split along the diagonal 1-3 into two T3; node ids 1..4 (+ shift).
   function two_triangles(shift, set_name) result(m)
      integer, intent(in) :: shift
      character(len=*), intent(in) :: set_name
      type(mesh_t) :: m
      m%x = reshape([0, 0, 1, 0, 1, 1, 0, 1]*1.0_wp, [2, 4])
      m%node_id = [1, 2, 3, 4] + shift
      allocate (m%esets(1), m%nsets(1), m%edge_sets(1))
      m%esets(1)%name = set_name; m%esets(1)%etype = 'T3'
      m%esets(1)%conn = reshape([1, 2, 3, 1, 3, 4], [3, 2])
      m%esets(1)%ids = [1, 2] + shift
      m%nsets(1) = node_set_t('n'//set_name, [1, 2])
      m%edge_sets(1) = edge_set_t('e'//set_name, reshape([1, 2], [2, 1]))
   end function two_triangles

   subroutine test_lookup_dense(error)
      type(error_t), allocatable, intent(out) :: error
      type(node_lookup_t) :: lk
      call lk%build_ids([3, 1, 2, 7], 'node id', error)
      if (allocated(error)) return
      ! position of each id in the list; absent ids (inside and outside the range) give 0
      call check(error, lk%index(7) == 4 .and. lk%index(3) == 1 .and. lk%index(2) == 3, &
         'dense lookup returns list positions')
      if (allocated(error)) return
      call check(error, lk%index(5) == 0 .and. lk%index(-1) == 0 .and. lk%index(1000) == 0, &
         'absent ids give 0')
   end subroutine test_lookup_dense

   subroutine test_lookup_sparse(error)
      type(error_t), allocatable, intent(out) :: error
      type(node_lookup_t) :: lk
      integer, allocatable :: ids(:)
      integer :: i
      logical :: ok
      ! spread over ~1e9: the table would be huge, so the sorted path is taken
      ids = [(modulo(i*100003, 999999937) - 499999968, i=1, 10000)]
      call lk%build_ids(ids, 'node id', error)
      if (allocated(error)) return
      ok = .true.
      do i = 1, size(ids)
         ok = ok .and. lk%index(ids(i)) == i
      end do
      call check(error, ok, 'every sparse id maps back to its position')
      if (allocated(error)) return
      call check(error, lk%index(ids(1) + 1) == 0 .and. lk%index(huge(1)) == 0 .and. &
         lk%index(-huge(1)) == 0, 'absent sparse ids give 0')
   end subroutine test_lookup_sparse

   subroutine test_lookup_duplicate(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(node_lookup_t) :: lk
      call lk%build_ids([5, 42, 1000000000, 42], 'node id', e)
      call check(error, allocated(e), 'a repeated id must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'node id 42 is defined twice') > 0, 'names the id: '//e%text())
   end subroutine test_lookup_duplicate

   subroutine test_append(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: a, b
      type(node_lookup_t) :: lk
      a = two_triangles(0, 'a')
      b = two_triangles(10, 'b')
      b%x(1, :) = b%x(1, :) + 1.0_wp
      call append_mesh(a, b, error)
      if (allocated(error)) return
      call check(error, a%nnode() == 8 .and. size(a%esets) == 2 .and. size(a%nsets) == 2 .and. &
         size(a%edge_sets) == 2, 'nodes and sets of both meshes')
      if (allocated(error)) return
      ! b's connectivity is renumbered, so user ids and coordinates seen through it are unchanged
      call check(error, all(a%node_id(a%esets(2)%conn(:, 1)) == b%node_id(b%esets(1)%conn(:, 1))) &
         .and. all(a%node_id(a%esets(2)%conn(:, 2)) == b%node_id(b%esets(1)%conn(:, 2))), &
         'appended connectivity refers to the same user nodes')
      if (allocated(error)) return
      call check(error, maxval(abs(a%x(:, a%esets(2)%conn(:, 2)) - b%x(:, b%esets(1)%conn(:, 2)))) &
         <= 0.0_wp, &
         'appended coordinates')
      if (allocated(error)) return
      call check(error, all(a%node_id(a%nsets(2)%nodes) == [11, 12]) .and. &
         all(a%node_id(a%edge_sets(2)%nodes(:, 1)) == [11, 12]), 'node and edge sets shifted')
      if (allocated(error)) return
      call check(error, a%find_eset('B') == 2 .and. a%find_edge_set('eb') == 2, 'names kept')
      if (allocated(error)) return
      call lk%build(a, error)
      if (allocated(error)) return
      ! b's first node (user id 11) follows a's four nodes
      call check(error, lk%index(11) == 5 .and. lk%index(4) == 4 .and. lk%index(5) == 0, &
         'lookup built from the appended mesh')
   end subroutine test_append

   subroutine test_append_collisions(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(mesh_t) :: a, b, a0
      a0 = two_triangles(0, 'a')
      a = a0
      b = two_triangles(3, 'b')
      call append_mesh(a, b, e)
      call check(error, allocated(e), 'node id 4 in both meshes must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'node id 4 ') > 0, 'names the id: '//e%text())
      if (allocated(error)) return
      a = a0
      b = two_triangles(10, 'A')
      call append_mesh(a, b, e)
      call check(error, allocated(e), 'element set name in both meshes (any case) is an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'element set ''A''') > 0, 'names the set: '//e%text())
   end subroutine test_append_collisions

   !> Twice the signed area of corners c(1:nc).
   pure real(wp) function area2(x, c, nc)
      real(wp), intent(in) :: x(:, :)
      integer, intent(in) :: c(:), nc
      integer :: i, k
      area2 = 0.0_wp
      do i = 1, nc
         k = modulo(i, nc) + 1
         area2 = area2 + x(1, c(i))*x(2, c(k)) - x(1, c(k))*x(2, c(i))
      end do
   end function area2

   subroutine test_check_flip(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: m
      integer :: nflip, k
      ! T6 on (0,0), (0,1), (1,0) listed clockwise, midsides 4 (1-2), 5 (2-3), 6 (3-1)
      m%x = reshape([0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, 0.0_wp, &
                     0.0_wp, 0.5_wp, 0.5_wp, 0.5_wp, 0.5_wp, 0.0_wp], [2, 6])
      m%node_id = [(k, k=1, 6)]
      allocate (m%esets(2))
      m%esets(1) = element_set_t('t6', 'T6', reshape([1, 2, 3, 4, 5, 6], [6, 1]), [9], 'mat', 0)
      m%esets(2) = element_set_t('t3', 'T3', reshape([1, 3, 2], [3, 1]), [8], 'mat', 0)
      call check_elements(m, nflip, error)
      if (allocated(error)) return
      call check(error, nflip == 1, 'exactly the clockwise T6 is renumbered')
      if (allocated(error)) return
      call check(error, area2(m%x, m%esets(1)%conn(:, 1), 3) > 0.0_wp, 'T6 now counter-clockwise')
      if (allocated(error)) return
      ! midside k must still lie halfway between corners k and k+1 (exact: binary halves)
      do k = 1, 3
         call check(error, maxval(abs(m%x(:, m%esets(1)%conn(3 + k, 1)) - 0.5_wp*( &
            m%x(:, m%esets(1)%conn(k, 1)) + m%x(:, m%esets(1)%conn(modulo(k, 3) + 1, 1))))) <= 0.0_wp, &
            'midside node between its corners after renumbering')
         if (allocated(error)) return
      end do
      call check(error, all(m%esets(2)%conn(:, 1) == [1, 3, 2]), 'CCW T3 untouched')
   end subroutine test_check_flip

   subroutine test_check_errors(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(mesh_t) :: m
      integer :: nflip
      m%x = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, &
                     0.0_wp, 1.0_wp, 1.0_wp, 0.2_wp], [2, 6])
      m%node_id = [10, 20, 30, 40, 50, 60]
      allocate (m%esets(1))
      ! nodes 10, 20, 30 are collinear
      m%esets(1) = element_set_t('flat', 'T3', reshape([1, 2, 3], [3, 1]), [77], 'mat', 0)
      call check_elements(m, nflip, e)
      call check(error, allocated(e), 'zero-area element must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'element 77') > 0 .and. index(e%text(), '''flat''') > 0, &
         'names element and set: '//e%text())
      if (allocated(error)) return
      m%esets(1) = element_set_t('twice', 'Q4', reshape([1, 2, 4, 2], [4, 1]), [78], 'mat', 0)
      call check_elements(m, nflip, e)
      call check(error, allocated(e), 'repeated node must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'uses node 20 twice') > 0, 'names the node: '//e%text())
      if (allocated(error)) return
      ! (0,0) (2,0) (1,0.2) (0,1): positive area but re-entrant at (1,0.2)
      m%esets(1) = element_set_t('dart', 'Q4', reshape([1, 3, 6, 5], [4, 1]), [79], 'mat', 0)
      call check_elements(m, nflip, e)
      call check(error, allocated(e), 'non-convex quadrilateral must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), 'element 79') > 0 .and. index(e%text(), 'node 60') > 0, &
         'names element and corner: '//e%text())
   end subroutine test_check_errors

   subroutine test_orient(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: m
      m = two_triangles(0, 'a')
      ! bottom 2->1 (body on the right: must turn), right 2->3 (fine), diagonal 3->1 (interior:
      ! there is a triangle on each side, so the given direction stays)
      m%edge_sets(1) = edge_set_t('e', reshape([2, 1, 2, 3, 3, 1], [2, 3]))
      call orient_edge_sets(m, error)
      if (allocated(error)) return
      call check(error, all(m%edge_sets(1)%nodes == reshape([1, 2, 2, 3, 3, 1], [2, 3])), &
         'bottom reversed, right and interior diagonal kept')
   end subroutine test_orient

   subroutine test_orient_errors(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(mesh_t) :: m
      m = two_triangles(100, 'a')
      ! 2 -> 4 is the other diagonal: a side of no element
      m%edge_sets(1) = edge_set_t('diag', reshape([2, 4], [2, 1]))
      call orient_edge_sets(m, e)
      call check(error, allocated(e), 'an edge of no element must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), '''diag''') > 0 .and. index(e%text(), '(102 104)') > 0, &
         'names set and user ids: '//e%text())
      if (allocated(error)) return
      ! a 3-node edge on the side of a linear triangle
      m%edge_sets(1) = edge_set_t('quad', reshape([1, 2, 3], [3, 1]))
      call orient_edge_sets(m, e)
      call check(error, allocated(e), '3-node edge on a T3 side must be an error')
      if (allocated(error)) return
      call check(error, index(e%text(), '''quad''') > 0 .and. index(e%text(), 'element 101') > 0, &
         'names set and element: '//e%text())
   end subroutine test_orient_errors

end module test_model_mesh_tools
