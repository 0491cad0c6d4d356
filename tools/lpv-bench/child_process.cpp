#include "child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace bench {
namespace {

int exit_status(int raw) { return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw); }

std::runtime_error system_error(const std::string& what) {
  return std::runtime_error(what + ": " + std::strerror(errno));
}

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& log_file, bool talk) {
  const int log = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (log < 0) throw system_error("cannot write '" + log_file.string() + "'");
  int input[2] = {-1, -1};
  int output[2] = {-1, -1};
  if (talk && (::pipe2(input, O_CLOEXEC) != 0 || ::pipe2(output, O_CLOEXEC) != 0)) {
    const std::runtime_error error = system_error("cannot make pipes");
    for (int fd : {log, input[0], input[1], output[0], output[1]})
      if (fd >= 0) ::close(fd);
    throw error;
  }
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t parent = ::getpid();
  pid_ = ::fork();
  if (pid_ == 0) {
    // In the child only async-signal-safe calls until exec; dup2 clears O_CLOEXEC on the copies.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(127);  // the parent is already gone
    if (talk) {
      ::dup2(input[0], STDIN_FILENO);
      ::dup2(output[1], STDOUT_FILENO);
    } else {
      ::dup2(log, STDOUT_FILENO);
    }
    ::dup2(log, STDERR_FILENO);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  const int fork_errno = errno;
  ::close(log);
  if (talk) {
    ::close(input[0]);
    ::close(output[1]);
    to_child_ = input[1];
    from_child_ = output[0];
  }
  if (pid_ < 0) {
    close_fd(to_child_);
    close_fd(from_child_);
    errno = fork_errno;
    throw system_error("cannot start " + argv.front());
  }
  // A child that dies leaves a closed pipe: writing to it must fail, not kill lpv-bench.
  ::signal(SIGPIPE, SIG_IGN);
}

ChildProcess::~ChildProcess() {
  close_fd(to_child_);
  if (status_ < 0) stop();
  close_fd(from_child_);
}

void ChildProcess::write_line(const std::string& line) {
  const std::string text = line + "\n";
  for (std::size_t sent = 0; sent < text.size();) {
    const ssize_t n = ::write(to_child_, text.data() + sent, text.size() - sent);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw system_error("cannot write to the child process");
    sent += std::size_t(n);
  }
}

std::string ChildProcess::read_line(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (const auto end = pending_.find('\n'); end != std::string::npos) {
      std::string line = pending_.substr(0, end);
      pending_.erase(0, end + 1);
      return line;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) throw std::runtime_error("no answer within " + std::to_string(timeout.count() / 1000) + " s");
    pollfd readable{from_child_, POLLIN, 0};
    const int ready = ::poll(&readable, 1, int(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) throw system_error("cannot wait for the child process");
    if (ready == 0) continue;
    char buffer[65536];
    const ssize_t n = ::read(from_child_, buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("the child process closed its output");
    pending_.append(buffer, std::size_t(n));
  }
}

void ChildProcess::close_input() { close_fd(to_child_); }

int ChildProcess::wait() {
  if (status_ >= 0) return status_;
  int raw = 0;
  while (::waitpid(pid_, &raw, 0) < 0 && errno == EINTR) {
  }
  status_ = exit_status(raw);
  return status_;
}

bool ChildProcess::running() {
  if (status_ >= 0) return false;
  int raw = 0;
  if (::waitpid(pid_, &raw, WNOHANG) != pid_) return true;
  status_ = exit_status(raw);
  return false;
}

bool ChildProcess::exits_within(std::chrono::milliseconds time) {
  const auto until = std::chrono::steady_clock::now() + time;
  while (running() && std::chrono::steady_clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  return !running();
}

int ChildProcess::stop(std::chrono::milliseconds patience, std::chrono::milliseconds grace) {
  if (exits_within(patience)) return status_;
  ::kill(pid_, SIGTERM);
  if (!exits_within(grace)) ::kill(pid_, SIGKILL);
  return wait();
}

TemporaryLog::TemporaryLog(const std::string& prefix) {
  std::string name = "/tmp/" + prefix + "-XXXXXX";
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw system_error("cannot create a log file in /tmp");
  ::close(fd);
  path_ = name;
}

TemporaryLog::~TemporaryLog() {
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

std::string TemporaryLog::tail(std::size_t max_bytes) const {
  std::ifstream in(path_, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return text.size() > max_bytes ? "..." + text.substr(text.size() - max_bytes) : text;
}

}  // namespace bench
