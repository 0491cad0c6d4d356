#include "http_case_runner.hpp"

#include "api/request_json.hpp"
#include "core/elapsed.hpp"
#include "image/pfm.hpp"
#include "input_files.hpp"
#include "lab/bench/image_fingerprint.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>

namespace bench {

HttpCaseRunner::HttpCaseRunner(const std::string& url) : server_(url) {}

api::BenchDevice HttpCaseRunner::device() {
  const auto result = server_.http().Get("/v1/device");
  if (!result || result->status != 200) throw server_.failure("GET /v1/device", result);
  const nlohmann::json device = parse_answer(result->body, "GET /v1/device's answer");
  return {device.value("name", ""), device.value("driver", "")};
}

nlohmann::json HttpCaseRunner::request_body(const api::BenchCase& c) {
  nlohmann::json body = api::to_json(c.request);
  if (!c.scene_file) return body;
  auto it = uploaded_.find(*c.scene_file);
  if (it == uploaded_.end()) {
    const std::string bytes = read_text_file(*c.scene_file);
    const std::string name = std::filesystem::path(*c.scene_file).stem().string();
    const auto result = server_.http().Post(httplib::append_query_params("/v1/scenes", {{"name", name}}).c_str(), bytes,
                                      "application/octet-stream");
    if (!result || (result->status != 200 && result->status != 201))
      throw server_.failure("uploading " + *c.scene_file, result);
    it = uploaded_.emplace(*c.scene_file, parse_answer(result->body, "the upload's answer").value("id", "")).first;
  }
  body["scene"] = it->second;
  return body;
}

httplib::Result HttpCaseRunner::post_render(const nlohmann::json& body, bool want_json) {
  httplib::Headers headers;
  if (want_json) headers.emplace("Accept", "application/json");
  return server_.http().Post("/v1/render", headers, body.dump(), "application/json");
}

Measurement HttpCaseRunner::render_timed(const api::BenchCase& c) {
  const bool round_trip = c.kind == api::BenchCaseKind::server_round_trip;
  const nlohmann::json body = request_body(c);
  const auto start = std::chrono::steady_clock::now();
  const httplib::Result result = post_render(body, !round_trip);
  const double round_trip_ms = core::ms_since(start);
  if (!result || result->status != 200) throw server_.failure("POST /v1/render", result);
  const nlohmann::json stats = round_trip ? parse_answer(result->get_header_value("X-Render-Stats"), "X-Render-Stats")
                                          : parse_answer(result->body, "the render's answer").value("stats", nlohmann::json());
  Measurement m = stats_metrics(stats);
  m.insert(m.begin() + 2, {"round_trip_ms", round_trip_ms});  // after the frame's totals, before the passes
  return m;
}

api::BenchImage HttpCaseRunner::render_image(const api::BenchCase& c) {
  nlohmann::json body = request_body(c);
  body["output"]["format"] = "pfm";
  const httplib::Result result = post_render(body, false);
  if (!result || result->status != 200) throw server_.failure("POST /v1/render", result);
  const std::string& pfm = result->body;
  return fingerprint(image::decode_pfm(std::span(reinterpret_cast<const std::uint8_t*>(pfm.data()), pfm.size())));
}

}  // namespace bench
