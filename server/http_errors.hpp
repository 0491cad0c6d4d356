// Every error the server answers is JSON: {"error": {"code", "message", "field"}}.
// This file maps the failures of each layer to a status and a stable code.
#pragma once

#include "api/request_error.hpp"
#include "scene/gltf_loader.hpp"
#include "server/limits.hpp"

#include <httplib.h>

#include <cstddef>
#include <string>

namespace server {

struct HttpError {
  int status = 500;
  std::string code;     // stable, for programs: "invalid_value", "queue_full", ...
  std::string message;  // for people
  std::string field;    // JSON path into the request, or "" when no one field is at fault
};

// Sets status, the JSON body and its content type.
void send_error(httplib::Response& response, const HttpError& error);
// The same answer as raw HTTP/1.1 with "Connection: close", for what answers without httplib
// (the front, server/http_front, and its streams): the statuses it gives have their reasons.
std::string raw_error_response(const HttpError& error);

// The request did not parse or did not validate against the schema: 400.
HttpError parse_error(const api::RequestError& error);
// The request is valid but over this server's limits: 422.
HttpError limit_error(const LimitExceeded& error);
// Any of the three kinds by its type (api/request_error.hpp): api::NotFound 404
// scene_not_found, api::DoesNotFit 422 does_not_fit, otherwise as parse_error: 400.
HttpError request_error(const api::RequestError& error);
// A body over `limit_bytes`, which `flag` sets: 413.
HttpError payload_too_large(std::size_t limit_bytes, const std::string& flag);
// Neither a built-in scene nor an uploaded one: 404, naming `field` (where the request
// named it; "" when the path did).
HttpError unknown_scene(const std::string& name, const std::string& field);
// A scene file that does not load: 422 invalid_scene, unsupported_scene or scene_too_complex.
HttpError load_error(const scene::LoadError& error);
// Built-in scenes are part of the server: deleting one is 409.
HttpError builtin_scene_conflict(const std::string& name);

// For statuses httplib sets itself (no route, body too large, unparsable HTTP) and
// any other status that reached the client without a body.
HttpError error_for_status(int status, const httplib::Request& request);

}  // namespace server
