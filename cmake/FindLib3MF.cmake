# Finds lib3mf 1.x, the 3MF Consortium's reference library (Debian 12: lib3mf-dev), and defines
# the imported target Lib3MF::Lib3MF. The headers come from pkg-config's lib3MF.pc; the library
# is found by name, because lib3MF.pc also names -lzip and -lz while lib3mf-dev does not depend
# on libzip-dev: lib3MF.so carries its own dependency on libzip, so linking it alone is enough.
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(PC_LIB3MF QUIET lib3MF)
endif()
find_path(Lib3MF_INCLUDE_DIR NAMES Model/COM/NMR_DLLInterfaces.h
          HINTS ${PC_LIB3MF_INCLUDE_DIRS} PATH_SUFFIXES lib3mf)
find_library(Lib3MF_LIBRARY NAMES 3MF lib3MF HINTS ${PC_LIB3MF_LIBRARY_DIRS})
set(Lib3MF_VERSION ${PC_LIB3MF_VERSION})

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Lib3MF
  REQUIRED_VARS Lib3MF_LIBRARY Lib3MF_INCLUDE_DIR
  VERSION_VAR Lib3MF_VERSION
  REASON_FAILURE_MESSAGE "strata reads 3MF files through lib3mf 1.x: install Debian's lib3mf-dev (bash scripts/setup.sh does)")

if(Lib3MF_FOUND AND NOT TARGET Lib3MF::Lib3MF)
  add_library(Lib3MF::Lib3MF UNKNOWN IMPORTED)
  set_target_properties(Lib3MF::Lib3MF PROPERTIES
    IMPORTED_LOCATION ${Lib3MF_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${Lib3MF_INCLUDE_DIR})
endif()
mark_as_advanced(Lib3MF_INCLUDE_DIR Lib3MF_LIBRARY)
