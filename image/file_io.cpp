#include "image/file_io.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <string>
#include <system_error>

namespace image {
namespace {

[[noreturn]] void throw_errno(int err, const std::string& what, const std::filesystem::path& path) {
  // std::system_error is a std::runtime_error; what() becomes
  // "write_file_atomically: <what> '<path>': <strerror(err)>".
  throw std::system_error(err, std::generic_category(),
                          "write_file_atomically: " + what + " '" + path.string() + "'");
}

// A name unique within this process (counter) and unlikely to clash with other
// processes (pid, time); O_EXCL catches the rest.
std::string temp_suffix() {
  static std::atomic<uint64_t> counter{0};
  const auto ticks = static_cast<uint64_t>(
      std::chrono::steady_clock::now().time_since_epoch().count());
  return ".tmp." + std::to_string(::getpid()) + "." +
         std::to_string(counter.fetch_add(1, std::memory_order_relaxed)) + "." +
         std::to_string(ticks % 1000000007u);
}

// RAII for the temporary file: closes the descriptor and unlinks the file
// unless released after a successful rename.
class TempFile {
 public:
  explicit TempFile(const std::filesystem::path& target) {
    // Shorten very long names so the suffix cannot push us past NAME_MAX.
    std::string name = target.filename().string();
    if (name.size() > 180) name.resize(180);
    const std::filesystem::path dir = target.parent_path();
    for (int attempt = 0;; ++attempt) {
      path_ = dir / ("." + name + temp_suffix());
      // 0666 & ~umask: the final file gets the same permissions as a file
      // created by open(path, O_CREAT) would.
      fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd_ >= 0) return;
      const int err = errno;
      if (err == EINTR || (err == EEXIST && attempt < 100)) continue;
      throw_errno(err, "cannot create temporary file for", target);
    }
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!path_.empty()) ::unlink(path_.c_str());
  }

  int fd() const { return fd_; }
  const std::filesystem::path& path() const { return path_; }

  // Closes the descriptor; returns 0 or the errno of close().
  int close() {
    const int rc = ::close(fd_);
    fd_ = -1;
    // On Linux the descriptor is released even if close() fails (EINTR included),
    // so never retry; an error still means the data may not have been written.
    return rc == 0 ? 0 : errno;
  }

  // The file was renamed to its final name; nothing to clean up.
  void release() { path_.clear(); }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::span<const uint8_t> data) {
  if (path.empty() || !path.has_filename()) {
    throw std::system_error(EINVAL, std::generic_category(),
                            "write_file_atomically: invalid target path '" + path.string() + "'");
  }
  TempFile tmp(path);

  const uint8_t* p = data.data();
  size_t left = data.size();
  while (left > 0) {
    const ssize_t n = ::write(tmp.fd(), p, left);
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;  // write() returning 0 would loop forever
      if (err == EINTR) continue;
      throw_errno(err, "cannot write temporary file for", path);
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
  if (const int err = tmp.close(); err != 0) {
    throw_errno(err, "cannot close temporary file for", path);
  }
  if (::rename(tmp.path().c_str(), path.c_str()) != 0) {
    const int err = errno;
    throw_errno(err, "cannot rename temporary file to", path);
  }
  tmp.release();
}

}  // namespace image
