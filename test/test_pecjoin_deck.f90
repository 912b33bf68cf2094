!> Deck input of joints and interface laws: the good decks give the expected model (laws,
!> joint sets, integration, thickness; a TYPE=KATONA law is Katona contact, no law, and marks
!> its joint sets); every bad deck of test/data/joints/bad_*.inp fails
!> with an input error naming its file, line and keyword and the key words of the message,
!> and through `run_deck` it exits with code 2 and writes no results file.
module test_pecjoin_deck
   use pecplas_base_kinds, only: wp
   use pecplas_joints_laws_checks, only: tan_deg
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_base_files, only: make_directories
   use pecplas_problem_type, only: problem_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use fixtures_bad_decks, only: bad_case_t, bad, run_bad_cases
   implicit none (type, external)
   private
   public :: collect_pecjoin_deck

   character(len=*), parameter :: DATA = 'test/data/joints/'
   character(len=*), parameter :: DIR = 'build/test_out/pecjoin'

   !> One bad deck: the line and keyword of its error and up to three words it must hold.

contains

   subroutine collect_pecjoin_deck(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('good_decks', test_good), &
               new_unittest('bad_laws', test_bad_laws), &
               new_unittest('bad_explicit_joints', test_bad_explicit), &
               new_unittest('bad_generated_joints', test_bad_generated), &
               new_unittest('bad_decks_exit_2_no_file', test_exit_codes)]
   end subroutine collect_pecjoin_deck

   !> A generated deck: law, set, type, integration, thickness as written.
   subroutine test_good(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      call read_deck(DATA//'patch_thin_layer_plane_gen.inp', model, error)
      if (allocated(error)) return
      call check(error, size(model%laws) == 1 .and. size(model%joint_sets) == 1, &
         'one law, one joint set')
      if (allocated(error)) return
      associate (js => model%joint_sets(1))
         call check(error, model%laws(1)%law%name == 'contact' .and. js%law_index == 1 .and. &
            js%is_thin_layer() .and. js%integration == 'GAUSS' .and. &
            abs(js%thickness - 0.01_wp) < 1.0e-15_wp .and. size(js%conn, 1) == 6 .and. &
            size(js%conn, 2) == 2, 'THIN_LAYER on quadratic edges: 2 joints of 6 nodes, e = 0.01')
         if (allocated(error)) return
      end associate
      call read_deck(DATA//'patch_goodman6_plane_lobatto.inp', model, error)
      if (allocated(error)) return
      call check(error, model%joint_sets(1)%integration == 'LOBATTO' .and. &
         all(model%joint_sets(1)%ids == [101, 102]), 'LOBATTO, explicit ids 101, 102')
      if (allocated(error)) return
      ! TYPE=KATONA: contact parameters, no interface law; the set that uses it is a Katona set
      call read_deck('test/data/katona/pad_stick.inp', model, error)
      if (allocated(error)) return
      call check(error, size(model%laws) == 0 .and. size(model%contacts) == 1, &
         'a KATONA law is a contact, not an interface law')
      if (allocated(error)) return
      associate (js => model%joint_sets(1), c => model%contacts(1))
         call check(error, js%is_katona() .and. js%contact_index == 1 .and. &
            js%law_index == 0 .and. js%law == 'friction' .and. c%name == 'friction', &
            'its joint set is marked Katona and refers to the contact')
         if (allocated(error)) return
         ! PHI = 16.69924423399362 deg, C = 0 as written (tan of the same double: exact)
         call check(error, c%mu == tan_deg(16.69924423399362_wp) .and. c%c == 0.0_wp .and. &
            c%tension == 0.0_wp, 'the contact parameters as written')
      end associate
   end subroutine test_good

   subroutine test_bad_laws(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DATA, [ &
         bad('unknown_law_type', 3, '*INTERFACE_LAW', "unknown interface law type 'COULOMB'", &
             'known types: ELASTIC', 'KATONA'), &
         bad('undefined_law', 5, '*JOINTS', "undefined interface law 'friction'", &
             'known laws: contact'), &
         bad('law_parameter', 4, '*INTERFACE_LAW', 'KN and KT must be positive'), &
         bad('law_unknown_parameter', 4, '*INTERFACE_LAW', 'unknown parameter KX', 'KN KT'), &
         bad('duplicate_law', 5, '*INTERFACE_LAW', "'Contact' is defined twice", &
             'bad_duplicate_law.inp:3'), &
         bad('duplicate_contact', 5, '*INTERFACE_LAW', "'Contact' is defined twice", &
             'bad_duplicate_contact.inp:3'), &
         bad('duplicate_contact2', 5, '*INTERFACE_LAW', "'Contact' is defined twice", &
             'bad_duplicate_contact2.inp:3')], error)
   end subroutine test_bad_laws

   subroutine test_bad_explicit(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DATA, [ &
         bad('non_coincident', 9, '*JOINTS', 'joint on non-coincident nodes', 'joint 102', &
             'nodes 6 and 13'), &
         bad('unknown_joint_type', 5, '*JOINTS', "unknown joint type 'GOODMAN8'", &
             'SPRING GOODMAN4 GOODMAN6 THIN_LAYER'), &
         bad('joint_node_count', 7, '*JOINTS', 'wrong number of nodes for a GOODMAN4', &
             'found 6 node'), &
         bad('joint_inverted', 7, '*JOINTS', 'joint 102 is inverted', 'id, n2, n1, n4, n3'), &
         bad('joint_undefined_node', 7, '*JOINTS', 'undefined node 99 in joint 102'), &
         bad('duplicate_joint_id', 7, '*JOINTS', 'duplicate element id 3'), &
         bad('thin_layer_thickness', 5, '*JOINTS', 'THICKNESS=e is required'), &
         bad('spring_alone', 6, '*JOINTS', "joint set 'joint', spring 101 at node 5", &
             'no adjacent joint edge')], error)
   end subroutine test_bad_explicit

   subroutine test_bad_generated(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DATA, [ &
         bad('edges_not_side', 5, '*JOINTS', "edge (1 2) of edge set 'bottom'", &
             'not a side of an element of the SIDE body', "SIDE='upper'"), &
         bad('edges_nothing_to_join', 5, '*JOINTS', "edge set 'top'", 'nothing to join'), &
         bad('side_undefined', 5, '*JOINTS', "undefined element set 'pile' in SIDE=", &
             'lower upper'), &
         bad('edges_undefined', 5, '*JOINTS', "undefined edge set 'shaft' in EDGES=", &
             'interface bottom top'), &
         bad('edges_without_side', 5, '*JOINTS', 'EDGES=edge_set and SIDE=element_set go '// &
             'together'), &
         bad('goodman6_linear_edges', 5, '*JOINTS', 'GOODMAN6 joints need 3-node', &
             'use GOODMAN4'), &
         bad('faces_goodman6_linear_edges', 5, '*JOINTS', 'GOODMAN6 joints need 3-node', &
             'use GOODMAN4'), &
         bad('faces_edges_undefined', 5, '*JOINTS', "undefined edge set 'shaft' in EDGES=", &
             'interface bottom top'), &
         bad('edges_twice', 6, '*JOINTS', 'is already split')], error)
   end subroutine test_bad_generated

   !> Every bad_*.inp of test/data/joints: exit code 2, no results file.
   subroutine test_exit_codes(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(problem_t) :: problem
      character(len=256) :: name
      character(len=:), allocatable :: out
      logical :: there
      integer :: u, ios, code, count
      call make_directories(DIR)
      call execute_command_line('ls '//DATA//'bad_*.inp > '//DIR//'/bad_list.txt', exitstat=code)
      call check(error, code == 0, 'listing the bad joint decks')
      if (allocated(error)) return
      out = DIR//'/bad.h5'
      count = 0
      open (newunit=u, file=DIR//'/bad_list.txt', status='old', action='read')
      do
         read (u, '(a)', iostat=ios) name
         if (ios /= 0) exit
         open (newunit=code, file=out, status='replace')
         close (code, status='delete')
         code = run_deck(trim(name), out, .true., model, problem)
         inquire (file=out, exist=there)
         if (code /= 2 .or. there) then
            call fatal_error(error, trim(name)//': expected exit 2 and no results file')
            close (u)
            return
         end if
         count = count + 1
      end do
      close (u)
      call check(error, count >= 21, 'the 21 bad joint decks were run')
   end subroutine test_exit_codes

end module test_pecjoin_deck
