# Finds Debian's lib3mf (package lib3mf-dev, version 1.8): the 3MF writer of src/mesh.
# Defines the imported target Lib3MF::Lib3MF. Its pkg-config file names -lzip and -lz, which the
# shared library already links itself, so the library is found directly instead.
find_path(LIB3MF_INCLUDE_DIR Model/COM/NMR_DLLInterfaces.h PATH_SUFFIXES lib3mf)
find_library(LIB3MF_LIBRARY NAMES 3MF lib3MF)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Lib3MF REQUIRED_VARS LIB3MF_LIBRARY LIB3MF_INCLUDE_DIR)
if(Lib3MF_FOUND AND NOT TARGET Lib3MF::Lib3MF)
  add_library(Lib3MF::Lib3MF UNKNOWN IMPORTED GLOBAL)  # seen by the tests too
  set_target_properties(Lib3MF::Lib3MF PROPERTIES IMPORTED_LOCATION "${LIB3MF_LIBRARY}"
                                                  INTERFACE_INCLUDE_DIRECTORIES "${LIB3MF_INCLUDE_DIR}")
endif()
mark_as_advanced(LIB3MF_INCLUDE_DIR LIB3MF_LIBRARY)
