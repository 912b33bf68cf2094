!> Isoparametric line joint with two or three node doublets (Goodman kinematics,
!> (B.1)–(B.11)): shared by GOODMAN4, GOODMAN6 and THIN_LAYER. Geometry from face 1
!> (the doublets are coincident), integration by Gauss or Lobatto (Newton–Cotes) points,
!> as many points as doublets. Lobatto points sit on the doublets, which decouples them
!> and removes the traction oscillations of stiff joints under Gauss integration.
module pecplas_joints_elements_line
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error, input_error
   use pecplas_model_options, only: PLANE_STRAIN, AXISYMMETRIC
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t
   implicit none (type, external)
   private

   public :: line_joint_t, line_shape, line_rule

   real(wp), parameter :: TWO_PI = 2.0_wp*acos(-1.0_wp)

   !> Face-1 and face-2 node of shape function a (ends, then mid): (B.8)/(B.10) order.
   integer, parameter :: FACE1(3) = [1, 2, 5], FACE2(3) = [4, 3, 6]

   type, abstract, extends(joint_element_t) :: line_joint_t
      !> Number of doublets (2 or 3).
      integer :: ndoublet = 2
      !> Lobatto (Newton–Cotes) points instead of Gauss points.
      logical :: lobatto = .false.
      !> Thin layer thickness e (relative displacements / e are strains); 0: zero thickness.
      real(wp) :: layer = 0.0_wp
   contains
      procedure :: nnode => line_nnode
      procedure :: npoint => line_npoint
      procedure :: points => line_points
   end type line_joint_t

contains

   pure integer function line_nnode(this)
      class(line_joint_t), intent(in) :: this
      line_nnode = 2*this%ndoublet
   end function line_nnode

   pure integer function line_npoint(this)
      class(line_joint_t), intent(in) :: this
      line_npoint = this%ndoublet
   end function line_npoint

   !> Points and weights on [-1, 1]: Gauss (exact to degree 2n-1) or Lobatto (ends included).
   pure subroutine line_rule(n, lobatto, xi, w)
      integer, intent(in) :: n
      logical, intent(in) :: lobatto
      real(wp), intent(out) :: xi(n), w(n)
      if (lobatto) then
         if (n == 2) then
            xi = [-1.0_wp, 1.0_wp]; w = [1.0_wp, 1.0_wp]
         else
            xi = [-1.0_wp, 0.0_wp, 1.0_wp]; w = [1.0_wp, 4.0_wp, 1.0_wp]/3.0_wp
         end if
      else
         if (n == 2) then
            xi = [-1.0_wp, 1.0_wp]/sqrt(3.0_wp); w = [1.0_wp, 1.0_wp]
         else
            xi = [-sqrt(0.6_wp), 0.0_wp, sqrt(0.6_wp)]; w = [5.0_wp, 8.0_wp, 5.0_wp]/9.0_wp
         end if
      end if
   end subroutine line_rule

   !> Line shape functions of n = 2 or 3 nodes (ends at -1, +1, mid at 0) and d/dxi.
   pure subroutine line_shape(n, xi, sh, dsh)
      integer, intent(in) :: n
      real(wp), intent(in) :: xi
      real(wp), intent(out) :: sh(n), dsh(n)
      if (n == 2) then
         sh = [0.5_wp*(1.0_wp - xi), 0.5_wp*(1.0_wp + xi)]
         dsh = [-0.5_wp, 0.5_wp]
      else
         sh = [0.5_wp*xi*(xi - 1.0_wp), 0.5_wp*xi*(xi + 1.0_wp), 1.0_wp - xi*xi]
         dsh = [xi - 0.5_wp, xi + 0.5_wp, -2.0_wp*xi]
      end if
   end subroutine line_shape

   !> D of (B.8)/(B.10) at each point, with t = dX/dxi / J (B.4–B.5), S = t_y, C = t_x.
   subroutine line_points(this, xe, analysis_kind, thickness, pts, error, tangent, tributary)
      class(line_joint_t), intent(in) :: this
      real(wp), intent(in) :: xe(:, :)
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness
      type(joint_point_t), intent(out) :: pts(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: tangent(2), tributary
      real(wp) :: xi(3), w(3), sh(3), dsh(3), dx(2), jac, s, c, scale
      real(wp) :: xf(2, 3)
      character(len=120) :: buf
      integer :: n, ip, a, i1, i2

      n = this%ndoublet
      if (size(xe, 2) /= 2*n .or. size(pts) /= n) then
         call fatal_error(error, 'line joint: xe must be (2, nnode) and pts of size npoint')
         return
      end if
      scale = 1.0_wp
      if (this%layer > 0.0_wp) scale = 1.0_wp/this%layer
      xf(:, 1:n) = xe(:, FACE1(1:n))
      call line_rule(n, this%lobatto, xi(1:n), w(1:n))
      do ip = 1, n
         call line_shape(n, xi(ip), sh(1:n), dsh(1:n))
         dx = matmul(xf(:, 1:n), dsh(1:n))
         jac = norm2(dx)
         pts(ip)%x = matmul(xf(:, 1:n), sh(1:n))
         if (.not. (jac > 0.0_wp)) then
            write (buf, '(a,2es11.3,a)') 'zero length near (', pts(ip)%x, ')'
            call input_error(error, 'degenerate joint element: '//trim(buf)// &
               ': expected distinct nodes along its face')
            return
         end if
         c = dx(1)/jac
         s = dx(2)/jac
         pts(ip)%t = [c, s]
         pts(ip)%d = 0.0_wp
         do a = 1, n
            i1 = 2*FACE1(a) - 1
            i2 = 2*FACE2(a) - 1
            ! row 1: g_n = n . (u(face 2) - u(face 1)), n = (-S, C)
            pts(ip)%d(1, i1:i1 + 1) = sh(a)*[s, -c]
            pts(ip)%d(1, i2:i2 + 1) = sh(a)*[-s, c]
            ! row 2: eps_t = t . (u(face 2) - u(face 1))
            pts(ip)%d(2, i1:i1 + 1) = sh(a)*[-c, -s]
            pts(ip)%d(2, i2:i2 + 1) = sh(a)*[c, s]
         end do
         pts(ip)%d = scale*pts(ip)%d
         select case (analysis_kind)
         case (PLANE_STRAIN)
            pts(ip)%da = w(ip)*jac*thickness
         case (AXISYMMETRIC)
            ! r = 0 (a point on the axis) is allowed: its ring has no area
            if (pts(ip)%x(1) < -1.0e-12_wp*maxval(abs(xe))) then
               write (buf, '(a,es11.3)') 'r = ', pts(ip)%x(1)
               call input_error(error, 'axisymmetric joint element with a negative radius '// &
                  'at an integration point, '//trim(buf)//': expected r >= 0 along the '// &
                  'element (is a midside node off the middle of its side?)')
               return
            end if
            pts(ip)%da = w(ip)*jac*TWO_PI*max(pts(ip)%x(1), 0.0_wp)
         case default
            call fatal_error(error, 'line joint: unknown analysis kind')
            return
         end select
         if (this%layer > 0.0_wp) pts(ip)%da = pts(ip)%da*this%layer
      end do
   end subroutine line_points

end module pecplas_joints_elements_line
