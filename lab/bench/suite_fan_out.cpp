#include "lab/bench/suite_fan_out.hpp"

#include "core/utc_time.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

namespace bench {
namespace {

api::BenchSuite one_case(const api::BenchSuite& suite, std::size_t index) {
  api::BenchSuite one = suite;
  one.cases = {suite.cases[index]};
  return one;
}

// The cases' noise as one run's (see the header).
api::BenchNoise merged_noise(const std::vector<api::BenchResults>& parts) {
  api::BenchNoise all;
  for (const api::BenchResults& part : parts) {
    if (!part.noise) continue;
    all.probe_ms.insert(all.probe_ms.end(), part.noise->probe_ms.begin(), part.noise->probe_ms.end());
    all.steal = std::max(all.steal, part.noise->steal);
  }
  if (parts.front().noise) all.load_start = parts.front().noise->load_start;
  if (parts.back().noise) all.load_end = parts.back().noise->load_end;
  return all;
}

}  // namespace

api::BenchResults run_suite_fanned(const api::BenchSuite& suite, const std::vector<Runners>& runners,
                                   const RunOptions& options, const RunObserver& observer) {
  if (runners.empty()) throw std::invalid_argument("run_suite_fanned needs a runner");
  if (suite.cases.empty()) return run_suite(suite, runners.front(), options, observer);
  const auto start = std::chrono::steady_clock::now();
  const std::string started_at = core::utc_timestamp();
  const std::size_t per_case = 1 + options.warmup + options.repetitions;
  const std::size_t total = suite.cases.size() * per_case;

  std::vector<std::optional<api::BenchResults>> parts(suite.cases.size());
  std::atomic<std::size_t> next_case{0};
  std::mutex observer_mutex;
  std::size_t done = 0;  // renders of every runner, under observer_mutex
  std::exception_ptr error;

  const auto work = [&](const Runners& runners_k) {
    try {
      for (std::size_t i = next_case++; i < suite.cases.size(); i = next_case++) {
        RunObserver mine;
        std::size_t done_here = 0;
        if (observer.progress)
          mine.progress = [&](std::size_t done_in_case, std::size_t, const api::BenchCase& c) {
            std::lock_guard lock(observer_mutex);
            done += done_in_case - done_here;
            done_here = done_in_case;
            observer.progress(done, total, c);
          };
        if (observer.stop_requested)
          mine.stop_requested = [&] {
            std::lock_guard lock(observer_mutex);
            return observer.stop_requested();
          };
        parts[i] = run_suite(one_case(suite, i), runners_k, options, mine);
        if (!parts[i]->complete) break;  // stopped: no further case starts here
      }
    } catch (...) {
      std::lock_guard lock(observer_mutex);
      if (!error) error = std::current_exception();
      next_case = suite.cases.size();  // the other runners start no further case
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t k = 1; k < runners.size(); ++k) threads.emplace_back(work, std::cref(runners[k]));
  work(runners.front());
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);

  // The cases in the suite's order, up to the first that did not run to its end (the first
  // case always ran: the first runner takes it).
  std::vector<api::BenchResults> ran;
  for (auto& part : parts) {
    if (!part) break;
    ran.push_back(std::move(*part));
    if (!ran.back().complete) break;
  }
  api::BenchResults results = ran.front();
  results.cases.clear();
  for (const api::BenchResults& part : ran)
    for (const api::BenchCaseResult& c : part.cases) results.cases.push_back(c);
  results.started_at = started_at;
  results.duration_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  results.complete = ran.size() == suite.cases.size() && ran.back().complete;
  results.noise = merged_noise(ran);
  return results;
}

}  // namespace bench
