// A request that cannot be served as asked, in three kinds a client answers differently:
// RequestError itself, the request is invalid (fix the request); NotFound, it names what does
// not exist (a scene); DoesNotFit, it is valid but this scene, device or server cannot serve
// it (a grid over the device's buffers, a light edit past the scene's lights). The server
// answers them 400, 404 and 422 (server/http_errors.hpp), by type.
// `field` is a JSON path into the request ("output.width", "lights[2].intensity"),
// empty when the problem is the document as a whole (e.g. malformed JSON).
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace api {

class RequestError : public std::runtime_error {
 public:
  RequestError(std::string field, const std::string& message)
      : std::runtime_error(field.empty() ? message : field + ": " + message), field_(std::move(field)) {}

  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

class NotFound : public RequestError {
 public:
  using RequestError::RequestError;
};

class DoesNotFit : public RequestError {
 public:
  using RequestError::RequestError;
};

}  // namespace api
