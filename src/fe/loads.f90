!> Nodal vectors of the load patterns at factor 1: consistent forces (point forces,
!> edge pressures, body forces, gravity) and imposed displacements.
module pecplas_fe_loads
   use pecplas_base_kinds, only: wp
   use pecplas_model_loads, only: LOAD_FORCE, LOAD_PRESSURE, LOAD_BODY_FORCE, LOAD_GRAVITY, LOAD_DISPLACEMENT
   use pecplas_model_columns, only: nodal_columns, rotation_column
   use pecplas_fe_plate_assembly, only: add_plate_load
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_loads, only: load_pattern_t
   use pecplas_fe_element_context, only: element_context, edge_context
   use pecplas_massif_kinematics, only: massif_rule_t, massif_point_t, massif_gauss_point
   use pecplas_massif_element_matrices, only: massif_body_force
   use pecplas_massif_edge_load, only: edge_pressure_forces, edge_linear_pressure_forces
   implicit none (type, external)
   private

   public :: pattern_vectors, add_body_force

contains

   !> force(2, ncolumns, npattern) and displacement(2, ncolumns, npattern) of every pattern
   !> (the columns of the plate rotations after the nodes: pecplas_model_columns).
   !> `active` (phases): the body forces and gravity of the active element sets only.
   !> `level`: the phreatic level in force (model%water%levels; 0 none; default: that of
   !> the first step), which gives the unit weights below it (gamma_sat).
   subroutine pattern_vectors(model, rules, force, displacement, error, active, plate_active, &
      level)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      real(wp), allocatable, intent(out) :: force(:, :, :), displacement(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: active(:)
      !> Phases: the loads of the active plate sets only.
      logical, intent(in), optional :: plate_active(:)
      integer, intent(in), optional :: level
      integer :: p, k, nnode, npat, nen, c, d
      real(wp) :: fe(6)

      nnode = nodal_columns(model)
      npat = 0
      if (allocated(model%patterns)) npat = size(model%patterns)
      allocate (force(2, nnode, npat), displacement(2, nnode, npat), source=0.0_wp)
      do p = 1, npat
         associate (pat => model%patterns(p))
            select case (pat%kind)
            case (LOAD_FORCE)
               do k = 1, size(pat%node)
                  call column_of(pat%node(k), pat%dof(k), c, d)
                  if (c > 0) force(d, c, p) = force(d, c, p) + pat%value(k)
               end do
            case (LOAD_DISPLACEMENT)
               do k = 1, size(pat%node)
                  call column_of(pat%node(k), pat%dof(k), c, d)
                  if (c > 0) displacement(d, c, p) = pat%value(k)
               end do
            case (LOAD_PRESSURE)
               do k = 1, size(pat%pressure)
                  nen = merge(3, 2, pat%edge(3, k) > 0)
                  call pressure_forces(model, pat, k, model%mesh%x(:, pat%edge(1:nen, k)), &
                     fe(1:2*nen), error)
                  if (allocated(error)) then
                     call edge_context(error, model, pat%name, pat%edge(1:nen, k))
                     return
                  end if
                  force(:, pat%edge(1:nen, k), p) = force(:, pat%edge(1:nen, k), p) + &
                     reshape(fe(1:2*nen), [2, nen])
               end do
            case (LOAD_BODY_FORCE, LOAD_GRAVITY)
               do k = 1, size(pat%eset)
                  if (present(active)) then
                     if (.not. active(pat%eset(k))) cycle
                  end if
                  call add_body_force(model, rules, pat%eset(k), pat%vector(:, k), &
                     pat%kind == LOAD_GRAVITY, force(:, :, p), error, level)
                  if (allocated(error)) return
               end do
            end select
            ! plate line loads (PLATE_LOAD) and plate weights (GRAVITY naming a plate set)
            if (allocated(pat%plate)) then
               do k = 1, size(pat%plate)
                  if (present(plate_active)) then
                     if (.not. plate_active(pat%plate(k))) cycle
                  end if
                  call add_plate_load(model, pat%plate(k), pat%plate_vector(:, k), &
                     pat%kind == LOAD_GRAVITY, force(:, :, p))
               end do
            end if
         end associate
      end do
   contains
      !> Column and row of dof `dof` of `node` in the nodal arrays (c = 0: a rotation the
      !> node does not carry, e.g. the duplicate of a split plate node).
      pure subroutine column_of(node, dof, c, d)
         integer, intent(in) :: node, dof
         integer, intent(out) :: c, d
         if (dof <= 2) then
            c = node
            d = dof
         else
            c = rotation_column(model, node)
            d = 1
         end if
      end subroutine column_of
   end subroutine pattern_vectors

   !> Consistent nodal forces of the pressure of edge k of pattern `pat`: uniform, or linear in
   !> y (pecplas_massif_edge_load), floored at pat%p_min when the pattern says so.
   subroutine pressure_forces(model, pat, k, xedge, fe, error)
      type(model_t), intent(in) :: model
      type(load_pattern_t), intent(in) :: pat
      integer, intent(in) :: k
      real(wp), intent(in) :: xedge(:, :)
      real(wp), intent(out) :: fe(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: gradient
      gradient = 0.0_wp
      if (allocated(pat%pressure_gradient)) gradient = pat%pressure_gradient(k)
      if (gradient == 0.0_wp) then
         ! uniform: the historical rule, bit for bit
         if (pat%floored) then
            call edge_pressure_forces(model%analysis%kind, model%analysis%thickness, xedge, &
               max(pat%p_min, pat%pressure(k)), fe, error)
         else
            call edge_pressure_forces(model%analysis%kind, model%analysis%thickness, xedge, &
               pat%pressure(k), fe, error)
         end if
      else if (pat%floored) then
         call edge_linear_pressure_forces(model%analysis%kind, model%analysis%thickness, &
            xedge, pat%pressure(k), gradient, pat%pressure_y_ref(k), fe, error, pat%p_min)
      else
         call edge_linear_pressure_forces(model%analysis%kind, model%analysis%thickness, &
            xedge, pat%pressure(k), gradient, pat%pressure_y_ref(k), fe, error)
      end if
   end subroutine pressure_forces

   !> Consistent nodal forces of a body force per unit volume `vec` (or, for gravity, of
   !> the material unit weight times the direction `vec`) over element set `s`. With
   !> groundwater the unit weight is gamma_sat below the phreatic level `level` (default:
   !> the level of the first step) in a wet set: point by point (pecplas_water_type).
   subroutine add_body_force(model, rules, s, vec, gravity, force, error, level)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      integer, intent(in) :: s
      real(wp), intent(in) :: vec(2)
      logical, intent(in) :: gravity
      real(wp), intent(inout) :: force(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: level
      real(wp), allocatable :: xe(:, :), fe(:)
      real(wp) :: bf(2)
      integer :: e, j, nn, k

      if (gravity .and. model%water%used()) then
         k = model%water%level_at(1)
         if (present(level)) k = level
         if (k > 0) then
            call add_wet_weight(model, rules, s, vec, k, force, error)
            return
         end if
      end if
      associate (set => model%mesh%esets(s))
         bf = vec
         if (gravity) bf = vec*model%materials(set%material_index)%m%unit_weight
         nn = rules(s)%nnode
         allocate (xe(2, nn), fe(2*nn))
         do e = 1, size(set%conn, 2)
            xe = model%mesh%x(:, set%conn(:, e))
            call massif_body_force(rules(s), model%analysis%kind, model%analysis%thickness, &
               xe, bf, fe, error)
            if (allocated(error)) then
               call element_context(error, model, s, e)
               return
            end if
            do j = 1, nn
               force(:, set%conn(j, e)) = force(:, set%conn(j, e)) + fe(2*j - 1:2*j)
            end do
         end do
      end associate
   end subroutine add_body_force

   !> Gravity over element set s with the unit weight of each integration point under
   !> phreatic level k (gamma_sat below it in a wet set, the material's gamma elsewhere).
   subroutine add_wet_weight(model, rules, s, vec, k, force, error)
      type(model_t), intent(in) :: model
      type(massif_rule_t), intent(in) :: rules(:)
      integer, intent(in) :: s, k
      real(wp), intent(in) :: vec(2)
      real(wp), intent(inout) :: force(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(massif_point_t) :: pt
      real(wp), allocatable :: xe(:, :)
      real(wp) :: w
      integer :: e, j, g, m
      associate (set => model%mesh%esets(s), rule => rules(s))
         m = set%material_index
         allocate (xe(2, rule%nnode))
         do e = 1, size(set%conn, 2)
            xe = model%mesh%x(:, set%conn(:, e))
            do g = 1, rule%ngauss
               call massif_gauss_point(rule, g, model%analysis%kind, &
                  model%analysis%thickness, xe, pt, error)
               if (allocated(error)) then
                  call element_context(error, model, s, e)
                  return
               end if
               w = model%water%unit_weight(k, s, m, model%materials(m)%m%unit_weight, pt%x)
               do j = 1, rule%nnode
                  force(:, set%conn(j, e)) = force(:, set%conn(j, e)) + &
                     pt%n(j)*vec*w*pt%dvol
               end do
            end do
         end do
      end associate
   end subroutine add_wet_weight

end module pecplas_fe_loads
