// The HTTP surface of lpv-server (api/openapi.yaml is its contract): routes, 405s,
// authentication, JSON bodies for httplib's own errors, the request log and metrics.
#pragma once

#include "server/metrics.hpp"
#include "server/render_queue.hpp"
#include "server/scene_store.hpp"
#include "server/server_options.hpp"

#include <httplib.h>

#include <string>

namespace server {

struct Service {
  const ServerOptions& options;
  RenderQueue& queue;
  Metrics& metrics;
  SceneStore& scenes;
};

// Installs every handler on `http`; `service` must outlive it.
void install_routes(httplib::Server& http, Service& service);

// The route pattern a path belongs to ("/v1/scenes/{id}"), or "unmatched": metrics
// labels must not grow with whatever paths clients make up.
std::string route_pattern(const std::string& path);

}  // namespace server
