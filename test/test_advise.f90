!> The advice mode (`pecplas --advise`, pecplas_driver_advise) in-process: on S3's pile deck
!> (elastoplastic soil, Goodman joints; modified Newton does not converge there, Newton does)
!> and on the default deck (a geostatic step before the loading one). S3 is Q4 with GOODMAN4
!> joints and the footing Q8: both have the refined-mesh rows and their reference.
module test_advise
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pecplas_kinds, only: wp
   use pecplas_error, only: error_t, ERR_INPUT
   use pecplas_driver_advise, only: advise_row_t, advise_deck, ADVISE_METHODS, ADVISE_FACTORS, &
      ADVISE_FINE_FACTORS
   use pecplas_model, only: model_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_advise

contains

   subroutine collect_advise(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('s3_reference_and_advice', test_s3), &
               new_unittest('default_deck_loading_step', test_default), &
               new_unittest('bad_node_is_input_error', test_bad_node)]
   end subroutine collect_advise

   !> Every configuration is run, NEWTON x1 and x2 on the refined mesh (h/2) too; the reference
   !> (NEWTON x2 on the refined mesh) has error exactly 0 (it is compared with itself); every
   !> completed run has a finite error >= 0; the advice for 1 % and 5 % names a completed
   !> configuration whose error is below the threshold and whose wall time is the smallest of
   !> those below it (the definition of the advice). The monitored node is a node of the deck.
   subroutine test_s3(error)
      type(error_t), allocatable, intent(out) :: error
      type(advise_row_t), allocatable :: rows(:)
      type(model_t) :: model
      integer :: ref, best(2), node
      call check_advice('input/s3/s3_psi5.inp', .true., error)
      if (allocated(error)) return
      call advise_deck('input/s3/s3_psi5.inp', 0, rows, ref, best, node, error)
      if (allocated(error)) return
      call read_deck('input/s3/s3_psi5.inp', model, error)
      if (allocated(error)) return
      call check(error, findloc(model%mesh%node_id, node, 1) > 0, &
         'the monitored node is a node of the deck')
   end subroutine test_s3

   !> The same on the strip-footing example deck; the increments reported are those of its
   !> loading step (5 in the deck: 3, 5, 10 for x1/2, x1, x2), not of its one-increment
   !> geostatic step. Its Q8 mesh is refined (h/2) like a Q4 one.
   subroutine test_default(error)
      type(error_t), allocatable, intent(out) :: error
      type(advise_row_t), allocatable :: rows(:)
      character(len=:), allocatable :: note
      integer :: ref, best(2), node
      call check_advice('input/examples/strip_footing.inp', .true., error)
      if (allocated(error)) return
      call advise_deck('input/examples/strip_footing.inp', 0, rows, ref, best, node, error, note)
      if (allocated(error)) return
      call check(error, all(rows(1:3)%increments == [3, 5, 10]), &
         'increments of the loading step: 3, 5, 10')
      if (allocated(error)) return
      call check(error, .not. allocated(note), 'Q8: the mesh level is varied')
   end subroutine test_default

   !> --advise-node with an id that is not in the mesh: an input error, no advice.
   subroutine test_bad_node(error)
      type(error_t), allocatable, intent(out) :: error
      type(advise_row_t), allocatable :: rows(:)
      type(error_t), allocatable :: e
      integer :: ref, best(2), node
      call advise_deck('input/examples/strip_footing.inp', 999999, rows, ref, best, node, e)
      call check(error, allocated(e), 'an unknown node is reported')
      if (allocated(error)) return
      call check(error, e%kind == ERR_INPUT, 'as an input error')
   end subroutine test_bad_node

   subroutine check_advice(deck, refined, error)
      character(len=*), intent(in) :: deck
      !> The deck's model refines: the fine rows exist and hold the reference.
      logical, intent(in) :: refined
      type(error_t), allocatable, intent(out) :: error
      type(advise_row_t), allocatable :: rows(:)
      real(wp), parameter :: TOL(2) = [0.01_wp, 0.05_wp]
      integer :: ref, best(2), node, i, m
      call advise_deck(deck, 0, rows, ref, best, node, error)
      if (allocated(error)) return
      call check(error, size(rows) == size(ADVISE_METHODS)*size(ADVISE_FACTORS) + &
         merge(size(ADVISE_FINE_FACTORS), 0, refined), deck//': one row per configuration')
      if (allocated(error)) return
      call check(error, count(rows%fine) == merge(size(ADVISE_FINE_FACTORS), 0, refined) .and. &
         all(rows%fine .eqv. [(i > size(ADVISE_METHODS)*size(ADVISE_FACTORS), i=1, size(rows))]), &
         deck//': the refined-mesh rows come last')
      if (allocated(error)) return
      call check(error, rows(ref)%ok .and. rows(ref)%err == 0.0_wp .and. &
         rows(ref)%method == 'NEWTON' .and. rows(ref)%factor == 2.0_wp .and. &
         (rows(ref)%fine .eqv. refined) .and. ref == size(rows), &
         deck//': reference NEWTON x2 (refined mesh when it refines), error exactly 0')
      if (allocated(error)) return
      do i = 1, size(rows)
         if (.not. rows(i)%ok) cycle
         call check(error, ieee_is_finite(rows(i)%err) .and. rows(i)%err >= 0.0_wp .and. &
            rows(i)%wall >= 0.0_wp, deck//': finite errors and times')
         if (allocated(error)) return
      end do
      do m = 1, 2
         call check(error, best(m) > 0, deck//': an advice exists (the reference qualifies)')
         if (allocated(error)) return
         call check(error, rows(best(m))%ok .and. rows(best(m))%err < TOL(m), &
            deck//': the advised configuration is below the threshold')
         if (allocated(error)) return
         do i = 1, size(rows)
            if (.not. rows(i)%ok .or. .not. rows(i)%err < TOL(m)) cycle
            call check(error, rows(best(m))%wall <= rows(i)%wall, &
               deck//': the advised configuration is the cheapest below the threshold')
            if (allocated(error)) return
         end do
      end do
   end subroutine check_advice

end module test_advise
