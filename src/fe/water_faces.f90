!> The water pressure on the faces of the model (doc/theory.md, Groundwater): every side of
!> an active massif element that no other active element shares (a free face: the ground
!> surface, an excavation face, the model's boundary) and that is no face of a joint carries
!> the hydrostatic pressure p = gamma_w (h - y)+ of the level in force, pushing into the body.
!> With it the total stresses are in equilibrium with the water standing on the faces (a
!> flooded pit, a level above the ground), and on supported faces the pressure goes into the
!> reactions, which are then those of the effective stresses and the buoyant weight.
!> Joint faces are left out: a joint carries the pore pressure itself (pecplas_fe_pore); so
!> are the sides an element of an active plate set lies on: a plate is impermeable and takes
!> the free water on its own faces, as its *PLATE_WATER mode says (add_plate_water).
module pecplas_fe_water_faces
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_mesh_sides, only: side_table_t, build_side_table, find_sides
   use pecplas_massif_edge_load, only: edge_linear_pressure_forces, &
      edge_part_pressure_forces
   use pecplas_model_options, only: AXISYMMETRIC
   use pecplas_structures_beam, only: beam_line_load, beam_part_load, MAX_BEAM_DOFS, &
      beam_curved_pressure, beam_on_chord
   use pecplas_fe_plate_assembly, only: plate_element_x, scatter_plate_vector
   use pecplas_model_plate_water_sides, only: plate_water_sides
   use pecplas_water_wet_parts, only: wet_parts, line_lowest
   use pecplas_water_phreatic, only: phreatic_t
   implicit none (type, external)
   private

   public :: add_water_faces, add_plate_water, plate_water_load

contains

   !> force(2, nnode) += the water's pressure on the free faces of the active element sets
   !> `eactive` under level k (0: none), joint sets `jactive` active. With `pactive`: a side
   !> of an element of an active plate set is no free face, whatever the set's *PLATE_WATER
   !> mode: the impermeable plate lies against it and takes the water on its own faces
   !> (add_plate_water), so the water is counted once whether the plate shares its nodes
   !> with the soil or joints lie between.
   subroutine add_water_faces(model, eactive, jactive, k, force, error, pactive)
      type(model_t), intent(in) :: model
      logical, intent(in) :: eactive(:), jactive(:)
      integer, intent(in) :: k
      real(wp), intent(inout) :: force(:, :)
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: pactive(:)
      type(side_table_t) :: table
      logical, allocatable :: on_joint(:), on_plate(:)
      integer, allocatable :: same(:)
      real(wp) :: xedge(2, 3), fe(6), h, xm
      integer :: side, j, nen, n
      if (k <= 0) return
      call build_side_table(model%mesh, table)
      allocate (on_plate(model%mesh%nnode()), source=.false.)
      if (present(pactive)) on_plate = active_plate_nodes(model, pactive)
      allocate (on_joint(model%mesh%nnode()), source=.false.)
      if (allocated(model%joint_sets)) then
         do j = 1, size(model%joint_sets)
            if (j > size(jactive)) exit
            if (jactive(j)) on_joint(pack(model%joint_sets(j)%conn, &
               model%joint_sets(j)%conn > 0)) = .true.
         end do
      end if
      do side = 1, size(table%set)
         if (.not. eactive(table%set(side))) cycle
         associate (nodes => table%nodes(:, side))
            if (on_joint(nodes(1)) .and. on_joint(nodes(2))) cycle
            if (on_plate(nodes(1)) .and. on_plate(nodes(2))) then
               if (on_active_plate(model, pactive, nodes(1:2))) cycle
            end if
            same = find_sides(table, nodes)
            n = 0
            do j = 1, size(same)
               if (eactive(table%set(same(j)))) n = n + 1
            end do
            if (n /= 1) cycle
            nen = merge(3, 2, nodes(3) > 0)
            xedge(:, 1:nen) = model%mesh%x(:, nodes(1:nen))
            if (size(model%water%levels(k)%y) > 1 .and. &
                any(xedge(1, 2:nen) /= xedge(1, 1))) then
               ! a polyline level along a side not vertical: h(x) varies along it, with kinks
               ! at the level's vertices; p cut there and at the level, each part exact
               call sloping_face(model, model%water%levels(k), xedge(:, 1:nen), fe(1:2*nen), &
                  error)
               if (allocated(error)) return
            else
               xm = 0.5_wp*(xedge(1, 1) + xedge(1, 2))
               h = model%water%levels(k)%head(xm)
               ! the side's lowest point: a curved side can dip below all its nodes
               if (.not. line_lowest(xedge(:, 1:nen)) < h) cycle
               ! p = gamma_w (h - y), floored at 0 above the level (h is one along the side),
               ! cut at the level and each part exact (edge_linear_pressure_forces)
               call edge_linear_pressure_forces(model%analysis%kind, &
                  model%analysis%thickness, xedge(:, 1:nen), 0.0_wp, &
                  model%water%levels(k)%gamma_w, h, fe(1:2*nen), error, 0.0_wp)
               if (allocated(error)) return
            end if
            force(:, nodes(1:nen)) = force(:, nodes(1:nen)) + reshape(fe(1:2*nen), [2, nen])
         end associate
      end do
   end subroutine add_water_faces

   !> fe(2 nen) of the water p = gamma_w (h(x) - y)+ of a polyline level on the side with
   !> nodes xedge (ends, then the mid node): the side is cut where it crosses the x of a
   !> vertex of the level and where p falls to 0 (pecplas_water_wet_parts), and each wet part
   !> integrated exactly (p is a polynomial of degree nen - 1 along it).
   subroutine sloping_face(model, level, xedge, fe, error)
      type(model_t), intent(in) :: model
      type(phreatic_t), intent(in) :: level
      real(wp), intent(in) :: xedge(:, :)
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: from(:), to(:), p(:, :)
      real(wp) :: part(6)
      logical :: split
      integer :: j
      fe = 0.0_wp
      call wet_parts(level, xedge, from, to, p, split)
      do j = 1, size(from)
         ! the parameter of the parts in [0, 1], the edge's in [-1, 1]
         call edge_part_pressure_forces(model%analysis%kind, model%analysis%thickness, &
            xedge, 2.0_wp*from(j) - 1.0_wp, 2.0_wp*to(j) - 1.0_wp, p(:, j), &
            part(1:size(fe)), error)
         if (allocated(error)) return
         fe = fe + part(1:size(fe))
      end do
   end subroutine sloping_face

   !> Nodes of the elements of the active plate sets (`pactive`).
   pure function active_plate_nodes(model, pactive) result(on)
      type(model_t), intent(in) :: model
      logical, intent(in) :: pactive(:)
      logical, allocatable :: on(:)
      integer :: s
      allocate (on(model%mesh%nnode()), source=.false.)
      if (.not. allocated(model%plates)) return
      do s = 1, min(size(model%plates), size(pactive))
         if (.not. pactive(s)) cycle
         on(pack(model%plates(s)%conn(1:2, :), .true.)) = .true.
      end do
   end function active_plate_nodes

   !> Whether the end nodes `ends` are those of an element of an active plate set
   !> (`pactive`).
   pure logical function on_active_plate(model, pactive, ends) result(on)
      type(model_t), intent(in) :: model
      logical, intent(in) :: pactive(:)
      integer, intent(in) :: ends(2)
      integer :: s, e
      on = .false.
      do s = 1, min(size(model%plates), size(pactive))
         if (.not. pactive(s)) cycle
         associate (conn => model%plates(s)%conn)
            do e = 1, size(conn, 2)
               if ((conn(1, e) == ends(1) .and. conn(2, e) == ends(2)) .or. &
                   (conn(1, e) == ends(2) .and. conn(2, e) == ends(1))) then
                  on = .true.
                  return
               end if
            end do
         end associate
      end do
   end function on_active_plate

   !> force(:, :) += the water's pressure on the plate sets active in `pactive` under level
   !> k (0: none), by their *PLATE_WATER mode in step istep (FREE where *PLATE_WATER does
   !> not name them) and, for the sets whose water stands on their free faces, the element
   !> sets `eactive` and joint sets `jactive` active: see plate_water_load.
   subroutine add_plate_water(model, pactive, eactive, jactive, k, istep, force)
      type(model_t), intent(in) :: model
      logical, intent(in) :: pactive(:), eactive(:), jactive(:)
      integer, intent(in) :: k, istep
      real(wp), intent(inout) :: force(:, :)
      real(wp) :: fe(MAX_BEAM_DOFS)
      integer, allocatable :: side(:)
      integer :: s, e, nd
      logical :: any_load
      if (k <= 0 .or. .not. allocated(model%water%plate_side)) return
      do s = 1, size(model%water%plate_side)
         if (model%water%plate_side_at(s, istep) == 0) cycle
         if (s > size(pactive)) cycle
         if (.not. pactive(s)) cycle
         side = plate_water_sides(model, s, istep, eactive, jactive)
         nd = 3*size(model%plates(s)%conn, 1)
         do e = 1, size(model%plates(s)%conn, 2)
            call plate_water_load(model, s, e, k, side(e), fe(1:nd), any_load)
            if (any_load) call scatter_plate_vector(model, model%plates(s), e, fe(1:nd), force)
         end do
      end do
   end subroutine add_plate_water

   !> Consistent nodal vector fe(3 nen) of the water's pressure on element e of plate set s
   !> under level k, pressing from the face `side` (+1 left, -1 right, 0 none: the element's
   !> entry of plate_water_sides): p = gamma_w (h - y)+ normal to the element's own geometry,
   !> integrated along it. On an element that is its chord (2 nodes, or a mid node at the
   !> middle: beam_on_chord), where p is one polynomial along the element (wholly below or
   !> above the level, the level at a node) it is interpolated from the nodal pressures like
   !> the geometry, which is exact; where the level crosses the element (or a polyline level
   !> has a kink on it) the element is cut there (pecplas_water_wet_parts) and each wet part
   !> integrated exactly (beam_part_load). A curved 3-node element (its mid node off the
   !> middle of the chord) is a parabola: it is cut where the level crosses the parabola
   !> (the root of p in its parameter), and each wet part takes p normal to the curve,
   !> integrated exactly along it (beam_curved_pressure). A plate is impermeable: the water
   !> or the soil's pore pressure on its other face is not this load. `loaded`: false
   !> (fe = 0) when p = 0 along the element or side = 0.
   subroutine plate_water_load(model, s, e, k, side, fe, loaded)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s, e, k, side
      real(wp), intent(out) :: fe(:)
      logical, intent(out) :: loaded
      real(wp) :: t(2), q(2), p(3), x(2, 3), part(MAX_BEAM_DOFS)
      real(wp), allocatable :: from(:), to(:), pp(:, :)
      logical :: split
      integer :: j, nen
      fe = 0.0_wp
      loaded = .false.
      if (k <= 0 .or. side == 0) return
      associate (pl => model%plates(s), level => model%water%levels(k))
         nen = size(pl%conn, 1)
         x(:, 1:nen) = plate_element_x(model, pl, e)
         ! the chord's direction; water on the left (+1) presses towards the right
         t = x(:, 2) - x(:, 1)
         t = t/norm2(t)
         q = real(side, wp)*[t(2), -t(1)]
         call wet_parts(level, x(:, 1:nen), from, to, pp, split)
         if (.not. beam_on_chord(x(:, 1:nen))) then
            loaded = size(from) > 0
            do j = 1, size(from)
               call beam_curved_pressure(x(:, 1:nen), model%analysis%kind == AXISYMMETRIC, &
                  model%analysis%thickness, side, from(j), to(j), pp(:, j), part(1:size(fe)))
               fe = fe + part(1:size(fe))
            end do
            return
         end if
         if (split) then
            loaded = size(from) > 0
            do j = 1, size(from)
               call beam_part_load(x(:, 1:nen), pl%section, &
                  model%analysis%kind == AXISYMMETRIC, &
                  model%analysis%thickness, q, from(j), to(j), pp(:, j), part(1:size(fe)))
               fe = fe + part(1:size(fe))
            end do
            return
         end if
         do j = 1, nen
            p(j) = level%pressure(x(:, j))
         end do
         if (all(p(1:nen) == 0.0_wp)) return
         loaded = .true.
         call beam_line_load(x(:, 1:nen), pl%section, model%analysis%kind == AXISYMMETRIC, &
            model%analysis%thickness, q, fe, p(1:nen))
      end associate
   end subroutine plate_water_load

end module pecplas_fe_water_faces
