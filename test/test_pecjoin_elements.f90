!> Joint elements of PECJOIN against Annex B: D matrices of (B.8), (B.10) (last entry of
!> row 1 read as N3 C, doc/theory.md §6.4) and (B.17) for an element inclined at 30 degrees, rigid
!> motions giving no relative displacement, a pure opening / slip giving g_n / eps_t with
!> the right signs, point measures (length, 2 pi r length, thin layer thickness), stiffness
!> and internal force consistent with each other, spring tributaries, the factory.
module test_pecjoin_elements
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t, joint_strain, &
      joint_force, joint_stiffness
   use pecplas_joints_elements_factory, only: new_joint_element
   use pecplas_joints_elements_tributary, only: spring_tributaries
   use pecplas_testing, only: unittest_t, new_unittest, check, check_close
   implicit none (type, external)
   private
   public :: collect_pecjoin_elements

   real(wp), parameter :: PI = acos(-1.0_wp), THETA = PI/6.0_wp

contains

   subroutine collect_pecjoin_elements(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('d_goodman4_b8', test_d4), &
               new_unittest('d_goodman6_b10', test_d6), &
               new_unittest('d_spring_b17', test_d_spring), &
               new_unittest('rigid_motion_no_jump', test_rigid), &
               new_unittest('opening_and_slip_signs', test_opening), &
               new_unittest('measures', test_measures), &
               new_unittest('stiffness_force_consistent', test_consistency), &
               new_unittest('spring_tributaries', test_tributaries), &
               new_unittest('factory', test_factory)]
   end subroutine collect_pecjoin_elements

   !> Inclined element of length 2 at THETA: face 1 = 1 -> 2 (+ mid 5), face 2 coincident
   !> (3 on 2, 4 on 1, 6 on 5).
   pure function inclined(nnode) result(xe)
      integer, intent(in) :: nnode
      real(wp) :: xe(2, nnode)
      real(wp) :: x1(2), x2(2)
      x1 = [0.3_wp, -0.2_wp]
      x2 = x1 + 2.0_wp*[cos(THETA), sin(THETA)]
      xe(:, 1) = x1; xe(:, 2) = x2; xe(:, 3) = x2; xe(:, 4) = x1
      if (nnode == 6) then
         xe(:, 5) = 0.5_wp*(x1 + x2); xe(:, 6) = xe(:, 5)
      end if
   end function inclined

   subroutine element(name, nnode, rule, thick, elem, error)
      character(len=*), intent(in) :: name, rule
      integer, intent(in) :: nnode
      real(wp), intent(in) :: thick
      class(joint_element_t), allocatable, intent(out) :: elem
      type(error_t), allocatable, intent(out) :: error
      call new_joint_element(name, nnode, rule, thick, elem, error)
   end subroutine element

   !> Largest |a - b| over two arrays of the same shape.
   pure real(wp) function maxdiff(a, b)
      real(wp), intent(in) :: a(:, :), b(:, :)
      maxdiff = maxval(abs(a - b))
   end function maxdiff

   subroutine test_d4(error)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t) :: pts(2)
      real(wp) :: d(2, 8), xi(2), n1, n2, s, c
      integer :: ip
      call element('GOODMAN4', 4, 'GAUSS', 0.0_wp, elem, error)
      if (allocated(error)) return
      call elem%points(inclined(4), PLANE_STRAIN, 1.0_wp, pts, error)
      if (allocated(error)) return
      s = sin(THETA); c = cos(THETA)
      xi = [-1.0_wp, 1.0_wp]/sqrt(3.0_wp)
      do ip = 1, 2
         n1 = 0.5_wp*(1.0_wp - xi(ip)); n2 = 0.5_wp*(1.0_wp + xi(ip))
         d(1, :) = [n1*s, -n1*c, n2*s, -n2*c, -n2*s, n2*c, -n1*s, n1*c]
         d(2, :) = [-n1*c, -n1*s, -n2*c, -n2*s, n2*c, n2*s, n1*c, n1*s]
         call check(error, maxdiff(pts(ip)%d(:, 1:8), d) < 1.0e-14_wp, &
            'GOODMAN4 D = (B.8) at each Gauss point')
         if (allocated(error)) return
         call check(error, norm2(pts(ip)%t - [c, s]) < 1.0e-14_wp, 't = dX/dxi / J')
         if (allocated(error)) return
      end do
   end subroutine test_d4

   subroutine test_d6(error)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t) :: pts(3)
      real(wp) :: d(2, 12), xi(3), n1, n2, n3, s, c
      integer :: ip
      call element('GOODMAN6', 6, 'GAUSS', 0.0_wp, elem, error)
      if (allocated(error)) return
      call elem%points(inclined(6), PLANE_STRAIN, 1.0_wp, pts, error)
      if (allocated(error)) return
      s = sin(THETA); c = cos(THETA)
      xi = [-sqrt(0.6_wp), 0.0_wp, sqrt(0.6_wp)]
      do ip = 1, 3
         n1 = 0.5_wp*xi(ip)*(xi(ip) - 1.0_wp)
         n2 = 0.5_wp*xi(ip)*(xi(ip) + 1.0_wp)
         n3 = 1.0_wp - xi(ip)**2
         ! (B.10) with the misprint of row 1, column 12 corrected to N3 C
         d(1, :) = [n1*s, -n1*c, n2*s, -n2*c, -n2*s, n2*c, -n1*s, n1*c, n3*s, -n3*c, -n3*s, n3*c]
         d(2, :) = [-n1*c, -n1*s, -n2*c, -n2*s, n2*c, n2*s, n1*c, n1*s, -n3*c, -n3*s, n3*c, n3*s]
         call check(error, maxdiff(pts(ip)%d(:, 1:12), d) < 1.0e-14_wp, &
            'GOODMAN6 D = (B.10) (row 1 last entry N3 C) at each Gauss point')
         if (allocated(error)) return
      end do
   end subroutine test_d6

   subroutine test_d_spring(error)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t) :: pts(1)
      real(wp) :: d(2, 4), s, c, xe(2, 2)
      s = sin(THETA); c = cos(THETA)
      xe = reshape([1.0_wp, 2.0_wp, 1.0_wp, 2.0_wp], [2, 2])
      call element('spring', 2, '', 0.0_wp, elem, error)
      if (allocated(error)) return
      call elem%points(xe, PLANE_STRAIN, 1.0_wp, pts, error, [c, s], 0.7_wp)
      if (allocated(error)) return
      d(1, :) = [s, -c, -s, c]
      d(2, :) = [-c, -s, c, s]
      call check(error, maxdiff(pts(1)%d(:, 1:4), d) < 1.0e-15_wp, 'spring D = (B.17)')
      if (allocated(error)) return
      call check_close(error, pts(1)%da, 0.7_wp, 1.0e-15_wp, 'spring measure = tributary')
   end subroutine test_d_spring

   !> Translations and an infinitesimal rotation of both faces move coincident nodes alike.
   subroutine test_rigid(error)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t), allocatable :: pts(:)
      real(wp), allocatable :: xe(:, :), u(:, :)
      character(len=10), parameter :: names(3) = [character(len=10) :: 'GOODMAN4', 'GOODMAN6', &
         'THIN_LAYER']
      integer, parameter :: nodes(3) = [4, 6, 6]
      integer :: k, ip, j
      do k = 1, 3
         call element(names(k), nodes(k), 'LOBATTO', 0.05_wp, elem, error)
         if (allocated(error)) return
         xe = inclined(nodes(k))
         allocate (u(2, nodes(k)), pts(elem%npoint()))
         do j = 1, nodes(k)
            ! translation (0.3, -0.7) plus rotation 0.01 about the origin
            u(:, j) = [0.3_wp, -0.7_wp] + 0.01_wp*[-xe(2, j), xe(1, j)]
         end do
         call elem%points(xe, AXISYMMETRIC, 1.0_wp, pts, error)
         if (allocated(error)) return
         do ip = 1, size(pts)
            call check(error, norm2(joint_strain(pts(ip), reshape(u, [2*nodes(k)]))) < 1.0e-13_wp, &
               trim(names(k))//': rigid motion gives no relative displacement')
            if (allocated(error)) return
         end do
         deallocate (u, pts)
      end do
   end subroutine test_rigid

   !> Face 2 moved by delta along n: g_n = delta (opening), law eps_n = -delta, eps_t = 0;
   !> along t: eps_t = delta.
   subroutine test_opening(error)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t) :: pts(3)
      real(wp) :: u(2, 6), n(2), t(2), eps(2), delta
      integer :: ip
      delta = 1.0e-3_wp
      t = [cos(THETA), sin(THETA)]
      n = [-t(2), t(1)]
      call element('GOODMAN6', 6, 'GAUSS', 0.0_wp, elem, error)
      if (allocated(error)) return
      call elem%points(inclined(6), PLANE_STRAIN, 1.0_wp, pts, error)
      if (allocated(error)) return
      u = 0.0_wp
      u(:, [3, 4, 6]) = spread(delta*n, 2, 3)
      do ip = 1, 3
         eps = joint_strain(pts(ip), reshape(u, [12]))
         call check(error, abs(dot_product(pts(ip)%d(1, 1:12), reshape(u, [12])) - delta) < 1.0e-16_wp &
            .and. abs(eps(1) + delta) < 1.0e-16_wp .and. abs(eps(2)) < 1.0e-16_wp, &
            'opening: g_n = +delta, law eps_n = -delta (closure positive), eps_t = 0')
         if (allocated(error)) return
      end do
      u = 0.0_wp
      u(:, [3, 4, 6]) = spread(delta*t, 2, 3)
      do ip = 1, 3
         eps = joint_strain(pts(ip), reshape(u, [12]))
         call check(error, abs(eps(1)) < 1.0e-16_wp .and. abs(eps(2) - delta) < 1.0e-16_wp, &
            'slip of face 2 along t: eps_t = U_t(2) - U_t(1) = +delta')
         if (allocated(error)) return
      end do
   end subroutine test_opening

   !> Sum of the point measures: L t (plane strain, any rule), 2 pi r_mid L (axisymmetric,
   !> Gauss exact for the linear r), and e L t for a thin layer with D scaled by 1/e.
   subroutine test_measures(error)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t) :: pts(3), ref(3)
      real(wp) :: xe(2, 6), rmid
      xe = inclined(6)
      rmid = 0.5_wp*(xe(1, 1) + xe(1, 2))
      call element('GOODMAN6', 6, 'LOBATTO', 0.0_wp, elem, error)
      if (allocated(error)) return
      call elem%points(xe, PLANE_STRAIN, 0.5_wp, pts, error)
      if (allocated(error)) return
      call check_close(error, sum(pts%da), 2.0_wp*0.5_wp, 1.0e-14_wp, 'plane: L x thickness')
      if (allocated(error)) return
      call check(error, norm2(pts(1)%x - xe(:, 1)) < 1.0e-15_wp .and. &
         norm2(pts(3)%x - xe(:, 2)) < 1.0e-15_wp, 'Lobatto points sit on the doublets')
      if (allocated(error)) return
      call element('GOODMAN4', 4, 'GAUSS', 0.0_wp, elem, error)
      if (allocated(error)) return
      call elem%points(xe(:, 1:4), AXISYMMETRIC, 0.5_wp, pts(1:2), error)
      if (allocated(error)) return
      call check_close(error, sum(pts(1:2)%da), 2.0_wp*PI*rmid*2.0_wp, 1.0e-14_wp, &
         'axisymmetric: 2 pi r_mid L')
      if (allocated(error)) return
      call element('GOODMAN6', 6, 'GAUSS', 0.0_wp, elem, error)
      if (allocated(error)) return
      call elem%points(xe, PLANE_STRAIN, 1.0_wp, ref, error)
      if (allocated(error)) return
      call element('THIN_LAYER', 6, 'GAUSS', 0.02_wp, elem, error)
      if (allocated(error)) return
      call elem%points(xe, PLANE_STRAIN, 1.0_wp, pts, error)
      if (allocated(error)) return
      call check(error, abs(sum(pts%da) - 0.02_wp*2.0_wp) < 1.0e-15_wp .and. &
         maxdiff(pts(2)%d(:, 1:12)*0.02_wp, ref(2)%d(:, 1:12)) < 1.0e-13_wp, &
         'thin layer: measure e L, strains = jump / e')
   end subroutine test_measures

   !> K u = f(C S D u) for a linear law with coupling terms (non-symmetric C), and
   !> K symmetric for a diagonal C.
   subroutine test_consistency(error)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t) :: pts(3)
      real(wp) :: k(12, 12), f(12), u(12), c(2, 2)
      integer :: ip, i
      call element('GOODMAN6', 6, 'GAUSS', 0.0_wp, elem, error)
      if (allocated(error)) return
      call elem%points(inclined(6), AXISYMMETRIC, 1.0_wp, pts, error)
      if (allocated(error)) return
      c = reshape([3.0e3_wp, -4.0e2_wp, 7.0e2_wp, 1.0e3_wp], [2, 2])
      u = [(0.001_wp*sin(real(i, wp)), i=1, 12)]
      k = 0.0_wp; f = 0.0_wp
      do ip = 1, 3
         call joint_stiffness(pts(ip), c, k)
         call joint_force(pts(ip), matmul(c, joint_strain(pts(ip), u)), f)
      end do
      call check(error, maxval(abs(matmul(k, u) - f)) < 1.0e-12_wp*maxval(abs(f)), &
         'internal force of a linear law = K u (non-symmetric C)')
      if (allocated(error)) return
      c(1, 2) = 0.0_wp; c(2, 1) = 0.0_wp
      k = 0.0_wp
      do ip = 1, 3
         call joint_stiffness(pts(ip), c, k)
      end do
      call check(error, maxval(abs(k - transpose(k))) < 1.0e-12_wp*maxval(abs(k)), &
         'elastic joint stiffness is symmetric')
   end subroutine test_consistency

   !> Two linear plane edges of lengths 1 and 3: tributaries 0.5, 2, 1.5 (half of each
   !> adjacent segment); one quadratic edge of length 2: 1/3, 1/3, 4/3 (consistent); one
   !> axisymmetric linear edge from r = 1 to r = 2: 2 pi L (2 r_a + r_b) / 6.
   subroutine test_tributaries(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      real(wp) :: x(2, 3), trib(3), tang(2, 3)
      integer :: bad
      x = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 4.0_wp, 0.0_wp], [2, 3])
      call spring_tributaries(x, PLANE_STRAIN, 1.0_wp, [1, 2, 3], &
         reshape([1, 2, 2, 3], [2, 2]), trib, tang, bad, error)
      if (allocated(error)) return
      call check(error, maxval(abs(trib - [0.5_wp, 2.0_wp, 1.5_wp])) < 1.0e-14_wp .and. &
         maxval(abs(tang - spread([1.0_wp, 0.0_wp], 2, 3))) < 1.0e-15_wp, &
         'linear plane edges: half of each adjacent segment, tangent +x')
      if (allocated(error)) return
      x = reshape([0.0_wp, 0.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, 1.0_wp], [2, 3])
      call spring_tributaries(x, PLANE_STRAIN, 1.0_wp, [1, 2, 3], &
         reshape([1, 2, 3], [3, 1]), trib, tang, bad, error)
      if (allocated(error)) return
      call check(error, maxval(abs(trib - [1.0_wp, 1.0_wp, 4.0_wp]/3.0_wp)) < 1.0e-14_wp .and. &
         maxval(abs(tang - spread([0.0_wp, 1.0_wp], 2, 3))) < 1.0e-15_wp, &
         'quadratic edge: L/6, L/6, 2L/3, tangent +y')
      if (allocated(error)) return
      x = reshape([1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, 9.0_wp, 9.0_wp], [2, 3])
      call spring_tributaries(x, AXISYMMETRIC, 1.0_wp, [1, 2], reshape([1, 2], [2, 1]), &
         trib(1:2), tang(:, 1:2), bad, error)
      if (allocated(error)) return
      call check(error, abs(trib(1) - 2.0_wp*PI*4.0_wp/6.0_wp) < 1.0e-13_wp .and. &
         abs(trib(2) - 2.0_wp*PI*5.0_wp/6.0_wp) < 1.0e-13_wp, &
         'axisymmetric: 2 pi integral of N_a r ds')
      if (allocated(error)) return
      call spring_tributaries(x, PLANE_STRAIN, 1.0_wp, [1, 2, 3], reshape([1, 2], [2, 1]), &
         trib, tang, bad, e)
      call check(error, allocated(e) .and. bad == 3, 'a spring with no adjacent edge is an error')
   end subroutine test_tributaries

   subroutine test_factory(error)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(error_t), allocatable :: e
      call new_joint_element('GOODMAN5', 4, 'GAUSS', 0.0_wp, elem, e)
      call check(error, allocated(e), 'unknown joint type is an error')
      if (allocated(error)) return
      call check(error, index(e%message, 'SPRING') > 0 .and. index(e%message, 'GOODMAN4') > 0 &
         .and. index(e%message, 'GOODMAN6') > 0 .and. index(e%message, 'THIN_LAYER') > 0, &
         'the message lists the known types: '//e%message)
      if (allocated(error)) return
      call new_joint_element('GOODMAN6', 4, 'GAUSS', 0.0_wp, elem, e)
      call check(error, allocated(e), 'GOODMAN6 with 4 nodes is an error')
      if (allocated(error)) return
      call new_joint_element('THIN_LAYER', 4, 'GAUSS', 0.0_wp, elem, e)
      call check(error, allocated(e), 'THIN_LAYER without thickness is an error')
      if (allocated(error)) return
      call new_joint_element('goodman4', 4, 'simpson', 0.0_wp, elem, e)
      call check(error, allocated(e), 'unknown integration is an error')
      if (allocated(error)) return
      call new_joint_element('thin_layer', 6, 'lobatto', 0.1_wp, elem, e)
      call check(error, .not. allocated(e), 'thin_layer (any case) with 6 nodes is known')
      if (allocated(error)) return
      call check(error, elem%name() == 'THIN_LAYER' .and. elem%nnode() == 6 .and. &
         elem%npoint() == 3, 'THIN_LAYER, 6 nodes, 3 points')
   end subroutine test_factory

end module test_pecjoin_elements
