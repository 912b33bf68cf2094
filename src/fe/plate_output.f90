!> The section forces of a plate set for the results: N (tension positive), Q and M at both
!> ends of every element, from the element's nodal forces less its own load (the forces the
!> rest of the structure exerts on the element: exact for the linked 2-node element), in the
!> element's frame at that end (t from its first node to its second, n = (-t_y, t_x)); at the
!> plate's nodes, the mean of the element ends there (a mid-side node: the mean of its
!> element's points). Per unit width (plane strain: divided by the analysis thickness) or per
!> unit length of circumference (axisymmetry: divided by 2 pi r). Sign of M: M = D kappa with
!> kappa = d theta / ds, positive when the plate bends towards n; Q = GAs gamma with
!> gamma = dw/ds - theta (w along n), so that dM/ds = -Q without load.
module pecplas_fe_plate_output
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_columns, only: rotation_column
   use pecplas_model_loads, only: LOAD_GRAVITY
   use pecplas_structures_beam, only: NGEN, MAX_BEAM_DOFS, beam_point_t, beam_npoint, &
      beam_line_load
   use pecplas_structures_state, only: plate_state_t
   use pecplas_fe_water_faces, only: plate_water_load
   use pecplas_fe_plate_assembly, only: plate_points, plate_element_x
   use pecplas_model_plate_water_sides, only: plate_water_sides
   use pecplas_io_results_increment, only: plate_fields_t
   implicit none (type, external)
   private

   public :: plate_results, plate_nodes

   real(wp), parameter :: PI = acos(-1.0_wp)

contains

   !> The distinct nodes of plate set s in the order of its elements.
   pure function plate_nodes(model, s) result(nodes)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      integer, allocatable :: nodes(:)
      integer :: e, k
      allocate (nodes(0))
      associate (conn => model%plates(s)%conn)
         do e = 1, size(conn, 2)
            do k = 1, size(conn, 1)
               if (.not. any(nodes == conn(k, e))) nodes = [nodes, conn(k, e)]
            end do
         end do
      end associate
   end function plate_nodes

   !> Fields of plate set s at the converged state (u, pstate, pattern factors); `level`:
   !> the phreatic level in force (groundwater: the water's pressure on the plate's faces
   !> by its *PLATE_WATER mode is one of its own loads; default none); `step`: the step whose
   !> *PLATE_WATER sides are in force (default the last); `sides`: the face the water stands
   !> on, element by element (+1 left, -1 right, 0 none), instead of those of `step`.
   subroutine plate_results(model, u, pstate, factors, s, f, error, level, step, sides)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: u(:, :), factors(:)
      type(plate_state_t), intent(in) :: pstate
      integer, intent(in) :: s
      type(plate_fields_t), intent(out) :: f
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: level, step
      integer, intent(in), optional :: sides(:)
      type(beam_point_t) :: pts(3)
      logical :: wet
      real(wp) :: fe(MAX_BEAM_DOFS), fl(MAX_BEAM_DOFS), x(2, 3), t(2), n(2), scale, q(2)
      real(wp) :: dxd(2)
      integer, allocatable :: count(:), at(:), wside(:)
      integer :: e, p, k, nd, np, nel, end, j
      associate (pl => model%plates(s), st => pstate%sets(s))
         nd = 3*pl%nen
         np = beam_npoint(pl%nen)
         nel = size(pl%conn, 2)
         f%node_index = plate_nodes(model, s)
         allocate (at(model%mesh%nnode()), source=0)
         at(f%node_index) = [(k, k=1, size(f%node_index))]
         allocate (f%end_forces(3, 2, nel), f%node_forces(3, size(f%node_index)), source=0.0_wp)
         allocate (count(size(f%node_index)), source=0)
         f%displacement = u(:, f%node_index)
         allocate (f%rotation(size(f%node_index)))
         do k = 1, size(f%node_index)
            f%rotation(k) = u(1, rotation_column(model, f%node_index(k)))
         end do
         f%resultants = st%s
         f%plastic = st%hist
         f%name = pl%name
         f%active = st%active
         if (.not. st%active) return
         if (present(level)) then
            ! the faces the water stands on in that step (the phase plan's activity)
            if (present(sides)) then
               wside = sides
            else if (present(step)) then
               wside = plate_water_sides(model, s, step)
            else
               wside = plate_water_sides(model, s, size(model%steps))
            end if
         end if
         do e = 1, nel
            x(:, 1:pl%nen) = plate_element_x(model, pl, e)
            call plate_points(model, pl, e, pts(1:np), error)
            if (allocated(error)) return
            fe(1:nd) = 0.0_wp
            do p = 1, np
               fe(1:nd) = fe(1:nd) + pts(p)%weight*matmul(st%s(:, p, e), pts(p)%b(:, 1:nd))
            end do
            ! less the element's own load (line loads, weight) at the current factors
            if (allocated(model%patterns)) then
               do p = 1, size(model%patterns)
                  if (.not. allocated(model%patterns(p)%plate)) cycle
                  do j = 1, size(model%patterns(p)%plate)
                     if (model%patterns(p)%plate(j) /= s .or. factors(p) == 0.0_wp) cycle
                     q = model%patterns(p)%plate_vector(:, j)
                     if (model%patterns(p)%kind == LOAD_GRAVITY) q = pl%section%w*q
                     call beam_line_load(x(:, 1:pl%nen), pl%section, model%analysis%kind == 2, &
                        model%analysis%thickness, q, fl(1:nd))
                     fe(1:nd) = fe(1:nd) - factors(p)*fl(1:nd)
                  end do
               end do
            end if
            if (present(level)) then
               call plate_water_load(model, s, e, level, wside(e), fl(1:nd), wet)
               if (wet) fe(1:nd) = fe(1:nd) - fl(1:nd)
            end if
            do end = 1, 2
               if (pl%nen == 2) then
                  t = (x(:, 2) - x(:, 1))/norm2(x(:, 2) - x(:, 1))
               else
                  ! tangent of the quadratic side at xi = -1 / +1
                  dxd = merge(-1.5_wp, 0.5_wp, end == 1)*x(:, 1) + &
                     merge(-0.5_wp, 1.5_wp, end == 1)*x(:, 2) + &
                     merge(2.0_wp, -2.0_wp, end == 1)*x(:, 3)
                  t = dxd/norm2(dxd)
               end if
               n = [-t(2), t(1)]
               if (model%analysis%kind == 2) then
                  scale = 1.0_wp/(2.0_wp*PI*x(1, end))
               else
                  scale = 1.0_wp/model%analysis%thickness
               end if
               if (end == 1) scale = -scale
               j = 3*(end - 1)
               f%end_forces(:, end, e) = scale*[dot_product(t, fe(j + 1:j + 2)), &
                  dot_product(n, fe(j + 1:j + 2)), fe(j + 3)]
               k = at(pl%conn(end, e))
               f%node_forces(:, k) = f%node_forces(:, k) + f%end_forces(:, end, e)
               count(k) = count(k) + 1
            end do
            if (pl%nen == 3) then
               k = at(pl%conn(3, e))
               f%node_forces(:, k) = f%node_forces(:, k) + &
                  0.5_wp*(st%s(1:3, 1, e) + st%s(1:3, 2, e))
               count(k) = count(k) + 1
            end if
         end do
         do k = 1, size(count)
            if (count(k) > 0) f%node_forces(:, k) = f%node_forces(:, k)/count(k)
         end do
      end associate
   end subroutine plate_results

end module pecplas_fe_plate_output
