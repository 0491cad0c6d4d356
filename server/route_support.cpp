#include "server/route_support.hpp"

#include "api/request_error.hpp"
#include "scene/builtin_scenes.hpp"
#include "server/access.hpp"
#include "server/client_connection.hpp"
#include "server/http_errors.hpp"
#include "server/request_log.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>

namespace server {

void send_json(httplib::Response& response, const nlohmann::json& body, int status, const char* content_type) {
  response.status = status;
  response.set_content(body.dump(-1, ' ', true, nlohmann::json::error_handler_t::replace) + "\n", content_type);
}

void send_unavailable(httplib::Response& response, const std::string& code, const std::string& message) {
  send_error(response, {503, code, message, ""});  // with Retry-After
}



// X-Deadline-Ms lets a client ask for a shorter deadline than the server's.
std::chrono::milliseconds deadline_for(const httplib::Request& request, std::chrono::milliseconds server_deadline) {
  if (!request.has_header("X-Deadline-Ms")) return server_deadline;
  const std::string text = request.get_header_value("X-Deadline-Ms");
  long long ms = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), ms);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || ms < 1)
    throw api::RequestError("X-Deadline-Ms", "must be a whole number of milliseconds >= 1, got '" + text + "'");
  return std::min(server_deadline, std::chrono::milliseconds(ms));
}

bool wants_json(const httplib::Request& request) {
  return request.get_header_value("Accept").find("application/json") != std::string::npos;
}

// httplib's payload limit is the largest of all routes' (largest_body_bytes: scene uploads)
// and covers Content-Length but not a chunked body. A body over `limit` is still read to its
// end, as httplib does past its own limit, so the 413 comes after it and the connection stays
// usable; but a chunked one only up to httplib's limit.
std::optional<std::string> read_body(const httplib::Request& request, httplib::Response& response,
                                     const httplib::ContentReader& content, const ServerOptions& options,
                                     std::size_t limit, const char* flag) {
  // RFC 9112 6.3: a request with neither Content-Length nor Transfer-Encoding has no body.
  // httplib 0.11 reads such a body until the client closes, which a client waiting for the
  // answer never does (`curl -X POST` without -d stalled 5 s, then got 400).
  if (!request.has_header("Content-Length") && !request.has_header("Transfer-Encoding")) return std::string();
  std::string body;
  std::size_t received = 0;
  const bool complete = content([&](const char* data, std::size_t length) {
    received += length;
    if (received <= limit) body.append(data, length);
    return received <= largest_body_bytes(options);
  });
  if (received > limit || response.status == 413) {
    send_error(response, payload_too_large(limit, flag));
    return std::nullopt;
  }
  if (!complete) {
    send_error(response, error_for_status(400, request));
    return std::nullopt;
  }
  return body;
}

bool media_type_accepted(const httplib::Request& request, httplib::Response& response,
                         std::span<const std::string_view> types) {
  const bool typed = request.has_header("Content-Type");
  const bool no_body = !request.has_header("Transfer-Encoding") &&
                       (!request.has_header("Content-Length") || request.get_header_value("Content-Length") == "0");
  if (!typed && no_body) return true;
  const std::string value = request.get_header_value("Content-Type");
  std::string type = ascii_lowercase(value.substr(0, value.find(';')));
  type.erase(std::remove_if(type.begin(), type.end(), [](char c) { return c == ' ' || c == '\t'; }), type.end());
  if (std::find(types.begin(), types.end(), type) != types.end()) return true;
  std::string listed;
  for (const std::string_view t : types) listed += (listed.empty() ? "" : ", ") + std::string(t);
  send_error(response, {415, "unsupported_media_type",
                        (typed ? "a body of type '" + value + "'" : std::string("a body without a Content-Type")) +
                            " is not read here: send it as " + listed,
                        ""});
  response.set_header("Accept-Post", listed);
  return false;  // the body is left unread: the server closes the connection after the answer
}

Clock::time_point request_arrival() {
  return Clock::now() - std::chrono::duration_cast<Clock::duration>(
                            std::chrono::duration<double, std::milli>(request_elapsed_ms().value_or(0.0)));
}

std::optional<HttpError> missing_scene(const std::string& name, const std::string& field, const Service& service) {
  for (const auto& info : scene::builtin_scenes())
    if (info.name == name) return std::nullopt;
  if (service.scenes.contains(name)) return std::nullopt;
  return unknown_scene(name, field);
}

bool admit_job(const std::shared_ptr<Job>& job, httplib::Response& response, Service& service) {
  switch (service.queue.submit(job)) {
    case RenderQueue::Admission::accepted: return true;
    case RenderQueue::Admission::full:
      service.metrics.count_render("queue_full");
      send_unavailable(response, "queue_full", "the render queue is full; retry shortly");
      return false;
    case RenderQueue::Admission::stopping:
      send_unavailable(response, "shutting_down", "the server is shutting down");
      return false;
  }
  return false;
}

bool answer_job_error(const Job& job, httplib::Response& response, Service& service) {
  if (!job.error) return false;
  try {
    std::rethrow_exception(job.error);
  } catch (const JobStopped& e) {
    service.metrics.count_render("deadline_exceeded");
    send_error(response, {504, "deadline_exceeded", e.what(), ""});
  } catch (const renderer::RenderStopped&) {
    service.metrics.count_render("deadline_exceeded");
    send_error(response, {504, "deadline_exceeded",
                          "stopped before it finished: past its deadline, or the server is shutting down", ""});
  } catch (const api::RequestError& e) {
    service.metrics.count_render("rejected");
    send_error(response, request_error(e));
  } catch (const scene::LoadError& e) {
    // A stored scene over limits lowered since it was uploaded.
    service.metrics.count_render("rejected");
    send_error(response, load_error(e));
  } catch (const std::exception& e) {
    service.metrics.count_render("failed");
    send_error(response, {500, "render_failed", e.what(), ""});
  }
  return true;
}

bool run_job(const std::shared_ptr<Job>& job, std::chrono::milliseconds deadline, const httplib::Request& request,
             httplib::Response& response, Service& service) {
  if (!admit_job(job, response, service)) return false;
  const ClientConnection client(request);
  const RenderQueue::Outcome outcome = service.queue.wait(*job, [&] { return client.closed(); });
  // Answered without its result: a long job still running ends at its next step.
  if (outcome != RenderQueue::Outcome::done) job->abandoned = true;
  note_queue_wait_ms(job->queue_wait_ms);
  service.metrics.observe_queue_wait(job->queue_wait_ms / 1000.0);
  if (outcome == RenderQueue::Outcome::client_gone) {
    service.metrics.count_render("client_gone");
    // Nobody reads this; the status is for the log and the metrics (as nginx's 499).
    send_error(response, {499, "client_closed_request", "the client closed the connection", ""});
    return false;
  }
  if (outcome == RenderQueue::Outcome::deadline_exceeded) {
    service.metrics.count_render("deadline_exceeded");
    send_error(response, {504, "deadline_exceeded",
                          "no result within the deadline of " + std::to_string(deadline.count()) + " ms", ""});
    return false;
  }
  if (answer_job_error(*job, response, service)) return false;
  service.metrics.count_render("ok");
  return true;
}

}  // namespace server
