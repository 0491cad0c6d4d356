// POST /v1/bench (docs/perf-regression.md, api/openapi.yaml).
#pragma once

#include "server/route_support.hpp"

#include <httplib.h>

namespace server {

// The body is a suite (bench/suites/*.json, without scene files); the answer its results
// (bench/results.schema.json), rendered by a render worker as one job.
void handle_bench(const httplib::Request& request, httplib::Response& response, const httplib::ContentReader& content,
                  Service& service);

}  // namespace server
