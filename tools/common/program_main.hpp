// The one error ladder of lpv-render, lpv-bench and lpv-server: a program's body runs inside
// run_program, and whatever escapes it becomes "NAME: message" on standard error and an exit
// status every program shares (0 done, 1 failure, 2 bad usage or bad input; a program may
// give its own input errors another).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace tools {

inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

// The command line asks for what the program cannot do: the message, then `hint` (a pointer
// to --help, or the usage itself), exit 2.
class UsageError : public std::runtime_error {
 public:
  UsageError(const std::string& message, std::string hint) : std::runtime_error(message), hint_(std::move(hint)) {}
  const std::string& hint() const { return hint_; }

 private:
  std::string hint_;
};

// Input the program cannot use (a file, a suite, a scene): the message, exit `status`.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message, int status = kExitBadInput)
      : std::runtime_error(message), status_(status) {}
  int status() const { return status_; }

 private:
  int status_;
};

// Runs `body` and returns its status; a UsageError, an api::RequestError ("bad request: ..."),
// an InputError or any other std::exception (1) is reported on standard error as above.
int run_program(const char* name, const std::function<int()>& body);

}  // namespace tools
