#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

namespace image {

// Writes `data` to `path` so that readers only ever see the old file or the
// complete new one: the bytes go to a fresh temporary file in the same
// directory (".<name>.tmp.<unique>"), which is closed and then rename()d over
// `path`. On any failure the temporary file is removed and `path` is left as it
// was.
//
// No fsync: this guards against partially written files being observed, not
// against power loss (our outputs can be re-rendered).
//
// Throws std::runtime_error (a std::system_error carrying the errno) whose
// message names the path and the strerror text.
void write_file_atomically(const std::filesystem::path& path, std::span<const uint8_t> data);

}  // namespace image
