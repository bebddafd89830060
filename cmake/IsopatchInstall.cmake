# Install rules and the exported CMake package: find_package(isopatch) gives isopatch::isopatch.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS isopatch EXPORT isopatchTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The .vdb reader, loaded when a .vdb file is read (src/vdb/openvdb_loader.hpp looks in <libdir>/isopatch).
install(TARGETS isopatch_openvdb LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/isopatch)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/isopatch DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${ISOPATCH_GENERATED_INCLUDE_DIR}/isopatch/version.hpp  # generated, IsopatchVersion.cmake
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/isopatch)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/THIRD_PARTY_NOTICES.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})  # share/doc/isopatch
if(ISOPATCH_BUILD_APPS)
  install(TARGETS isopatch_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

set(ISOPATCH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/isopatch)
install(EXPORT isopatchTargets NAMESPACE isopatch:: DESTINATION ${ISOPATCH_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/isopatchConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/isopatchConfig.cmake
                              INSTALL_DESTINATION ${ISOPATCH_CMAKE_DIR})
# Before 1.0 a minor release may break the API (0.2 does not satisfy find_package(isopatch 0.1)).
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(ISOPATCH_COMPATIBILITY SameMinorVersion)
else()
  set(ISOPATCH_COMPATIBILITY SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/isopatchConfigVersion.cmake
                                 COMPATIBILITY ${ISOPATCH_COMPATIBILITY})
install(FILES ${PROJECT_BINARY_DIR}/isopatchConfig.cmake ${PROJECT_BINARY_DIR}/isopatchConfigVersion.cmake
        DESTINATION ${ISOPATCH_CMAKE_DIR})
