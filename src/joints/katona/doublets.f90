!> The node doublets of the Katona joint sets, from the same joint meshes as the penalty laws
!> (so that a deck switches method by the law's TYPE only):
!> - SPRING sets: each spring is a doublet, with the set's tributary measure and tangent;
!> - line joints (GOODMAN4/6, THIN_LAYER): the doublets (1,4), (2,3) [, (5,6)] of the elements,
!>   with the consistent tributary measure A_a = sum over the points of N_a dA (the same
!>   measure as spring_tributaries: 1/2, 1/2 on linear edges, 1/6, 2/3, 1/6 on quadratic
!>   ones, 2 pi r in axisymmetry) and the N_a dA-weighted mean tangent.
!> The initial contact force of a doublet is the projection of the joint's initial stress
!> (f0 = sigma0 A, same weights); its nodal force D^T f0 joins the initial-stress load, so
!> the initial state stays in equilibrium. Explicit Katona doublets may have an initial gap
!> g0 = n . (x_2 - x_1) >= 0 (node-to-node contact of curved bodies, e.g. Hertz).
module pecplas_joints_katona_doublets
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error
   use pecplas_base_strings, only: itoa
   use pecplas_model_type, only: model_t
   use pecplas_model_provenance, only: place_t
   use pecplas_joints_state, only: joint_state_t
   use pecplas_joints_laws_type, only: MODE_OPEN
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t
   use pecplas_joints_points, only: joint_set_element, joint_element_points
   use pecplas_joints_katona_type, only: katona_t
   use pecplas_joints_katona_operator, only: add_contact_forces
   implicit none (type, external)
   private

   public :: setup_katona, doublet_weights

contains

   !> Builds the doublets of every Katona set of `model` (none: kt%active stays false) and adds
   !> their initial forces to `initial_force` (2, nnode).
   subroutine setup_katona(model, jstate, kt, initial_force, error)
      type(model_t), intent(in) :: model
      type(joint_state_t), intent(in) :: jstate
      type(katona_t), intent(out) :: kt
      real(wp), intent(inout) :: initial_force(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: s0(:, :)
      real(wp) :: size_model, tol, n(2)
      integer :: s, k, k0
      character(len=32) :: buf
      allocate (kt%node(2, 0), kt%set_of(0), kt%t(2, 0), kt%area(0), s0(2, 0))
      allocate (kt%mu(0), kt%cohesion(0), kt%tension(0))
      if (.not. allocated(model%joint_sets)) return
      do s = 1, size(model%joint_sets)
         if (.not. model%joint_sets(s)%is_katona()) cycle
         associate (law => model%contacts(model%joint_sets(s)%contact_index))
            k0 = size(kt%area)
            call set_doublets(model, s, jstate, kt, s0, error)
            if (allocated(error)) return
            kt%mu = [real(wp) :: kt%mu, (law%mu, k=k0 + 1, size(kt%area))]
            kt%cohesion = [real(wp) :: kt%cohesion, law%c*kt%area(k0 + 1:)]
            kt%tension = [real(wp) :: kt%tension, law%tensile_limit()*kt%area(k0 + 1:)]
         end associate
      end do
      kt%nd = size(kt%area)
      if (kt%nd == 0) return
      kt%active = .true.
      call kt%allocate_states()
      size_model = norm2(maxval(model%mesh%x, dim=2) - minval(model%mesh%x, dim=2))
      tol = 1.0e-9_wp*size_model
      allocate (kt%gap0(kt%nd))
      do k = 1, kt%nd
         n = [-kt%t(2, k), kt%t(1, k)]
         kt%gap0(k) = dot_product(n, model%mesh%x(:, kt%node(2, k)) - model%mesh%x(:, kt%node(1, k)))
         if (kt%gap0(k) < -tol) then
            write (buf, '(i0,a,i0)') model%mesh%node_id(kt%node(1, k)), ', ', &
               model%mesh%node_id(kt%node(2, k))
            call input_error(error, 'Katona doublet (nodes '//trim(buf)//') of joint set '// &
               model%joint_sets(kt%set_of(k))%name//' starts interpenetrated: its face-2 node '// &
               'lies behind face 1 (swap the faces, or move the nodes)')
            call locate_doublet(model, kt%set_of(k), kt%node(:, k), error)
            return
         end if
         if (kt%gap0(k) <= tol) then
            kt%gap0(k) = 0.0_wp
            kt%f(:, k) = s0(:, k)*kt%area(k)
         else
            kt%mode(k) = MODE_OPEN
         end if
      end do
      ! with zero relative displacement a stick doublet is anchored at eps_t = 0
      call kt%begin_increment()
      call add_contact_forces(kt, kt%f, initial_force)

   end subroutine setup_katona

   !> Doublets of joint set s appended to kt (node, set_of, t, area) and s0 (initial stress).
   subroutine set_doublets(model, s, jstate, kt, s0, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      type(joint_state_t), intent(in) :: jstate
      type(katona_t), intent(inout) :: kt
      real(wp), allocatable, intent(inout) :: s0(:, :)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t), allocatable :: pts(:)
      integer, allocatable :: of_node(:)
      real(wp), allocatable :: tplain(:, :)
      real(wp) :: wgt(3)
      integer :: e, ip, j, k, k0, npair, pairs(2, 3)
      associate (set => model%joint_sets(s), st => jstate%sets(s))
         k0 = size(kt%area)
         if (set%is_spring()) then
            kt%node = reshape([kt%node, set%conn(1:2, :)], [2, k0 + size(set%conn, 2)])
            kt%t = reshape([kt%t, set%tangent], [2, k0 + size(set%conn, 2)])
            kt%area = [kt%area, set%tributary]
            kt%set_of = [kt%set_of, (s, e=1, size(set%conn, 2))]
            s0 = reshape([s0, st%sigma(:, 1, :)], [2, k0 + size(set%conn, 2)])
            return
         end if
         call joint_set_element(set, elem, error)
         if (allocated(error)) return
         allocate (pts(elem%npoint()))
         allocate (of_node(model%mesh%nnode()), source=0)
         allocate (tplain(2, 0))
         pairs = reshape([1, 4, 2, 3, 5, 6], [2, 3])
         npair = size(set%conn, 1)/2
         do e = 1, size(set%conn, 2)
            call joint_element_points(model, set, elem, e, pts, error)
            if (allocated(error)) return
            do j = 1, npair
               k = of_node(set%conn(pairs(1, j), e))
               if (k == 0) then
                  k = size(kt%area) + 1
                  of_node(set%conn(pairs(1, j), e)) = k
                  kt%node = reshape([kt%node, set%conn(pairs(:, j), e)], [2, k])
                  kt%t = reshape([kt%t, 0.0_wp, 0.0_wp], [2, k])
                  kt%area = [kt%area, 0.0_wp]
                  kt%set_of = [kt%set_of, s]
                  s0 = reshape([s0, 0.0_wp, 0.0_wp], [2, k])
                  tplain = reshape([tplain, 0.0_wp, 0.0_wp], [2, k - k0])
               else if (kt%node(2, k) /= set%conn(pairs(2, j), e)) then
                  call input_error(error, 'joint set '//set%name//': face-1 node '// &
                     itoa(model%mesh%node_id(set%conn(pairs(1, j), e)))//' faces two different '// &
                     'face-2 nodes ('//itoa(model%mesh%node_id(kt%node(2, k)))//', '// &
                     itoa(model%mesh%node_id(set%conn(pairs(2, j), e)))//'); Katona doublets '// &
                     'need one partner per node')
                  return
               end if
               do ip = 1, size(pts)
                  wgt = doublet_weights(pts(ip), npair)
                  kt%area(k) = kt%area(k) + wgt(j)*pts(ip)%da
                  kt%t(:, k) = kt%t(:, k) + wgt(j)*pts(ip)%da*pts(ip)%t
                  s0(:, k) = s0(:, k) + wgt(j)*pts(ip)%da*st%sigma(:, ip, e)
                  tplain(:, k - k0) = tplain(:, k - k0) + pts(ip)%t
               end do
            end do
         end do
         do k = k0 + 1, size(kt%area)
            ! A corner node on the axis of a quadratic axisymmetric edge has a zero measure
            ! (int N_1 2 pi r ds = 0): it stays a constraint, with the plain mean tangent.
            if (.not. (norm2(kt%t(:, k)) > 1.0e-12_wp*kt%area(k) .and. kt%area(k) > 0.0_wp)) &
               kt%t(:, k) = tplain(:, k - k0)
            if (.not. (norm2(kt%t(:, k)) > 0.0_wp)) then
               call input_error(error, 'joint set '//set%name//': a Katona doublet has no '// &
                  'tangent (its joint edges turn back on each other)')
               return
            end if
            kt%t(:, k) = kt%t(:, k)/norm2(kt%t(:, k))
            if (kt%area(k) > 0.0_wp) s0(:, k) = s0(:, k)/kt%area(k)
         end do
      end associate
   end subroutine set_doublets

   !> Shape-function weights N_j of the doublets j = 1..npair (pairs (1,4), (2,3), (5,6)) at a
   !> line-joint point, read from its D matrix: row 2 holds -N_j t on the face-1 node j. For a
   !> thin layer D is divided by the thickness and da multiplied by it, so N da is unchanged.
   pure function doublet_weights(pt, npair) result(wgt)
      type(joint_point_t), intent(in) :: pt
      integer, intent(in) :: npair
      real(wp) :: wgt(3)
      integer, parameter :: face1(3) = [1, 2, 5]
      integer :: j
      wgt = 0.0_wp
      do j = 1, npair
         wgt(j) = -dot_product(pt%d(2, 2*face1(j) - 1:2*face1(j)), pt%t)
      end do
   end function doublet_weights

   !> Gives `error` the deck line of the first joint of set s holding both doublet nodes.
   subroutine locate_doublet(model, s, nodes, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s, nodes(2)
      type(error_t), intent(inout) :: error
      type(place_t) :: p
      character(len=:), allocatable :: keyword
      integer :: e
      associate (conn => model%joint_sets(s)%conn)
         do e = 1, size(conn, 2)
            if (any(conn(:, e) == nodes(1)) .and. any(conn(:, e) == nodes(2))) then
               call model%provenance%joint(s, e, p, keyword)
               call model%provenance%locate(error, p, keyword)
               return
            end if
         end do
      end associate
   end subroutine locate_doublet

end module pecplas_joints_katona_doublets
