#include "server/metrics.hpp"

#include <gtest/gtest.h>

namespace server {
namespace {

bool has_line(const std::string& text, const std::string& line) {
  return text.find("\n" + line + "\n") != std::string::npos || text.rfind(line + "\n", 0) == 0;
}

TEST(Histogram, BucketsAreCumulativeWithSumAndCount) {
  Histogram h({1.0, 2.0});
  for (double v : {0.5, 1.0, 1.5, 3.0}) h.observe(v);
  std::string out;
  h.write(out, "x", "k=\"v\"");
  EXPECT_EQ(out,
            "x_bucket{k=\"v\",le=\"1\"} 2\n"
            "x_bucket{k=\"v\",le=\"2\"} 3\n"
            "x_bucket{k=\"v\",le=\"+Inf\"} 4\n"
            "x_sum{k=\"v\"} 6\n"
            "x_count{k=\"v\"} 4\n");
}

TEST(Metrics, PrometheusTextHasEverySeriesWithTypes) {
  Metrics m;
  m.count_request("/v1/render", "POST", 200, 0.02);
  m.count_request("/v1/render", "POST", 200, 0.03);
  m.count_request("unmatched", "GET", 404, 0.0001);
  m.observe_pass("shade", 0.011);
  m.observe_queue_wait(0.002);
  m.count_render("ok");
  const std::string text = m.prometheus_text(
      {.depth = 3, .capacity = 8, .in_flight = 1, .ready = true, .scene_caches = {{4, 1000}, {2, 500}}},
      {.scenes = 2, .bytes = 4696});
  EXPECT_TRUE(has_line(text, "# TYPE lpv_http_requests_total counter"));
  EXPECT_TRUE(has_line(text, "lpv_http_requests_total{route=\"/v1/render\",method=\"POST\",status=\"200\"} 2"));
  EXPECT_TRUE(has_line(text, "lpv_http_requests_total{route=\"unmatched\",method=\"GET\",status=\"404\"} 1"));
  EXPECT_TRUE(has_line(text, "# TYPE lpv_http_request_duration_seconds histogram"));
  EXPECT_TRUE(has_line(text, "lpv_http_request_duration_seconds_count{route=\"/v1/render\"} 2"));
  EXPECT_TRUE(has_line(text, "lpv_render_pass_gpu_seconds_bucket{pass=\"shade\",le=\"0.01\"} 0"));
  EXPECT_TRUE(has_line(text, "lpv_render_pass_gpu_seconds_bucket{pass=\"shade\",le=\"0.025\"} 1"));
  EXPECT_TRUE(has_line(text, "lpv_render_queue_wait_seconds_count 1"));
  EXPECT_TRUE(has_line(text, "lpv_renders_total{outcome=\"ok\"} 1"));
  EXPECT_TRUE(has_line(text, "lpv_render_queue_depth 3"));
  EXPECT_TRUE(has_line(text, "lpv_render_queue_capacity 8"));
  EXPECT_TRUE(has_line(text, "lpv_renders_in_flight 1"));
  EXPECT_TRUE(has_line(text, "lpv_ready 1"));
  EXPECT_TRUE(has_line(text, "# TYPE lpv_scene_cache_bytes gauge"));
  EXPECT_TRUE(has_line(text, "lpv_scene_cache_scenes{worker=\"1\"} 2"));
  EXPECT_TRUE(has_line(text, "lpv_scene_cache_bytes{worker=\"0\"} 1000"));
  EXPECT_TRUE(has_line(text, "lpv_uploaded_scenes 2"));
  EXPECT_TRUE(has_line(text, "lpv_uploaded_scene_bytes 4696"));
}

}  // namespace
}  // namespace server
