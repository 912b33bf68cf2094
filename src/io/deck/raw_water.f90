!> What the groundwater keywords collect before references are resolved (see
!> pecplas_io_deck_reader_water): the line of each *WATER, the sets named by *DRY and the
!> *CHANGE_WATER of the steps, each with its line.
module pecplas_io_deck_raw_water
   implicit none (type, external)
   private

   public :: raw_water_t, raw_water_change_t, raw_name_t

   !> A name as written and its line.
   type :: raw_name_t
      character(len=:), allocatable :: name
      integer :: at = 0
   end type raw_name_t

   !> *CHANGE_WATER in step `step`: LEVEL= as written ('' keep it), RESET_EXCESS=YES.
   type :: raw_water_change_t
      integer :: step = 0, at = 0
      character(len=:), allocatable :: level
      logical :: reset = .false.
   end type raw_water_change_t

   type :: raw_water_t
      !> Line of each *WATER (parallel to model%water%levels).
      integer, allocatable :: level_at(:)
      type(raw_name_t), allocatable :: dry(:)
      type(raw_water_change_t), allocatable :: changes(:)
      !> *PLATE_WATER: plate set names and the side ('LEFT', 'RIGHT', 'FREE' or 'NONE', upper
      !> case); plate_step: the step it was given in (0: before the first step).
      type(raw_name_t), allocatable :: plate(:), plate_side(:)
      integer, allocatable :: plate_step(:)
   end type raw_water_t

end module pecplas_io_deck_raw_water
