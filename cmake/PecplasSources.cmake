# Source discovery that mirrors fpm's auto-discovery, so CMake needs no edit when a helper adds
# a module, a C shim, an app or a test suite. Globs use CONFIGURE_DEPENDS: `cmake --build`
# re-globs and reconfigures by itself when files appear or vanish.

# pecplas_glob(<out> <dir> <patterns>): files below <dir> (recursively) matching any pattern.
function(pecplas_glob out dir patterns)
  set(globs "")
  foreach(pattern IN LISTS patterns)
    list(APPEND globs "${PROJECT_SOURCE_DIR}/${dir}/${pattern}")
  endforeach()
  file(GLOB_RECURSE files CONFIGURE_DEPENDS ${globs})
  list(SORT files)
  set(${out} "${files}" PARENT_SCOPE)
endfunction()

# pecplas_split_programs(<dir> <programs-out> <others-out>): Fortran files below <dir> that
# hold a main `program` (each becomes an executable) and the rest (modules they share).
function(pecplas_split_programs dir programs_out others_out)
  pecplas_glob(files ${dir} "*.f90;*.F90")
  set(programs "")
  set(others "")
  foreach(file IN LISTS files)
    file(STRINGS "${file}" hits REGEX "^[ \t]*[Pp][Rr][Oo][Gg][Rr][Aa][Mm][ \t]+[A-Za-z]")
    if(hits)
      list(APPEND programs "${file}")
    else()
      list(APPEND others "${file}")
    endif()
  endforeach()
  set(${programs_out} "${programs}" PARENT_SCOPE)
  set(${others_out} "${others}" PARENT_SCOPE)
endfunction()

# pecplas_test_suites(<driver> <out>): the suite names registered in the test driver by lines
# `new_testsuite('name', collect_name)`. Editing the driver re-runs the configure step.
function(pecplas_test_suites driver out)
  set_property(DIRECTORY "${PROJECT_SOURCE_DIR}" APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${driver}")
  file(STRINGS "${driver}" lines REGEX "^[^!]*new_testsuite[ \t]*\\([ \t]*['\"][A-Za-z0-9_]+['\"]")
  set(names "")
  foreach(line IN LISTS lines)
    string(REGEX MATCH "new_testsuite[ \t]*\\([ \t]*['\"]([A-Za-z0-9_]+)['\"]" _ "${line}")
    list(APPEND names "${CMAKE_MATCH_1}")
  endforeach()
  list(REMOVE_DUPLICATES names)
  if(NOT names)
    message(WARNING "no new_testsuite('name', ...) line found in ${driver}")
  endif()
  set(${out} "${names}" PARENT_SCOPE)
endfunction()
