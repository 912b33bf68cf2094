!> The advice mode (`pecplas --advise`, pecplas_advise_advise) in-process, on the strip-footing
!> example deck (Q8, elastic, a geostatic step before the loading one): the structure of the
!> advice (levels of the adaptive sequence, reference rows, errors, cost, the cheapest within
!> each tolerance) and its input errors. Whether the advised configuration really meets its
!> claim against an independent reference is tested in test/python/test_advise.py.
module test_advise
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, ERR_INPUT
   use pecplas_advise_advise, only: advice_t, advise_deck, ADVISE_METHODS, ADVISE_FACTORS, &
      ADVISE_TOLERANCES, REF_TARGET
   use pecplas_testing, only: unittest_t, new_unittest, check
   implicit none (type, external)
   private
   public :: collect_advise

   character(len=*), parameter :: DECK = 'input/examples/strip_footing.inp'

contains

   subroutine collect_advise(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('footing_sequence_and_advice', test_footing), &
               new_unittest('bad_goal_is_input_error', test_bad_goal)]
   end subroutine collect_advise

   !> The sequence has at least three levels (the extrapolation needs them) and ends below the
   !> reference target or with a reason; each level has its NEWTON x2 reference row, the level 1
   !> every configuration, with the increments of the loading step (5 in the deck: 3, 5, 10 for
   !> x1/2, x1, x2), not of the one-increment geostatic step; every error is at least the
   !> reference's own estimate (the definition: distance + that estimate); the cost of a row is
   !> its wall time plus that of the same configuration on the coarser levels; the advice is the
   !> completed row of least cost below each tolerance. The goal is the footing centre, node 29
   !> (largest displacement), vertical.
   subroutine test_footing(error)
      type(error_t), allocatable, intent(out) :: error
      type(advice_t) :: adv
      integer :: k, m, i, nconf
      nconf = size(ADVISE_METHODS)*size(ADVISE_FACTORS)
      call advise_deck(DECK, '', 0, 0, adv, error)
      if (allocated(error)) return
      call check(error, adv%node_id == 29 .and. adv%dof == 2, 'goal: node 29, y')
      if (allocated(error)) return
      call check(error, adv%nlevels >= 3 .and. size(adv%level_dofs) == adv%nlevels .and. &
         allocated(adv%stop_reason), 'three levels at least, and why the sequence ended')
      if (allocated(error)) return
      call check(error, adv%ref_error <= REF_TARGET .and. adv%ref_error >= 0.0_wp, &
         'the reference reached its target (0.2 %)')
      if (allocated(error)) return
      call check(error, all(adv%level_dofs(2:) > adv%level_dofs(:adv%nlevels - 1)), &
         'the DOFs grow along the sequence')
      if (allocated(error)) return
      call check(error, count(adv%rows%level == 1) == nconf .and. &
         all(adv%rows(1:3)%increments == [3, 5, 10]), 'level 1: every configuration, '// &
         'increments of the loading step 3, 5, 10')
      if (allocated(error)) return
      do k = 1, adv%nlevels
         call check(error, count(adv%rows%level == k .and. adv%rows%method == 'NEWTON' .and. &
            adv%rows%factor == 2.0_wp) == 1, 'a reference row on every level')
         if (allocated(error)) return
      end do
      do i = 1, size(adv%rows)
         associate (r => adv%rows(i))
            call check(error, r%ok .and. ieee_is_finite(r%err) .and. &
               r%err >= adv%ref_error .and. r%wall >= 0.0_wp .and. r%cost >= r%wall - 1e-12_wp, &
               'completed, finite error >= the reference''s estimate, cost >= wall')
            if (allocated(error)) return
            ! the cost sums the same configuration's wall times up to this level
            call check(error, abs(r%cost - sum(adv%rows%wall, mask=adv%rows%method == r%method &
               .and. adv%rows%factor == r%factor .and. adv%rows%level <= r%level)) <= &
               1e-12_wp*max(1.0_wp, r%cost), 'cost = wall times on levels 1 .. level')
            if (allocated(error)) return
         end associate
      end do
      do m = 1, size(ADVISE_TOLERANCES)
         call check(error, adv%best(m) > 0, 'an advice within each tolerance')
         if (allocated(error)) return
         call check(error, adv%rows(adv%best(m))%err < ADVISE_TOLERANCES(m) .and. &
            adv%rows(adv%best(m))%cost <= minval(adv%rows%cost, mask=adv%rows%ok .and. &
            adv%rows%err < ADVISE_TOLERANCES(m)), 'the advice: the cheapest within tolerance')
         if (allocated(error)) return
      end do
   end subroutine test_footing

   !> An unknown node (by --goal or --advise-node) or a goal that is not a node's displacement:
   !> an input error, no advice.
   subroutine test_bad_goal(error)
      type(error_t), allocatable, intent(out) :: error
      type(advice_t) :: adv
      type(error_t), allocatable :: e
      call advise_deck(DECK, '', 999999, 0, adv, e)
      call check(error, allocated(e), '--advise-node 999999 is reported')
      if (allocated(error)) return
      call check(error, e%kind == ERR_INPUT, 'as an input error')
      if (allocated(error)) return
      deallocate (e)
      call advise_deck(DECK, 'energy', 0, 0, adv, e)
      call check(error, allocated(e), '--goal energy is reported')
      if (allocated(error)) return
      call check(error, e%kind == ERR_INPUT .and. index(e%text(), 'node goal') > 0, &
         'as an input error asking for a node goal')
   end subroutine test_bad_goal

end module test_advise
