// The HTTP surface of lpv-server (api/openapi.yaml is its contract): routes, 405s,
// authentication, JSON bodies for httplib's own errors, the request log and metrics.
#pragma once

#include "server/route_support.hpp"

#include <httplib.h>

#include <string>

namespace server {

// Installs every handler on `http`; `service` must outlive it.
void install_routes(httplib::Server& http, Service& service);

// GET /healthz and /readyz alone: the main routes have them, and so does --health-port's
// listener, whose threads no client of the main port can take.
void install_probe_routes(httplib::Server& http, const RenderQueue& queue);

// The route pattern a path belongs to ("/v1/scenes/{id}"), or "unmatched": metrics
// labels must not grow with whatever paths clients make up.
std::string route_pattern(const std::string& path);

}  // namespace server
