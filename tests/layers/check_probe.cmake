# Script mode (tests/layers/CMakeLists.txt): builds OK_TARGET, which must succeed, then BAD_TARGET,
# which must fail because FORBIDDEN is not found on the include path of src/MODULE/.
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY_DIR} --target ${OK_TARGET}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the probe of src/${MODULE}/ without the forbidden include does not build, so the "
                      "check below would prove nothing:\n${out}")
endif()
message(STATUS "${OK_TARGET}: builds")

execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY_DIR} --target ${BAD_TARGET}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc EQUAL 0)
  message(FATAL_ERROR "src/${MODULE}/ can include ${FORBIDDEN}: the layer is not enforced")
endif()
# g++: "x.hpp: No such file or directory"; clang++: "'x.hpp' file not found".
string(FIND "${out}" "${FORBIDDEN}: No such file or directory" gcc_pos)
string(FIND "${out}" "'${FORBIDDEN}' file not found" clang_pos)
if(gcc_pos EQUAL -1 AND clang_pos EQUAL -1)
  message(FATAL_ERROR "${BAD_TARGET} failed, but not because ${FORBIDDEN} is out of reach:\n${out}")
endif()
string(REGEX MATCH "[^\n]*${FORBIDDEN}[^\n]*(No such file or directory|file not found)" line "${out}")
message(STATUS "${BAD_TARGET}: fails as it should: ${line}")
