#include "server/render_queue.hpp"

#include "scene/builtin_scenes.hpp"
#include "server/device_report.hpp"

#include <algorithm>
#include <stdexcept>

namespace server {
namespace {

constexpr auto kClientPollInterval = std::chrono::milliseconds(50);

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// Every built-in scene resident and warmed up (Renderer::prepare) before the first request:
// lavapipe JIT-compiles shaders on first use, ~250 ms.
void warm_up(renderer::Renderer& renderer) {
  for (const auto& info : scene::builtin_scenes()) renderer.prepare(info.name);
}

}  // namespace

RenderQueue::RenderQueue(Config config, const SceneStore& scenes, FatalHandler on_fatal)
    : config_(std::move(config)),
      scenes_(scenes),
      on_fatal_(std::move(on_fatal)),
      running_(config_.workers),
      scene_caches_(config_.workers) {
  for (std::size_t i = 0; i < config_.workers; ++i) workers_.emplace_back([this, i] { work(i); });
}

RenderQueue::~RenderQueue() { shutdown(); }

RenderQueue::Admission RenderQueue::submit(const std::shared_ptr<Job>& job) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return Admission::stopping;
    if (queue_.size() >= config_.capacity) return Admission::full;
    job->submitted_ = Clock::now();
    job->state_ = Job::State::queued;
    queue_.push_back(job);
  }
  work_available_.notify_one();
  return Admission::accepted;
}

RenderQueue::Outcome RenderQueue::wait(Job& job, const std::function<bool()>& client_gone) {
  return *wait_until(job, client_gone, Clock::time_point::max());
}

std::optional<RenderQueue::Outcome> RenderQueue::wait_until(Job& job, const std::function<bool()>& client_gone,
                                                            Clock::time_point until) {
  std::unique_lock lock(mutex_);
  for (;;) {
    if (job.state_ == Job::State::done) return Outcome::done;
    if (job.state_ == Job::State::expired) return Outcome::deadline_exceeded;
    const auto now = Clock::now();
    const bool past_deadline = now >= job.deadline;
    if (past_deadline && !(job.state_ == Job::State::running && job.answers_partially())) {
      withdraw(job);
      return Outcome::deadline_exceeded;
    }
    if (now >= until) return std::nullopt;
    lock.unlock();
    const bool gone = client_gone();  // a system call: not under the lock
    lock.lock();
    if (gone && job.state_ != Job::State::done) {
      withdraw(job);
      return Outcome::client_gone;
    }
    Clock::time_point wake = std::min(now + kClientPollInterval, until);
    if (!past_deadline) wake = std::min(wake, job.deadline);
    job_finished_.wait_until(lock, wake);
  }
}

void RenderQueue::withdraw(Job& job) {
  if (job.state_ != Job::State::queued) return;  // running: the worker finishes it
  const auto it = std::find_if(queue_.begin(), queue_.end(), [&](const auto& queued) { return queued.get() == &job; });
  if (it != queue_.end()) queue_.erase(it);
  job.state_ = Job::State::withdrawn;
  job.queue_wait_ms = ms_between(job.submitted_, Clock::now());
}

bool RenderQueue::ready() const {
  std::lock_guard lock(mutex_);
  return ready_workers_ == config_.workers && !stopping_ && queue_.size() < config_.capacity;
}

QueueGauges RenderQueue::gauges() const {
  std::lock_guard lock(mutex_);
  return {queue_.size(), config_.capacity, in_flight_, ready_workers_ == config_.workers && !stopping_, scene_caches_};
}

std::optional<nlohmann::json> RenderQueue::device_report() const {
  std::lock_guard lock(mutex_);
  return device_report_;
}

void RenderQueue::begin_drain(std::chrono::milliseconds grace) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_ && drainer_.joinable()) return;  // one drain
    stopping_ = true;
  }
  work_available_.notify_all();
  const Clock::time_point end = Clock::now() + grace;
  drainer_ = std::thread([this, end] { abandon_at(end); });
}

void RenderQueue::abandon_at(Clock::time_point end) {
  std::unique_lock lock(mutex_);
  // Woken by every finished job; done early when nothing is left.
  while (Clock::now() < end && (in_flight_ > 0 || !queue_.empty())) job_finished_.wait_until(lock, end);
  for (const auto& job : queue_) job->abandoned = true;  // dropped when a worker takes it
  for (const auto& job : running_)
    if (job) job->abandoned = true;
}

void RenderQueue::shutdown() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  work_available_.notify_all();
  for (auto& worker : workers_)
    if (worker.joinable()) worker.join();
  job_finished_.notify_all();
  if (drainer_.joinable()) drainer_.join();
}

void RenderQueue::run(Job& job, accuracy::Workbench& bench) const {
  // A deleted scene may still be resident on this worker's device: dropped, so the job
  // asks the store, which no longer has it, and answers "unknown scene".
  if (is_scene_id(job.scene) && !scenes_.contains(job.scene)) bench.renderer.forget_scene(job.scene);
  bench.renderer.set_stop_check([&job] { return job.should_interrupt(); });
  struct ClearStopCheck {
    renderer::Renderer& renderer;
    ~ClearStopCheck() { renderer.set_stop_check({}); }
  } clear{bench.renderer};
  job.run(bench);
}

void RenderQueue::work(std::size_t index) {
  // Declared in this order so the renderer is destroyed before its device.
  std::optional<renderer::GpuDevice> device;
  std::optional<renderer::Renderer> renderer;
  std::optional<accuracy::Workbench> bench;
  try {
    device.emplace(config_.device);
    renderer.emplace(device->vulkan(), renderer::RendererOptions{[this](const std::string& id) { return scenes_.load(id); },
                                                        config_.scene_cache_bytes});
    warm_up(*renderer);
    bench.emplace(*renderer);
  } catch (const std::exception& e) {
    const std::string message = "render worker " + std::to_string(index) + ": " + e.what();
    {
      // The server is going down (on_fatal_ stops it): fail what waits rather than let it
      // sit until its deadline.
      std::lock_guard lock(mutex_);
      stopping_ = true;
      for (const auto& job : queue_) {
        job->error = std::make_exception_ptr(std::runtime_error(message));
        job->state_ = Job::State::done;
      }
      queue_.clear();
    }
    job_finished_.notify_all();
    on_fatal_(message);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    if (index == 0) device_report_ = server::device_report(device->report());
    const renderer::SceneCacheStats cache = renderer->scene_cache();
    scene_caches_[index] = {cache.scenes, cache.bytes};
    ++ready_workers_;
  }

  for (;;) {
    std::shared_ptr<Job> job;
    {
      std::unique_lock lock(mutex_);
      work_available_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping, and nothing left to do
      job = std::move(queue_.front());
      queue_.pop_front();
      const auto now = Clock::now();
      job->queue_wait_ms = ms_between(job->submitted_, now);
      if (now >= job->deadline || job->abandoned) {
        job->state_ = Job::State::expired;
        job_finished_.notify_all();
        continue;
      }
      job->state_ = Job::State::running;
      running_[index] = job;
      ++in_flight_;
    }
    std::exception_ptr error;
    try {
      run(*job, *bench);
    } catch (...) {
      error = std::current_exception();
    }
    const renderer::SceneCacheStats cache = renderer->scene_cache();
    {
      std::lock_guard lock(mutex_);
      scene_caches_[index] = {cache.scenes, cache.bytes};
      running_[index] = nullptr;
      --in_flight_;
      job->error = error;
      job->state_ = Job::State::done;
    }
    job_finished_.notify_all();
  }
}

}  // namespace server
