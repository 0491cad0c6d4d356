#include "server/http_errors.hpp"

#include "scene/builtin_scenes.hpp"

#include <nlohmann/json.hpp>

namespace server {
namespace {

// RequestError::what() is "field: message"; the body carries the two apart.
std::string message_of(const api::RequestError& error) {
  std::string what = error.what();
  const std::string prefix = error.field() + ": ";
  if (!error.field().empty() && what.starts_with(prefix)) what.erase(0, prefix.size());
  return what;
}

std::string builtin_scene_names() {
  std::string names;
  for (const auto& info : scene::builtin_scenes()) names += (names.empty() ? "" : ", ") + info.name;
  return names;
}

}  // namespace

namespace {

// The JSON body of every error answer.
std::string error_body(const HttpError& error) {
  const nlohmann::json body = {
      {"error", {{"code", error.code}, {"message", error.message}, {"field", error.field}}}};
  // Messages may quote what a client sent (a path), which need not be UTF-8.
  return body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

// Every 503 is worth retrying: a render takes tens of milliseconds, so a second is ample.
constexpr const char* kRetryAfter503 = "1";

const char* reason_phrase(int status) {
  switch (status) {
    case 400: return "Bad Request";
    case 408: return "Request Timeout";
    case 413: return "Content Too Large";
    case 431: return "Request Header Fields Too Large";
    case 501: return "Not Implemented";
    case 503: return "Service Unavailable";
    default: return "Error";
  }
}

}  // namespace

void send_error(httplib::Response& response, const HttpError& error) {
  response.status = error.status;
  response.set_content(error_body(error), "application/json");
  if (error.status == 503 && !response.has_header("Retry-After")) response.set_header("Retry-After", kRetryAfter503);
}

std::string raw_error_response(const HttpError& error) {
  const std::string body = error_body(error);
  std::string head = "HTTP/1.1 " + std::to_string(error.status) + " " + reason_phrase(error.status) +
                     "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) +
                     "\r\nConnection: close\r\n";
  if (error.status == 503) head += std::string("Retry-After: ") + kRetryAfter503 + "\r\n";
  return head + "\r\n" + body;
}

HttpError parse_error(const api::RequestError& error) {
  std::string message = message_of(error);
  const bool malformed = error.field().empty() && message.starts_with("invalid JSON");
  return {400, malformed ? "malformed_json" : "invalid_value", std::move(message), error.field()};
}

HttpError limit_error(const LimitExceeded& error) { return {422, "limit_exceeded", error.what(), error.field()}; }

HttpError request_error(const api::RequestError& error) {
  if (dynamic_cast<const api::NotFound*>(&error)) return {404, "scene_not_found", message_of(error), error.field()};
  if (dynamic_cast<const api::DoesNotFit*>(&error)) return {422, "does_not_fit", message_of(error), error.field()};
  return parse_error(error);
}

HttpError unknown_scene(const std::string& name, const std::string& field) {
  return {404, "scene_not_found",
          "unknown scene '" + name + "'; built-in scenes: " + builtin_scene_names() +
              ", or the id of an uploaded scene (GET /v1/scenes lists them)",
          field};
}

HttpError load_error(const scene::LoadError& error) {
  switch (error.kind()) {
    case scene::LoadError::Kind::invalid: return {422, "invalid_scene", error.what(), ""};
    case scene::LoadError::Kind::unsupported: return {422, "unsupported_scene", error.what(), ""};
    case scene::LoadError::Kind::too_complex: return {422, "scene_too_complex", error.what(), ""};
    case scene::LoadError::Kind::busy: return {503, "busy_decoding", error.what(), ""};
  }
  return {422, "invalid_scene", error.what(), ""};
}

HttpError payload_too_large(std::size_t limit_bytes, const std::string& flag) {
  return {413, "payload_too_large",
          "the request body is over this server's limit of " + std::to_string(limit_bytes) + " bytes (" + flag + ")",
          ""};
}

HttpError builtin_scene_conflict(const std::string& name) {
  return {409, "builtin_scene", "'" + name + "' is a built-in scene; only uploaded scenes can be deleted", ""};
}

HttpError error_for_status(int status, const httplib::Request& request) {
  switch (status) {
    case 400: return {400, "bad_http_request", "the HTTP request could not be read", ""};
    case 404: return {404, "not_found", "no route " + request.method + " " + request.path, ""};
    case 413: return {413, "payload_too_large", "the request body is over the server's limit", ""};
    case 414: return {414, "uri_too_long", "the request target is too long", ""};
    default: return {status, "http_" + std::to_string(status), "HTTP status " + std::to_string(status), ""};
  }
}

}  // namespace server
