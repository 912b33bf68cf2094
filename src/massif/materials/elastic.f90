!> Linear isotropic elasticity (plane strain / axisymmetric, 4 components).
module pecplas_massif_materials_elastic
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, deck_error
   use pecplas_base_params, only: params_t
   use pecplas_massif_materials_type, only: material_t, NCOMP
   implicit none (type, external)
   private

   public :: elastic_t, new_elastic

   type, extends(material_t) :: elastic_t
      real(wp) :: young = 0.0_wp, poisson = 0.0_wp
   contains
      procedure :: nstate => elastic_nstate
      procedure :: elastic_tangent => elastic_elastic_tangent
      procedure :: update => elastic_update
      procedure :: constant_tangent => elastic_constant_tangent
   end type elastic_t

contains

   !> Builds from deck parameters E, NU and optional GAMMA; checks 0 < E, -1 < NU < 0.5.
   subroutine new_elastic(mat, name, params, error)
      type(elastic_t), intent(out) :: mat
      character(len=*), intent(in) :: name
      type(params_t), intent(in) :: params
      type(error_t), allocatable, intent(out) :: error
      character(len=40) :: buf
      call params%unknown_keys([character(len=5) :: 'E', 'NU', 'GAMMA'], error)
      if (allocated(error)) return
      mat%name = name
      call params%get('E', mat%young, error)
      if (allocated(error)) return
      call params%get('NU', mat%poisson, error)
      if (allocated(error)) return
      call params%get('GAMMA', mat%unit_weight, error, default=0.0_wp)
      if (allocated(error)) return
      if (.not. (mat%young > 0.0_wp)) then
         write (buf, '(es12.4)') mat%young
         call deck_error(error, params%file, params%line, params%keyword, &
            'Young modulus E must be positive, got '//trim(adjustl(buf)))
      else if (.not. (mat%poisson > -1.0_wp .and. mat%poisson < 0.5_wp)) then
         write (buf, '(g12.5)') mat%poisson  ! (f10.4 printed stars for |NU| >= 1e5)
         call deck_error(error, params%file, params%line, params%keyword, &
            'Poisson ratio NU must satisfy -1 < NU < 0.5, got '//trim(adjustl(buf)))
      else if (mat%unit_weight < 0.0_wp) then
         call deck_error(error, params%file, params%line, params%keyword, &
            'unit weight GAMMA must not be negative')
      end if
   end subroutine new_elastic

   pure integer function elastic_nstate(this) result(n)
      class(elastic_t), intent(in) :: this
      n = 0
   end function elastic_nstate

   !> Hooke matrix for (xx, yy, zz, xy) with engineering shear strain.
   pure subroutine elastic_elastic_tangent(this, tangent)
      class(elastic_t), intent(in) :: this
      real(wp), intent(out) :: tangent(NCOMP, NCOMP)
      real(wp) :: lam, mu
      lam = this%young*this%poisson/((1.0_wp + this%poisson)*(1.0_wp - 2.0_wp*this%poisson))
      mu = this%young/(2.0_wp*(1.0_wp + this%poisson))
      tangent = 0.0_wp
      tangent(1:3, 1:3) = lam
      tangent(1, 1) = lam + 2.0_wp*mu
      tangent(2, 2) = lam + 2.0_wp*mu
      tangent(3, 3) = lam + 2.0_wp*mu
      tangent(4, 4) = mu
   end subroutine elastic_elastic_tangent

   pure logical function elastic_constant_tangent(this)
      class(elastic_t), intent(in) :: this
      elastic_constant_tangent = .true.
   end function elastic_constant_tangent

   subroutine elastic_update(this, stress_old, dstrain, state, stress, tangent, error)
      class(elastic_t), intent(in) :: this
      real(wp), intent(in) :: stress_old(NCOMP), dstrain(NCOMP)
      real(wp), intent(inout) :: state(:)
      real(wp), intent(out) :: stress(NCOMP), tangent(NCOMP, NCOMP)
      type(error_t), allocatable, intent(out) :: error
      call this%elastic_tangent(tangent)
      stress = stress_old + matmul(tangent, dstrain)
   end subroutine elastic_update

end module pecplas_massif_materials_elastic
