// The programs' one error ladder (tools/common/program_main.hpp): what each kind of error
// prints and the status it exits with.
#include "tools/common/program_main.hpp"

#include "api/request_error.hpp"

#include <gtest/gtest.h>

namespace {

// The status and what went to standard error.
std::pair<int, std::string> run(const std::function<int()>& body) {
  testing::internal::CaptureStderr();
  const int status = tools::run_program("prog", body);
  return {status, testing::internal::GetCapturedStderr()};
}

TEST(ProgramMain, EachKindOfErrorHasItsMessageAndStatus) {
  EXPECT_EQ(run([] { return 7; }), std::make_pair(7, std::string()));
  EXPECT_EQ(run([]() -> int { throw tools::UsageError("unknown option --x", "Try 'prog --help'.\n"); }),
            std::make_pair(2, std::string("prog: unknown option --x\nTry 'prog --help'.\n")));
  EXPECT_EQ(run([]() -> int { throw api::RequestError("output.width", "must be positive"); }),
            std::make_pair(2, std::string("prog: bad request: output.width: must be positive\n")));
  EXPECT_EQ(run([]() -> int { throw tools::InputError("scene.glb: not glTF", 3); }),
            std::make_pair(3, std::string("prog: scene.glb: not glTF\n")));
  EXPECT_EQ(run([]() -> int { throw std::runtime_error("device lost"); }),
            std::make_pair(1, std::string("prog: device lost\n")));
}

}  // namespace
