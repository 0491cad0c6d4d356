// tiny_gltf.h with this project's configuration: every file that includes tinygltf includes
// it through here, so all see the same declarations. No built-in file access, image decoding
// or writing: the loader reads files through its own callbacks, confined to one directory,
// and decodes images itself (image_decode.hpp).
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_FS
#include <tiny_gltf.h>
