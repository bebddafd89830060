# The HTML API reference of the public headers (include/isopatch/*.hpp and the generated version.hpp),
# made by Doxygen with docs/Doxyfile.in: target isopatch_api_docs, output <build>/docs/api/html/
# (index.html is docs/api.md). Any Doxygen warning fails it (WARN_AS_ERROR = FAIL_ON_WARNINGS). The
# target is not part of ALL; the test docs.api_reference (label "docs") builds it, so the test suite
# checks that the reference builds without warnings. Without Doxygen 1.9.4 or later (Debian's
# doxygen, scripts/install-deps.sh) there is neither target nor test.
option(ISOPATCH_BUILD_DOCS "Build the API reference with Doxygen (target isopatch_api_docs)"
       ${PROJECT_IS_TOP_LEVEL})
if(NOT ISOPATCH_BUILD_DOCS)
  return()
endif()
find_package(Doxygen 1.9.4 QUIET)
if(NOT DOXYGEN_FOUND)
  message(STATUS "isopatch: no Doxygen 1.9.4 or later found, so no isopatch_api_docs target")
  return()
endif()

set(ISOPATCH_API_DOCS_DIR ${PROJECT_BINARY_DIR}/docs/api)
configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${PROJECT_BINARY_DIR}/docs/Doxyfile @ONLY)
file(GLOB isopatch_public_headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/include/isopatch/*.hpp)
set(isopatch_api_docs_stamp ${ISOPATCH_API_DOCS_DIR}/isopatch_api_docs.stamp)
# The old pages go first (a removed header leaves none behind); the stamp is written only when Doxygen
# succeeds, so a failed run is repeated by the next build.
add_custom_command(
  OUTPUT ${isopatch_api_docs_stamp} ${ISOPATCH_API_DOCS_DIR}/html/index.html
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${ISOPATCH_API_DOCS_DIR}/html ${isopatch_api_docs_stamp}
  COMMAND Doxygen::doxygen ${PROJECT_BINARY_DIR}/docs/Doxyfile
  COMMAND ${CMAKE_COMMAND} -E touch ${isopatch_api_docs_stamp}
  DEPENDS ${isopatch_public_headers} ${ISOPATCH_GENERATED_INCLUDE_DIR}/isopatch/version.hpp
          ${PROJECT_SOURCE_DIR}/docs/api.md ${PROJECT_BINARY_DIR}/docs/Doxyfile
  WORKING_DIRECTORY ${PROJECT_BINARY_DIR}/docs
  COMMENT "Doxygen: the API reference into docs/api/html"
  VERBATIM)
add_custom_target(isopatch_api_docs DEPENDS ${isopatch_api_docs_stamp})

if(ISOPATCH_BUILD_TESTS)
  add_test(NAME docs.api_reference
           COMMAND ${CMAKE_COMMAND} --build ${PROJECT_BINARY_DIR} --config $<CONFIG>
                   --target isopatch_api_docs)
  # It runs the build tool in the project's build tree: one build tool at a time (as tests/layers).
  set_tests_properties(docs.api_reference PROPERTIES LABELS docs RESOURCE_LOCK isopatch_build_tree
                                                     TIMEOUT 300)
endif()
