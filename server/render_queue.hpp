// The bounded queue between HTTP threads and the render workers. Each worker owns one
// Vulkan device and one renderer (neither is thread-safe) for its whole life, so renders
// on one device are serialised; more workers mean more devices rendering in parallel.
// A full queue refuses at once instead of piling up; a job whose deadline passed, or whose
// client went away, before a worker took it never renders. Uploaded scenes come from the
// scene store, loaded by each worker's renderer when it first needs them.
#pragma once

#include "api/render_request.hpp"
#include "lab/accuracy/budget.hpp"
#include "lab/accuracy/workbench.hpp"
#include "renderer/renderer.hpp"
#include "server/metrics.hpp"
#include "server/scene_store.hpp"
#include "vkx/device_options.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace server {

using Clock = std::chrono::steady_clock;

class RenderQueue;

// Work for a render worker: a render, a compare, a sweep or a benchmark suite. The HTTP thread that submitted it
// waits for it (RenderQueue::wait) and reads its result once it is done.
class Job {
 public:
  Job(std::string scene, Clock::time_point deadline) : scene(std::move(scene)), deadline(deadline) {}
  virtual ~Job() = default;

  const std::string scene;  // the scene it renders
  // A job still queued at its deadline never runs; a running render or compare finishes and
  // its result is dropped; a job that answers_partially() stops at its next step.
  const Clock::time_point deadline;

  // Valid once RenderQueue::wait returned Outcome::done: error is set or the job's result is.
  std::exception_ptr error;
  double queue_wait_ms = 0.0;  // from submission to a worker taking it (or dropping it)

  // Nobody waits for the result any more (the client left, or was answered without it).
  std::atomic<bool> abandoned{false};
  // For long jobs (a sweep, a benchmark suite) to ask between steps: abandoned, or past the
  // deadline.
  bool should_stop() const { return abandoned.load() || Clock::now() >= deadline; }
  // What the worker's renderer asks between its submissions (Renderer::set_stop_check): stop
  // what nobody waits for, and a job past its deadline unless it answers partially (which
  // stops between its own steps, keeping what it has).
  bool should_interrupt() const { return abandoned.load() || (!answers_partially() && Clock::now() >= deadline); }
  // A long job that, running at its deadline, stops at its next step and is answered with
  // what it has (its result says it is incomplete) rather than with 504.
  virtual bool answers_partially() const { return false; }

 protected:
  friend class RenderQueue;
  // On the worker thread, with its renderer and references; throws what it cannot do.
  virtual void run(accuracy::Workbench& bench) = 0;

 private:
  enum class State { queued, running, done, expired, withdrawn };
  State state_ = State::queued;
  Clock::time_point submitted_;
};

// Thrown by a long job that stopped (should_stop) before it had anything to answer with.
struct JobStopped : std::runtime_error {
  JobStopped() : std::runtime_error("stopped before any result: the deadline passed") {}
};

class RenderJob : public Job {
 public:
  RenderJob(api::RenderRequest request, Clock::time_point deadline)
      : Job(request.scene, deadline), request(std::move(request)) {}

  const api::RenderRequest request;
  std::optional<renderer::RenderResult> result;

 protected:
  void run(accuracy::Workbench& bench) override {
    result = request.budget_ms ? accuracy::render_within_budget(bench, request, renderer::readback_for(request.output))
                               : bench.renderer.render(request);
  }
};

// Makes an uploaded scene resident on a worker and warms it up (Renderer::prepare), so that
// its first render costs what later ones do.
class PrepareJob : public Job {
 public:
  using Job::Job;
  double warm_up_ms = 0.0;

 protected:
  void run(accuracy::Workbench& bench) override { warm_up_ms = bench.renderer.prepare(scene); }
};

class RenderQueue {
 public:
  struct Config {
    std::size_t capacity = 8;
    std::size_t workers = 1;
    vkx::DeviceOptions device;
    std::uint64_t scene_cache_bytes = 1ull << 30;  // per worker
  };
  // Called from a worker thread when its device cannot be opened or warmed up.
  using FatalHandler = std::function<void(const std::string& message)>;

  // `scenes` must outlive the queue.
  RenderQueue(Config config, const SceneStore& scenes, FatalHandler on_fatal);
  ~RenderQueue();  // shutdown()
  RenderQueue(const RenderQueue&) = delete;
  RenderQueue& operator=(const RenderQueue&) = delete;

  enum class Admission { accepted, full, stopping };
  Admission submit(const std::shared_ptr<Job>& job);

  enum class Outcome { done, deadline_exceeded, client_gone };
  // Blocks until the job is done, its deadline passes or `client_gone` (polled every
  // 50 ms) says nobody waits for it. In the last two cases a queued job is removed; a
  // running one finishes on its worker and its result is dropped. A running job that
  // answers_partially() is waited for past its deadline: it stops at its next step.
  Outcome wait(Job& job, const std::function<bool()>& client_gone);
  // The same, giving up at `until`: empty then, the job still queued or running.
  std::optional<Outcome> wait_until(Job& job, const std::function<bool()>& client_gone, Clock::time_point until);

  // Every worker has its device warm, the queue has room and no shutdown has begun.
  bool ready() const;
  QueueGauges gauges() const;
  // GET /v1/device: the first worker's device, once it is open.
  std::optional<nlohmann::json> device_report() const;

  // Refuses new jobs from now on; what is queued and running may go on for `grace`, after
  // which it is abandoned: a render stops at its next submission (Renderer::set_stop_check),
  // a sweep or suite at its next step, and what is still queued is dropped. SIGTERM's drain.
  void begin_drain(std::chrono::milliseconds grace);
  // Refuses new jobs, lets the workers finish what is queued and running (within the
  // drain's grace when one began), joins them.
  void shutdown();

 private:
  void work(std::size_t index);
  void withdraw(Job& job);  // with mutex_ held
  void abandon_at(Clock::time_point end);  // the drain's timer
  void run(Job& job, accuracy::Workbench& bench) const;

  const Config config_;
  const SceneStore& scenes_;
  const FatalHandler on_fatal_;
  mutable std::mutex mutex_;
  std::condition_variable work_available_;
  std::condition_variable job_finished_;
  std::deque<std::shared_ptr<Job>> queue_;
  std::vector<std::shared_ptr<Job>> running_;  // by worker
  std::size_t in_flight_ = 0;
  std::size_t ready_workers_ = 0;
  bool stopping_ = false;
  std::optional<nlohmann::json> device_report_;
  std::vector<SceneCacheGauges> scene_caches_;  // by worker
  std::vector<std::thread> workers_;
  std::thread drainer_;  // begin_drain's timer
};

}  // namespace server
