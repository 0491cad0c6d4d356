// POST /v1/compare and POST /v1/sweep (docs/accuracy.md, api/openapi.yaml).
#pragma once

#include "server/route_support.hpp"

#include <httplib.h>

namespace server {

// Answers JSON: both images (PNG, base64), the difference heat map, the metrics on the final
// image and on the indirect light, both sides' stats (or the reference's report).
void handle_compare(const httplib::Request& request, httplib::Response& response,
                    const httplib::ContentReader& content, Service& service);

// ?format=json (the default): the finished table with the reference's report; csv; svg (the
// error-against-time plot); ndjson (or Accept: application/x-ndjson): events streamed as the
// sweep runs, one JSON object per line, the last {"event": "done", ...} or {"event": "error"}.
void handle_sweep(const httplib::Request& request, httplib::Response& response, const httplib::ContentReader& content,
                  Service& service);

}  // namespace server
