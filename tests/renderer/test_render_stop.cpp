// A render asked to stop (Renderer::set_stop_check) stops at its next submission, and the
// renderer is as good as before: the next render gives the same bits as one that was never
// interrupted. The server stops with it what nobody waits for (docs/server.md, "Work model").
#include "gpu_test.hpp"

#include <cstring>

namespace {

using gpu_test::GpuTest;

class RenderStop : public GpuTest {};

api::RenderRequest long_request() {
  api::RenderRequest r;
  r.output.width = r.output.height = 64;
  r.output.format = api::ImageFormat::pfm;
  r.plan = api::PlanMode::exact;  // no convergence: propagation is chunked for the stop check alone
  r.lpv.iterations = 40;
  r.lpv.transfer = api::Transfer::sharpened;  // propagation's chunks
  r.repeat = 3;
  return r;
}

TEST_F(RenderStop, StopsAtTheNextSubmissionAndLeavesTheRendererWhole) {
  auto& r = gpu_test::renderer();
  const renderer::RenderResult before = r.render(long_request());
  ASSERT_FALSE(before.linear.pixels.empty());
  // Count the submissions of a whole render, then stop one at each of a few points: within
  // the first frame's propagation, and at a later frame.
  int submissions = 0;
  r.set_stop_check([&] {
    ++submissions;
    return false;
  });
  const renderer::RenderResult counted = r.render(long_request());
  // 40 steps in chunks of 4: 10 submissions, where plan exact made one before.
  EXPECT_GE(submissions, 3 * (10 + 4)) << "passes and propagation chunks of 3 frames";
  for (const int stop_at : {3, 8, submissions / 2, submissions}) {
    SCOPED_TRACE(stop_at);
    int asked = 0;
    r.set_stop_check([&] { return ++asked >= stop_at; });
    EXPECT_THROW(r.render(long_request()), renderer::RenderStopped);
    EXPECT_EQ(asked, stop_at) << "no submission after the stop";
  }
  r.set_stop_check({});
  const renderer::RenderResult after = r.render(long_request());
  ASSERT_EQ(after.linear.pixels.size(), before.linear.pixels.size());
  EXPECT_EQ(std::memcmp(after.linear.pixels.data(), before.linear.pixels.data(), before.linear.pixels.size() * 4), 0);
  EXPECT_EQ(std::memcmp(counted.linear.pixels.data(), before.linear.pixels.data(), before.linear.pixels.size() * 4),
            0)
      << "propagation in chunks gives the same bits as in one submission";
}

}  // namespace
