// The examples of api/openapi.yaml, read without a YAML library. The file keeps to a
// convention (stated at its top) that makes that possible: every example is a
// `value:` line holding one line of JSON, under a key naming it; paths are indented 2
// spaces, operations 4, their requestBody/parameters/responses 6 and status codes 8.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace server_test {

struct OpenApiExample {
  std::string path;      // "/v1/scenes/{id}"
  std::string method;    // "get", "post"
  std::string location;  // "requestBody", "parameters", or a response status ("200", "404")
  std::string name;      // the example's key
  nlohmann::json value;
};

// Throws std::runtime_error naming the line when an example's value is not JSON.
std::vector<OpenApiExample> read_openapi_examples(const std::string& yaml_file);

}  // namespace server_test
