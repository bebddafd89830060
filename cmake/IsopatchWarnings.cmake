# Per-target warning and sanitizer settings: isopatch_target_defaults(<target>)
function(isopatch_target_defaults target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  set_target_properties(${target} PROPERTIES CXX_EXTENSIONS OFF)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wcast-align -Wunused -Woverloaded-virtual -Wnull-dereference
                                           -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
  if(ISOPATCH_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(ISOPATCH_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=${ISOPATCH_SANITIZE} -fno-omit-frame-pointer
                                             -fno-sanitize-recover=all)
    target_link_options(${target} PRIVATE -fsanitize=${ISOPATCH_SANITIZE})
  endif()
endfunction()
