#include "server/routes.hpp"

#include "api/request_error.hpp"
#include "api/request_json.hpp"
#include "core/utc_time.hpp"
#include "scene/builtin_scenes.hpp"
#include "server/access.hpp"
#include "server/accuracy_routes.hpp"
#include "server/bench_route.hpp"
#include "server/client_connection.hpp"
#include "server/http_errors.hpp"
#include "server/render_response.hpp"
#include "server/request_log.hpp"
#include "server/route_table.hpp"
#include "server/scene_report.hpp"
#include "server/web_routes.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string_view>
#include <vector>

namespace server {
namespace {

// The longest a scene's name may be; it is only ever shown.
constexpr std::size_t kMaxSceneNameBytes = 200;

// httplib percent-decodes the path, which then need not be UTF-8, and JSON must be: the log
// line percent-encodes every byte outside printable ASCII again.
std::string loggable_path(const std::string& path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (const unsigned char c : path) {
    if (c >= 0x20 && c < 0x7f && c != '%') {
      out += char(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 0xf];
    }
  }
  return out;
}

std::string known_method(const std::string& method) {
  for (const char* m : {"GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS"})
    if (method == m) return method;
  return "other";
}

void handle_render(const httplib::Request& request, httplib::Response& response,
                   const httplib::ContentReader& content, Service& service) {
  auto accepted = accept_request<api::RenderRequest>(
      request, response, content, service, api::parse_render_request, service.options.deadline,
      [&](const api::RenderRequest& r) { return missing_scene(r.scene, "scene", service); });
  if (!accepted) return;
  const api::ImageFormat format = accepted->request.output.format;
  auto job = std::make_shared<RenderJob>(std::move(accepted->request), request_arrival() + accepted->deadline);
  if (!run_job(job, accepted->deadline, request, response, service)) return;
  if (job->request.dry_run)  // the plan alone: what would run, nothing rendered (nor timed)
    return send_json(response, {{"stats", api::to_json(job->result->stats)}, {"queue_ms", job->queue_wait_ms}});
  for (const auto& pass : job->result->stats.passes)
    if (pass.ran) service.metrics.observe_pass(pass.name, pass.gpu_ms.median / 1000.0);
  // Encoding counts against the deadline too: a 4096^2 PNG takes seconds.
  if (Clock::now() >= job->deadline)
    return send_error(response, {504, "deadline_exceeded",
                                 "rendered, but the deadline of " + std::to_string(accepted->deadline.count()) +
                                     " ms passed before the image could be encoded",
                                 ""});
  send_render_result(response, *job->result, format, wants_json(request), job->queue_wait_ms);
}

// ?name=: shown in listings, so it must be printable text of a sane length; absent or empty: the id.
std::string scene_name(const httplib::Request& request) {
  const std::string name = request.get_param_value("name");
  if (name.size() > kMaxSceneNameBytes)
    throw api::RequestError("name", "must be at most " + std::to_string(kMaxSceneNameBytes) + " bytes");
  if (std::any_of(name.begin(), name.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; }))
    throw api::RequestError("name", "must not contain control characters");
  try {
    (void)nlohmann::json(name).dump();  // throws on invalid UTF-8
  } catch (const nlohmann::json::exception&) {
    throw api::RequestError("name", "must be UTF-8 text");
  }
  return name;
}

// A new scene warmed up on a render worker before the upload is answered, so that the
// client's first render of it costs what later ones do (Renderer::prepare). Best effort: a
// full queue, or a warm-up slower than kUploadWarmUpWait, leaves it to the first render,
// which then reports the time as cpu_ms.warm_up. Other workers warm it on first use.
void prepare_uploaded(const std::string& id, const httplib::Request& request, httplib::Response& response,
                      Service& service) {
  constexpr auto kUploadWarmUpWait = std::chrono::seconds(20);
  const auto job = std::make_shared<PrepareJob>(id, Clock::now() + kUploadWarmUpWait);
  if (service.queue.submit(job) != RenderQueue::Admission::accepted) return;
  const ClientConnection client(request);
  const std::optional<RenderQueue::Outcome> outcome =
      service.queue.wait_until(*job, [&] { return client.closed(); }, Clock::now() + kUploadWarmUpWait);
  if (outcome == RenderQueue::Outcome::done && !job->error)
    response.set_header("Server-Timing", "warm_up;dur=" + std::to_string(job->warm_up_ms));
}

void handle_upload(const httplib::Request& request, httplib::Response& response,
                   const httplib::ContentReader& content, Service& service) {
  std::string name;
  try {
    name = scene_name(request);
  } catch (const api::RequestError& e) {
    send_error(response, parse_error(e));
    return;
  }
  if (!media_type_accepted(request, response, kSceneMediaTypes)) return;
  const std::optional<std::string> body =
      read_body(request, response, content, service.options, service.options.max_scene_bytes, "--max-scene-bytes");
  if (!body) return;
  try {
    const SceneStore::Added added = service.scenes.add(*body, name);
    const std::string id = added.report.at("id").get<std::string>();
    if (added.created) prepare_uploaded(id, request, response, service);
    // The same bytes again are the same scene: 200 with the first upload's report.
    send_json(response, added.report, added.created ? 201 : 200);
    response.set_header("Location", "/v1/scenes/" + id);
  } catch (const scene::LoadError& e) {
    send_error(response, load_error(e));
  } catch (const StoreFull& e) {
    send_error(response, {507, "insufficient_storage", e.what(), ""});
  }
}

// Every scene a client can name: the built-in ones, reported once since they never change
// while the server runs, then the uploaded ones as the store has them now.
class SceneCatalog {
 public:
  explicit SceneCatalog(const SceneStore& store) : builtin_(builtin_scene_reports()), store_(store) {}

  nlohmann::json list() const {
    nlohmann::json scenes = nlohmann::json::array();
    for (const auto& report : builtin_) scenes.push_back(report);
    for (auto& report : store_.reports()) scenes.push_back(std::move(report));
    return {{"scenes", std::move(scenes)}};
  }
  const nlohmann::json* builtin(const std::string& name) const {
    for (const auto& report : builtin_)
      if (report["name"] == name) return &report;
    return nullptr;
  }

 private:
  const std::vector<nlohmann::json> builtin_;
  const SceneStore& store_;
};

void handle_get_scene(const std::string& id, httplib::Response& response, const SceneCatalog& catalog,
                      const SceneStore& store) {
  if (const nlohmann::json* builtin = catalog.builtin(id)) return send_json(response, *builtin);
  if (const std::optional<nlohmann::json> uploaded = store.report(id)) return send_json(response, *uploaded);
  send_error(response, unknown_scene(id, ""));
}

void handle_delete_scene(const std::string& id, httplib::Response& response, const SceneCatalog& catalog,
                         SceneStore& store) {
  if (catalog.builtin(id)) return send_error(response, builtin_scene_conflict(id));
  if (!store.remove(id)) return send_error(response, unknown_scene(id, ""));
  response.status = 204;
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

bool changes_state(const std::string& method) {
  return method == "POST" || method == "PUT" || method == "PATCH" || method == "DELETE";
}

// What a web page elsewhere must not make a browser do here (docs/server.md, "Cross-site
// requests"): without a token, be answered under a name that is not this server's (a
// DNS-rebinding page reads the answers: 421); ever, change state from another origin (403).
// Requests without Host or Origin come from no browser and pass.
std::optional<HttpError> cross_site_refusal(const httplib::Request& request, const Service& service,
                                            const HostPolicy& hosts, const RouteTable& routes) {
  const std::string host = request.get_header_value("Host");
  if (service.options.token.empty() && request.has_header("Host") && !hosts.allows(host)) {
    const Route* route = routes.find(request.path);
    if (!route || !route->probe)
      return HttpError{421, "misdirected_request",
                       "this server answers requests for loopback names and those --allowed-host names, not '" +
                           host + "' (without a token, another name may be a page's DNS rebinding)",
                       ""};
  }
  if (changes_state(request.method) && request.has_header("Origin")) {
    const std::string origin = request.get_header_value("Origin");
    const std::string authority = origin_authority(origin);
    if (authority.empty() || (authority != ascii_lowercase(host) && !hosts.allows(authority)))
      return HttpError{403, "forbidden_origin",
                       "a page from '" + origin + "' may not " + request.method + " here: only this server's own "
                       "page, loopback origins and --allowed-host names may",
                       ""};
  }
  return std::nullopt;
}

// The names requests may carry: loopback ones, --allowed-host's, and the address the server
// listens on when it is one (not 0.0.0.0 or ::).
HostPolicy host_policy(const ServerOptions& options) {
  std::vector<std::string> allowed = options.allowed_hosts;
  if (options.host != "0.0.0.0" && options.host != "::" && !options.host.empty()) allowed.push_back(options.host);
  return HostPolicy(std::move(allowed));
}

std::vector<Route> probe_routes(const RenderQueue& queue) {
  return {
      {"/healthz", "/healthz", true, true,
       {{"GET", [](const httplib::Request&, httplib::Response& response) { send_json(response, {{"status", "alive"}}); }}}},
      {"/readyz", "/readyz", true, true,
       {{"GET", [&queue](const httplib::Request&, httplib::Response& response) { handle_readyz(response, queue); }}}},
  };
}

// A POST handler that reads its own body, with the service: the form of every handle_* that
// takes one.
using BodyHandler = void (*)(const httplib::Request&, httplib::Response&, const httplib::ContentReader&, Service&);
httplib::Server::HandlerWithContentReader reading_body(BodyHandler handle, Service& service) {
  return [handle, &service](const httplib::Request& request, httplib::Response& response,
                            const httplib::ContentReader& content) { handle(request, response, content, service); };
}

// Every route of the main listener: api/openapi.yaml's paths, then the web page.
RouteTable service_routes(Service& service) {
  using Request = httplib::Request;
  using Response = httplib::Response;
  auto catalog = std::make_shared<const SceneCatalog>(service.scenes);
  std::vector<Route> routes = probe_routes(service.queue);
  const std::vector<Route> rest = {
      {"/metrics", "/metrics", false, false,
       {{"GET", [&service](const Request&, Response& response) {
           const SceneStore::Totals stored = service.scenes.totals();
           response.set_content(service.metrics.prometheus_text(service.queue.gauges(), {stored.scenes, stored.bytes}),
                                "text/plain; version=0.0.4");
         }}}},
      {"/v1/scenes", "/v1/scenes", false, false,
       {{"GET", [catalog](const Request&, Response& response) { send_json(response, catalog->list()); }},
        {"POST", reading_body(handle_upload, service)}}},
      {"/v1/scenes/([^/]+)", "/v1/scenes/{id}", false, false,
       {{"GET", [catalog, &service](const Request& request, Response& response) {
           handle_get_scene(request.matches[1].str(), response, *catalog, service.scenes);
         }},
        {"DELETE", [catalog, &service](const Request& request, Response& response) {
           handle_delete_scene(request.matches[1].str(), response, *catalog, service.scenes);
         }}}},
      {"/v1/device", "/v1/device", false, false,
       {{"GET", [&service](const Request&, Response& response) {
           if (const auto report = service.queue.device_report()) return send_json(response, *report);
           send_unavailable(response, "not_ready", "the render device is still starting");
         }}}},
      {"/v1/render", "/v1/render", false, false,
       {{"POST", reading_body(handle_render, service)}}},
      {"/v1/compare", "/v1/compare", false, false,
       {{"POST", reading_body(handle_compare, service)}}},
      {"/v1/sweep", "/v1/sweep", false, false,
       {{"POST", reading_body(handle_sweep, service)}}},
      {"/v1/bench", "/v1/bench", false, false,
       {{"POST", reading_body(handle_bench, service)}}},
      // The web page (docs/web.md) and its assets.
      {kWebPageRoute, "/", true, false, {{"GET", serve_web_asset}}},
      {kWebAssetRoute, "/{asset}", true, false, {{"GET", serve_web_asset}}},
  };
  routes.insert(routes.end(), rest.begin(), rest.end());
  return RouteTable(std::move(routes));
}

}  // namespace

void install_probe_routes(httplib::Server& http, const RenderQueue& queue) {
  RouteTable(probe_routes(queue)).install(http);
}

void install_routes(httplib::Server& http, Service& service) {
  auto hosts = std::make_shared<const HostPolicy>(host_policy(service.options));
  auto routes = std::make_shared<const RouteTable>(service_routes(service));
  http.set_pre_routing_handler([&service, hosts, routes](const httplib::Request& request, httplib::Response& response) {
    start_request_clock();
    if (const std::optional<HttpError> refusal = cross_site_refusal(request, service, *hosts, *routes)) {
      send_error(response, *refusal);
      return httplib::Server::HandlerResponse::Handled;
    }
    if (service.options.token.empty()) return httplib::Server::HandlerResponse::Unhandled;
    // The token first: a request that has it never runs the route regexes here.
    if (bearer_token_matches(request.get_header_value("Authorization"), service.options.token))
      return httplib::Server::HandlerResponse::Unhandled;
    if (const Route* route = routes->find(request.path); route && route->open)
      return httplib::Server::HandlerResponse::Unhandled;
    send_error(response, {401, "unauthorized", "this server needs 'Authorization: Bearer <token>'", ""});
    response.set_header("WWW-Authenticate", "Bearer");
    return httplib::Server::HandlerResponse::Handled;
  });
  routes->install(http);

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
  // Metrics label requests by their route's pattern, or "unmatched": labels must not grow with
  // whatever paths clients make up.
  http.set_logger([&service, routes](const httplib::Request& request, const httplib::Response& response) {
    const std::optional<double> ms = request_elapsed_ms();
    const Route* matched = routes->find(request.path);
    const std::string route = matched ? matched->pattern : "unmatched";
    service.metrics.count_request(route, known_method(request.method), response.status, ms.value_or(0.0) / 1000.0);
    nlohmann::json line = {{"time", core::utc_timestamp()},
                           {"method", request.method},
                           {"path", loggable_path(request.path)},
                           {"status", response.status},
                           {"ms", nullptr},
                           {"queue_ms", nullptr},
                           {"bytes", response.body.size()},
                           {"remote", request.remote_addr}};
    if (ms) line["ms"] = *ms;
    if (const auto wait = queue_wait_ms()) line["queue_ms"] = *wait;
    write_log_line(line);
    end_request_clock();
  });
}

}  // namespace server
