# Builds each include probe of tests/layers/CMakeLists.txt and checks the outcome: a header of
# a layer above must not be found, a library's own header must compile. Run by CTest
# `layers_enforced`:
#   cmake -DBUILD_DIR=<build> -DCOMPILER=<c++> -DPROBES=<target|library|header|expect,...> -P ...

cmake_minimum_required(VERSION 3.25)

# The probes build in the tree they were configured in, through its include roots. Skipped
# only where that tree has moved (its include roots are links that no longer reach the
# sources) or there is no compiler: include roots that are missing are a broken build, which
# the probes report (the controls fail).
set(root_link "${BUILD_DIR}/include_roots/lpv_scene/scene")
if(NOT EXISTS "${COMPILER}" OR (IS_SYMLINK "${root_link}" AND NOT EXISTS "${root_link}/scene.hpp"))
  message("layers_enforced: skipped: no compiler at ${COMPILER}, or the include roots of ${BUILD_DIR} do not "
          "reach the sources (a build moved elsewhere, as a portable bundle is)")
  return()
endif()

string(REPLACE "," ";" probes "${PROBES}")
set(failures "")
foreach(probe IN LISTS probes)
  string(REPLACE "|" ";" fields "${probe}")
  list(GET fields 0 target)
  list(GET fields 1 library)
  list(GET fields 2 header)
  list(GET fields 3 expect)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${target}
                  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  # GCC: "fatal error: x.hpp: No such file or directory"; clang: "'x.hpp' file not found".
  string(REGEX REPLACE "([.+])" "[\\1]" header_pattern "${header}")
  set(not_found FALSE)
  if(output MATCHES "${header_pattern}'?:? (No such file or directory|file not found)")
    set(not_found TRUE)
  endif()
  if(expect STREQUAL "climbs")
    if(status EQUAL 0 OR NOT not_found)
      list(APPEND failures "${library} reached ${header}, a layer above it (probe ${target}):\n${output}")
    else()
      message(STATUS "refused: ${library} -> ${header}")
    endif()
  elseif(NOT status EQUAL 0)
    list(APPEND failures "${library} could not compile its own ${header} (probe ${target}):\n${output}")
  else()
    message(STATUS "compiles: ${library} -> ${header}")
  endif()
endforeach()

if(failures)
  string(REPLACE ";" "\n" text "${failures}")
  message(FATAL_ERROR "${text}")
endif()
