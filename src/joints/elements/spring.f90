!> SPRING (ressort, B.13–B.18): one node doublet (face-1 node, face-2 node), zero length,
!> D = [S, -C, -S, C; -C, -S, C, S] for the doublet's tangent t = (C, S). The law sees the
!> relative displacement and returns a stress; the doublet force is that stress times the
!> doublet's tributary measure (computed by the joint set from its adjacent joint edges).
module pecplas_joints_elements_spring
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error, input_error
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t
   implicit none (type, external)
   private

   public :: spring_t

   type, extends(joint_element_t) :: spring_t
   contains
      procedure :: name => spring_name
      procedure :: nnode => spring_nnode
      procedure :: npoint => spring_npoint
      procedure :: points => spring_points
   end type spring_t

contains

   pure function spring_name(this) result(name)
      class(spring_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = 'SPRING'
   end function spring_name

   pure integer function spring_nnode(this)
      class(spring_t), intent(in) :: this
      spring_nnode = 2
   end function spring_nnode

   pure integer function spring_npoint(this)
      class(spring_t), intent(in) :: this
      spring_npoint = 1
   end function spring_npoint

   !> (B.17) with the given unit tangent; da = tributary (analysis kind and thickness are
   !> already in the tributary measure).
   subroutine spring_points(this, xe, analysis_kind, thickness, pts, error, tangent, tributary)
      class(spring_t), intent(in) :: this
      real(wp), intent(in) :: xe(:, :)
      integer, intent(in) :: analysis_kind
      real(wp), intent(in) :: thickness
      type(joint_point_t), intent(out) :: pts(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: tangent(2), tributary
      real(wp) :: s, c
      if (size(xe, 2) /= 2 .or. size(pts) /= 1) then
         call fatal_error(error, 'spring joint: xe must be (2, 2) and pts of size 1')
         return
      end if
      if (.not. (present(tangent) .and. present(tributary))) then
         call fatal_error(error, 'spring joint: tangent and tributary are required')
         return
      end if
      if (.not. (tributary >= 0.0_wp) .or. abs(norm2(tangent) - 1.0_wp) > 1.0e-9_wp) then
         call input_error(error, 'spring joint: the tangent must be a unit vector and the '// &
            'tributary measure non-negative')
         return
      end if
      c = tangent(1)
      s = tangent(2)
      pts(1)%x = xe(:, 1)
      pts(1)%t = tangent
      pts(1)%d = 0.0_wp
      pts(1)%d(1, 1:4) = [s, -c, -s, c]
      pts(1)%d(2, 1:4) = [-c, -s, c, s]
      pts(1)%da = tributary
   end subroutine spring_points

end module pecplas_joints_elements_spring
