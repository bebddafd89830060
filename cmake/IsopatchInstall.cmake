# Install rules and the exported CMake package: find_package(isopatch) gives isopatch::isopatch.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS isopatch EXPORT isopatchTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/isopatch DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${ISOPATCH_GENERATED_INCLUDE_DIR}/isopatch/version.hpp  # generated, IsopatchVersion.cmake
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/isopatch)
if(ISOPATCH_BUILD_APPS)
  install(TARGETS isopatch_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

set(ISOPATCH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/isopatch)
install(EXPORT isopatchTargets NAMESPACE isopatch:: DESTINATION ${ISOPATCH_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/isopatchConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/isopatchConfig.cmake
                              INSTALL_DESTINATION ${ISOPATCH_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/isopatchConfigVersion.cmake
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/isopatchConfig.cmake ${PROJECT_BINARY_DIR}/isopatchConfigVersion.cmake
        DESTINATION ${ISOPATCH_CMAKE_DIR})
