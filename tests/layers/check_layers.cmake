# The layers' one-way ladder (docs/architecture.md), checked on the sources' includes: a file
# of a layer must not reach, directly or through the project's headers it includes, a layer
# above it or a Vulkan header where Vulkan must stay invisible. Fails naming the chain of
# includes. Run by CTest `layers`:  cmake -DSOURCE_DIR=<repo> -P check_layers.cmake
#
# Quoted includes are followed (resolved against the repository root, then the including
# file's folder); angle includes are leaves, of which only <vulkan/...> matters here.

cmake_minimum_required(VERSION 3.25)

if(NOT SOURCE_DIR)
  message(FATAL_ERROR "check_layers.cmake: pass -DSOURCE_DIR=<repository root>")
endif()

# Each rule: the files it covers (globs under SOURCE_DIR), then, after each @, a regular
# expression of includes (repository paths, or <...> for system headers) they must not reach.
# The build stops most climbs already (each library sees only the headers of what it links,
# cmake/include_root.cmake); this check also names the chain, and keeps Vulkan out of the
# layers that link the renderer, which the build cannot (Vulkan's headers are public there).
set(rules
  "core/*.hpp core/*.cpp@^(api|image|scene|reference|shaders|vkx|renderer|lab|server|tools|web)/@^<vulkan/"
  "api/*.hpp api/*.cpp@^(image|scene|reference|shaders|vkx|renderer|lab|server|tools|web)/@^<vulkan/"
  "shaders/shared/*.h@^(core|api|image|scene|reference|vkx|renderer|lab|server|tools|web)/"
  "image/*.hpp image/*.cpp@^(scene|reference|shaders|vkx|renderer|lab|server|tools|web)/@^<vulkan/"
  "scene/*.hpp scene/*.cpp@^(reference|vkx|renderer|lab|server|tools|web)/@^<vulkan/"
  "reference/*.hpp reference/*.cpp@^(vkx|renderer|lab|server|tools|web)/@^<vulkan/"
  "vkx/*.hpp vkx/*.cpp@^(api|image|scene|reference|shaders|renderer|lab|server|tools|web)/"
  "renderer/*.hpp renderer/*.cpp@^(reference|lab|server|tools|web)/"
  "lab/*.hpp lab/*.cpp@^(server|tools|web)/"
  "server/*.hpp server/*.cpp@^<vulkan/@^vkx/device[.]hpp$"
  "renderer/renderer.hpp@^<vulkan/@^vkx/device[.]hpp$"
)

# The includes of one repository file, as repository paths or <system> names.
function(file_includes path out)
  file(STRINGS "${SOURCE_DIR}/${path}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
  get_filename_component(folder "${path}" DIRECTORY)
  set(found "")
  foreach(line IN LISTS lines)
    if(line MATCHES "#[ \t]*include[ \t]*\"([^\"]+)\"")
      set(name "${CMAKE_MATCH_1}")
      if(EXISTS "${SOURCE_DIR}/${name}")
        list(APPEND found "${name}")
      elseif(folder AND EXISTS "${SOURCE_DIR}/${folder}/${name}")
        file(RELATIVE_PATH relative "${SOURCE_DIR}" "${SOURCE_DIR}/${folder}/${name}")
        list(APPEND found "${relative}")
      endif()  # generated headers (build folder): not the sources' layering
    elseif(line MATCHES "#[ \t]*include[ \t]*<([^>]+)>")
      list(APPEND found "<${CMAKE_MATCH_1}>")
    endif()
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

set(failures "")
set(checked 0)
foreach(rule IN LISTS rules)
  string(REPLACE "@" ";" parts "${rule}")
  list(GET parts 0 globs)
  list(SUBLIST parts 1 -1 forbidden)
  string(REPLACE " " ";" globs "${globs}")
  set(patterns "")
  foreach(g IN LISTS globs)
    list(APPEND patterns "${SOURCE_DIR}/${g}")
  endforeach()
  file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}" ${patterns})
  foreach(start IN LISTS files)
    math(EXPR checked "${checked} + 1")
    # Breadth-first over the includes, remembering how each was reached.
    set(queue "${start}")
    set(seen "${start}")
    set(via_${start} "${start}")
    while(queue)
      list(POP_FRONT queue current)
      if(current MATCHES "^<")
        continue()
      endif()
      file_includes("${current}" includes)
      foreach(included IN LISTS includes)
        if(included IN_LIST seen)
          continue()
        endif()
        list(APPEND seen "${included}")
        set(via_${included} "${via_${current}} -> ${included}")
        foreach(pattern IN LISTS forbidden)
          if(included MATCHES "${pattern}")
            list(APPEND failures "${via_${included}}")
          endif()
        endforeach()
        list(APPEND queue "${included}")
      endforeach()
    endwhile()
    foreach(name IN LISTS seen)
      unset(via_${name})
    endforeach()
  endforeach()
endforeach()

if(failures)
  list(LENGTH failures count)
  string(REPLACE ";" "\n  " text "${failures}")
  message(FATAL_ERROR "${count} include(s) climb a layer:\n  ${text}")
endif()
message(STATUS "layers: ${checked} files checked, no include climbs")
