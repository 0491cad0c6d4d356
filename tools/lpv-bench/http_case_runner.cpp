#include "http_case_runner.hpp"

#include "api/request_json.hpp"
#include "input_files.hpp"
#include "renderer/bench/image_fingerprint.hpp"
#include "renderer/image/pfm.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <stdexcept>

namespace bench {
namespace {

// A long render on lavapipe takes seconds; a suite's case is never meant to take minutes.
constexpr time_t kReadTimeoutSeconds = 600;
constexpr time_t kConnectTimeoutSeconds = 10;

nlohmann::json parse_json(const std::string& text, const std::string& what) {
  nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (json.is_discarded()) throw std::runtime_error(what + " is not JSON");
  return json;
}

}  // namespace

// "POST /v1/render: 422: limit_exceeded: lpv.grid: grid x * y * z ...": what the server said.
std::runtime_error HttpCaseRunner::failure(const std::string& what, const httplib::Result& result) const {
  if (!result) return std::runtime_error(what + ": " + httplib::to_string(result.error()) + " error with " + url_);
  std::string message = std::to_string(result->status);
  const nlohmann::json body = nlohmann::json::parse(result->body, nullptr, false);
  if (body.is_object() && body.contains("error") && body["error"].is_object()) {
    const nlohmann::json& e = body["error"];
    for (const std::string& part : {e.value("code", ""), e.value("field", ""), e.value("message", "")}) {
      if (part.empty()) continue;
      message += ": ";  // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on ": " + string
      message += part;
    }
  }
  return std::runtime_error(what + ": " + message);
}

HttpCaseRunner::HttpCaseRunner(const std::string& url) {
  static const std::regex base_url(R"(http://[A-Za-z0-9.\-]+(:[0-9]{1,5})?/?|http://\[[0-9A-Fa-f:]+\](:[0-9]{1,5})?/?)");
  if (!std::regex_match(url, base_url))
    throw BadInput("--url must be http://HOST[:PORT] (the server's root, no path), got '" + url + "'");
  url_ = url.back() == '/' ? url.substr(0, url.size() - 1) : url;
  client_ = std::make_unique<httplib::Client>(url_);
  client_->set_read_timeout(kReadTimeoutSeconds, 0);
  client_->set_connection_timeout(kConnectTimeoutSeconds, 0);
  client_->set_keep_alive(true);  // one connection for the whole suite: no connection set-up in the round trips
  // A request's headers and body go out in separate writes: without this, Nagle's algorithm
  // holds the body until the server acknowledges the headers, which it may delay by 40 ms,
  // and round_trip_ms measured that stall (75.8 against 32.7 ms of frame at 256^2 in one run).
  client_->set_tcp_nodelay(true);
  if (const char* token = std::getenv("LPV_SERVER_TOKEN"); token && *token) client_->set_bearer_token_auth(token);
}

api::BenchDevice HttpCaseRunner::device() {
  const auto result = client_->Get("/v1/device");
  if (!result || result->status != 200) throw failure("GET /v1/device", result);
  const nlohmann::json device = parse_json(result->body, "GET /v1/device's answer");
  return {device.value("name", ""), device.value("driver", "")};
}

nlohmann::json HttpCaseRunner::request_body(const api::BenchCase& c) {
  nlohmann::json body = api::to_json(c.request);
  if (!c.scene_file) return body;
  auto it = uploaded_.find(*c.scene_file);
  if (it == uploaded_.end()) {
    const std::string bytes = read_text_file(*c.scene_file);
    const std::string name = std::filesystem::path(*c.scene_file).stem().string();
    const auto result = client_->Post(httplib::append_query_params("/v1/scenes", {{"name", name}}).c_str(), bytes,
                                      "application/octet-stream");
    if (!result || (result->status != 200 && result->status != 201))
      throw failure("uploading " + *c.scene_file, result);
    it = uploaded_.emplace(*c.scene_file, parse_json(result->body, "the upload's answer").value("id", "")).first;
  }
  body["scene"] = it->second;
  return body;
}

httplib::Result HttpCaseRunner::post_render(const nlohmann::json& body, bool want_json) {
  httplib::Headers headers;
  if (want_json) headers.emplace("Accept", "application/json");
  return client_->Post("/v1/render", headers, body.dump(), "application/json");
}

Measurement HttpCaseRunner::render_timed(const api::BenchCase& c) {
  const bool round_trip = c.kind == api::BenchCaseKind::server_round_trip;
  const nlohmann::json body = request_body(c);
  const auto start = std::chrono::steady_clock::now();
  const httplib::Result result = post_render(body, !round_trip);
  const double round_trip_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!result || result->status != 200) throw failure("POST /v1/render", result);
  const nlohmann::json stats = round_trip ? parse_json(result->get_header_value("X-Render-Stats"), "X-Render-Stats")
                                          : parse_json(result->body, "the render's answer").value("stats", nlohmann::json());
  Measurement m = stats_metrics(stats);
  m.insert(m.begin() + 2, {"round_trip_ms", round_trip_ms});  // after the frame's totals, before the passes
  return m;
}

api::BenchImage HttpCaseRunner::render_image(const api::BenchCase& c) {
  nlohmann::json body = request_body(c);
  body["output"]["format"] = "pfm";
  const httplib::Result result = post_render(body, false);
  if (!result || result->status != 200) throw failure("POST /v1/render", result);
  const std::string& pfm = result->body;
  return fingerprint(image::decode_pfm(std::span(reinterpret_cast<const std::uint8_t*>(pfm.data()), pfm.size())));
}

}  // namespace bench
