!> Plate (beam) sets of a model: shear-deformable beams along a line of nodes, each node of a
!> plate carrying a rotation besides its two translations (`model_t%node_rotation`). The
!> section is given as PLAXIS gives a plate: normal stiffness EA and bending stiffness EI per
!> unit width, Poisson's ratio, weight per unit area, and optionally the plastic limits Np, Mp.
module pecplas_model_plates
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: plate_set_t, plate_section_t

   !> Section data of a plate (per unit width out of plane in plane strain, per unit length
   !> of circumference in axisymmetry).
   type :: plate_section_t
      !> EA, EI as given; nu: the stiffnesses used are EA/(1-nu^2), EI/(1-nu^2) (a plate that
      !> is a wall: plane strain in its width), the shear stiffness 5 EA / (12 (1 + nu)).
      real(wp) :: ea = 0.0_wp, ei = 0.0_wp, nu = 0.0_wp
      !> Weight per unit area of the plate (its own weight: `*LOAD, TYPE=GRAVITY` naming the set).
      real(wp) :: w = 0.0_wp
      !> Plastic limits (0: none): axial force Np and moment Mp of the interaction
      !> (N/Np)^2 + (M/Mp)^2 <= 1 (pecplas_structures_section).
      real(wp) :: np = 0.0_wp, mp = 0.0_wp
   contains
      procedure :: plastic => section_plastic
   end type plate_section_t

   type :: plate_set_t
      character(len=:), allocatable :: name
      !> Nodes per element: 2 (linear) or 3 (end, end, mid: on the sides of T6/Q8 elements).
      integer :: nen = 2
      !> Connectivity (nen, nel), internal node numbers; elements follow each other along the
      !> plate's lines (node 2 of one element is node 1 of the next where they join).
      integer, allocatable :: conn(:, :)
      type(plate_section_t) :: section
      !> Deck position of the *PLATE line (for messages).
      character(len=:), allocatable :: file
      integer :: line = 0
   end type plate_set_t

contains

   !> True when the section has a plastic limit.
   pure logical function section_plastic(this)
      class(plate_section_t), intent(in) :: this
      section_plastic = this%np > 0.0_wp .or. this%mp > 0.0_wp
   end function section_plastic

end module pecplas_model_plates
