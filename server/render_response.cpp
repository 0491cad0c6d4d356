#include "server/render_response.hpp"

#include "api/request_json.hpp"
#include "core/base64.hpp"
#include "core/elapsed.hpp"
#include "renderer/output.hpp"
#include "server/request_log.hpp"
#include "server/route_support.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace server {
namespace {

std::string ascii_json(const nlohmann::json& j) { return j.dump(-1, ' ', true); }

std::string timing_entry(const std::string& name, double ms, const char* description) {
  char text[160];
  std::snprintf(text, sizeof(text), "%s;dur=%.3f;desc=\"%s\"", name.c_str(), ms, description);
  return text;
}

}  // namespace

std::string stats_header_value(const nlohmann::json& stats, std::string& omitted) {
  nlohmann::json shorter = stats;
  std::string value = ascii_json(shorter);
  std::vector<std::string> parts;
  const auto too_long = [&] { return value.size() > kMaxStatsHeaderBytes; };
  const auto dropped = [&](const std::string& what) {
    parts.push_back(what);
    value = ascii_json(shorter);
  };
  // What goes while the header is too long, least useful first: the LPV's per-iteration flux,
  // a budget's list of candidates (its choice and runner-up stay), then the LPV stats whole.
  if (too_long() && shorter.contains("lpv") && shorter["lpv"].contains("cascades")) {
    for (auto& cascade : shorter["lpv"]["cascades"]) cascade.erase("propagated_flux");
    dropped("lpv.cascades[].propagated_flux");
  }
  if (too_long() && shorter.contains("budget")) {
    shorter["budget"].erase("candidates");
    dropped("budget.candidates");
  }
  if (too_long() && shorter.contains("lpv")) {
    shorter.erase("lpv");
    std::erase(parts, "lpv.cascades[].propagated_flux");  // it went with the rest
    dropped("lpv");
  }
  omitted.clear();
  for (const std::string& part : parts) omitted += (omitted.empty() ? "" : ", ") + part;
  return value;
}

std::string server_timing_value(const api::RenderStats& stats, double queue_ms, double encode_ms, double total_ms) {
  std::string value;
  for (const auto& pass : stats.passes)
    if (pass.ran) value += timing_entry(pass.name, pass.gpu_ms.median, "pass") + ", ";
  value += timing_entry("gpu", stats.gpu_ms.median, "sum of passes") + ", ";
  value += timing_entry("wall", stats.wall_ms.median, "one frame") + ", ";
  value += timing_entry("queue", queue_ms, "wait for a worker") + ", ";
  value += timing_entry("encode", encode_ms, "image encoding") + ", ";
  value += timing_entry("total", total_ms, "arrival to response");
  return value;
}

void send_render_result(httplib::Response& response, renderer::RenderResult& result, api::ImageFormat format,
                        bool as_json, double queue_ms) {
  const auto encode_start = std::chrono::steady_clock::now();
  const std::vector<std::uint8_t> bytes = renderer::encode_output(result, format);
  const double encode_ms =
      core::ms_since(encode_start);
  result.stats.cpu_ms["encode"] = api::TimeSummary::of({encode_ms});
  // The pixels are no longer needed; free them before building the response.
  result.display = {};
  result.linear = {};

  const nlohmann::json stats = api::to_json(result.stats);
  response.status = 200;
  if (as_json) {
    const nlohmann::json body = {
        {"stats", stats},
        {"queue_ms", queue_ms},
        {"image",
         {{"format", api::to_string(format)},
          {"media_type", renderer::media_type(format)},
          {"width", result.stats.width},
          {"height", result.stats.height},
          {"base64", core::base64_encode(bytes)}}}};
    send_json(response, body, 200, kImageJson);
  } else {
    std::string omitted;
    response.set_header("X-Render-Stats", stats_header_value(stats, omitted));
    if (!omitted.empty()) response.set_header("X-Render-Stats-Omitted", omitted);
    response.set_content(std::string(bytes.begin(), bytes.end()), renderer::media_type(format));
  }
  response.set_header("Server-Timing", server_timing_value(result.stats, queue_ms, encode_ms, request_elapsed_ms().value_or(0.0)));
}

}  // namespace server
