// tinygltf compiled into this project rather than linked from Debian's shared library, so
// the sanitizer build and the fuzzer instrument the parser that reads untrusted files.
// tinygltf's writer (never called) uses <fstream> without including it when TINYGLTF_NO_FS.
#include <fstream>

#define TINYGLTF_IMPLEMENTATION
#include "scene/tinygltf_config.hpp"
