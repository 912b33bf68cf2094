!> Bad decks (test/data/decks/bad_*.inp, one error each): each must fail with an input
!> error naming the file that holds the faulty line (the include file when inside one),
!> its line number (0 for what is missing from the whole deck), the keyword in force, and
!> the key words of the message, each checked on its own.
module test_io_deck_errors
   use pecplas_base_error, only: error_t
   use pecplas_testing, only: unittest_t, new_unittest
   use test_io_deck, only: DECKS
   use fixtures_bad_decks, only: bad_case_t, bad, run_bad_cases
   implicit none (type, external)
   private
   public :: collect_io_deck_errors

   !> One bad deck and what its error must say.

contains

   subroutine collect_io_deck_errors(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('syntax', test_syntax), &
               new_unittest('numbers_and_fields', test_numbers), &
               new_unittest('mesh', test_mesh), &
               new_unittest('references', test_references), &
               new_unittest('materials', test_materials), &
               new_unittest('steps', test_steps), &
               new_unittest('includes', test_includes), &
               new_unittest('missing_parts', test_missing_parts)]
   end subroutine collect_io_deck_errors

   subroutine test_syntax(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DECKS, [ &
         bad('unknown_keyword', 14, '*BOUNDRY', "unknown keyword '*BOUNDRY'", &
         'known keywords:', '(did you mean *BOUNDARY?)'), &
         bad('unknown_parameter', 7, '*ELEMENTS', 'unknown parameter MATERIAL', &
         'known parameters: TYPE SET'), &
         bad('missing_set', 7, '*ELEMENTS', 'missing required parameter SET='), &
         bad('missing_type', 16, '*LOAD', 'missing required parameter TYPE='), &
         bad('missing_name', 12, '*NSET', 'missing required parameter NAME='), &
         bad('missing_value', 7, '*ELEMENTS', 'missing value for TYPE='), &
         bad('duplicate_parameter', 7, '*ELEMENTS', 'parameter SET given twice'), &
         bad('data_before_keyword', 2, '', 'data line before the first keyword', "'1, 0, 0'"), &
         bad('section_with_data', 12, '*SECTION', '*SECTION takes no data lines', "'soil, sand'"), &
         bad('thickness_axisym', 2, '*ANALYSIS', 'THICKNESS is only for PLANE_STRAIN')], error)
   end subroutine test_syntax

   subroutine test_numbers(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DECKS, [ &
         bad('too_few_fields', 5, '*NODES', 'too few fields', '"id, x, y"', 'found 2'), &
         bad('bad_number_exp', 5, '*NODES', 'expected y as a number', "'2.0e'"), &
         bad('bad_number_abc', 10, '*MATERIAL', 'expected E as a number', "'abc'"), &
         bad('missing_material_value', 10, '*MATERIAL', 'missing value for NU'), &
         bad('bad_dof', 15, '*BOUNDARY', "bad dof '4'", 'X Y R Z ROT XY ALL'), &
         bad('bad_dof_word', 17, '*LOAD', "bad dof 'XZ'")], error)
   end subroutine test_numbers

   subroutine test_mesh(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DECKS, [ &
         bad('wrong_node_count', 8, '*ELEMENTS', 'wrong number of nodes for a Q4', &
         '(4 nodes)', 'found 3'), &
         bad('unknown_element_type', 7, '*ELEMENTS', "unknown element type 'Q9'", &
         'T3 T6 Q4 Q8'), &
         bad('abaqus_element', 7, '*ELEMENTS', "unknown element type 'CPE4'", &
         '(Abaqus CPE4 is Q4 here', 'known types: T3 T6 Q4 Q8'), &
         bad('duplicate_node', 6, '*NODES', 'duplicate node id 2', &
         'bad_duplicate_node.inp:4'), &
         bad('duplicate_element', 11, '*ELEMENTS', 'duplicate element id 1', &
         'bad_duplicate_element.inp:10'), &
         bad('mixed_types', 9, '*ELEMENTS', 'already holds Q4 elements', 'cannot add T3'), &
         bad('degenerate_element', 10, '*ELEMENTS', 'element 1 is degenerate', 'zero area'), &
         bad('missing_mesh', 7, '*MESH', 'cannot read mesh file', 'nowhere.msh'), &
         bad('mesh_node_clash', 7, '*MESH', 'node id 1 is defined twice'), &
         bad('edge_not_a_side', 14, '*EDGES', "edge set 'diag'", 'not a side of any element'), &
         bad('mixed_edges', 16, '*EDGES', "edge set 'lid' mixes 2-node and 3-node edges")], &
         error)
   end subroutine test_mesh

   subroutine test_references(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DECKS, [ &
         bad('undefined_node', 8, '*ELEMENTS', 'undefined node 5', 'in element 1'), &
         bad('undefined_eset', 11, '*SECTION', "undefined element set 'clay'", &
         'known element sets: soil'), &
         bad('undefined_nset', 15, '*BOUNDARY', "undefined node set 'bottom'", &
         'known node sets: base'), &
         bad('misspelt_nset', 15, '*BOUNDARY', "undefined node set 'bsae'", &
         "(did you mean base?); known node sets: base"), &
         bad('undefined_edge_set', 19, '*LOAD', "undefined edge set 'top'", &
         'known edge sets: (none)'), &
         bad('undefined_material', 11, '*SECTION', "undefined material 'clay'", &
         'known materials: sand'), &
         bad('undefined_pattern', 19, '*STEP', "undefined load pattern 'pull'", &
         'known patterns: push')], error)
   end subroutine test_references

   subroutine test_materials(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DECKS, [ &
         bad('negative_e', 10, '*MATERIAL', 'Young modulus E must be positive', '-1.0'), &
         bad('nu_half', 10, '*MATERIAL', 'Poisson ratio NU', '-1 < NU < 0.5', '0.5000'), &
         bad('nu_minus_one', 10, '*MATERIAL', 'Poisson ratio NU', '-1.0000'), &
         bad('unknown_material_type', 9, '*MATERIAL', "unknown material type 'MOHR'", &
         'known types: ELASTIC', '(did you mean MOHR_COULOMB?)'), &
         bad('unknown_material_key', 10, '*MATERIAL', 'unknown parameter NUU', &
         'known parameters: E NU GAMMA;', &
         'water parameters: GAMMA_UNSAT GAMMA_SAT KW_N CU CU_INC CU_YREF'), &
         bad('unknown_water_key', 10, '*MATERIAL', 'unknown parameter KWN', &
         'known parameters: E NU C PHI PSI GAMMA TENSION;', &
         'water parameters: GAMMA_UNSAT GAMMA_SAT KW_N CU CU_INC CU_YREF'), &
         bad('misspelt_water_key', 10, '*MATERIAL', 'unknown parameter GAMA_SAT', &
         '(did you mean GAMMA_SAT?)', 'water parameters: GAMMA_UNSAT GAMMA_SAT'), &
         bad('unknown_material_key', 10, '*MATERIAL', 'unknown parameter NUU', &
         '(did you mean NU?)'), &
         bad('duplicate_material', 11, '*MATERIAL', "material 'SAND' is defined twice", &
         'bad_duplicate_material.inp:9'), &
         bad('no_section', 7, '*ELEMENTS', "element set 'soil' has no material", &
         '*SECTION, SET=soil')], error)
   end subroutine test_materials

   subroutine test_steps(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DECKS, [ &
         bad('increments_zero', 18, '*STEP', 'INCREMENTS must be >= 1', 'found 0'), &
         bad('duplicate_pattern', 18, '*LOAD', "load pattern 'Push' is defined twice", &
         'bad_duplicate_pattern.inp:16')], error)
   end subroutine test_steps

   subroutine test_includes(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DECKS, [ &
         bad('missing_file', 14, '*INCLUDE', 'missing required parameter FILE='), &
         bad('missing_include', 8, '*INCLUDE', 'cannot read include file', &
         'inc/nowhere.inp'), &
         bad('recursive_include', 4, '*INCLUDE', 'recursive include', 'inc/rec_a.inp', &
         'rec_b.inp', file='inc/rec_b.inp'), &
         bad('error_in_include', 3, '*NODES', 'expected y as a number', "'x'", &
         file='inc/bad_nodes.inp')], error)
   end subroutine test_includes

   subroutine test_missing_parts(error)
      type(error_t), allocatable, intent(out) :: error
      call run_bad_cases(DECKS, [ &
         bad('no_nodes', 0, '*NODES', 'no nodes'), &
         bad('empty_deck', 0, '*NODES', 'the deck is empty', 'complete example of doc/deck.md'), &
         bad('no_elements', 0, '*ELEMENTS', 'no elements'), &
         bad('no_step', 0, '*STEP', 'no *STEP')], error)
   end subroutine test_missing_parts

end module test_io_deck_errors
