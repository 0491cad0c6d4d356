// The render queue's jobs for POST /v1/compare and POST /v1/sweep. A sweep runs for a long
// time: it reports as it goes (reference progress, each row) through an event channel that
// the HTTP thread streams to the client, and stops between rows when asked to.
#pragma once

#include "api/accuracy_request.hpp"
#include "lab/accuracy/compare.hpp"
#include "lab/accuracy/sweep.hpp"
#include "server/render_queue.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>

namespace server {

class CompareJob : public Job {
 public:
  CompareJob(api::CompareRequest request, Clock::time_point deadline)
      : Job(request.base.scene, deadline), request(std::move(request)) {}

  const api::CompareRequest request;
  std::optional<accuracy::Comparison> result;

 protected:
  void run(accuracy::Workbench& bench) override;
};

// Events of a running job, in order, from the worker to one reader; closed when the job ends.
class EventChannel {
 public:
  void push(nlohmann::json event);
  void close();
  // The next event; empty when none came within `timeout`, or the channel is closed and drained
  // (closed() tells which).
  std::optional<nlohmann::json> next(std::chrono::milliseconds timeout);
  bool closed() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<nlohmann::json> events_;
  bool closed_ = false;
};

class SweepJob : public Job {
 public:
  SweepJob(api::SweepRequest request, Clock::time_point deadline)
      : Job(request.base.scene, deadline), request(std::move(request)) {}

  const api::SweepRequest request;
  std::optional<accuracy::SweepResult> result;
  // {"event": "reference_progress", "fraction"}, {"event": "reference", "reference": {...}},
  // {"event": "row", "index", "total", "row": {...}}; closed when the sweep ends.
  EventChannel events;

  bool answers_partially() const override { return true; }  // the rows done, complete: false

 protected:
  void run(accuracy::Workbench& bench) override;
};

}  // namespace server
