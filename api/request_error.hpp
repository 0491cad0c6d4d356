// The one error type for a request that cannot be served as asked.
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

}  // namespace api
