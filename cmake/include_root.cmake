# Each library's headers are found from an include root of its own, which holds only that
# library's folder: lpv_scene's root has `scene/` and nothing else, so "scene/scene.hpp"
# resolves in a target only if it links lpv_scene (directly or through a library that does).
# A layer that reaches up to a library it does not link fails to build, naming the header.
# (With the repository root as everyone's include path, any file could include any header.)
#
# The root is a folder in the build tree whose one entry is a symbolic link to the source
# folder, so the sources keep their place and their paths ("scene/scene.hpp").

# lpv_include_root(<target> <folder> [INTERFACE]): <folder> is a repository path
# ("scene", "lab/bench", "shaders/shared"); its headers become <target>'s public headers.
function(lpv_include_root target folder)
  set(root ${PROJECT_BINARY_DIR}/include_roots/${target})
  get_filename_component(parent ${root}/${folder} DIRECTORY)
  file(MAKE_DIRECTORY ${parent})
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${root}/${folder} SYMBOLIC)
  if(ARGV2 STREQUAL "INTERFACE")
    target_include_directories(${target} INTERFACE ${root})
  else()
    target_include_directories(${target} PUBLIC ${root})
  endif()
endfunction()
