// The suite loops on fake runners: what renders when, in which order, and what a failure or
// a missing round-trip runner does to the results.
#include "lab/bench/suite_runner.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace {

// Renders nothing; logs "NAME:image:CASE" and "NAME:time:CASE", and fails the case named
// `failing` on its second timed render.
class FakeRunner : public bench::CaseRunner {
 public:
  FakeRunner(std::string name, double ms, std::vector<std::string>& log, std::string failing = "")
      : name_(std::move(name)), ms_(ms), log_(log), failing_(std::move(failing)) {}

  api::BenchDevice device() override { return {"fake " + name_, "none"}; }
  bench::Measurement render_timed(const api::BenchCase& c) override {
    log_.push_back(name_ + ":time:" + c.name);
    if (c.name == failing_ && ++failing_renders_ == 2) throw std::runtime_error("device lost");
    return {{"gpu_ms", ms_}, {"wall_ms", ms_ + 1.0}};
  }
  api::BenchImage render_image(const api::BenchCase& c) override {
    log_.push_back(name_ + ":image:" + c.name);
    return {std::string(64, '0'), 8, 8, 8, 8, ""};
  }

 private:
  std::string name_;
  double ms_;
  std::vector<std::string>& log_;
  std::string failing_;
  int failing_renders_ = 0;
};

api::BenchSuite suite() {
  api::BenchSuite s;
  s.name = "fake";
  s.version = 4;
  s.cases = {{"one", api::BenchCaseKind::render, {}, {}},
             {"trip", api::BenchCaseKind::server_round_trip, {}, {}},
             {"two", api::BenchCaseKind::render, {}, {}}};
  return s;
}

TEST(BenchRunner, ImageThenWarmUpThenRepetitionsPerCase) {
  std::vector<std::string> log;
  FakeRunner runner("A", 5.0, log);
  std::size_t last_done = 0, total = 0;
  bench::RunObserver observer;
  observer.progress = [&](std::size_t done, std::size_t all, const api::BenchCase&) {
    EXPECT_EQ(done, last_done + 1);
    last_done = done;
    total = all;
  };
  const api::BenchResults r = bench::run_suite(suite(), {&runner, nullptr, "no server"}, {3, 1}, observer);
  EXPECT_EQ(log, (std::vector<std::string>{"A:image:one", "A:time:one", "A:time:one", "A:time:one", "A:time:one",
                                           "A:image:two", "A:time:two", "A:time:two", "A:time:two", "A:time:two"}));
  EXPECT_EQ(total, 15u);  // 3 cases x (image + 1 warm-up + 3 repetitions)
  EXPECT_EQ(last_done, total);
  EXPECT_EQ(r.suite, "fake");
  EXPECT_EQ(r.suite_version, 4u);
  EXPECT_EQ(r.device.name, "fake A");
  EXPECT_TRUE(r.complete);
  ASSERT_EQ(r.cases.size(), 3u);
  EXPECT_EQ(r.cases[0].metrics[0].samples, (std::vector<double>{5.0, 5.0, 5.0}));
  EXPECT_TRUE(r.cases[0].image);
  EXPECT_EQ(r.cases[1].status, api::BenchCaseStatus::skipped);
  EXPECT_EQ(r.cases[1].reason, "no server");
}

TEST(BenchRunner, PairedSidesTakeTurnsInAlternatingOrder) {
  std::vector<std::string> log;
  FakeRunner a("A", 5.0, log);
  FakeRunner b("B", 6.0, log);
  const auto [ra, rb] = bench::run_suite_paired(suite(), {&a, &a, ""}, {&b, &b, ""}, {2, 1});
  const std::vector<std::string> first_case(log.begin(), log.begin() + 8);
  EXPECT_EQ(first_case, (std::vector<std::string>{"A:image:one", "B:image:one", "B:time:one", "A:time:one",
                                                  "A:time:one", "B:time:one", "B:time:one", "A:time:one"}));
  EXPECT_EQ(ra.cases[2].metrics[0].samples, (std::vector<double>{5.0, 5.0}));
  EXPECT_EQ(rb.cases[2].metrics[0].samples, (std::vector<double>{6.0, 6.0}));
  EXPECT_EQ(rb.device.name, "fake B");
}

TEST(BenchRunner, AFailureFailsThatCaseOnThatSideOnly) {
  std::vector<std::string> log;
  FakeRunner a("A", 5.0, log);
  FakeRunner b("B", 6.0, log, "one");
  const auto [ra, rb] = bench::run_suite_paired(suite(), {&a, &a, ""}, {&b, &b, ""}, {3, 0});
  EXPECT_EQ(ra.cases[0].status, api::BenchCaseStatus::ok);
  EXPECT_EQ(ra.cases[0].metrics[0].samples.size(), 3u);
  EXPECT_EQ(rb.cases[0].status, api::BenchCaseStatus::failed);
  EXPECT_EQ(rb.cases[0].reason, "device lost");
  EXPECT_TRUE(rb.cases[0].metrics.empty());  // no half-measured case
  EXPECT_EQ(rb.cases[2].status, api::BenchCaseStatus::ok);  // the next case runs again
  EXPECT_EQ(std::count(log.begin(), log.end(), "B:time:one"), 2);  // not asked again after failing
}

TEST(BenchRunner, AStopEndsTheRunBetweenRenders) {
  std::vector<std::string> log;
  FakeRunner runner("A", 5.0, log);
  bench::RunObserver observer;
  observer.stop_requested = [&] { return log.size() >= 7; };
  const api::BenchResults r = bench::run_suite(suite(), {&runner, &runner, ""}, {3, 1}, observer);
  EXPECT_FALSE(r.complete);
  ASSERT_EQ(r.cases.size(), 1u);  // the case in progress is dropped
  EXPECT_EQ(log.size(), 7u);
}

}  // namespace
