// api/openapi.yaml is the contract: every request example in it is sent to the server
// exactly as written and must be answered as the response example of the same name
// documents, an error with the example's code, field and message (or 200 when there is
// none); every operation without request examples is
// called and compared with its 200 example. An example that nothing sends fails the test.
#include "http_checks.hpp"
#include "openapi_examples.hpp"
#include "server_process.hpp"

#include <gtest/gtest.h>

#include <set>

namespace server_test {
namespace {

using Examples = std::vector<OpenApiExample>;

const OpenApiExample* response_example(const Examples& all, const OpenApiExample& request) {
  for (const auto& e : all)
    if (e.path == request.path && e.method == request.method && e.name == request.name &&
        e.location != "requestBody" && e.location != "parameters")
      return &e;
  return nullptr;
}

// `{id}` in the path replaced by the parameter example's value.
std::string concrete_path(const std::string& path, const nlohmann::json& parameter) {
  const auto open = path.find('{');
  if (open == std::string::npos) return path;
  return path.substr(0, open) + parameter.get<std::string>() + path.substr(path.find('}', open) + 1);
}

// Request bodies are sent as JSON (a .gltf is JSON too); parameters fill in the path.
httplib::Result send(httplib::Client& http, const OpenApiExample& e) {
  if (e.method == "post") return http.Post(e.path, e.value.dump(), "application/json");
  if (e.method == "delete") return http.Delete(concrete_path(e.path, e.value));
  return http.Get(concrete_path(e.path, e.value));
}

void check_answer(const httplib::Result& r, const OpenApiExample* documented, const std::string& what) {
  ASSERT_TRUE(r) << what << ": " << httplib::to_string(r.error());
  const int status = documented ? std::stoi(documented->location) : 200;
  ASSERT_EQ(r->status, status) << what << ": " << r->body.substr(0, 500);
  if (!documented) return;
  if (documented->value.contains("error")) {
    EXPECT_TRUE(is_json_error(r, status, documented->value["error"]["code"], documented->value["error"]["field"]))
        << what;
    // The example's words are this version's, not a stale copy (issue 43: the unknown-field
    // list and the built-in scenes had moved on).
    const auto body = nlohmann::json::parse(r->body, nullptr, false);
    if (body.is_object() && body.contains("error")) {
      EXPECT_EQ(body["error"].value("message", ""), documented->value["error"].value("message", "")) << what;
    }
  } else {
    EXPECT_TRUE(has_shape_of(documented->value, nlohmann::json::parse(r->body))) << what;
  }
}

TEST(HttpContract, EveryOpenApiExampleIsAnsweredAsDocumented) {
  const Examples examples = read_openapi_examples(openapi_file());
  ASSERT_GE(examples.size(), 10u) << "the contract has lost its examples";
  auto http = shared_server().client();
  std::set<const OpenApiExample*> used;
  std::set<std::pair<std::string, std::string>> operations_with_requests;

  for (const auto& e : examples) {
    if (e.location != "requestBody" && e.location != "parameters") continue;
    operations_with_requests.insert({e.path, e.method});
    const OpenApiExample* documented = response_example(examples, e);
    used.insert(&e);
    if (documented) used.insert(documented);
    const std::string what = e.method + " " + e.path + " example " + e.name;
    const httplib::Result r = send(*http, e);
    if (e.path == "/v1/render") {
      if (r && r->status == 200) {
        // A PNG of the size the example asks for (512x512 by default).
        const auto output = e.value.value("output", nlohmann::json::object());
        if (output.value("format", "png") == "png") {
          const auto size = png_size(r->body);
          ASSERT_TRUE(size) << what;
          EXPECT_EQ(size->width, output.value("width", 512)) << what;
          EXPECT_EQ(size->height, output.value("height", 512)) << what;
        }
      }
    }
    check_answer(r, documented, what);
  }

  for (const auto& e : examples) {
    if (e.location != "200" || operations_with_requests.count({e.path, e.method})) continue;
    used.insert(&e);
    check_answer(http->Get(e.path), &e, "get " + e.path + " example " + e.name);
  }

  for (const auto& e : examples)
    EXPECT_TRUE(used.count(&e)) << "example " << e.name << " of " << e.method << " " << e.path << " ("
                                << e.location << ") is never sent: name it after a request example";
}

}  // namespace
}  // namespace server_test
