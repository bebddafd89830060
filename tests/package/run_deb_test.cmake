# Script mode: build the Debian package with CPack from a configured and built tree, check its control
# data (name, version, architecture, the dependencies dpkg-shlibdeps found and the Python ones declared),
# unpack it into a scratch root (no installation, no root) and run what it installed: the tool meshes the
# torus, the Python package imports with the tool's version, `man -l` shows the page and the bash
# completion completes a subcommand and an option.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${CPACK_COMMAND} -G DEB --config ${ISOPATCH_BINARY_DIR}/CPackConfig.cmake -B ${WORK_DIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cpack failed (${rc}): ${out}${err}")
endif()
set(deb ${WORK_DIR}/isopatch_${VERSION}_amd64.deb)
if(NOT EXISTS ${deb})
  file(GLOB made ${WORK_DIR}/*.deb)
  message(FATAL_ERROR "no ${deb} (made: ${made})")
endif()

function(check_contains text what)
  string(FIND "${text}" "${what}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "expected '${what}' in:\n${text}")
  endif()
endfunction()

execute_process(COMMAND dpkg-deb --info ${deb} RESULT_VARIABLE rc OUTPUT_VARIABLE info)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "dpkg-deb --info failed (${rc})")
endif()
message(STATUS "${info}")
foreach(field "Package: isopatch" "Version: ${VERSION}" "Architecture: amd64" "libtbb12" "zlib1g" "libc6"
              "python3-numpy" "python3 (>= 3.11)" "libopenvdb")  # libopenvdb: the .vdb plugin's
  check_contains("${info}" "${field}")
endforeach()
# The writers are isopatch's own (3MF through zlib): the readers the tests use are not dependencies.
foreach(absent "lib3mf" "libtinygltf")
  string(FIND "${info}" "${absent}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "'${absent}' should not be a dependency:\n${info}")
  endif()
endforeach()

set(root ${WORK_DIR}/root)
execute_process(COMMAND dpkg-deb -x ${deb} ${root} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "dpkg-deb -x failed (${rc})")
endif()
foreach(file usr/bin/isopatch usr/include/isopatch/isopatch.hpp usr/include/isopatch/version.hpp
             usr/lib/libisopatch.a usr/lib/cmake/isopatch/isopatchConfig.cmake
             usr/lib/python3/dist-packages/isopatch/__init__.py usr/share/man/man1/isopatch.1
             usr/lib/isopatch/isopatch_openvdb.so usr/lib/python3/dist-packages/isopatch/isopatch_openvdb.so
             usr/share/bash-completion/completions/isopatch usr/share/doc/isopatch/LICENSE)
  if(NOT EXISTS ${root}/${file})
    message(FATAL_ERROR "the package has no /${file}")
  endif()
endforeach()

execute_process(COMMAND ${root}/usr/bin/isopatch --version RESULT_VARIABLE rc OUTPUT_VARIABLE version)
check_contains("${version}" "${VERSION}")
execute_process(COMMAND ${root}/usr/bin/isopatch mesh torus --edge-length 0.1 -q -o ${WORK_DIR}/torus.ply
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK_DIR}/torus.ply)
  message(FATAL_ERROR "the installed tool did not mesh the torus (${rc}): ${err}")
endif()
execute_process(COMMAND ${root}/usr/bin/isopatch analyze ${WORK_DIR}/torus.ply RESULT_VARIABLE rc OUTPUT_VARIABLE report)
check_contains("${report}" "watertight yes")

execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${root}/usr/lib/python3/dist-packages
                        ${PYTHON} -c "import isopatch; print(isopatch.__version__, isopatch.__file__)"
                RESULT_VARIABLE rc OUTPUT_VARIABLE imported ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed Python package does not import (${rc}): ${err}")
endif()
check_contains("${imported}" "${VERSION} ${root}/usr/lib/python3/dist-packages/isopatch/")

execute_process(COMMAND man -l ${root}/usr/share/man/man1/isopatch.1 RESULT_VARIABLE rc OUTPUT_VARIABLE page
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "man -l failed (${rc}): ${err}")
endif()
foreach(word "ISOPATCH(1)" "SYNOPSIS" "--edge-length" "--split" "analyze" "EXIT STATUS")
  check_contains("${page}" "${word}")
endforeach()

execute_process(
  COMMAND bash -c "source '${root}/usr/share/bash-completion/completions/isopatch'; COMP_WORDS=(isopatch me); COMP_CWORD=1; _isopatch; echo \"\${COMPREPLY[*]}\"; COMP_WORDS=(isopatch mesh --edge-l); COMP_CWORD=2; _isopatch; echo \"\${COMPREPLY[*]}\""
  RESULT_VARIABLE rc OUTPUT_VARIABLE completed ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the bash completion failed (${rc}): ${err}")
endif()
check_contains("${completed}" "mesh\n--edge-length")
