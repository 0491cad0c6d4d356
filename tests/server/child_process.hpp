// A program the HTTP tests run beside them (lpv-server, HAProxy): started with its output
// in a log file, stopped by a signal, killed at the end if it still runs.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace server_test {

class ChildProcess {
 public:
  // Runs argv[0] (a path) with `argv`; its standard output and error go to a log file.
  explicit ChildProcess(std::vector<std::string> argv);
  ~ChildProcess();  // SIGKILL if it still runs
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  // Sends `signal` and waits up to `timeout` for the exit; returns the exit status, or
  // -1 when it did not exit normally in time.
  int stop(int signal, std::chrono::seconds timeout = std::chrono::seconds(30));
  bool running();
  std::string log() const;  // its standard output and error so far

 private:
  std::filesystem::path log_file_;
  pid_t pid_ = -1;
  bool reaped_ = false;
  int exit_status_ = -1;  // once reaped: the exit code, or -1 when killed by a signal
};

}  // namespace server_test
