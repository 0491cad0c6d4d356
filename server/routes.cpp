#include "server/routes.hpp"

#include "api/request_error.hpp"
#include "api/request_json.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "server/access.hpp"
#include "server/client_connection.hpp"
#include "server/http_errors.hpp"
#include "server/request_log.hpp"
#include "server/render_response.hpp"
#include "server/scene_report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <ctime>
#include <regex>
#include <vector>

namespace server {
namespace {

struct Route {
  const char* regex;    // what httplib matches
  const char* pattern;  // how docs and metrics name it
  const char* method;   // the one method it answers; others get 405
};

constexpr std::array kRoutes = {
    Route{"/healthz", "/healthz", "GET"},
    Route{"/readyz", "/readyz", "GET"},
    Route{"/metrics", "/metrics", "GET"},
    Route{"/v1/scenes", "/v1/scenes", "GET"},
    Route{"/v1/scenes/([^/]+)", "/v1/scenes/{id}", "GET"},
    Route{"/v1/device", "/v1/device", "GET"},
    Route{"/v1/render", "/v1/render", "POST"},
};

// Retry-After for 503s: a render takes tens of milliseconds, so a second is ample.
constexpr const char* kRetryAfterSeconds = "1";

void send_json(httplib::Response& response, const nlohmann::json& body) {
  response.status = 200;
  response.set_content(body.dump(-1, ' ', true) + "\n", "application/json");
}

void send_unavailable(httplib::Response& response, const std::string& code, const std::string& message) {
  send_error(response, {503, code, message, ""});
  response.set_header("Retry-After", kRetryAfterSeconds);
}

std::string utc_timestamp() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%S", &utc);
  char with_ms[40];
  std::snprintf(with_ms, sizeof(with_ms), "%s.%03dZ", text, int(ms));
  return with_ms;
}

std::string known_method(const std::string& method) {
  for (const char* m : {"GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS"})
    if (method == m) return method;
  return "other";
}

// X-Deadline-Ms lets a client ask for a shorter deadline than the server's.
std::chrono::milliseconds deadline_for(const httplib::Request& request, const ServerOptions& options) {
  if (!request.has_header("X-Deadline-Ms")) return options.deadline;
  const std::string text = request.get_header_value("X-Deadline-Ms");
  long long ms = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), ms);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || ms < 1)
    throw api::RequestError("X-Deadline-Ms", "must be a whole number of milliseconds >= 1, got '" + text + "'");
  return std::min(options.deadline, std::chrono::milliseconds(ms));
}

// Checked before queueing, so an unknown scene never takes a queue slot.
bool is_builtin_scene(const std::string& name) {
  for (const auto& info : scene::builtin_scenes())
    if (info.name == name) return true;
  return false;
}

bool wants_json(const httplib::Request& request) {
  return request.get_header_value("Accept").find("application/json") != std::string::npos;
}

void handle_render(const httplib::Request& request, httplib::Response& response,
                   const httplib::ContentReader& content, Service& service) {
  // Read the body ourselves: httplib's payload limit covers Content-Length but not a
  // chunked upload, which is cut off here as soon as it is too long.
  std::string body;
  bool too_large = false;
  const bool complete = content([&](const char* data, std::size_t length) {
    if (body.size() + length > service.options.max_body_bytes) {
      too_large = true;
      return false;
    }
    body.append(data, length);
    return true;
  });
  if (!complete) {
    send_error(response, error_for_status(too_large || response.status == 413 ? 413 : 400, request));
    return;
  }

  api::RenderRequest render_request;
  std::chrono::milliseconds deadline{};
  try {
    render_request = api::parse_render_request(body);
    deadline = deadline_for(request, service.options);
  } catch (const api::RequestError& e) {
    send_error(response, parse_error(e));
    return;
  }
  if (!is_builtin_scene(render_request.scene)) {
    send_error(response, unknown_scene(render_request.scene));
    return;
  }
  try {
    check_limits(render_request, service.options.limits);
  } catch (const LimitExceeded& e) {
    send_error(response, limit_error(e));
    return;
  }

  const auto arrival = Clock::now() - std::chrono::duration_cast<Clock::duration>(
                                          std::chrono::duration<double, std::milli>(request_elapsed_ms().value_or(0.0)));
  const api::ImageFormat format = render_request.output.format;
  auto job = std::make_shared<RenderJob>(std::move(render_request), arrival + deadline);
  switch (service.queue.submit(job)) {
    case RenderQueue::Admission::accepted: break;
    case RenderQueue::Admission::full:
      service.metrics.count_render("queue_full");
      send_unavailable(response, "queue_full", "the render queue is full; retry shortly");
      return;
    case RenderQueue::Admission::stopping:
      send_unavailable(response, "shutting_down", "the server is shutting down");
      return;
  }

  const ClientConnection client(request);
  const RenderQueue::Outcome outcome = service.queue.wait(*job, [&] { return client.closed(); });
  note_queue_wait_ms(job->queue_wait_ms);
  service.metrics.observe_queue_wait(job->queue_wait_ms / 1000.0);
  if (outcome == RenderQueue::Outcome::client_gone) {
    service.metrics.count_render("client_gone");
    // Nobody reads this; the status is for the log and the metrics (as nginx's 499).
    send_error(response, {499, "client_closed_request", "the client closed the connection", ""});
    return;
  }
  if (outcome == RenderQueue::Outcome::deadline_exceeded) {
    service.metrics.count_render("deadline_exceeded");
    send_error(response, {504, "deadline_exceeded",
                          "no image within the deadline of " + std::to_string(deadline.count()) + " ms", ""});
    return;
  }
  if (job->error) {
    try {
      std::rethrow_exception(job->error);
    } catch (const api::RequestError& e) {
      service.metrics.count_render("rejected");
      send_error(response, render_error(e));
    } catch (const std::exception& e) {
      service.metrics.count_render("failed");
      send_error(response, {500, "render_failed", e.what(), ""});
    }
    return;
  }
  service.metrics.count_render("ok");
  for (const auto& pass : job->result->stats.passes)
    if (pass.ran) service.metrics.observe_pass(pass.name, pass.gpu_ms.median / 1000.0);
  send_render_result(response, *job->result, format, wants_json(request), job->queue_wait_ms);
}

void handle_readyz(httplib::Response& response, const RenderQueue& queue) {
  const QueueGauges gauges = queue.gauges();
  if (!gauges.ready) {
    send_unavailable(response, "not_ready", "the render device is starting or the server is shutting down");
  } else if (gauges.depth >= gauges.capacity) {
    send_unavailable(response, "queue_full", "the render queue is full");
  } else {
    send_json(response, {{"status", "ready"}, {"queue_depth", gauges.depth}, {"queue_capacity", gauges.capacity}});
  }
}

void install_method_not_allowed(httplib::Server& http, const Route& route) {
  const httplib::Server::Handler refuse = [&route](const httplib::Request& request, httplib::Response& response) {
    send_error(response, {405, "method_not_allowed",
                          request.method + " is not allowed on " + route.pattern + "; use " + route.method, ""});
    response.set_header("Allow", route.method);
  };
  const std::string method = route.method;
  if (method != "GET") http.Get(route.regex, refuse);  // also HEAD
  if (method != "POST") http.Post(route.regex, refuse);
  http.Put(route.regex, refuse);
  http.Patch(route.regex, refuse);
  http.Delete(route.regex, refuse);
  http.Options(route.regex, refuse);
}

}  // namespace

std::string route_pattern(const std::string& path) {
  static const std::vector<std::regex> compiled = [] {
    std::vector<std::regex> regexes;
    for (const Route& route : kRoutes) regexes.emplace_back(route.regex);
    return regexes;
  }();
  for (std::size_t i = 0; i < kRoutes.size(); ++i)
    if (std::regex_match(path, compiled[i])) return kRoutes[i].pattern;
  return "unmatched";
}

void install_routes(httplib::Server& http, Service& service) {
  http.set_pre_routing_handler([&service](const httplib::Request& request, httplib::Response& response) {
    start_request_clock();
    if (service.options.token.empty() || request.path == "/healthz" || request.path == "/readyz")
      return httplib::Server::HandlerResponse::Unhandled;
    if (bearer_token_matches(request.get_header_value("Authorization"), service.options.token))
      return httplib::Server::HandlerResponse::Unhandled;
    send_error(response, {401, "unauthorized", "this server needs 'Authorization: Bearer <token>'", ""});
    response.set_header("WWW-Authenticate", "Bearer");
    return httplib::Server::HandlerResponse::Handled;
  });

  http.Get("/healthz", [](const httplib::Request&, httplib::Response& response) {
    send_json(response, {{"status", "alive"}});
  });
  http.Get("/readyz", [&service](const httplib::Request&, httplib::Response& response) {
    handle_readyz(response, service.queue);
  });
  http.Get("/metrics", [&service](const httplib::Request&, httplib::Response& response) {
    response.set_content(service.metrics.prometheus_text(service.queue.gauges()), "text/plain; version=0.0.4");
  });
  // Scenes are built in code and never change while the server runs: reported once.
  auto scenes = std::make_shared<const nlohmann::json>(scene_list_report());
  http.Get("/v1/scenes", [scenes](const httplib::Request&, httplib::Response& response) { send_json(response, *scenes); });
  http.Get("/v1/scenes/([^/]+)", [scenes](const httplib::Request& request, httplib::Response& response) {
    for (const auto& scene : (*scenes)["scenes"])
      if (scene["name"] == request.matches[1].str()) return send_json(response, scene);
    HttpError error = unknown_scene(request.matches[1].str());
    error.field = "";  // the scene is named by the path, not by a request field
    send_error(response, error);
  });
  http.Get("/v1/device", [&service](const httplib::Request&, httplib::Response& response) {
    if (const auto report = service.queue.device_report()) return send_json(response, *report);
    send_unavailable(response, "not_ready", "the render device is still starting");
  });
  http.Post("/v1/render", [&service](const httplib::Request& request, httplib::Response& response,
                                     const httplib::ContentReader& content) {
    handle_render(request, response, content, service);
  });
  for (const Route& route : kRoutes) install_method_not_allowed(http, route);

  // httplib answers some requests itself (no route, body too large, unreadable HTTP)
  // with an empty body; give those the same JSON error body as ours.
  http.set_error_handler([](const httplib::Request& request, httplib::Response& response) {
    if (response.body.empty()) send_error(response, error_for_status(response.status, request));
  });
  http.set_exception_handler([](const httplib::Request&, httplib::Response& response, std::exception_ptr error) {
    std::string message = "unexpected error";
    try {
      std::rethrow_exception(error);
    } catch (const std::exception& e) {
      message = e.what();
    } catch (...) {
    }
    send_error(response, {500, "internal_error", message, ""});
  });
  http.set_logger([&service](const httplib::Request& request, const httplib::Response& response) {
    const std::optional<double> ms = request_elapsed_ms();
    const std::string route = route_pattern(request.path);
    service.metrics.count_request(route, known_method(request.method), response.status, ms.value_or(0.0) / 1000.0);
    nlohmann::json line = {{"time", utc_timestamp()},   {"method", request.method}, {"path", request.path},
                           {"status", response.status}, {"ms", nullptr},          {"queue_ms", nullptr},
                           {"bytes", response.body.size()}, {"remote", request.remote_addr}};
    if (ms) line["ms"] = *ms;
    if (const auto wait = queue_wait_ms()) line["queue_ms"] = *wait;
    write_log_line(line);
    end_request_clock();
  });
}

}  // namespace server
