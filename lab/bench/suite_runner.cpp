#include "lab/bench/suite_runner.hpp"

#include "api/request_json.hpp"
#include "core/utc_time.hpp"
#include "lab/bench/build_info.hpp"
#include "lab/bench/machine_noise.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace bench {
namespace {

// Thrown between renders when the observer asks to stop.
struct Stopped {};

double median_of(const nlohmann::json& summary, const std::string& what) {
  if (!summary.is_object() || !summary.contains("median") || !summary["median"].is_number())
    throw std::runtime_error("the render's stats have no " + what + " median");
  return summary["median"].get<double>();
}

void add(api::BenchCaseResult& result, const Measurement& measurement) {
  for (const auto& [name, value] : measurement) {
    const auto it = std::ranges::find(result.metrics, name, &api::BenchMetric::name);
    if (it == result.metrics.end())
      result.metrics.push_back({name, {value}});
    else
      it->samples.push_back(value);
  }
}

nlohmann::json request_record(const api::BenchCase& c) {
  nlohmann::json request = api::to_json(c.request);
  if (c.scene_file) request["scene_file"] = *c.scene_file;
  return request;
}

// One side of a run: the runners of one build and what they measured.
struct Side {
  const Runners& runners;
  api::BenchResults results;
  api::BenchCaseResult current;  // the case in progress
  CaseRunner* runner = nullptr;  // null once the case is skipped or failed on this side
};

// Every case on every side, render by render: sides take turns, their order alternating
// from one round of renders to the next.
class SuiteLoop {
 public:
  SuiteLoop(const api::BenchSuite& suite, std::vector<Side>& sides, const RunOptions& options,
            const RunObserver& observer, NoiseMonitor& noise)
      : suite_(suite),
        sides_(sides),
        options_(options),
        observer_(observer),
        noise_(noise),
        total_(suite.cases.size() * sides.size() * (1 + options.warmup + options.repetitions)) {}

  // Runs every case; false when stopped before the end.
  bool run() {
    try {
      for (const api::BenchCase& c : suite_.cases) run_case(c);
    } catch (const Stopped&) {
      return false;
    }
    return true;
  }

 private:
  void run_case(const api::BenchCase& c) {
    for (Side& side : sides_) {
      side.current = {c.name, c.kind, api::BenchCaseStatus::ok, "", request_record(c), {}, {}};
      side.runner = c.kind == api::BenchCaseKind::server_round_trip ? side.runners.round_trips : side.runners.renders;
      if (!side.runner) {
        side.current.status = api::BenchCaseStatus::skipped;
        side.current.reason = side.runners.no_round_trips;
      }
    }
    std::size_t round = 0;
    each_side(c, round++, [&](Side& side) { side.current.image = side.runner->render_image(c); });
    for (std::uint32_t i = 0; i < options_.warmup; ++i)
      each_side(c, round++, [&](Side& side) { (void)side.runner->render_timed(c); });
    for (std::uint32_t i = 0; i < options_.repetitions; ++i)
      each_side(c, round++, [&](Side& side) { add(side.current, side.runner->render_timed(c)); });
    for (Side& side : sides_) side.results.cases.push_back(std::move(side.current));
  }

  // One render on each side still running the case, in this round's order. A side whose
  // render throws fails the case; what it measured so far is dropped, so that a case's
  // samples all come from complete runs.
  template <class Render>
  void each_side(const api::BenchCase& c, std::size_t round, Render render) {
    noise_.probe();  // the machine's state as this round starts; no render runs meanwhile
    for (std::size_t k = 0; k < sides_.size(); ++k) {
      Side& side = sides_[round % 2 == 0 ? k : sides_.size() - 1 - k];
      if (observer_.stop_requested && observer_.stop_requested()) throw Stopped{};
      if (side.runner) {
        try {
          render(side);
        } catch (const std::exception& e) {
          side.current.status = api::BenchCaseStatus::failed;
          side.current.reason = e.what();
          side.current.metrics.clear();
          side.current.image.reset();
          side.runner = nullptr;
        }
      }
      ++done_;  // skipped and failed renders count as done: the bar moves at the same pace
      if (observer_.progress) observer_.progress(done_, total_, c);
    }
  }

  const api::BenchSuite& suite_;
  std::vector<Side>& sides_;
  const RunOptions& options_;
  const RunObserver& observer_;
  NoiseMonitor& noise_;
  const std::size_t total_;
  std::size_t done_ = 0;
};

std::vector<api::BenchResults> run_sides(const api::BenchSuite& suite, const std::vector<const Runners*>& runners,
                                         const RunOptions& options, const RunObserver& observer) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Side> sides;
  for (const Runners* r : runners) {
    api::BenchResults results;
    results.suite = suite.name;
    results.suite_version = suite.version;
    results.started_at = core::utc_timestamp();
    results.repetitions = options.repetitions;
    results.warmup = options.warmup;
    results.machine = this_machine();
    results.build = r->renders->build();
    results.device = r->renders->device();
    sides.push_back({*r, std::move(results), {}, nullptr});
  }
  NoiseMonitor noise;
  const bool complete = SuiteLoop(suite, sides, options, observer, noise).run();
  const double duration_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<api::BenchResults> all;
  for (Side& side : sides) {
    side.results.complete = complete;
    side.results.duration_s = duration_s;
    side.results.noise = noise.noise();
    all.push_back(std::move(side.results));
  }
  return all;
}

}  // namespace

api::BenchBuild CaseRunner::build() { return this_build(); }

Measurement stats_metrics(const nlohmann::json& stats) {
  Measurement m;
  m.emplace_back("gpu_ms", median_of(stats.value("gpu_ms", nlohmann::json()), "gpu_ms"));
  m.emplace_back("wall_ms", median_of(stats.value("wall_ms", nlohmann::json()), "wall_ms"));
  if (!stats.contains("passes") || !stats["passes"].is_array()) throw std::runtime_error("the render's stats have no passes");
  for (const nlohmann::json& pass : stats["passes"]) {
    if (!pass.is_object() || !pass.value("ran", false)) continue;
    const std::string name = pass.value("name", "");
    m.emplace_back("pass." + name, median_of(pass.value("gpu_ms", nlohmann::json()), "pass " + name));
  }
  return m;
}

api::BenchResults run_suite(const api::BenchSuite& suite, const Runners& runners, const RunOptions& options,
                            const RunObserver& observer) {
  return std::move(run_sides(suite, {&runners}, options, observer).front());
}

std::pair<api::BenchResults, api::BenchResults> run_suite_paired(const api::BenchSuite& suite, const Runners& a,
                                                                 const Runners& b, const RunOptions& options,
                                                                 const RunObserver& observer) {
  std::vector<api::BenchResults> both = run_sides(suite, {&a, &b}, options, observer);
  return {std::move(both[0]), std::move(both[1])};
}

}  // namespace bench
