# FindSuiteSparse: the parts of SuiteSparse that PECPLAS binds (CHOLMOD, UMFPACK) and their
# common config library. Debian puts the headers in /usr/include/suitesparse; other installs
# put them in <prefix>/include or <prefix>/include/suitesparse. Hint with SuiteSparse_ROOT.
#   SuiteSparse_INCLUDE_DIRS  the header directory and its parent (both include spellings work)
#   SuiteSparse_LIBRARIES     umfpack, cholmod, suitesparseconfig
find_path(SuiteSparse_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_path(SuiteSparse_UMFPACK_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse)
find_library(SuiteSparse_CHOLMOD_LIBRARY cholmod)
find_library(SuiteSparse_UMFPACK_LIBRARY umfpack)
find_library(SuiteSparse_CONFIG_LIBRARY suitesparseconfig)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse
  REQUIRED_VARS SuiteSparse_CHOLMOD_LIBRARY SuiteSparse_UMFPACK_LIBRARY
                SuiteSparse_CONFIG_LIBRARY SuiteSparse_CHOLMOD_INCLUDE_DIR
                SuiteSparse_UMFPACK_INCLUDE_DIR)

if(SuiteSparse_FOUND)
  get_filename_component(_ss_parent "${SuiteSparse_CHOLMOD_INCLUDE_DIR}" DIRECTORY)
  set(SuiteSparse_INCLUDE_DIRS
    "${SuiteSparse_CHOLMOD_INCLUDE_DIR}" "${SuiteSparse_UMFPACK_INCLUDE_DIR}" "${_ss_parent}")
  list(REMOVE_DUPLICATES SuiteSparse_INCLUDE_DIRS)
  set(SuiteSparse_LIBRARIES "${SuiteSparse_UMFPACK_LIBRARY}" "${SuiteSparse_CHOLMOD_LIBRARY}"
    "${SuiteSparse_CONFIG_LIBRARY}")
  unset(_ss_parent)
endif()
mark_as_advanced(SuiteSparse_CHOLMOD_INCLUDE_DIR SuiteSparse_UMFPACK_INCLUDE_DIR
  SuiteSparse_CHOLMOD_LIBRARY SuiteSparse_UMFPACK_LIBRARY SuiteSparse_CONFIG_LIBRARY)
