# Finds Debian's OpenVDB (package libopenvdb-dev, version 10): the .vdb reader of src/vdb.
# Defines the imported target OpenVDB::openvdb. Debian's own FindOpenVDB.cmake brings its own FindTBB
# and Blosc modules, which would shadow oneTBB's CMake package; the shared library links those itself,
# so it is found directly (its headers need Imath, TBB and Boost headers, all dependencies of the -dev package).
find_path(OPENVDB_INCLUDE_DIR openvdb/openvdb.h)
find_library(OPENVDB_LIBRARY NAMES openvdb)
# Imath: OpenVDB's headers instantiate its half-float type, so its users link it too.
find_library(OPENVDB_IMATH_LIBRARY NAMES Imath-3_1 Imath)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenVDBLibrary REQUIRED_VARS OPENVDB_LIBRARY OPENVDB_IMATH_LIBRARY OPENVDB_INCLUDE_DIR)
if(OpenVDBLibrary_FOUND AND NOT TARGET OpenVDB::openvdb)
  add_library(OpenVDB::openvdb UNKNOWN IMPORTED GLOBAL)  # seen by the tests and fuzzers too
  set_target_properties(OpenVDB::openvdb PROPERTIES IMPORTED_LOCATION "${OPENVDB_LIBRARY}"
                                                    INTERFACE_INCLUDE_DIRECTORIES "${OPENVDB_INCLUDE_DIR}"
                                                    INTERFACE_LINK_LIBRARIES "${OPENVDB_IMATH_LIBRARY};TBB::tbb")
endif()
mark_as_advanced(OPENVDB_INCLUDE_DIR OPENVDB_LIBRARY OPENVDB_IMATH_LIBRARY)
