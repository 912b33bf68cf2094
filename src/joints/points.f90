!> Integration points of the joint sets of a model: the element object of a set, the
!> points of one element (springs get their tangent and tributary from the set), the
!> physical coordinates and tangents of every point (results file, initial stresses).
module pecplas_joints_points
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_model_joints, only: joint_set_t
   use pecplas_model_provenance, only: place_t
   use pecplas_joints_elements_type, only: joint_element_t, joint_point_t
   use pecplas_joints_elements_factory, only: new_joint_element
   implicit none (type, external)
   private

   public :: joint_set_element, joint_element_points, joint_point_geometry, element_context

contains

   !> The element object of a joint set.
   subroutine joint_set_element(set, elem, error)
      type(joint_set_t), intent(in) :: set
      class(joint_element_t), allocatable, intent(out) :: elem
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: rule
      rule = 'GAUSS'
      if (allocated(set%integration)) rule = set%integration
      call new_joint_element(set%type_name(), size(set%conn, 1), rule, set%thickness, elem, error)
      if (allocated(error)) error%message = 'joint set '//set%name//': '//error%message
   end subroutine joint_set_element

   !> Points of element e of joint set `set` (elem from joint_set_element).
   subroutine joint_element_points(model, set, elem, e, pts, error)
      type(model_t), intent(in) :: model
      type(joint_set_t), intent(in) :: set
      class(joint_element_t), intent(in) :: elem
      integer, intent(in) :: e
      type(joint_point_t), intent(out) :: pts(:)
      type(error_t), allocatable, intent(out) :: error
      if (allocated(set%tributary)) then
         call elem%points(model%mesh%x(:, set%conn(:, e)), model%analysis%kind, &
            model%analysis%thickness, pts, error, set%tangent(:, e), set%tributary(e))
      else
         call elem%points(model%mesh%x(:, set%conn(:, e)), model%analysis%kind, &
            model%analysis%thickness, pts, error)
      end if
      if (allocated(error)) then
         call element_context(error, set, e)
         call locate_joint(model, set, e, error)
      end if
   end subroutine joint_element_points

   !> Gives a geometry error of joint e of `set` the deck line and keyword of the joint (its
   !> line of *JOINTS, or the *JOINTS line that generated it): the message names file:line.
   subroutine locate_joint(model, set, e, error)
      type(model_t), intent(in) :: model
      type(joint_set_t), intent(in) :: set
      integer, intent(in) :: e
      type(error_t), intent(inout) :: error
      type(place_t) :: p
      character(len=:), allocatable :: keyword
      integer :: s
      if (.not. allocated(model%joint_sets)) return
      do s = 1, size(model%joint_sets)
         if (model%joint_sets(s)%name /= set%name) cycle
         call model%provenance%joint(s, e, p, keyword)
         call model%provenance%locate(error, p, keyword)
         return
      end do
   end subroutine locate_joint

   !> Coordinates xy(2, np, nel) and unit tangents t(2, np, nel) of the points of set s.
   subroutine joint_point_geometry(model, s, xy, t, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: s
      real(wp), allocatable, intent(out) :: xy(:, :, :), t(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      class(joint_element_t), allocatable :: elem
      type(joint_point_t), allocatable :: pts(:)
      integer :: e, ip, np, nel
      associate (set => model%joint_sets(s))
         call joint_set_element(set, elem, error)
         if (allocated(error)) return
         np = elem%npoint()
         nel = size(set%conn, 2)
         allocate (pts(np), xy(2, np, nel), t(2, np, nel))
         do e = 1, nel
            call joint_element_points(model, set, elem, e, pts, error)
            if (allocated(error)) return
            do ip = 1, np
               xy(:, ip, e) = pts(ip)%x
               t(:, ip, e) = pts(ip)%t
            end do
         end do
      end associate
   end subroutine joint_point_geometry

   !> Prefixes an element-level error with the joint set and element id.
   subroutine element_context(error, set, e)
      type(error_t), allocatable, intent(inout) :: error
      type(joint_set_t), intent(in) :: set
      integer, intent(in) :: e
      character(len=32) :: buf
      write (buf, '(i0)') e
      if (allocated(set%ids)) write (buf, '(i0)') set%ids(e)
      error%message = 'joint element '//trim(buf)//' of set '//set%name//': '//error%message
   end subroutine element_context

end module pecplas_joints_points
