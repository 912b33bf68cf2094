!> Bad decks (test/data/decks/bad_*.inp, one error each): each must fail with an input
!> error naming the file that holds the faulty line (the include file when inside one),
!> its line number (0 for what is missing from the whole deck), the keyword in force, and
!> the key words of the message, each checked on its own.
module test_io_deck_errors
   use pecplas_error, only: error_t, ERR_INPUT
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_model, only: model_t
   use pecplas_testing, only: unittest_t, new_unittest, check
   use test_io_deck, only: DECKS
   implicit none (type, external)
   private
   public :: collect_io_deck_errors

   !> One bad deck and what its error must say.
   type :: bad_case_t
      character(len=40) :: deck = '', file = '', keyword = ''
      integer :: line = 0
      character(len=48) :: words(3) = ''
   end type bad_case_t

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

   pure function bad(deck, line, keyword, w1, w2, w3, file) result(c)
      character(len=*), intent(in) :: deck, keyword, w1
      integer, intent(in) :: line
      character(len=*), intent(in), optional :: w2, w3, file
      type(bad_case_t) :: c
      c%deck = 'bad_'//deck//'.inp'
      c%file = c%deck
      if (present(file)) c%file = file
      c%line = line
      c%keyword = keyword
      c%words(1) = w1
      if (present(w2)) c%words(2) = w2
      if (present(w3)) c%words(3) = w3
   end function bad

   !> Reads each deck and checks kind, file, line, keyword and every word.
   subroutine run_cases(cases, error)
      type(bad_case_t), intent(in) :: cases(:)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(model_t) :: model
      character(len=16) :: buf
      integer :: i, j
      do i = 1, size(cases)
         associate (c => cases(i), what => trim(cases(i)%deck)//': ')
            call read_deck(DECKS//trim(c%deck), model, e)
            call check(error, allocated(e), what//'no error reported')
            if (allocated(error)) return
            call check(error, e%kind == ERR_INPUT, what//'not an input error: '//e%text())
            if (allocated(error)) return
            call check(error, allocated(e%file), what//'no file in: '//e%text())
            if (allocated(error)) return
            call check(error, ends_with(e%file, '/'//trim(c%file)), what//'file should be '// &
               trim(c%file)//': '//e%text())
            if (allocated(error)) return
            write (buf, '(i0)') c%line
            call check(error, e%line == c%line, what//'line should be '//trim(buf)//': '// &
               e%text())
            if (allocated(error)) return
            if (c%line > 0) then
               call check(error, index(e%text(), trim(c%file)//':'//trim(buf)//': ') > 0, &
                  what//'text should name file:line: '//e%text())
               if (allocated(error)) return
            end if
            call check(error, e%keyword == trim(c%keyword), what//'keyword should be '// &
               trim(c%keyword)//': '//e%text())
            if (allocated(error)) return
            do j = 1, size(c%words)
               if (len_trim(c%words(j)) == 0) cycle
               call check(error, index(e%message, trim(c%words(j))) > 0, what//'message '// &
                  'lacks "'//trim(c%words(j))//'": '//e%text())
               if (allocated(error)) return
            end do
         end associate
      end do
   end subroutine run_cases

   pure logical function ends_with(s, tail)
      character(len=*), intent(in) :: s, tail
      ends_with = .false.
      if (len(s) >= len(tail)) ends_with = s(len(s) - len(tail) + 1:) == tail
   end function ends_with

   subroutine test_syntax(error)
      type(error_t), allocatable, intent(out) :: error
      call run_cases([ &
         bad('unknown_keyword', 14, '*BOUNDRY', "unknown keyword '*BOUNDRY'", &
         'known keywords:', '*BOUNDARY'), &
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
      call run_cases([ &
         bad('too_few_fields', 5, '*NODES', 'too few fields', '"id, x, y"', 'found 2'), &
         bad('bad_number_exp', 5, '*NODES', 'expected y as a number', "'2.0e'"), &
         bad('bad_number_abc', 10, '*MATERIAL', 'expected E as a number', "'abc'"), &
         bad('missing_material_value', 10, '*MATERIAL', 'missing value for NU'), &
         bad('bad_dof', 15, '*BOUNDARY', "bad dof '3'", 'X Y R Z XY ALL'), &
         bad('bad_dof_word', 17, '*LOAD', "bad dof 'XZ'")], error)
   end subroutine test_numbers

   subroutine test_mesh(error)
      type(error_t), allocatable, intent(out) :: error
      call run_cases([ &
         bad('wrong_node_count', 8, '*ELEMENTS', 'wrong number of nodes for a Q4', &
         '(4 nodes)', 'found 3'), &
         bad('unknown_element_type', 7, '*ELEMENTS', "unknown element type 'Q9'", &
         'T3 T6 Q4 Q8'), &
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
      call run_cases([ &
         bad('undefined_node', 8, '*ELEMENTS', 'undefined node 5', 'in element 1'), &
         bad('undefined_eset', 11, '*SECTION', "undefined element set 'clay'", &
         'known element sets: soil'), &
         bad('undefined_nset', 15, '*BOUNDARY', "undefined node set 'bottom'", &
         'known node sets: base'), &
         bad('undefined_edge_set', 19, '*LOAD', "undefined edge set 'top'", &
         'known edge sets: (none)'), &
         bad('undefined_material', 11, '*SECTION', "undefined material 'clay'", &
         'known materials: sand'), &
         bad('undefined_pattern', 19, '*STEP', "undefined load pattern 'pull'", &
         'known patterns: push')], error)
   end subroutine test_references

   subroutine test_materials(error)
      type(error_t), allocatable, intent(out) :: error
      call run_cases([ &
         bad('negative_e', 10, '*MATERIAL', 'Young modulus E must be positive', '-1.0'), &
         bad('nu_half', 10, '*MATERIAL', 'Poisson ratio NU', '-1 < NU < 0.5', '0.5000'), &
         bad('nu_minus_one', 10, '*MATERIAL', 'Poisson ratio NU', '-1.0000'), &
         bad('unknown_material_type', 9, '*MATERIAL', "unknown material type 'MOHR'", &
         'known types: ELASTIC'), &
         bad('unknown_material_key', 10, '*MATERIAL', 'unknown parameter NUU', &
         'known parameters: E NU GAMMA'), &
         bad('duplicate_material', 11, '*MATERIAL', "material 'SAND' is defined twice", &
         'bad_duplicate_material.inp:9'), &
         bad('no_section', 7, '*ELEMENTS', "element set 'soil' has no material", &
         '*SECTION, SET=soil')], error)
   end subroutine test_materials

   subroutine test_steps(error)
      type(error_t), allocatable, intent(out) :: error
      call run_cases([ &
         bad('empty_step', 18, '*STEP', "empty step 's1'", 'pattern, target_factor'), &
         bad('increments_zero', 18, '*STEP', 'INCREMENTS must be >= 1', 'found 0'), &
         bad('duplicate_pattern', 18, '*LOAD', "load pattern 'Push' is defined twice", &
         'bad_duplicate_pattern.inp:16')], error)
   end subroutine test_steps

   subroutine test_includes(error)
      type(error_t), allocatable, intent(out) :: error
      call run_cases([ &
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
      call run_cases([ &
         bad('no_nodes', 0, '*NODES', 'no nodes'), &
         bad('no_elements', 0, '*ELEMENTS', 'no elements'), &
         bad('no_step', 0, '*STEP', 'no *STEP')], error)
   end subroutine test_missing_parts

end module test_io_deck_errors
