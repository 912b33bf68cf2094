!> Which face of each plate element the free water presses on (doc/deck.md, *PLATE_WATER;
!> doc/theory.md, Groundwater). Under LEFT or RIGHT every element of the set has the water on
!> that face; under FREE the water stands on each face of an element that nothing active lies
!> against: no active massif element has the element's side as one of its own sides on that
!> face, and no active joint joins the element to a body on that face (a joint carries the
!> pore pressure of its soil onto the plate itself). Where both faces are covered the pore
!> pressure acts through the soil and joints; where both are free the two equal pressures
!> cancel. The activity is the run's (passed in) or the plan's for a step (phase_plan).
!> FREE is the mode of a plate set *PLATE_WATER does not name.
module pecplas_model_plate_water_sides
   use pecplas_base_kinds, only: wp
   use pecplas_model_type, only: model_t
   use pecplas_model_mesh_sides, only: side_table_t, build_side_table, find_sides, &
      element_centroid
   use pecplas_model_phase_plan, only: initial_activity, step_activity
   use pecplas_water_type, only: PLATE_FREE
   implicit none (type, external)
   private

   public :: plate_water_sides, planned_activity

contains

   !> Per element of plate set s, the face the water presses from in step istep (0: before
   !> the first step): +1 the left face (walking from the element's first node to its
   !> second), -1 the right, 0 none (no water, or under FREE both faces free or both
   !> covered). Under FREE the element and joint sets active are `eactive` and `jactive`
   !> when given (both), else those the phase plan gives for step istep.
   function plate_water_sides(model, s, istep, eactive, jactive) result(side)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s, istep
      logical, intent(in), optional :: eactive(:), jactive(:)
      integer, allocatable :: side(:)
      logical, allocatable :: eon(:), jon(:), covered(:, :)
      integer :: mode
      allocate (side(size(model%plates(s)%conn, 2)), source=0)
      mode = model%water%plate_side_at(s, istep)
      if (mode /= PLATE_FREE) then
         side = mode
         return
      end if
      if (present(eactive) .and. present(jactive)) then
         eon = eactive
         jon = jactive
      else
         call planned_activity(model, istep, eon, jon)
      end if
      covered = covered_faces(model, s, eon, jon)
      ! a free face takes the water: +1 from the left, -1 from the right, both cancel
      side = merge(1, 0, .not. covered(1, :)) - merge(1, 0, .not. covered(2, :))
   end function plate_water_sides

   !> The element and joint sets active in step istep (0: before the first step) by the phase
   !> plan: the initial activity, then the activations and deactivations of steps 1 .. istep
   !> (joint sets a deactivation leaves hanging go with it), as the run applies them.
   subroutine planned_activity(model, istep, eactive, jactive)
      type(model_t), intent(in) :: model
      integer, intent(in) :: istep
      logical, allocatable, intent(out) :: eactive(:), jactive(:)
      logical, allocatable :: dropped(:)
      integer :: i
      call initial_activity(model, eactive, jactive)
      if (.not. allocated(model%steps)) return
      do i = 1, min(istep, size(model%steps))
         call step_activity(model, i, eactive, jactive, dropped)
      end do
   end subroutine planned_activity

   !> covered(1, e) / covered(2, e): something active lies against the left / right face of
   !> element e of plate set s: an active massif element whose side is the element's side,
   !> a Goodman or thin-layer joint of an active set with the element's end nodes as one of
   !> its faces (the body lies towards its other face), or springs of an active set at both
   !> end nodes whose partner nodes belong to a massif element on that face.
   function covered_faces(model, s, eactive, jactive) result(covered)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      logical, intent(in) :: eactive(:), jactive(:)
      logical, allocatable :: covered(:, :)
      type(side_table_t) :: table
      integer, allocatable :: head(:), item(:), sides(:), owner(:, :)
      logical, allocatable :: spring_hit(:, :, :)
      real(wp) :: nl(2), dir(2)
      integer :: e, k, j, nel, nn, face, p, q, i, m, f
      associate (pl => model%plates(s), x => model%mesh%x)
         nel = size(pl%conn, 2)
         nn = model%mesh%nnode()
         allocate (covered(2, nel), source=.false.)
         ! massif elements sharing the element's side
         call build_side_table(model%mesh, table)
         do e = 1, nel
            nl = left_normal(model, s, e)
            sides = find_sides(table, pl%conn(:, e))
            do k = 1, size(sides)
               if (.not. eactive(table%set(sides(k)))) cycle
               dir = element_centroid(model%mesh, table%set(sides(k)), table%elem(sides(k))) - &
                  x(:, pl%conn(1, e))
               call mark(covered(:, e), dot_product(dir, nl))
            end do
         end do
         if (.not. allocated(model%joint_sets)) return
         ! the plate elements at each node (by their end nodes)
         allocate (head(nn + 1), source=0)
         do e = 1, nel
            head(pl%conn(1:2, e)) = head(pl%conn(1:2, e)) + 1
         end do
         do k = 2, nn + 1
            head(k) = head(k) + head(k - 1)
         end do
         allocate (item(max(head(nn + 1), 1)))
         do e = 1, nel
            do k = 1, 2
               item(head(pl%conn(k, e))) = e
               head(pl%conn(k, e)) = head(pl%conn(k, e)) - 1
            end do
         end do
         head = head + 1
         ! now the elements at node n are item(head(n) : head(n + 1) - 1)
         do j = 1, size(model%joint_sets)
            if (j > size(jactive)) exit
            if (.not. jactive(j)) cycle
            associate (js => model%joint_sets(j))
               if (js%is_spring()) cycle
               do i = 1, size(js%conn, 2)
                  do face = 1, 2
                     p = js%conn(2*face - 1, i)
                     q = js%conn(2*face, i)
                     do k = head(p), head(p + 1) - 1
                        e = item(k)
                        if (.not. any(pl%conn(1:2, e) == q) .or. p == q) cycle
                        ! the normal of face 1 (t from its first node to its second) points
                        ! into face 2: the body joined lies along it from face 1, against it
                        ! from face 2
                        dir = x(:, js%conn(2, i)) - x(:, js%conn(1, i))
                        dir = [-dir(2), dir(1)]
                        if (face == 2) dir = -dir
                        call mark(covered(:, e), dot_product(dir, left_normal(model, s, e)))
                     end do
                  end do
               end do
            end associate
         end do
         ! springs: a doublet at a plate node joins the body of its partner node
         allocate (spring_hit(2, 2, nel), source=.false.)
         do j = 1, size(model%joint_sets)
            if (j > size(jactive)) exit
            if (.not. jactive(j)) cycle
            associate (js => model%joint_sets(j))
               if (.not. js%is_spring()) cycle
               if (.not. allocated(owner)) owner = node_owners(model)
               do i = 1, size(js%conn, 2)
                  do face = 1, 2
                     p = js%conn(face, i)
                     m = js%conn(3 - face, i)
                     if (owner(1, m) == 0) cycle
                     do k = head(p), head(p + 1) - 1
                        e = item(k)
                        dir = element_centroid(model%mesh, owner(1, m), owner(2, m)) - x(:, p)
                        f = merge(1, 2, pl%conn(1, e) == p)
                        call mark(spring_hit(:, f, e), dot_product(dir, left_normal(model, s, e)))
                     end do
                  end do
               end do
            end associate
         end do
         covered = covered .or. (spring_hit(:, 1, :) .and. spring_hit(:, 2, :))
      end associate
   end function covered_faces

   !> hit(1) (left) when d > 0, hit(2) (right) when d < 0.
   pure subroutine mark(hit, d)
      logical, intent(inout) :: hit(2)
      real(wp), intent(in) :: d
      if (d > 0.0_wp) hit(1) = .true.
      if (d < 0.0_wp) hit(2) = .true.
   end subroutine mark

   !> The unit normal to the left of element e of plate set s (its chord from its first node
   !> to its second turned by +90 degrees).
   pure function left_normal(model, s, e) result(n)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s, e
      real(wp) :: n(2), t(2)
      associate (conn => model%plates(s)%conn)
         t = model%mesh%x(:, conn(2, e)) - model%mesh%x(:, conn(1, e))
      end associate
      t = t/norm2(t)
      n = [-t(2), t(1)]
   end function left_normal

   !> owner(:, n): the set and element of one massif element with node n (0, 0: none).
   pure function node_owners(model) result(owner)
      type(model_t), intent(in) :: model
      integer, allocatable :: owner(:, :)
      integer :: s, j, i, n
      allocate (owner(2, model%mesh%nnode()), source=0)
      do s = 1, size(model%mesh%esets)
         associate (conn => model%mesh%esets(s)%conn)
            do j = 1, size(conn, 2)
               do i = 1, size(conn, 1)
                  n = conn(i, j)
                  if (n > 0) owner(:, n) = [s, j]
               end do
            end do
         end associate
      end do
   end function node_owners

end module pecplas_model_plate_water_sides
