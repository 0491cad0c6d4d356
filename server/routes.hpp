// The HTTP surface of lpv-server (api/openapi.yaml is its contract): the route table
// (server/route_table.hpp) and its handlers, authentication, JSON bodies for httplib's own
// errors, the request log and metrics.
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

}  // namespace server
