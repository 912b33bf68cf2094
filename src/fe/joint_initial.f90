!> Initial joint stresses (thesis §II.1.1): a joint point takes the stress of the massif
!> around it projected on its frame, sigma_n = -n.sigma.n (compression positive) and
!> tau = t.sigma.n, and its law history is initialised from that stress (e.g. MODJOIN's
!> sigma_n0). The initial-stress driver calls `initial_joint_stress` with the same field it
!> gives the massif (homogeneous or geostatic); relative displacements stay zero.
module pecplas_fe_joint_initial
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_joints_state, only: joint_state_t
   use pecplas_joints_points, only: joint_point_geometry
   use pecplas_fe_joint_assembly, only: reset_joint_tangents, set_law
   implicit none (type, external)
   private

   public :: massif_stress_ifc, joint_stress_from_massif, initial_joint_stress, &
      set_joint_stress

   abstract interface
      !> Continuum stress (xx, yy, zz, xy), tension positive, at the point x.
      function massif_stress_ifc(x) result(stress)
         import :: wp
         real(wp), intent(in) :: x(2)
         real(wp) :: stress(4)
      end function massif_stress_ifc
   end interface

contains

   !> (sigma_n, tau) of a joint of unit tangent t (n = (-t_y, t_x)) in the continuum stress
   !> (xx, yy, zz, xy), tension positive.
   pure function joint_stress_from_massif(stress, t) result(sigma)
      real(wp), intent(in) :: stress(4), t(2)
      real(wp) :: sigma(2)
      real(wp) :: s(2, 2), n(2)
      s = reshape([stress(1), stress(4), stress(4), stress(2)], [2, 2])
      n = [-t(2), t(1)]
      sigma = [-dot_product(n, matmul(s, n)), dot_product(t, matmul(s, n))]
   end function joint_stress_from_massif

   !> Every joint point takes the projection of field(x) at its position.
   subroutine initial_joint_stress(model, jstate, field, error)
      type(model_t), intent(in) :: model
      type(joint_state_t), intent(inout) :: jstate
      procedure(massif_stress_ifc) :: field
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: xy(:, :, :), t(:, :, :), sigma0(:, :, :)
      integer :: s, e, ip
      if (.not. allocated(jstate%sets)) return
      do s = 1, size(jstate%sets)
         call joint_point_geometry(model, s, xy, t, error)
         if (allocated(error)) return
         allocate (sigma0(2, size(xy, 2), size(xy, 3)))
         do e = 1, size(xy, 3)
            do ip = 1, size(xy, 2)
               sigma0(:, ip, e) = joint_stress_from_massif(field(xy(:, ip, e)), t(:, ip, e))
            end do
         end do
         call set_joint_stress(model, jstate, s, sigma0, error)
         if (allocated(error)) return
         deallocate (sigma0)
      end do
   end subroutine initial_joint_stress

   !> Sets the converged and trial stress of joint set s to sigma0(2, np, nel) and
   !> re-initialises the law history from it (relative displacements unchanged).
   subroutine set_joint_stress(model, jstate, s, sigma0, error)
      type(model_t), intent(in) :: model
      type(joint_state_t), intent(inout) :: jstate
      integer, intent(in) :: s
      real(wp), intent(in) :: sigma0(:, :, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: e, ip
      associate (st => jstate%sets(s), set => model%joint_sets(s))
         if (any(shape(sigma0) /= shape(st%sigma))) then
            call fatal_error(error, 'initial joint stress of set '//set%name// &
               ' must be (2, npoint, nel)')
            return
         end if
         st%sigma = sigma0
         st%sigma_trial = sigma0
         ! (a Katona set has no law history: its doublets take this stress as their
         ! initial contact forces, pecplas_joints_katona_doublets)
         if (.not. set%is_katona()) then
            do e = 1, size(sigma0, 3)
               do ip = 1, size(sigma0, 2)
                  call model%laws(set_law(set, st))%law%init_state(sigma0(:, ip, e), &
                     st%hist(:, ip, e))
               end do
            end do
         end if
         st%hist_trial = st%hist
      end associate
      call reset_joint_tangents(model, jstate)
   end subroutine set_joint_stress

end module pecplas_fe_joint_initial
