#include "server/metrics.hpp"

#include <cstdio>

namespace server {
namespace {

const std::vector<double> kRequestBuckets = {0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1, 2.5, 5, 10, 30};
// Per-pass device times are milliseconds on a GPU and tens of milliseconds on lavapipe.
const std::vector<double> kPassBuckets = {0.0001, 0.00025, 0.0005, 0.001, 0.0025, 0.005,
                                          0.01,   0.025,   0.05,   0.1,   0.25,   1};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", v);
  return text;
}

// Label values are escaped as the format asks: backslash, double quote and newline.
std::string label_value(const std::string& v) {
  std::string out;
  for (char c : v) {
    if (c == '\\' || c == '"') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out;
}

void header(std::string& out, const char* name, const char* type, const char* help) {
  out += std::string("# HELP ") + name + " " + help + "\n# TYPE " + name + " " + type + "\n";
}

}  // namespace

Histogram::Histogram(std::vector<double> upper_bounds)
    : upper_bounds_(std::move(upper_bounds)), counts_(upper_bounds_.size() + 1, 0) {}

void Histogram::observe(double value) {
  std::size_t i = 0;
  while (i < upper_bounds_.size() && value > upper_bounds_[i]) ++i;
  ++counts_[i];
  sum_ += value;
  ++count_;
}

void Histogram::write(std::string& out, const std::string& name, const std::string& labels) const {
  const std::string sep = labels.empty() ? "" : ",";
  std::uint64_t cumulative = 0;
  for (std::size_t i = 0; i <= upper_bounds_.size(); ++i) {
    cumulative += counts_[i];
    const std::string le = i < upper_bounds_.size() ? number(upper_bounds_[i]) : "+Inf";
    out += name + "_bucket{" + labels + sep + "le=\"" + le + "\"} " + std::to_string(cumulative) + "\n";
  }
  const std::string braces = labels.empty() ? "" : "{" + labels + "}";
  out += name + "_sum" + braces + " " + number(sum_) + "\n";
  out += name + "_count" + braces + " " + std::to_string(count_) + "\n";
}

void Metrics::count_request(const std::string& route, const std::string& method, int status, double seconds) {
  std::lock_guard lock(mutex_);
  ++requests_[{route, method, status}];
  request_seconds_.try_emplace(route, kRequestBuckets).first->second.observe(seconds);
}

void Metrics::observe_queue_wait(double seconds) {
  std::lock_guard lock(mutex_);
  queue_wait_seconds_.observe(seconds);
}

void Metrics::observe_pass(const std::string& pass, double gpu_seconds) {
  std::lock_guard lock(mutex_);
  pass_seconds_.try_emplace(pass, kPassBuckets).first->second.observe(gpu_seconds);
}

void Metrics::count_refused_connection(int status, const std::string& code) {
  std::lock_guard lock(mutex_);
  ++refused_connections_[{status, code}];
}

void Metrics::count_render(const std::string& outcome) {
  std::lock_guard lock(mutex_);
  ++renders_[outcome];
}

std::string Metrics::prometheus_text(const QueueGauges& queue, const StoreGauges& store) const {
  std::lock_guard lock(mutex_);
  std::string out;
  header(out, "lpv_http_requests_total", "counter", "HTTP requests answered, by route pattern, method and status.");
  for (const auto& [key, count] : requests_) {
    const auto& [route, method, status] = key;
    out += "lpv_http_requests_total{route=\"" + label_value(route) + "\",method=\"" + label_value(method) +
           "\",status=\"" + std::to_string(status) + "\"} " + std::to_string(count) + "\n";
  }
  header(out, "lpv_http_request_duration_seconds", "histogram",
         "Time from the request's arrival to its response, by route pattern.");
  for (const auto& [route, histogram] : request_seconds_)
    histogram.write(out, "lpv_http_request_duration_seconds", "route=\"" + label_value(route) + "\"");
  header(out, "lpv_render_pass_gpu_seconds", "histogram", "Device time of each render pass (median over a request's frames).");
  for (const auto& [pass, histogram] : pass_seconds_)
    histogram.write(out, "lpv_render_pass_gpu_seconds", "pass=\"" + label_value(pass) + "\"");
  header(out, "lpv_render_queue_wait_seconds", "histogram", "Time a render waited in the queue for a worker.");
  queue_wait_seconds_.write(out, "lpv_render_queue_wait_seconds", "");
  header(out, "lpv_renders_total", "counter", "Render jobs by outcome.");
  for (const auto& [outcome, count] : renders_)
    out += "lpv_renders_total{outcome=\"" + label_value(outcome) + "\"} " + std::to_string(count) + "\n";
  header(out, "lpv_http_refused_connections_total", "counter",
         "Connections the front refused or cut short, by the status answered (0: none) and code.");
  for (const auto& [key, count] : refused_connections_)
    out += "lpv_http_refused_connections_total{status=\"" + std::to_string(key.first) + "\",code=\"" +
           label_value(key.second) + "\"} " + std::to_string(count) + "\n";
  header(out, "lpv_render_queue_depth", "gauge", "Renders waiting for a worker.");
  out += "lpv_render_queue_depth " + std::to_string(queue.depth) + "\n";
  header(out, "lpv_render_queue_capacity", "gauge", "Renders that may wait before requests are answered 503.");
  out += "lpv_render_queue_capacity " + std::to_string(queue.capacity) + "\n";
  header(out, "lpv_renders_in_flight", "gauge", "Renders running on a worker now.");
  out += "lpv_renders_in_flight " + std::to_string(queue.in_flight) + "\n";
  header(out, "lpv_ready", "gauge", "1 when every render worker has its device ready.");
  out += std::string("lpv_ready ") + (queue.ready ? "1" : "0") + "\n";
  header(out, "lpv_scene_cache_scenes", "gauge", "Scenes resident on a render worker's device, as of its last render.");
  for (std::size_t i = 0; i < queue.scene_caches.size(); ++i)
    out += "lpv_scene_cache_scenes{worker=\"" + std::to_string(i) + "\"} " +
           std::to_string(queue.scene_caches[i].scenes) + "\n";
  header(out, "lpv_scene_cache_bytes", "gauge", "Host and device memory of a render worker's resident scenes.");
  for (std::size_t i = 0; i < queue.scene_caches.size(); ++i)
    out += "lpv_scene_cache_bytes{worker=\"" + std::to_string(i) + "\"} " +
           std::to_string(queue.scene_caches[i].bytes) + "\n";
  header(out, "lpv_uploaded_scenes", "gauge", "Uploaded scenes the server stores.");
  out += "lpv_uploaded_scenes " + std::to_string(store.scenes) + "\n";
  header(out, "lpv_uploaded_scene_bytes", "gauge", "Size of the uploaded scenes' files.");
  out += "lpv_uploaded_scene_bytes " + std::to_string(store.bytes) + "\n";
  return out;
}

}  // namespace server
