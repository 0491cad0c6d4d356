#include "server/accuracy_jobs.hpp"

#include "api/accuracy_report.hpp"
#include "api/sweep_table.hpp"

namespace server {
namespace {

constexpr auto kProgressInterval = std::chrono::milliseconds(200);

}  // namespace

void CompareJob::run(accuracy::Workbench& bench) {
  // The reference (seconds to minutes of path tracing) stops at its next progress report.
  result = accuracy::compare(bench, request, [this](double) {
    if (should_interrupt()) throw JobStopped();
  });
}

void EventChannel::push(nlohmann::json event) {
  {
    std::lock_guard lock(mutex_);
    events_.push_back(std::move(event));
  }
  changed_.notify_all();
}

void EventChannel::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

std::optional<nlohmann::json> EventChannel::next(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, timeout, [&] { return closed_ || !events_.empty(); });
  if (events_.empty()) return std::nullopt;
  nlohmann::json event = std::move(events_.front());
  events_.pop_front();
  return event;
}

bool EventChannel::closed() const {
  std::lock_guard lock(mutex_);
  return closed_ && events_.empty();
}

void SweepJob::run(accuracy::Workbench& bench) {
  accuracy::SweepObserver observer;
  // A progress line at most every kProgressInterval, and the last one: enough for a bar.
  Clock::time_point last_progress{};
  observer.reference_progress = [&](double fraction) {
    if (should_stop()) throw JobStopped();  // no row without the reference
    const auto now = Clock::now();
    if (fraction < 1.0 && now - last_progress < kProgressInterval) return;
    last_progress = now;
    events.push({{"event", "reference_progress"}, {"fraction", fraction}});
  };
  observer.reference_done = [&](const api::ReferenceReport& report) {
    events.push({{"event", "reference"}, {"reference", api::to_json(report)}});
  };
  observer.row_measured = [&](std::size_t index, std::size_t total, const api::SweepRow& row) {
    events.push({{"event", "row"}, {"index", index}, {"total", total}, {"row", api::to_json(row)}});
  };
  Clock::time_point last_timing{};
  observer.timing_progress = [&](std::size_t done, std::size_t total) {
    const auto now = Clock::now();
    if (done < total && now - last_timing < kProgressInterval) return;
    last_timing = now;
    events.push({{"event", "timing_progress"}, {"done", done}, {"total", total}});
  };
  observer.stop_requested = [this] { return should_stop(); };
  try {
    result = accuracy::sweep(bench, request, observer);
  } catch (...) {
    events.close();
    throw;
  }
  events.close();
}

}  // namespace server
