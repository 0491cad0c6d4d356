// Other programs lpv-bench runs: the builds of an A/B comparison (as workers it talks to
// through their standard input and output), and the lpv-server of the round-trip cases.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace bench {

class ChildProcess {
 public:
  // Starts argv[0] (a path) with `argv`, its standard error going to `log_file`, and its
  // standard output too unless `talk` (then write_line and read_line reach its standard
  // input and output). The child is sent SIGTERM should lpv-bench die first. Throws
  // std::runtime_error.
  ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& log_file, bool talk = false);
  ~ChildProcess();  // stop() unless it exited
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // A line to its standard input ('\n' added), and the next line of its standard output
  // (without '\n'); both throw std::runtime_error when the child has gone or, reading, when
  // nothing came within `timeout`.
  void write_line(const std::string& line);
  std::string read_line(std::chrono::milliseconds timeout);
  // Closes its standard input: a worker's sign to exit.
  void close_input();

  // Its exit status (128 + the signal when a signal ended it); waits for it.
  int wait();
  // Gives it `patience` to exit by itself, then sends SIGTERM, then SIGKILL if it has not
  // exited within `grace`; its exit status.
  int stop(std::chrono::milliseconds patience = std::chrono::milliseconds(0),
           std::chrono::milliseconds grace = std::chrono::seconds(10));
  bool running();

 private:
  bool exits_within(std::chrono::milliseconds time);

  pid_t pid_ = -1;
  int status_ = -1;  // once reaped
  int to_child_ = -1;
  int from_child_ = -1;
  std::string pending_;  // read from the child, not yet returned as a line
};

// A new empty file in /tmp for a child's output ("/tmp/PREFIX-XXXXXX"), removed with this
// object. Throws std::runtime_error.
class TemporaryLog {
 public:
  explicit TemporaryLog(const std::string& prefix);
  ~TemporaryLog();
  TemporaryLog(const TemporaryLog&) = delete;
  TemporaryLog& operator=(const TemporaryLog&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // Its last `max_bytes`, for error messages.
  std::string tail(std::size_t max_bytes = 2000) const;

 private:
  std::filesystem::path path_;
};

}  // namespace bench
