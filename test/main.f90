!> Test driver: `fpm test` runs every suite; `fpm test -- SUITE [TEST]` runs one.
!> CTest registers one test per suite (see CMakeLists.txt).
program tester
   use pecplas_testing, only: testsuite_t, new_testsuite, run_testsuite
   use test_model_params, only: collect_model_params
   use test_strings, only: collect_strings
   use test_pecjoin_friction, only: collect_pecjoin_friction
   use test_s1, only: collect_s1
   use test_initial, only: collect_initial
   use test_phases, only: collect_phases
   use test_water, only: collect_water
   use test_anchors, only: collect_anchors
   use test_joint_faces, only: collect_joint_faces
   use test_phases_switch, only: collect_phases_switch
   use test_phases_orphans, only: collect_phases_orphans
   use test_plates, only: collect_plates
   use test_io_results_structures, only: collect_io_results_structures
   use test_safety, only: collect_safety
   use test_cli, only: collect_cli
   use test_lame, only: collect_lame
   use test_estimator, only: collect_estimator
   use test_model_mesh_tools, only: collect_model_mesh_tools
   use test_io_gmsh, only: collect_io_gmsh
   use test_massif_shapes, only: collect_massif_shapes
   use test_massif_elements, only: collect_massif_elements
   use test_massif_patch, only: collect_massif_patch
   use test_massif_edge_load, only: collect_massif_edge_load
   use test_io_results, only: collect_io_results
   use test_io_results_final, only: collect_io_results_final
   use test_io_results_copies, only: collect_io_results_copies
   use test_io_results_checksum, only: collect_io_results_checksum
   use test_io_results_phases, only: collect_io_results_phases
   use test_linalg_sparse, only: collect_linalg_sparse
   use test_linalg_sparse_reuse, only: collect_linalg_sparse_reuse
   use test_linalg_sparse_columns, only: collect_linalg_sparse_columns
   use test_linalg_solvers, only: collect_linalg_solvers
   use test_io_deck_fields, only: collect_io_deck_fields
   use test_io_deck, only: collect_io_deck
   use test_io_deck_errors, only: collect_io_deck_errors
   use test_io_deck_trust, only: collect_io_deck_trust
   use test_io_deck_user, only: collect_io_deck_user
   use test_solve_progress, only: collect_solve_progress
   use test_massif_materials_factory, only: collect_massif_materials_factory
   use test_pecjoin_elements, only: collect_pecjoin_elements
   use test_pecjoin_patch, only: collect_pecjoin_patch
   use test_pecjoin_split, only: collect_pecjoin_split
   use test_pecjoin_deck, only: collect_pecjoin_deck
   use test_pecjoin_solver, only: collect_pecjoin_solver
   use test_pecjoin_laws, only: collect_pecjoin_laws
   use test_pecjoin_laws_mc, only: collect_pecjoin_laws_mc
   use test_pecjoin_laws_tangent, only: collect_pecjoin_laws_tangent
   use test_pecjoin_path, only: collect_pecjoin_path
   use test_massif_plasticity, only: collect_massif_plasticity
   use test_massif_tangent_fd, only: collect_massif_tangent_fd
   use test_massif_plasticity_dp, only: collect_massif_plasticity_dp
   use test_massif_plasticity_paths, only: collect_massif_plasticity_paths
   use test_massif_plasticity_fe, only: collect_massif_plasticity_fe
   use test_pecjoin_modjoin, only: collect_pecjoin_modjoin
   use test_pecjoin_modjoin_paths, only: collect_pecjoin_modjoin_paths
   use test_pecjoin_modjoin_fe, only: collect_pecjoin_modjoin_fe
   use test_pecjoin_modjoin_cyclic, only: collect_pecjoin_modjoin_cyclic
   use test_advise, only: collect_advise
   use test_refine, only: collect_refine
   use test_refine_local, only: collect_refine_local
   use test_adapt, only: collect_adapt
   use test_pecjoin_katona, only: collect_pecjoin_katona
   use test_pecjoin_katona_friction, only: collect_pecjoin_katona_friction
   use test_pecjoin_claims, only: collect_pecjoin_claims
   use test_pecjoin_identify, only: collect_pecjoin_identify
   use test_pecjoin_sensitivity, only: collect_pecjoin_sensitivity
   use test_pecjoin_identify_roundtrip, only: collect_pecjoin_identify_roundtrip
   use test_driver_nonlinear, only: collect_driver_nonlinear
   use test_massif_collapse, only: collect_massif_collapse
   use test_massif_q8r, only: collect_massif_q8r
   use test_driver_sanity, only: collect_driver_sanity
   use test_linalg_threads, only: collect_linalg_threads
   use test_linalg_blas_core, only: collect_linalg_blas_core
   use test_model_units, only: collect_model_units
   use test_linalg_mumps, only: collect_linalg_mumps
   use test_fe_share, only: collect_fe_share
   use test_linalg_cholmod_ordering, only: collect_linalg_cholmod_ordering
   use test_io_deck_mesh_lines, only: collect_io_deck_mesh_lines
   use test_massif_kernels, only: collect_massif_kernels
   use test_linalg_omp_serial, only: collect_linalg_omp_serial
   use test_cmd_args, only: collect_cmd_args
   implicit none (type, external)
   type(testsuite_t), allocatable :: suites(:)
   character(len=128) :: arg1, arg2
   integer :: i, npass, nfail, nargs
   logical :: found

   ! One line per suite (appending keeps merges of new suites conflict-free).
   allocate (suites(0))
   suites = [suites, new_testsuite('model_params', collect_model_params)]
   suites = [suites, new_testsuite('strings', collect_strings)]
   suites = [suites, new_testsuite('lame', collect_lame)]
   suites = [suites, new_testsuite('pecjoin_friction', collect_pecjoin_friction)]
   suites = [suites, new_testsuite('s1', collect_s1)]
   suites = [suites, new_testsuite('initial', collect_initial)]
   suites = [suites, new_testsuite('phases', collect_phases)]
   suites = [suites, new_testsuite('water', collect_water)]
   suites = [suites, new_testsuite('anchors', collect_anchors)]
   suites = [suites, new_testsuite('joint_faces', collect_joint_faces)]
   suites = [suites, new_testsuite('phases_switch', collect_phases_switch)]
   suites = [suites, new_testsuite('phases_orphans', collect_phases_orphans)]
   suites = [suites, new_testsuite('io_results_structures', collect_io_results_structures)]
   suites = [suites, new_testsuite('safety', collect_safety)]
   suites = [suites, new_testsuite('cli', collect_cli)]
   suites = [suites, new_testsuite('model_mesh_tools', collect_model_mesh_tools)]
   suites = [suites, new_testsuite('io_gmsh', collect_io_gmsh)]
   suites = [suites, new_testsuite('massif_shapes', collect_massif_shapes)]
   suites = [suites, new_testsuite('massif_elements', collect_massif_elements)]
   suites = [suites, new_testsuite('massif_patch', collect_massif_patch)]
   suites = [suites, new_testsuite('massif_edge_load', collect_massif_edge_load)]
   suites = [suites, new_testsuite('io_results', collect_io_results)]
   suites = [suites, new_testsuite('io_results_final', collect_io_results_final)]
   suites = [suites, new_testsuite('linalg_sparse', collect_linalg_sparse)]
   suites = [suites, new_testsuite('linalg_sparse_reuse', collect_linalg_sparse_reuse)]
   suites = [suites, new_testsuite('linalg_sparse_columns', collect_linalg_sparse_columns)]
   suites = [suites, new_testsuite('linalg_solvers', collect_linalg_solvers)]
   suites = [suites, new_testsuite('io_deck_fields', collect_io_deck_fields)]
   suites = [suites, new_testsuite('io_deck', collect_io_deck)]
   suites = [suites, new_testsuite('io_deck_errors', collect_io_deck_errors)]
   suites = [suites, new_testsuite('massif_materials_factory', collect_massif_materials_factory)]
   suites = [suites, new_testsuite('pecjoin_elements', collect_pecjoin_elements)]
   suites = [suites, new_testsuite('pecjoin_patch', collect_pecjoin_patch)]
   suites = [suites, new_testsuite('pecjoin_split', collect_pecjoin_split)]
   suites = [suites, new_testsuite('pecjoin_deck', collect_pecjoin_deck)]
   suites = [suites, new_testsuite('pecjoin_solver', collect_pecjoin_solver)]
   suites = [suites, new_testsuite('pecjoin_laws', collect_pecjoin_laws)]
   suites = [suites, new_testsuite('pecjoin_laws_mc', collect_pecjoin_laws_mc)]
   suites = [suites, new_testsuite('pecjoin_laws_tangent', collect_pecjoin_laws_tangent)]
   suites = [suites, new_testsuite('pecjoin_path', collect_pecjoin_path)]
   suites = [suites, new_testsuite('massif_plasticity', collect_massif_plasticity)]
   suites = [suites, new_testsuite('massif_tangent_fd', collect_massif_tangent_fd)]
   suites = [suites, new_testsuite('massif_plasticity_dp', collect_massif_plasticity_dp)]
   suites = [suites, new_testsuite('massif_plasticity_paths', collect_massif_plasticity_paths)]
   suites = [suites, new_testsuite('massif_plasticity_fe', collect_massif_plasticity_fe)]
   suites = [suites, new_testsuite('pecjoin_modjoin', collect_pecjoin_modjoin)]
   suites = [suites, new_testsuite('pecjoin_modjoin_paths', collect_pecjoin_modjoin_paths)]
   suites = [suites, new_testsuite('pecjoin_modjoin_fe', collect_pecjoin_modjoin_fe)]
   suites = [suites, new_testsuite('pecjoin_modjoin_cyclic', collect_pecjoin_modjoin_cyclic)]
   suites = [suites, new_testsuite('advise', collect_advise)]
   suites = [suites, new_testsuite('refine', collect_refine)]
   suites = [suites, new_testsuite('pecjoin_katona', collect_pecjoin_katona)]
   suites = [suites, new_testsuite('pecjoin_katona_friction', collect_pecjoin_katona_friction)]
   suites = [suites, new_testsuite('pecjoin_claims', collect_pecjoin_claims)]
   suites = [suites, new_testsuite('pecjoin_identify', collect_pecjoin_identify)]
   suites = [suites, new_testsuite('pecjoin_sensitivity', collect_pecjoin_sensitivity)]
   suites = [suites, new_testsuite('pecjoin_identify_roundtrip', collect_pecjoin_identify_roundtrip)]
   suites = [suites, new_testsuite('driver_nonlinear', collect_driver_nonlinear)]
   suites = [suites, new_testsuite('massif_collapse', collect_massif_collapse)]
   suites = [suites, new_testsuite('massif_q8r', collect_massif_q8r)]
   suites = [suites, new_testsuite('driver_sanity', collect_driver_sanity)]
   suites = [suites, new_testsuite('linalg_threads', collect_linalg_threads)]
   suites = [suites, new_testsuite('linalg_blas_core', collect_linalg_blas_core)]
   suites = [suites, new_testsuite('io_deck_trust', collect_io_deck_trust)]
   suites = [suites, new_testsuite('io_deck_user', collect_io_deck_user)]
   suites = [suites, new_testsuite('solve_progress', collect_solve_progress)]
   suites = [suites, new_testsuite('driver_estimator', collect_estimator)]
   suites = [suites, new_testsuite('model_units', collect_model_units)]
   suites = [suites, new_testsuite('refine_local', collect_refine_local)]
   suites = [suites, new_testsuite('adapt', collect_adapt)]
   suites = [suites, new_testsuite('linalg_mumps', collect_linalg_mumps)]
   suites = [suites, new_testsuite('fe_share', collect_fe_share)]
   suites = [suites, new_testsuite('linalg_cholmod_ordering', collect_linalg_cholmod_ordering)]
   suites = [suites, new_testsuite('io_deck_mesh_lines', collect_io_deck_mesh_lines)]
   suites = [suites, new_testsuite('io_results_copies', collect_io_results_copies)]
   suites = [suites, new_testsuite('io_results_checksum', collect_io_results_checksum)]
   suites = [suites, new_testsuite('io_results_phases', collect_io_results_phases)]
   suites = [suites, new_testsuite('massif_kernels', collect_massif_kernels)]
   suites = [suites, new_testsuite('linalg_omp_serial', collect_linalg_omp_serial)]
   suites = [suites, new_testsuite('cmd_args', collect_cmd_args)]
   suites = [suites, new_testsuite('plates', collect_plates)]

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
