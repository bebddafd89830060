# Runs one C++ example and checks its output (examples/cpp/CMakeLists.txt, isopatch_add_example_test):
#   cmake -DEXAMPLE=<program> -DARGS=<a|b|...> -DEXPECT=<name=lo..hi|...> [-DPLY=<file> -DMIN_VERTICES=<n>]
#         -P check_example.cmake
# Fails unless the program exits 0, prints "name: value" with lo <= value <= hi for every EXPECT entry,
# and (with PLY) writes that PLY file with at least MIN_VERTICES vertices.
string(REPLACE "|" ";" args "${ARGS}")
string(REPLACE "|" ";" expect "${EXPECT}")
if(PLY)
  file(REMOVE "${PLY}")  # the file checked must be this run's
endif()

execute_process(COMMAND "${EXAMPLE}" ${args} RESULT_VARIABLE result OUTPUT_VARIABLE output
                ERROR_VARIABLE errors)
message("${output}${errors}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the example failed (exit status ${result})")
endif()

set(failures "")
foreach(entry IN LISTS expect)
  if(NOT entry MATCHES "^([^=]+)=([-+0-9.eE]+)\\.\\.([-+0-9.eE]+)$")
    message(FATAL_ERROR "bad EXPECT entry '${entry}' (name=lo..hi)")
  endif()
  set(name "${CMAKE_MATCH_1}")
  set(lo "${CMAKE_MATCH_2}")
  set(hi "${CMAKE_MATCH_3}")
  if(NOT output MATCHES "(^|\n)${name}: ([^\n]*)")
    list(APPEND failures "'${name}' not printed")
    continue()
  endif()
  set(value "${CMAKE_MATCH_2}")  # before another MATCHES resets CMAKE_MATCH_<n>
  if(NOT value MATCHES "^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$")
    list(APPEND failures "${name} is '${value}', not a number")
  elseif(value LESS lo OR value GREATER hi)
    list(APPEND failures "${name} is ${value}, outside [${lo}, ${hi}]")
  endif()
endforeach()

if(PLY)
  if(NOT EXISTS "${PLY}")
    list(APPEND failures "${PLY} was not written")
  else()
    file(READ "${PLY}" header LIMIT 1024)  # the PLY header is ASCII, whatever the body's encoding
    if(NOT header MATCHES "^ply\n" OR NOT header MATCHES "\nelement vertex ([0-9]+)\n")
      list(APPEND failures "${PLY} has no PLY header with a vertex count")
    elseif(CMAKE_MATCH_1 LESS MIN_VERTICES)  # CMAKE_MATCH_1: of the last MATCHES, the vertex count
      list(APPEND failures "${PLY} has ${CMAKE_MATCH_1} vertices, fewer than ${MIN_VERTICES}")
    endif()
  endif()
endif()

if(failures)
  list(JOIN failures "\n  " failures)
  message(FATAL_ERROR "the example's output is wrong:\n  ${failures}")
endif()
