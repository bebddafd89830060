# The generated header <isopatch/version.hpp>: the version of project() (cmake/version.hpp.in) in
# ISOPATCH_GENERATED_INCLUDE_DIR. src/CMakeLists.txt puts that folder on the isopatch target's public
# include path (build tree), IsopatchInstall.cmake installs the header with the others. configure_file
# rewrites it only when the version changes, so nothing is recompiled otherwise.
if(NOT PROJECT_VERSION_PATCH MATCHES "^[0-9]+$")
  message(FATAL_ERROR "project(isopatch VERSION ...) needs major.minor.patch, got '${PROJECT_VERSION}'")
endif()
set(ISOPATCH_GENERATED_INCLUDE_DIR ${PROJECT_BINARY_DIR}/generated/include)
configure_file(${PROJECT_SOURCE_DIR}/cmake/version.hpp.in ${ISOPATCH_GENERATED_INCLUDE_DIR}/isopatch/version.hpp
               @ONLY)
