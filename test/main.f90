!> Test driver: `fpm test` runs every suite; `fpm test -- SUITE [TEST]` runs one.
!> CTest registers one test per suite (see CMakeLists.txt).
program tester
   use pecplas_testing, only: testsuite_t, new_testsuite, run_testsuite
   use test_model_params, only: collect_model_params
   use test_model_mesh_tools, only: collect_model_mesh_tools
   use test_io_gmsh, only: collect_io_gmsh
   use test_io_deck_fields, only: collect_io_deck_fields
   use test_io_deck, only: collect_io_deck
   use test_io_deck_errors, only: collect_io_deck_errors
   use test_massif_materials_factory, only: collect_massif_materials_factory
   implicit none (type, external)
   type(testsuite_t), allocatable :: suites(:)
   character(len=128) :: arg1, arg2
   integer :: i, npass, nfail, nargs
   logical :: found

   suites = [ &
      new_testsuite('model_params', collect_model_params), &
      new_testsuite('model_mesh_tools', collect_model_mesh_tools), &
      new_testsuite('io_gmsh', collect_io_gmsh), &
      new_testsuite('io_deck_fields', collect_io_deck_fields), &
      new_testsuite('io_deck', collect_io_deck), &
      new_testsuite('io_deck_errors', collect_io_deck_errors), &
      new_testsuite('massif_materials_factory', collect_massif_materials_factory) &
      ]

   nargs = command_argument_count()
   arg1 = ''; arg2 = ''
   if (nargs >= 1) call get_command_argument(1, arg1)
   if (nargs >= 2) call get_command_argument(2, arg2)
   npass = 0; nfail = 0; found = .false.
   do i = 1, size(suites)
      if (len_trim(arg1) > 0 .and. suites(i)%name /= trim(arg1)) cycle
      found = .true.
      call run_testsuite(suites(i), npass, nfail, trim(arg2))
   end do
   if (.not. found) then
      write (*, '(a)') 'unknown suite '//trim(arg1)//'; known suites:'
      do i = 1, size(suites)
         write (*, '(a)') '  '//suites(i)%name
      end do
      error stop 2
   end if
   write (*, '(i0,a,i0,a)') npass, ' passed, ', nfail, ' failed'
   if (nfail > 0) error stop 1
end program tester
