// What the HTTP handlers of renders, compares, sweeps and benchmark suites share: reading
// and checking their requests, deadlines, and running a job through the render queue with
// every outcome answered.
#pragma once

#include "server/fronted_server.hpp"

#include "api/request_error.hpp"
#include "server/http_errors.hpp"
#include "server/limits.hpp"
#include "server/metrics.hpp"
#include "server/render_queue.hpp"
#include "server/scene_store.hpp"
#include "server/server_options.hpp"

#include <httplib.h>
#include <nlohmann/json_fwd.hpp>

#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace server {

struct Service {
  const ServerOptions& options;
  RenderQueue& queue;
  Metrics& metrics;
  SceneStore& scenes;
};

// JSON answers that carry base64 images are not compressed (server/fronted_server.hpp).
inline constexpr const char* kJson = "application/json";
inline constexpr const char* kImageJson = kUncompressedJson;

void send_json(httplib::Response& response, const nlohmann::json& body, int status = 200,
               const char* content_type = kJson);
// 503 with Retry-After.
void send_unavailable(httplib::Response& response, const std::string& code, const std::string& message);

// Reads the body ourselves, up to `limit` bytes (`flag` sets it). Empty after answering 413,
// or 400 for a body that ended early (the client went away).
std::optional<std::string> read_body(const httplib::Request& request, httplib::Response& response,
                                     const httplib::ContentReader& content, const ServerOptions& options,
                                     std::size_t limit, const char* flag);

// The media types a route reads: its body must carry one (type/subtype, any case, any
// parameters), else 415 with Accept-Post listing them, decided from the headers before any
// of the body is read (the connection then closes). A request with no body and no
// Content-Type passes (an empty render is "{}"). The three types a web page may send
// elsewhere without asking first (text/plain, forms) are none of them, so no other site's
// page can make a browser post here (docs/server.md, "Cross-site requests").
inline constexpr std::string_view kJsonMediaTypes[] = {"application/json"};
inline constexpr std::string_view kSceneMediaTypes[] = {"model/gltf-binary", "model/gltf+json", "application/json",
                                                        "application/octet-stream"};
bool media_type_accepted(const httplib::Request& request, httplib::Response& response,
                         std::span<const std::string_view> types);

// The server's deadline for this kind of work, shortened by the client's X-Deadline-Ms;
// throws api::RequestError for a malformed header.
std::chrono::milliseconds deadline_for(const httplib::Request& request, std::chrono::milliseconds server_deadline);
// When this thread's request arrived (deadlines count from there).
Clock::time_point request_arrival();

bool wants_json(const httplib::Request& request);
// 404 naming `field` unless the scene is built in or uploaded: checked before queueing, so an
// unknown scene never takes a queue slot.
std::optional<HttpError> missing_scene(const std::string& name, const std::string& field, const Service& service);

template <class Request>
struct AcceptedRequest {
  Request request;
  std::chrono::milliseconds deadline{};
};

// A POST body read within --max-body-bytes and parsed by `parse` (400; an empty body is
// "{}"), with its deadline (X-Deadline-Ms within `server_deadline`), what `unservable`
// finds (an unknown scene: 404) and the server's limits (422) checked, in that order. Answers every failure itself and
// returns empty then.
template <class Request, class Unservable>
std::optional<AcceptedRequest<Request>> accept_request(const httplib::Request& request, httplib::Response& response,
                                                       const httplib::ContentReader& content, const Service& service,
                                                       Request (*parse)(std::string_view),
                                                       std::chrono::milliseconds server_deadline,
                                                       Unservable unservable) {
  if (!media_type_accepted(request, response, kJsonMediaTypes)) return std::nullopt;
  const std::optional<std::string> body =
      read_body(request, response, content, service.options, service.options.max_body_bytes, "--max-body-bytes");
  if (!body) return std::nullopt;
  AcceptedRequest<Request> accepted;
  try {
    // An empty body (curl -X POST without -d) is the empty request: every field defaulted.
    accepted.request = parse(body->empty() ? std::string_view("{}") : std::string_view(*body));
    accepted.deadline = deadline_for(request, server_deadline);
  } catch (const api::RequestError& e) {
    send_error(response, parse_error(e));
    return std::nullopt;
  }
  if (const std::optional<HttpError> error = unservable(accepted.request)) {
    send_error(response, *error);
    return std::nullopt;
  }
  try {
    check_limits(accepted.request, service.options.limits);
  } catch (const LimitExceeded& e) {
    send_error(response, limit_error(e));
    return std::nullopt;
  }
  return accepted;
}

// Submits `job`; answers 503 itself (queue full, shutting down) and returns false then.
bool admit_job(const std::shared_ptr<Job>& job, httplib::Response& response, Service& service);
// When the finished `job` failed: answers with its error's status and returns true.
bool answer_job_error(const Job& job, httplib::Response& response, Service& service);

// Submits `job` and waits for it on behalf of `request`. Answers itself when the queue is
// full or stopping (503), the client left (499), the deadline passed (504; for a job that
// answers_partially, only while it is still queued) or the job failed
// (its error's status); true when the job is done and the caller answers with its result.
bool run_job(const std::shared_ptr<Job>& job, std::chrono::milliseconds deadline, const httplib::Request& request,
             httplib::Response& response, Service& service);

}  // namespace server
