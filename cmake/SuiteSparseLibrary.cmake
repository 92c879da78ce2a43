# emb_find_suitesparse_library(NAME header library): one SuiteSparse library (Debian
# libsuitesparse-dev) as the imported target NAME::NAME, with suitesparseconfig; sets NAME_FOUND.
# A macro so that find_package_handle_standard_args sets its variables in the Find module.
include(FindPackageHandleStandardArgs)
macro(emb_find_suitesparse_library name header library)
  find_path(${name}_INCLUDE_DIR ${header} PATH_SUFFIXES suitesparse)
  find_library(${name}_LIBRARY ${library})
  find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig)
  find_package_handle_standard_args(${name} REQUIRED_VARS ${name}_INCLUDE_DIR ${name}_LIBRARY
                                    SUITESPARSECONFIG_LIBRARY)
  if(${name}_FOUND AND NOT TARGET ${name}::${name})
    add_library(${name}::${name} UNKNOWN IMPORTED)
    set_target_properties(${name}::${name} PROPERTIES
      IMPORTED_LOCATION "${${name}_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${${name}_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES "${SUITESPARSECONFIG_LIBRARY}")
  endif()
endmacro()
