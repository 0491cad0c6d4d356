#include "server/render_queue.hpp"

#include "renderer/scene/builtin_scenes.hpp"
#include "server/device_report.hpp"

#include <algorithm>
#include <stdexcept>

namespace server {
namespace {

constexpr auto kClientPollInterval = std::chrono::milliseconds(50);

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// One small frame of every built-in scene: compiles the pipelines (lavapipe JIT-compiles
// shaders on first use, ~250 ms) and uploads the scenes before the first request.
void warm_up(renderer::Renderer& renderer) {
  for (const auto& info : scene::builtin_scenes()) {
    api::RenderRequest request;
    request.scene = info.name;
    request.output.width = 64;
    request.output.height = 64;
    renderer.render(request);
  }
}

}  // namespace

RenderQueue::RenderQueue(Config config, const SceneStore& scenes, FatalHandler on_fatal)
    : config_(std::move(config)), scenes_(scenes), on_fatal_(std::move(on_fatal)), scene_caches_(config_.workers) {
  for (std::size_t i = 0; i < config_.workers; ++i) workers_.emplace_back([this, i] { work(i); });
}

RenderQueue::~RenderQueue() { shutdown(); }

RenderQueue::Admission RenderQueue::submit(const std::shared_ptr<RenderJob>& job) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return Admission::stopping;
    if (queue_.size() >= config_.capacity) return Admission::full;
    job->submitted_ = Clock::now();
    job->state_ = RenderJob::State::queued;
    queue_.push_back(job);
  }
  work_available_.notify_one();
  return Admission::accepted;
}

RenderQueue::Outcome RenderQueue::wait(RenderJob& job, const std::function<bool()>& client_gone) {
  std::unique_lock lock(mutex_);
  for (;;) {
    if (job.state_ == RenderJob::State::done) return Outcome::done;
    if (job.state_ == RenderJob::State::expired) return Outcome::deadline_exceeded;
    const auto now = Clock::now();
    if (now >= job.deadline) {
      withdraw(job);
      return Outcome::deadline_exceeded;
    }
    lock.unlock();
    const bool gone = client_gone();  // a system call: not under the lock
    lock.lock();
    if (gone && job.state_ != RenderJob::State::done) {
      withdraw(job);
      return Outcome::client_gone;
    }
    job_finished_.wait_until(lock, std::min(job.deadline, now + kClientPollInterval));
  }
}

void RenderQueue::withdraw(RenderJob& job) {
  if (job.state_ != RenderJob::State::queued) return;  // running: the worker finishes it
  const auto it = std::find_if(queue_.begin(), queue_.end(), [&](const auto& queued) { return queued.get() == &job; });
  if (it != queue_.end()) queue_.erase(it);
  job.state_ = RenderJob::State::withdrawn;
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

void RenderQueue::shutdown() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  work_available_.notify_all();
  for (auto& worker : workers_)
    if (worker.joinable()) worker.join();
}

renderer::RenderResult RenderQueue::render(renderer::Renderer& renderer, const api::RenderRequest& request) const {
  // A deleted scene may still be resident on this worker's device: dropped, so the render
  // asks the store, which no longer has it, and answers "unknown scene".
  if (is_scene_id(request.scene) && !scenes_.contains(request.scene)) renderer.forget_scene(request.scene);
  return renderer.render(request);
}

void RenderQueue::work(std::size_t index) {
  // Declared in this order so the renderer is destroyed before its device.
  std::optional<vkx::Device> device;
  std::optional<renderer::Renderer> renderer;
  try {
    device.emplace(config_.device);
    renderer.emplace(*device, renderer::RendererOptions{[this](const std::string& id) { return scenes_.load(id); },
                                                        config_.scene_cache_bytes});
    warm_up(*renderer);
  } catch (const std::exception& e) {
    const std::string message = "render worker " + std::to_string(index) + ": " + e.what();
    {
      // The server is going down (on_fatal_ stops it): fail what waits rather than let it
      // sit until its deadline.
      std::lock_guard lock(mutex_);
      stopping_ = true;
      for (const auto& job : queue_) {
        job->error = std::make_exception_ptr(std::runtime_error(message));
        job->state_ = RenderJob::State::done;
      }
      queue_.clear();
    }
    job_finished_.notify_all();
    on_fatal_(message);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    if (index == 0) device_report_ = server::device_report(device->info());
    const renderer::SceneCacheStats cache = renderer->scene_cache();
    scene_caches_[index] = {cache.scenes, cache.bytes};
    ++ready_workers_;
  }

  for (;;) {
    std::shared_ptr<RenderJob> job;
    {
      std::unique_lock lock(mutex_);
      work_available_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping, and nothing left to do
      job = std::move(queue_.front());
      queue_.pop_front();
      const auto now = Clock::now();
      job->queue_wait_ms = ms_between(job->submitted_, now);
      if (now >= job->deadline) {
        job->state_ = RenderJob::State::expired;
        job_finished_.notify_all();
        continue;
      }
      job->state_ = RenderJob::State::running;
      ++in_flight_;
    }
    std::optional<renderer::RenderResult> result;
    std::exception_ptr error;
    try {
      result = render(*renderer, job->request);
    } catch (...) {
      error = std::current_exception();
    }
    const renderer::SceneCacheStats cache = renderer->scene_cache();
    {
      std::lock_guard lock(mutex_);
      scene_caches_[index] = {cache.scenes, cache.bytes};
      --in_flight_;
      job->result = std::move(result);
      job->error = error;
      job->state_ = RenderJob::State::done;
    }
    job_finished_.notify_all();
  }
}

}  // namespace server
