#include "server/durable_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>
#include <utility>
#include <vector>

namespace server {
namespace {

constexpr std::string_view kTemporaryPrefix = ".partial-";

[[noreturn]] void fail(const std::string& what, const std::string& name) {
  throw std::system_error(errno, std::generic_category(), what + " " + name);
}

// Closes the descriptor on every path out, the error paths included.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }
  // close() reports write-back errors of some file systems: checked, not ignored.
  int close() { return ::close(std::exchange(fd_, -1)); }

 private:
  int fd_;
};

void sync_directory(const std::filesystem::path& directory) {
  FileDescriptor fd(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() < 0 || ::fsync(fd.get()) != 0) fail("flushing the directory of", directory.filename().string());
}

void write_all(int fd, std::string_view bytes, const std::string& name) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) fail("writing", name);
    bytes.remove_prefix(std::size_t(written));
  }
}

}  // namespace

void write_file_durably(const std::filesystem::path& directory, const std::string& name, std::string_view bytes) {
  std::string temporary = (directory / (std::string(kTemporaryPrefix) + "XXXXXX")).string();
  std::vector<char> pattern(temporary.begin(), temporary.end());
  pattern.push_back('\0');
  FileDescriptor fd(::mkostemp(pattern.data(), O_CLOEXEC));
  if (fd.get() < 0) fail("creating a temporary file for", name);
  temporary = pattern.data();
  try {
    write_all(fd.get(), bytes, name);
    if (::fsync(fd.get()) != 0) fail("flushing", name);
    if (fd.close() != 0) fail("closing", name);
    if (::rename(temporary.c_str(), (directory / name).c_str()) != 0) fail("renaming into place", name);
  } catch (...) {
    ::unlink(temporary.c_str());
    throw;
  }
  sync_directory(directory);
}

void remove_file_durably(const std::filesystem::path& directory, const std::string& name) {
  if (::unlink((directory / name).c_str()) != 0 && errno != ENOENT) fail("removing", name);
  sync_directory(directory);
}

bool older_than(const std::filesystem::path& file, std::filesystem::file_time_type::duration age) {
  std::error_code ec;
  const auto written = std::filesystem::last_write_time(file, ec);
  return !ec && std::filesystem::file_time_type::clock::now() - written > age;
}

std::size_t remove_temporary_files(const std::filesystem::path& directory,
                                   std::filesystem::file_time_type::duration age) {
  std::vector<std::filesystem::path> leftovers;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    if (entry.path().filename().string().starts_with(kTemporaryPrefix) && older_than(entry.path(), age))
      leftovers.push_back(entry.path());
  for (const auto& path : leftovers) std::filesystem::remove(path);
  if (!leftovers.empty()) sync_directory(directory);
  return leftovers.size();
}

}  // namespace server
