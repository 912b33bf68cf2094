!> Resource caps of the deck language (doc/deck.md, "Limits"). Each bounds what one line
!> of the deck can ask for, so that a typo cannot exhaust memory or run for hours; every
!> cap is checked before anything is allocated or run.
module pecplas_io_deck_caps
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   !> Increments of one *STEP. The thesis runs use tens to a few hundred; a history row is
   !> written for each, so 1e5 increments of even a small mesh already take hours.
   integer, parameter, public :: MAX_INCREMENTS = 100000
   !> Equilibrium iterations of one increment (*SOLVER, MAX_ITERATIONS=).
   integer, parameter, public :: MAX_ITERATIONS_CAP = 10000
   !> Increment cuts (*SOLVER, MAX_CUTS=): each halves the increment, 2**40 is far below
   !> any meaningful load step.
   integer, parameter, public :: MAX_CUTS_CAP = 40

   !> Magnitude of a load value (*LOAD) or a step's target factor (*STEP): far above any
   !> physical load in any unit, low enough that the products of assembly (a load times
   !> a factor times a stiffness) stay finite.
   real(wp), parameter, public :: MAX_LOAD_MAGNITUDE = 1.0e100_wp

end module pecplas_io_deck_caps
