// One JSON line per request on standard output, and the per-request clock it needs.
// httplib runs the pre-routing handler, the route's handler and the logger of one
// request on the same thread, so the clock lives in a thread_local.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <optional>

namespace server {

// Marks the arrival of the request this thread is about to handle.
void start_request_clock();
// Milliseconds since the arrival; empty when the request never reached routing
// (httplib answers unparsable HTTP itself).
std::optional<double> request_elapsed_ms();
// The queue wait of this thread's render request, for its log line.
void note_queue_wait_ms(double ms);
std::optional<double> queue_wait_ms();
// Forgets both, after the log line is written.
void end_request_clock();

// Writes `line` as one line of compact JSON to standard output and flushes it; lines
// from concurrent requests never interleave.
void write_log_line(const nlohmann::json& line);

}  // namespace server
