// lpv-bench run --jobs N on fake runners: the cases spread over the runners at once, each case
// whole on one runner, and the results are a serial run's: the same cases in the suite's order
// with the same images and sample counts.
#include "lab/bench/suite_fan_out.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

namespace {

// Takes 5 ms a render; its image names the case; remembers which runner rendered what, and
// how many renders ran at once at most over all runners.
class SlowFakeRunner : public bench::CaseRunner {
 public:
  struct Shared {
    std::atomic<int> in_flight{0}, most_in_flight{0};
    std::mutex mutex;
    std::map<std::string, std::set<std::string>> rendered_by;  // case -> runners
  };
  SlowFakeRunner(std::string name, Shared& shared, bool broken_device = false)
      : name_(std::move(name)), shared_(shared), broken_device_(broken_device) {}

  api::BenchDevice device() override {
    if (broken_device_) throw std::runtime_error("GET /v1/device: connection refused");
    return {"fake", "none"};
  }
  bench::Measurement render_timed(const api::BenchCase& c) override {
    render(c);
    return {{"gpu_ms", 5.0}};
  }
  api::BenchImage render_image(const api::BenchCase& c) override {
    render(c);
    return {c.name, 8, 8, 8, 8, ""};
  }

 private:
  void render(const api::BenchCase& c) {
    const int now = ++shared_.in_flight;
    for (int most = shared_.most_in_flight; now > most && !shared_.most_in_flight.compare_exchange_weak(most, now);) {
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    --shared_.in_flight;
    std::lock_guard lock(shared_.mutex);
    shared_.rendered_by[c.name].insert(name_);
  }

  std::string name_;
  Shared& shared_;
  bool broken_device_;
};

api::BenchSuite six_cases() {
  api::BenchSuite s;
  s.name = "fan";
  for (const char* name : {"a", "b", "c", "d", "e", "f"}) s.cases.push_back({name, api::BenchCaseKind::render, {}, {}});
  return s;
}

std::vector<std::string> names_of(const api::BenchResults& r) {
  std::vector<std::string> names;
  for (const auto& c : r.cases) names.push_back(c.name);
  return names;
}

TEST(BenchFanOut, CasesRunAtOnceEachWholeOnOneRunnerAndComeBackInTheSuitesOrder) {
  SlowFakeRunner::Shared shared, serial_shared;
  SlowFakeRunner x("x", shared), y("y", shared), z("z", shared), serial("s", serial_shared);
  std::size_t last_done = 0, total = 0;
  bench::RunObserver observer;
  observer.progress = [&](std::size_t done, std::size_t all, const api::BenchCase&) {
    EXPECT_EQ(done, last_done + 1);  // one call per render, from one thread at a time
    last_done = done;
    total = all;
  };
  const api::BenchResults fanned =
      bench::run_suite_fanned(six_cases(), {{&x, &x, ""}, {&y, &y, ""}, {&z, &z, ""}}, {3, 1}, observer);
  const api::BenchResults alone = bench::run_suite(six_cases(), {&serial, &serial, ""}, {3, 1});

  EXPECT_GE(shared.most_in_flight.load(), 2) << "the runners rendered at once";
  EXPECT_EQ(serial_shared.most_in_flight.load(), 1);
  EXPECT_EQ(total, 6u * 5u);
  EXPECT_EQ(last_done, total);
  for (const auto& [name, runners] : shared.rendered_by) EXPECT_EQ(runners.size(), 1u) << name << " on one runner";
  EXPECT_TRUE(fanned.complete);
  EXPECT_EQ(names_of(fanned), names_of(alone));
  for (std::size_t i = 0; i < alone.cases.size(); ++i) {
    ASSERT_TRUE(fanned.cases[i].image && alone.cases[i].image);
    EXPECT_EQ(fanned.cases[i].image->sha256, alone.cases[i].image->sha256);
    EXPECT_EQ(fanned.cases[i].metrics[0].samples.size(), 3u);
  }
  ASSERT_TRUE(fanned.noise);
  EXPECT_EQ(fanned.noise->probe_ms.size(), 6u * 5u) << "every case's probes";
}

TEST(BenchFanOut, ARunnerThatCannotStartStopsTheRunWithItsError) {
  SlowFakeRunner::Shared shared;
  SlowFakeRunner good("good", shared), broken("broken", shared, true);
  EXPECT_THROW(bench::run_suite_fanned(six_cases(), {{&good, &good, ""}, {&broken, &broken, ""}}, {1, 0}),
               std::runtime_error);
}

TEST(BenchFanOut, AStopKeepsTheCasesBeforeTheFirstUnfinishedOne) {
  SlowFakeRunner::Shared shared;
  SlowFakeRunner x("x", shared), y("y", shared);
  std::atomic<int> asked{0};
  bench::RunObserver observer;
  observer.stop_requested = [&] { return ++asked > 9; };  // a few renders in
  const api::BenchResults r = bench::run_suite_fanned(six_cases(), {{&x, &x, ""}, {&y, &y, ""}}, {3, 0}, observer);
  EXPECT_FALSE(r.complete);
  EXPECT_LT(r.cases.size(), 6u);
  for (std::size_t i = 0; i < r.cases.size(); ++i) EXPECT_EQ(r.cases[i].name, std::string(1, char('a' + i)));
}

}  // namespace
