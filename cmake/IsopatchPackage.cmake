# The manual page and the bash completion (generated from the tool's own --help at build time), and the
# Debian package: `cpack -G DEB` (or `cmake --build BUILD --target package`) in a built tree makes
# isopatch_VERSION_amd64.deb with the tool, the static library, its headers and CMake package, the Python
# package where Debian's python3 looks (/usr/lib/python3/dist-packages), the manual page and the bash
# completion; the libraries it links are found by dpkg-shlibdeps, the Python ones declared.
include(GNUInstallDirs)

# Not in a sanitized build (the tool would run under the sanitizers at build time; it is not packaged).
if(TARGET isopatch_cli AND NOT ISOPATCH_SANITIZE)
  set(python ${Python_EXECUTABLE})
  if(NOT python)
    set(python /usr/bin/python3)
  endif()
  set(share ${PROJECT_BINARY_DIR}/share)
  set(manual ${share}/man/man1/isopatch.1)
  set(completion ${share}/bash-completion/completions/isopatch)
  add_custom_command(OUTPUT ${manual} ${completion}
                     COMMAND ${CMAKE_COMMAND} -E make_directory ${share}/man/man1 ${share}/bash-completion/completions
                     COMMAND ${python} ${PROJECT_SOURCE_DIR}/scripts/man_page.py $<TARGET_FILE:isopatch_cli> ${manual}
                     COMMAND ${python} ${PROJECT_SOURCE_DIR}/scripts/bash_completion.py $<TARGET_FILE:isopatch_cli>
                             ${completion}
                     DEPENDS isopatch_cli ${PROJECT_SOURCE_DIR}/scripts/man_page.py
                             ${PROJECT_SOURCE_DIR}/scripts/bash_completion.py
                     COMMENT "The manual page and the bash completion from isopatch --help" VERBATIM)
  add_custom_target(isopatch_manual ALL DEPENDS ${manual} ${completion})
  install(FILES ${manual} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  install(FILES ${completion} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME isopatch)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "isopatch maintainers <maintainers@isopatch.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "good-quality triangle meshes of smooth implicit surfaces")
# The long description under the summary (CPack indents its lines).
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "Turns implicit surfaces f(x,y,z) = 0 (formulas, catalogue surfaces, sampled
volumes, composite surfaces) into meshes of nearly equilateral triangles with
almost every vertex of valence 6 and every vertex on the surface. Contains the
command-line tool, the C++ library with its headers and CMake package, and the
Python package.")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The Python package's own needs (the compiled module is for this interpreter's version); a consumer of
# the library needs the development packages of what the static library links.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3 (>= 3.11), python3 (<< 3.12), python3-numpy")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-distributed")  # isopatch.distributed
# python3-openvdb: mesh_volume() of pyopenvdb grid objects; the -dev packages: a C++ consumer of the library.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS
    "python3-openvdb, libeigen3-dev, libtbb-dev, zlib1g-dev, libopenvdb-dev")
# Everything installed by default, and the Python package's copy for the Debian layout (component deb).
set(CPACK_INSTALL_CMAKE_PROJECTS "${PROJECT_BINARY_DIR};isopatch;ALL;/;${PROJECT_BINARY_DIR};isopatch;deb;/")
include(CPack)
