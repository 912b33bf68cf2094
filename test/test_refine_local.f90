!> Local refinement (pecplas_model_refine_local) and bulk marking: the refined meshes keep
!> their area and have no hanging node (conforming closure), for T3, T6, Q4 and Q8; joint
!> patch decks refined at one element still give their uniform state to 1e-10 for every
!> joint type (GOODMAN4/6, THIN_LAYER, SPRING, Katona doublets); all marked = the uniform
!> refiner's counts; Dörfler marking picks the fewest largest indicators.
module test_refine_local
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_mesh, only: mesh_t
   use pecplas_model_mesh_tools, only: corner_count
   use pecplas_model_refine_local, only: refine_marked
   use pecplas_model_refine_mark, only: bulk_marking
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use test_refine, only: run_model, total_area
   implicit none (type, external)
   private
   public :: collect_refine_local

contains

   subroutine collect_refine_local(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('bulk_marking', test_marking), &
               new_unittest('t3_t6_corner_conforming', test_triangles), &
               new_unittest('q8_footing_conforming', test_q8_footing), &
               new_unittest('all_marked_is_uniform', test_all_marked), &
               new_unittest('joint_patches_exact', test_joint_patches)]
   end subroutine collect_refine_local

   !> eta = (3, 1, 2, 0.5): eta^2 = (9, 1, 4, 0.25), total 14.25. theta = 0.5 needs 7.125:
   !> element 1 alone; theta = 0.7 needs 9.975: elements 1 and 3; theta = 1: all four.
   subroutine test_marking(error)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: eta(4) = [3.0_wp, 1.0_wp, 2.0_wp, 0.5_wp]
      call check(error, all(bulk_marking(eta, 0.5_wp) .eqv. [.true., .false., .false., &
         .false.]), 'theta 0.5: element 1')
      if (allocated(error)) return
      call check(error, all(bulk_marking(eta, 0.7_wp) .eqv. [.true., .false., .true., &
         .false.]), 'theta 0.7: elements 1 and 3')
      if (allocated(error)) return
      call check(error, all(bulk_marking(eta, 1.0_wp)), 'theta 1: all')
   end subroutine test_marking

   !> A 4 x 4 unit square of T3 (and of T6), refined three times at the element touching the
   !> corner (0, 0): area 1 (1e-12), no hanging node, fewer elements than uniform (4^3 x 32),
   !> and the corner element shrinks by 2^3 in size at least once per level.
   subroutine test_triangles(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model, fine
      character(len=:), allocatable :: reason
      logical :: quadratic
      integer :: level, q
      character(len=80) :: buf
      do q = 0, 1
         quadratic = q == 1
         call square_mesh(4, quadratic, model)
         do level = 1, 3
            call refine_marked(model, corner_marks(model), fine, reason)
            call check(error, .not. allocated(reason), 'triangles refine')
            if (allocated(error)) return
            model = fine
         end do
         write (buf, '(a,i0,a,es9.2,a,i0)') 'T', 3 + 3*q, ': area error ', &
            abs(total_area(fine%mesh) - 1.0_wp), ', elements ', fine%mesh%nelem()
         write (*, '(8x,a)') trim(buf)
         call check(error, abs(total_area(fine%mesh) - 1.0_wp) < 1.0e-12_wp .and. &
            fine%mesh%nelem() < 32*64, trim(buf))
         if (allocated(error)) return
         call check(error, hanging_nodes(fine%mesh) == 0, trim(buf)//': no hanging node')
         if (allocated(error)) return
         call check(error, smallest_side(fine%mesh) <= 0.25_wp/8.0_wp + 1.0e-12_wp, &
            'the corner is refined down to h/8')
         if (allocated(error)) return
      end do
   end subroutine test_triangles

   !> The strip footing (Q8, a footing-edge singularity), refined twice at the elements around
   !> the footing edge: area kept (1e-9 relative), no hanging node, quarter-point nodes lie on
   !> their sides; the run on the refined mesh is done by the adaptive tests.
   subroutine test_q8_footing(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model, fine
      character(len=:), allocatable :: reason
      real(wp) :: a0
      integer :: level
      character(len=80) :: buf
      call read_deck('input/examples/strip_footing.inp', model, error)
      if (allocated(error)) return
      a0 = total_area(model%mesh)
      do level = 1, 2
         call refine_marked(model, corner_marks(model), fine, reason)
         call check(error, .not. allocated(reason), 'Q8 footing refines')
         if (allocated(error)) return
         model = fine
      end do
      write (buf, '(a,es9.2,a,i0,a)') 'Q8 footing: relative area error ', &
         abs(total_area(fine%mesh) - a0)/a0, ', ', fine%mesh%nelem(), ' elements'
      write (*, '(8x,a)') trim(buf)
      call check(error, abs(total_area(fine%mesh) - a0) < 1.0e-9_wp*a0, trim(buf))
      if (allocated(error)) return
      call check(error, hanging_nodes(fine%mesh) == 0, 'Q8 footing: no hanging node')
   end subroutine test_q8_footing

   !> Every element marked on the GOODMAN4 patch deck: 30 nodes, 16 Q4, 4 joints, as the
   !> uniform refiner (test_refine).
   subroutine test_all_marked(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model, fine
      character(len=:), allocatable :: reason
      logical, allocatable :: marks(:)
      call read_deck('test/data/joints/patch_goodman4_plane.inp', model, error)
      if (allocated(error)) return
      allocate (marks(model%mesh%nelem()), source=.true.)
      call refine_marked(model, marks, fine, reason)
      call check(error, .not. allocated(reason), 'all marked refines')
      if (allocated(error)) return
      call check(error, fine%mesh%nnode() == 30 .and. fine%mesh%nelem() == 16 .and. &
         size(fine%joint_sets(1)%conn, 2) == 4, 'nodes 30, Q4 16, joints 4')
   end subroutine test_all_marked

   !> Joint patch decks refined at the elements on the first node of their first joint (the
   !> closure carries the refinement through the joint, transition triangles around it): the massif stress and the joint stress of every point equal the
   !> uniform state of the unrefined run to 1e-10 of its size; the joint has more points.
   subroutine test_joint_patches(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: J = 'test/data/joints/', K = 'test/data/katona/'
      character(len=60), parameter :: decks(9) = [character(len=60) :: &
         J//'patch_goodman4_plane.inp', J//'patch_goodman4_axi_gen.inp', &
         J//'patch_goodman6_plane.inp', J//'patch_goodman6_axi.inp', &
         J//'patch_thin_layer_plane.inp', J//'patch_spring_plane.inp', &
         J//'patch_spring_axi.inp', K//'disp_goodman4_plane.inp', K//'disp_goodman6_plane.inp']
      integer :: d
      do d = 1, size(decks)
         call joint_patch(trim(decks(d)), error)
         if (allocated(error)) return
      end do
   end subroutine test_joint_patches

   subroutine joint_patch(deck, error)
      character(len=*), intent(in) :: deck
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model, fine
      type(problem_t) :: coarse, problem
      character(len=:), allocatable :: reason
      logical, allocatable :: marks(:)
      real(wp) :: scale, worst
      integer :: s, c0
      character(len=120) :: buf
      call read_deck(deck, model, error)
      if (allocated(error)) return
      marks = touching(model, model%joint_sets(1)%conn(1, 1))
      call refine_marked(model, marks, fine, reason)
      call check(error, .not. allocated(reason), deck//' refines locally')
      if (allocated(error)) return
      call check(error, hanging_nodes(fine%mesh) == 0 .and. &
         size(fine%joint_sets(1)%conn, 2) > size(model%joint_sets(1)%conn, 2), &
         deck//': conforming, joints split')
      if (allocated(error)) return
      call run_model(model, coarse, error)
      if (allocated(error)) return
      call run_model(fine, problem, error)
      if (allocated(error)) return
      scale = 0.0_wp
      worst = 0.0_wp
      ! the patch state is uniform per material: every set against the first point of its
      ! unrefined set (transition triangles: of the set they came from, name + '_T3'/'_T6')
      do s = 1, size(problem%state%sets)
         c0 = model%mesh%find_eset(fine%mesh%esets(s)%name)
         if (c0 == 0) c0 = model%mesh%find_eset(fine%mesh%esets(s)%name(1: &
            len(fine%mesh%esets(s)%name) - 3))
         associate (st => problem%state%sets(s)%stress, c => coarse%state%sets(c0)%stress)
            scale = max(scale, maxval(abs(c)))
            worst = max(worst, maxval(abs(st - spread(spread(c(:, 1, 1), 2, size(st, 2)), &
               3, size(st, 3)))))
         end associate
      end do
      associate (js => problem%state%joints%sets(1)%sigma, &
                 jc => coarse%state%joints%sets(1)%sigma)
         worst = max(worst, maxval(abs(js - spread(spread(jc(:, 1, 1), 2, size(js, 2)), &
            3, size(js, 3)))))
         scale = max(scale, maxval(abs(jc)))
      end associate
      write (buf, '(a,es9.2,a,es9.2)') ': refined stress error ', worst, ' of ', scale
      write (*, '(8x,a)') deck//trim(buf)
      call check(error, scale > 0.0_wp .and. worst <= 1.0e-10_wp*scale, deck//trim(buf))
   end subroutine joint_patch

   !> Marks of the elements with a corner at the node nearest the origin (the singular point
   !> of the square; the footing edge for the strip footing is at its half-width).
   function corner_marks(model) result(marks)
      type(model_t), intent(in) :: model
      logical, allocatable :: marks(:)
      real(wp) :: p(2)
      integer :: s, j, g, nc
      p = 0.0_wp
      if (model%mesh%esets(1)%etype(1:1) == 'Q') p = footing_edge(model)
      allocate (marks(model%mesh%nelem()), source=.false.)
      g = 0
      do s = 1, size(model%mesh%esets)
         nc = corner_count(model%mesh%esets(s)%etype)
         do j = 1, size(model%mesh%esets(s)%conn, 2)
            g = g + 1
            marks(g) = any(norm2(model%mesh%x(:, model%mesh%esets(s)%conn(1:nc, j)) - &
               spread(p, 2, nc), dim=1) < 1.0e-9_wp)
         end do
      end do
   end function corner_marks

   !> Marks of the elements with node `node`.
   function touching(model, node) result(marks)
      type(model_t), intent(in) :: model
      integer, intent(in) :: node
      logical, allocatable :: marks(:)
      integer :: s, j, g
      allocate (marks(model%mesh%nelem()), source=.false.)
      g = 0
      do s = 1, size(model%mesh%esets)
         do j = 1, size(model%mesh%esets(s)%conn, 2)
            g = g + 1
            marks(g) = any(model%mesh%esets(s)%conn(:, j) == node)
         end do
      end do
   end function touching

   !> The strip footing deck's footing edge: the end of its loaded edges farthest from x = 0.
   function footing_edge(model) result(p)
      type(model_t), intent(in) :: model
      real(wp) :: p(2)
      integer :: k, i
      p = 0.0_wp
      do k = 1, size(model%patterns)
         if (.not. allocated(model%patterns(k)%edge)) cycle
         do i = 1, size(model%patterns(k)%edge, 2)
            if (model%mesh%x(1, model%patterns(k)%edge(1, i)) > p(1)) &
               p = model%mesh%x(:, model%patterns(k)%edge(1, i))
            if (model%mesh%x(1, model%patterns(k)%edge(2, i)) > p(1)) &
               p = model%mesh%x(:, model%patterns(k)%edge(2, i))
         end do
      end do
   end function footing_edge

   !> Number of (side, node) pairs with the node strictly inside the side and coincident with
   !> none of the side's own nodes: a hanging node (0 on a conforming mesh).
   integer function hanging_nodes(mesh) result(n)
      type(mesh_t), intent(in) :: mesh
      integer :: s, j, i, nc, a, b, m, p
      real(wp) :: d(2), t, l, dist
      logical, allocatable :: used(:)
      allocate (used(mesh%nnode()), source=.false.)
      do s = 1, size(mesh%esets)
         used(reshape(mesh%esets(s)%conn, [size(mesh%esets(s)%conn)])) = .true.
      end do
      n = 0
      do s = 1, size(mesh%esets)
         nc = corner_count(mesh%esets(s)%etype)
         do j = 1, size(mesh%esets(s)%conn, 2)
            do i = 1, nc
               a = mesh%esets(s)%conn(i, j)
               b = mesh%esets(s)%conn(mod(i, nc) + 1, j)
               m = 0
               if (size(mesh%esets(s)%conn, 1) > nc) m = mesh%esets(s)%conn(nc + i, j)
               d = mesh%x(:, b) - mesh%x(:, a)
               l = norm2(d)
               do p = 1, mesh%nnode()
                  if (.not. used(p)) cycle
                  t = dot_product(mesh%x(:, p) - mesh%x(:, a), d)/l**2
                  if (t <= 1.0e-9_wp .or. t >= 1.0_wp - 1.0e-9_wp) cycle
                  dist = abs(d(1)*(mesh%x(2, p) - mesh%x(2, a)) - d(2)*(mesh%x(1, p) - &
                     mesh%x(1, a)))/l
                  if (dist > 1.0e-9_wp*l) cycle
                  if (m > 0) then
                     if (norm2(mesh%x(:, p) - mesh%x(:, m)) < 1.0e-9_wp*l) cycle
                  end if
                  n = n + 1
               end do
            end do
         end do
      end do
   end function hanging_nodes

   real(wp) function smallest_side(mesh) result(h)
      type(mesh_t), intent(in) :: mesh
      integer :: s, j, i, nc
      h = huge(1.0_wp)
      do s = 1, size(mesh%esets)
         nc = corner_count(mesh%esets(s)%etype)
         do j = 1, size(mesh%esets(s)%conn, 2)
            do i = 1, nc
               h = min(h, norm2(mesh%x(:, mesh%esets(s)%conn(i, j)) - &
                  mesh%x(:, mesh%esets(s)%conn(mod(i, nc) + 1, j))))
            end do
         end do
      end do
   end function smallest_side

   !> Unit square, n x n cells, each cut into two triangles (T3, or T6 with mid nodes).
   subroutine square_mesh(n, quadratic, model)
      integer, intent(in) :: n
      logical, intent(in) :: quadratic
      type(model_t), intent(out) :: model
      integer :: i, j, m, k, c(4)
      m = 2*n + 1
      allocate (model%mesh%x(2, m*m))
      do j = 1, m
         do i = 1, m
            model%mesh%x(:, i + (j - 1)*m) = [real(i - 1, wp), real(j - 1, wp)]/real(2*n, wp)
         end do
      end do
      model%mesh%node_id = [(k, k=1, m*m)]
      allocate (model%mesh%esets(1), model%mesh%nsets(0), model%mesh%edge_sets(0))
      model%mesh%esets(1)%name = 'sq'
      model%mesh%esets(1)%etype = merge('T6', 'T3', quadratic)
      allocate (model%mesh%esets(1)%conn(merge(6, 3, quadratic), 2*n*n))
      k = 0
      do j = 1, n
         do i = 1, n
            c = [node(2*i - 1, 2*j - 1), node(2*i + 1, 2*j - 1), node(2*i + 1, 2*j + 1), &
               node(2*i - 1, 2*j + 1)]
            k = k + 1
            model%mesh%esets(1)%conn(1:3, k) = [c(1), c(2), c(3)]
            if (quadratic) model%mesh%esets(1)%conn(4:6, k) = [node(2*i, 2*j - 1), &
               node(2*i + 1, 2*j), node(2*i, 2*j)]
            k = k + 1
            model%mesh%esets(1)%conn(1:3, k) = [c(1), c(3), c(4)]
            if (quadratic) model%mesh%esets(1)%conn(4:6, k) = [node(2*i, 2*j), &
               node(2*i, 2*j + 1), node(2*i - 1, 2*j)]
         end do
      end do
      model%mesh%esets(1)%ids = [(k, k=1, 2*n*n)]
      allocate (model%joint_sets(0), model%patterns(0), model%supports%node(0), &
         model%supports%dof(0))
   contains
      integer function node(i, j)
         integer, intent(in) :: i, j
         node = i + (j - 1)*m
      end function node
   end subroutine square_mesh

end module test_refine_local
