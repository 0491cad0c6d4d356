// Files that a crash leaves either whole or absent: written to a temporary file in the same
// directory, flushed to disk, renamed over the final name, and the directory flushed so the
// rename itself is on disk. Temporary files carry a prefix so leftovers can be found.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace server {

// Writes `bytes` as directory/name, replacing any file of that name. Throws
// std::system_error naming the step and the file (not the directory) when it fails.
void write_file_durably(const std::filesystem::path& directory, const std::string& name, std::string_view bytes);

// Removes directory/name, if it exists, and flushes the directory.
void remove_file_durably(const std::filesystem::path& directory, const std::string& name);

// Removes the temporary files of writes a crash interrupted, those last written more than
// `older_than` ago (younger ones may be another process's writes in progress); returns how
// many.
std::size_t remove_temporary_files(const std::filesystem::path& directory,
                                   std::filesystem::file_time_type::duration older_than);

// True when the file was last written more than `age` ago (false when it cannot be read).
bool older_than(const std::filesystem::path& file, std::filesystem::file_time_type::duration age);

}  // namespace server
