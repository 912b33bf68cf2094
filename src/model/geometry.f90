!> Geometry checks after the element checks of pecplas_model_mesh_tools (which turn clockwise
!> elements and refuse zero-area and concave ones): distorted elements (corner Jacobian
!> ratio, midside nodes away from the middle of their side) are warnings; joints on the same
!> node pairs as another joint are warnings (their stiffnesses add up), joints whose faces
!> fold over one another are errors. Every message names the element's deck line.
module pecplas_model_geometry
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, input_error
   use pecplas_model_type, only: model_t
   use pecplas_model_provenance, only: place_t
   implicit none (type, external)
   private

   public :: check_geometry, corner_jacobian_ratio, JACOBIAN_RATIO_MIN

   !> Smallest accepted ratio min/max of detJ over the corners of a quadrilateral without a
   !> warning (1/40: a corner angle near 180 degrees or a very thin wedge).
   real(wp), parameter :: JACOBIAN_RATIO_MIN = 1.0_wp/40.0_wp

contains

   subroutine check_geometry(model, error)
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      call check_distortion(model)
      call check_joints(model, error)
   end subroutine check_geometry

   !> min/max over the corners of the corner Jacobian cross(x(i+1) - x(i), x(i-1) - x(i))
   !> of a counter-clockwise polygon (1 for a parallelogram; <= 0 when not convex).
   pure real(wp) function corner_jacobian_ratio(xc) result(ratio)
      real(wp), intent(in) :: xc(:, :)
      real(wp) :: d, dmin, dmax, a(2), b(2)
      integer :: i, nc
      nc = size(xc, 2)
      dmin = huge(1.0_wp); dmax = -huge(1.0_wp)
      do i = 1, nc
         a = xc(:, modulo(i, nc) + 1) - xc(:, i)
         b = xc(:, modulo(i - 2, nc) + 1) - xc(:, i)
         d = a(1)*b(2) - a(2)*b(1)
         dmin = min(dmin, d); dmax = max(dmax, d)
      end do
      ratio = 0.0_wp
      if (dmax > 0.0_wp) ratio = dmin/dmax
   end function corner_jacobian_ratio

   subroutine check_distortion(model)
      type(model_t), intent(inout) :: model
      integer :: s, e, nc, i, k
      real(wp) :: xc(2, 4), ratio, mid(2), side
      character(len=32) :: buf
      do s = 1, size(model%mesh%esets)
         associate (es => model%mesh%esets(s))
            nc = 3
            if (es%etype == 'Q4' .or. es%etype == 'Q8') nc = 4
            do e = 1, size(es%conn, 2)
               xc(:, 1:nc) = model%mesh%x(:, es%conn(1:nc, e))
               if (nc == 4) then
                  ratio = corner_jacobian_ratio(xc(:, 1:4))
                  if (ratio < JACOBIAN_RATIO_MIN) then
                     write (buf, '(f8.4)') ratio
                     call warn(model, s, e, 'element '//id_text(es%ids, e)//" of set '"// &
                        es%name//"' is distorted: corner Jacobian ratio "// &
                        trim(adjustl(buf))//' (min/max of detJ at its corners; below 1/40 '// &
                        'the stresses of this element are unreliable)')
                  end if
               end if
               if (size(es%conn, 1) /= 2*nc) cycle
               ! a midside node beyond a quarter of its side from the middle makes detJ
               ! vanish inside the element (the quarter-point position)
               do i = 1, nc
                  k = modulo(i, nc) + 1
                  mid = 0.5_wp*(xc(:, i) + xc(:, k))
                  side = norm2(xc(:, k) - xc(:, i))
                  if (norm2(model%mesh%x(:, es%conn(nc + i, e)) - mid) > 0.25_wp*side) then
                     call warn(model, s, e, 'element '//id_text(es%ids, e)//" of set '"// &
                        es%name//"' is distorted: midside node "// &
                        id_text(model%mesh%node_id, es%conn(nc + i, e))//' is more than a '// &
                        'quarter of its side from the middle (detJ vanishes inside)')
                     exit
                  end if
               end do
            end do
         end associate
      end do
   end subroutine check_distortion

   !> Joints are compared through their face-1 node pair (a, b) (springs: their doublet). Same pair twice, and
   !> the same face-2 nodes (the two faces of a line share face 1): a warning; two joints sharing a face-1
   !> node whose faces run the same way from it: an error (the faces overlap).
   subroutine check_joints(model, error)
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: head(:), next(:), js(:), je(:), a(:), b(:), f2(:, :)
      logical, allocatable :: spring(:)
      integer :: s, e, n, k, q, m, shared
      real(wp) :: u(2), v(2)
      type(place_t) :: p
      character(len=:), allocatable :: keyword, msg
      if (.not. allocated(model%joint_sets)) return
      n = 0
      do s = 1, size(model%joint_sets)
         n = n + size(model%joint_sets(s)%conn, 2)
      end do
      if (n == 0) return
      allocate (js(n), je(n), a(n), b(n), spring(n), next(2*n), head(model%mesh%nnode()), &
         f2(2, n))
      head = 0
      next = 0
      k = 0
      do s = 1, size(model%joint_sets)
         associate (set => model%joint_sets(s))
            do e = 1, size(set%conn, 2)
               k = k + 1
               js(k) = s; je(k) = e
               a(k) = set%conn(1, e)
               b(k) = set%conn(2, e)
               spring(k) = set%is_spring()
               ! face 2 (both faces of a line share face 1: FACES=BOTH)
               f2(:, k) = 0
               if (.not. spring(k)) f2(:, k) = [minval(set%conn(3:4, e)), maxval(set%conn(3:4, e))]
               do m = 1, 2
                  q = merge(a(k), b(k), m == 1)
                  call compare(q)
                  if (allocated(error)) return
               end do
               ! bucket entries 2k - 1 (node a) and 2k (node b) of joint k
               next(2*k - 1) = head(a(k))
               head(a(k)) = 2*k - 1
               next(2*k) = head(b(k))
               head(b(k)) = 2*k
            end do
         end associate
      end do
   contains
      !> Compares joint k with the joints already bucketed on node q.
      subroutine compare(q)
         integer, intent(in) :: q
         integer :: o, entry
         entry = head(q)
         do while (entry > 0)
            o = (entry + 1)/2
            if (same_pair(a(o), b(o), a(k), b(k)) .and. all(f2(:, o) == f2(:, k))) then
               msg = 'joint '//joint_text(k)//' is on the same nodes as joint '// &
                  joint_text(o)//location(o)//': their stiffnesses add up (a joint '// &
                  'written twice?)'
               call model%provenance%joint(js(k), je(k), p, keyword)
               call model%warnings%add(msg, file_of(p), p%line)
            else if (.not. (spring(k) .or. spring(o))) then
               ! both faces leave node q: overlap when they run the same way
               shared = q
               u = model%mesh%x(:, other(a(k), b(k), shared)) - model%mesh%x(:, shared)
               v = model%mesh%x(:, other(a(o), b(o), shared)) - model%mesh%x(:, shared)
               if (abs(u(1)*v(2) - u(2)*v(1)) <= 1.0e-9_wp*norm2(u)*norm2(v) .and. &
                   dot_product(u, v) > 0.0_wp .and. other(a(k), b(k), shared) /= &
                   other(a(o), b(o), shared)) then
                  call input_error(error, 'joint '//joint_text(k)//' overlaps joint '// &
                     joint_text(o)//location(o)//': their faces run along the same line '// &
                     'from node '//id_text(model%mesh%node_id, shared)// &
                     ' (an interface element covers a piece of boundary once)')
                  call model%provenance%joint(js(k), je(k), p, keyword)
                  call model%provenance%locate(error, p, keyword)
                  return
               end if
            end if
            entry = next(entry)
         end do
      end subroutine compare

      function joint_text(i) result(t)
         integer, intent(in) :: i
         character(len=:), allocatable :: t
         t = id_text(model%joint_sets(js(i))%ids, je(i))//" of set '"// &
            model%joint_sets(js(i))%name//"'"
      end function joint_text

      function location(i) result(t)
         integer, intent(in) :: i
         character(len=:), allocatable :: t
         type(place_t) :: pl
         character(len=:), allocatable :: kw
         call model%provenance%joint(js(i), je(i), pl, kw)
         t = model%provenance%text(pl)
         if (len(t) > 0) t = ' ('//t//')'
      end function location

      function file_of(pl) result(t)
         type(place_t), intent(in) :: pl
         character(len=:), allocatable :: t
         t = ''
         if (pl%file > 0) t = model%provenance%files(pl%file)%path
      end function file_of
   end subroutine check_joints

   pure logical function same_pair(a1, b1, a2, b2)
      integer, intent(in) :: a1, b1, a2, b2
      same_pair = (a1 == a2 .and. b1 == b2) .or. (a1 == b2 .and. b1 == a2)
   end function same_pair

   pure integer function other(a, b, q)
      integer, intent(in) :: a, b, q
      other = merge(b, a, a == q)
   end function other

   !> ids(i) as text (i itself when ids is not allocated).
   pure function id_text(ids, i) result(t)
      integer, allocatable, intent(in) :: ids(:)
      integer, intent(in) :: i
      character(len=:), allocatable :: t
      character(len=16) :: buf
      write (buf, '(i0)') i
      if (allocated(ids)) then
         if (i <= size(ids)) write (buf, '(i0)') ids(i)
      end if
      t = trim(buf)
   end function id_text

   !> Warning about element e of set s at its deck line.
   subroutine warn(model, s, e, text)
      type(model_t), intent(inout) :: model
      integer, intent(in) :: s, e
      character(len=*), intent(in) :: text
      type(place_t) :: p
      character(len=:), allocatable :: keyword
      call model%provenance%element(s, e, p, keyword)
      if (p%file > 0) then
         call model%warnings%add(text, model%provenance%files(p%file)%path, p%line)
      else
         call model%warnings%add(text)
      end if
   end subroutine warn

end module pecplas_model_geometry
