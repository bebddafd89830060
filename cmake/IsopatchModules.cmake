# The layers of the library as CMake targets (docs/architecture.md, "Layers and targets").
#
# isopatch_module(<name> [PUBLIC <module>...] [PRIVATE <module>...] [HEADERS <header>...])
#   Called at the top of src/<name>/CMakeLists.txt. Creates the OBJECT library isopatch_<name>
#   (alias isopatch::<name>); the module then lists its sources with target_sources(). PUBLIC names
#   the modules its headers (src/<name>/*.hpp and its public headers) include, PRIVATE those only its
#   .cpp files include; each must be a module defined earlier (src/CMakeLists.txt adds them bottom-up),
#   so the graph cannot have a cycle. HEADERS are the public headers in include/isopatch/ the module
#   owns; every public header has exactly one owner (isopatch_check_public_headers()).
#
# Enforcement: the module gets its own include root <build>/layers/<name>/ holding symbolic links
#   <name>/            -> src/<name>/
#   isopatch/<header>  -> include/isopatch/<header>   (only the headers it owns)
# which is its one INTERFACE include directory. A module's sources therefore see exactly the roots of
# itself and of the modules it links (transitively through PUBLIC links, as CMake propagates usage
# requirements), in both spellings ("surface/sampler.hpp" and <isopatch/surface.hpp>); anything else
# is "No such file or directory". src/ and include/ themselves are never on a module's include path.

set(ISOPATCH_LAYER_DIR ${PROJECT_BINARY_DIR}/layers)

function(isopatch_module name)
  cmake_parse_arguments(ARG "" "" "PUBLIC;PRIVATE;HEADERS" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "isopatch_module(${name}): unexpected arguments ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  set(target isopatch_${name})
  foreach(dep IN LISTS ARG_PUBLIC ARG_PRIVATE)
    if(NOT TARGET isopatch_${dep})
      message(FATAL_ERROR "isopatch module '${name}' uses '${dep}', which is not a module defined before "
                          "it: a module may use only modules below it (the list in src/CMakeLists.txt)")
    endif()
  endforeach()

  add_library(${target} OBJECT)
  add_library(isopatch::${name} ALIAS ${target})
  isopatch_target_defaults(${target})
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)

  # The include root: links to this module's folder and to the public headers it owns, rebuilt at
  # every configure so that a header given away or a module removed leaves no stale link behind.
  set(root ${ISOPATCH_LAYER_DIR}/${name})
  file(GLOB old_links LIST_DIRECTORIES true ${root}/* ${root}/isopatch/*)
  foreach(link IN LISTS old_links)
    if(IS_SYMLINK ${link})
      file(REMOVE ${link})  # the link only, never what it points to
    endif()
  endforeach()
  file(MAKE_DIRECTORY ${root}/isopatch)
  file(CREATE_LINK ${CMAKE_CURRENT_SOURCE_DIR} ${root}/${name} SYMBOLIC)
  foreach(header IN LISTS ARG_HEADERS)
    set(file ${PROJECT_SOURCE_DIR}/include/isopatch/${header})
    if(NOT EXISTS ${file})
      message(FATAL_ERROR "isopatch module '${name}' owns include/isopatch/${header}, which does not exist")
    endif()
    get_property(owner GLOBAL PROPERTY ISOPATCH_OWNER_${header})
    if(owner)
      message(FATAL_ERROR "include/isopatch/${header} is owned by two modules, '${owner}' and '${name}': "
                          "give it to one (HEADERS of isopatch_module in src/<module>/CMakeLists.txt)")
    endif()
    set_property(GLOBAL PROPERTY ISOPATCH_OWNER_${header} ${name})
    file(CREATE_LINK ${file} ${root}/isopatch/${header} SYMBOLIC)
  endforeach()
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${root}>)

  list(TRANSFORM ARG_PUBLIC PREPEND isopatch_)
  list(TRANSFORM ARG_PRIVATE PREPEND isopatch_)
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC} Eigen3::Eigen Threads::Threads TBB::tbb PRIVATE ${ARG_PRIVATE})
  set_property(GLOBAL APPEND PROPERTY ISOPATCH_MODULES ${name})
  set_target_properties(${target} PROPERTIES ISOPATCH_HEADERS "${ARG_HEADERS}")
endfunction()

# Fails the configure step unless every header in include/isopatch/ has an owner (two owners already
# failed in isopatch_module) and every folder of src/ is a module.
function(isopatch_check_public_headers)
  file(GLOB headers CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR}/include/isopatch
       ${PROJECT_SOURCE_DIR}/include/isopatch/*)
  set(orphans "")
  foreach(header IN LISTS headers)
    get_property(owner GLOBAL PROPERTY ISOPATCH_OWNER_${header})
    if(NOT owner)
      list(APPEND orphans include/isopatch/${header})
    endif()
  endforeach()
  if(orphans)
    list(JOIN orphans ", " orphans)
    message(FATAL_ERROR "public headers owned by no module: ${orphans}. Add each to the HEADERS of "
                        "isopatch_module() in the CMakeLists.txt of the module that implements it.")
  endif()
  get_property(modules GLOBAL PROPERTY ISOPATCH_MODULES)
  file(GLOB folders LIST_DIRECTORIES true RELATIVE ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/src/*)
  foreach(folder IN LISTS folders)
    if(IS_DIRECTORY ${PROJECT_SOURCE_DIR}/src/${folder} AND NOT folder IN_LIST modules)
      message(FATAL_ERROR "src/${folder}/ is not a module: add it to the list in src/CMakeLists.txt")
    endif()
  endforeach()
endfunction()
