// What a glTF file declares about itself, read before tinygltf parses it: its version and the
// extensions it requires. A file this loader cannot read for one of those reasons is refused
// as unsupported, naming the reason, rather than with the first error tinygltf meets on the
// way (a glTF 1.0 file's objects where 2.0 has arrays; a Draco mesh's accessors with no
// buffer view).
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace scene::gltf {

// Extensions whose meaning the renderer implements; any other required one is refused.
bool supported_extension(const std::string& name);

// Throws LoadError (unsupported) for a glTF version other than 2 (a missing "asset" is
// glTF 1.0, which did not require it) and for a required extension the renderer does not
// implement. Returns without a word when the JSON cannot be read or these fields are
// malformed: tinygltf says what is wrong then.
void check_declarations(std::span<const std::uint8_t> bytes);

}  // namespace scene::gltf
