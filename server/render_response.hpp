// The HTTP response for a finished render: the image in the requested format with its
// stats in headers, or (Accept: application/json) stats and image together as JSON.
#pragma once

#include "api/render_request.hpp"
#include "renderer/renderer.hpp"

#include <httplib.h>
#include <nlohmann/json_fwd.hpp>

#include <string>

namespace server {

// Headers carry at most this much stats JSON: HTTP clients cap header lines (httplib at
// 8 KiB, curl at 100 KiB). Larger stats lose their per-iteration LPV flux first.
inline constexpr std::size_t kMaxStatsHeaderBytes = 8000;

// The X-Render-Stats value: compact ASCII JSON, shortened as above when needed; the
// parts left out are listed in `omitted` (empty when nothing was).
std::string stats_header_value(const nlohmann::json& stats, std::string& omitted);

// The Server-Timing value: every pass that ran (its median device time), then gpu (their
// sum), wall (one frame), queue, encode and total (arrival to response), all in ms.
std::string server_timing_value(const api::RenderStats& stats, double queue_ms, double encode_ms, double total_ms);

// Encodes the image here, on the HTTP thread, so the render worker is already free for
// the next request, and fills `response`. The total in Server-Timing is this thread's
// request clock (request_log.hpp) read after encoding.
void send_render_result(httplib::Response& response, renderer::RenderResult& result, api::ImageFormat format,
                        bool as_json, double queue_ms);

}  // namespace server
