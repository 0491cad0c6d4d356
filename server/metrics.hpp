// Counters and histograms for GET /metrics, in the Prometheus text format (0.0.4).
// Thread-safe: HTTP threads and render workers record into one instance.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

namespace server {

class Histogram {
 public:
  explicit Histogram(std::vector<double> upper_bounds);
  void observe(double value);
  // The _bucket, _sum and _count lines; `labels` is "" or `key="value",...` without braces.
  void write(std::string& out, const std::string& name, const std::string& labels) const;

 private:
  std::vector<double> upper_bounds_;
  std::vector<std::uint64_t> counts_;  // per bucket, not cumulative; the last is +Inf
  double sum_ = 0.0;
  std::uint64_t count_ = 0;
};

// One render worker's resident scenes, as of its last render.
struct SceneCacheGauges {
  std::size_t scenes = 0;
  std::uint64_t bytes = 0;  // host and device memory
};

// What the render queue reports at scrape time.
struct QueueGauges {
  std::size_t depth = 0;
  std::size_t capacity = 0;
  std::size_t in_flight = 0;
  bool ready = false;
  std::vector<SceneCacheGauges> scene_caches;  // by worker index
};

// What the scene store holds at scrape time.
struct StoreGauges {
  std::size_t scenes = 0;
  std::uint64_t bytes = 0;  // as uploaded
};

class Metrics {
 public:
  // `route` is the route's pattern ("/v1/scenes/{id}"), or "unmatched".
  void count_request(const std::string& route, const std::string& method, int status, double seconds);
  void observe_queue_wait(double seconds);
  void observe_pass(const std::string& pass, double gpu_seconds);
  // "ok", "rejected" (by the renderer: 404/422), "failed" (500), "queue_full",
  // "deadline_exceeded", "client_gone"
  void count_render(const std::string& outcome);
  // A connection the front refused or cut short (server/http_front): the status it was
  // answered (0: closed unanswered) and the error's code.
  void count_refused_connection(int status, const std::string& code);

  std::string prometheus_text(const QueueGauges& queue, const StoreGauges& store) const;

 private:
  mutable std::mutex mutex_;
  std::map<std::tuple<std::string, std::string, int>, std::uint64_t> requests_;
  std::map<std::string, Histogram> request_seconds_;  // by route
  std::map<std::string, Histogram> pass_seconds_;     // by pass
  Histogram queue_wait_seconds_{{0.001, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1, 2.5, 5, 10, 30}};
  std::map<std::string, std::uint64_t> renders_;
  std::map<std::pair<int, std::string>, std::uint64_t> refused_connections_;
};

}  // namespace server
