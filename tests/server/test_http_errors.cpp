// Bad requests, each answered with its documented status and JSON error body, and the
// server still serving afterwards.
#include "http_checks.hpp"
#include "server_process.hpp"

#include <gtest/gtest.h>

namespace server_test {
namespace {

struct BadRequest {
  std::string name;
  std::string method;
  std::string path;
  std::string body;
  int status;
  std::string code;
  std::string field;
  httplib::Headers headers = {};
};

std::ostream& operator<<(std::ostream& out, const BadRequest& r) { return out << r.name; }

const std::vector<BadRequest> kBadRequests = {
    {"malformed JSON", "POST", "/v1/render", R"({"output": {)", 400, "malformed_json", ""},
    {"blank body (only an empty one means {})", "POST", "/v1/render", " \n", 400, "malformed_json", ""},
    {"NaN literal", "POST", "/v1/render", R"({"output": {"exposure": NaN}})", 400, "malformed_json", ""},
    {"trailing garbage", "POST", "/v1/render", R"({} {})", 400, "malformed_json", ""},
    {"infinite number", "POST", "/v1/render", R"({"output": {"exposure": 1e999}})", 400, "malformed_json", ""},
    {"number beyond float range", "POST", "/v1/render", R"({"output": {"exposure": 1e300}})", 400, "invalid_value",
     "output.exposure"},
    {"not an object", "POST", "/v1/render", R"([1, 2])", 400, "invalid_value", ""},
    {"wrong type", "POST", "/v1/render", R"({"repeat": "3"})", 400, "invalid_value", "repeat"},
    {"negative size", "POST", "/v1/render", R"({"output": {"width": -1}})", 400, "invalid_value", "output.width"},
    {"fractional size", "POST", "/v1/render", R"({"output": {"height": 10.5}})", 400, "invalid_value",
     "output.height"},
    {"unknown enum", "POST", "/v1/render", R"({"output": {"format": "gif"}})", 400, "invalid_value", "output.format"},
    {"unknown field", "POST", "/v1/render", R"({"shadow": {"enabled": false}})", 400, "invalid_value", "shadow"},
    {"NaN-like string in a vector", "POST", "/v1/render", R"({"camera": {"position": [0, "nan", 3]}})", 400,
     "invalid_value", "camera.position[1]"},
    {"huge size over the schema", "POST", "/v1/render", R"({"output": {"width": 100000}})", 400, "invalid_value",
     "output.width"},
    {"pixels over the server limit", "POST", "/v1/render", R"({"output": {"width": 2048, "height": 1024}})", 422,
     "limit_exceeded", "output"},
    {"grid over the server limit", "POST", "/v1/render", R"({"lpv": {"grid": 128, "cascades": 2}})", 422,
     "limit_exceeded", "lpv.grid"},
    {"iterations over the server limit", "POST", "/v1/render", R"({"lpv": {"iterations": 65}})", 422,
     "limit_exceeded", "lpv.iterations"},
    {"repeat over the server limit", "POST", "/v1/render", R"({"repeat": 101})", 422, "limit_exceeded", "repeat"},
    {"light edit of a light the scene lacks", "POST", "/v1/render", R"({"light_edits": [{"index": 7}]})", 422,
     "does_not_fit", "light_edits[0].index"},
    {"unknown scene", "POST", "/v1/render", R"({"scene": "atlantis"})", 404, "scene_not_found", "scene"},
    {"unknown scene by path", "GET", "/v1/scenes/atlantis", "", 404, "scene_not_found", ""},
    {"unknown route", "GET", "/v2/render", "", 404, "not_found", ""},
    {"unknown route by POST", "POST", "/nowhere", "{}", 404, "not_found", ""},
    {"GET on the render route", "GET", "/v1/render", "", 405, "method_not_allowed", ""},
    {"DELETE on scenes", "DELETE", "/v1/scenes", "", 405, "method_not_allowed", ""},
    {"PUT on a scene", "PUT", "/v1/scenes/cornell-box", "{}", 405, "method_not_allowed", ""},
    {"body over the limit", "POST", "/v1/render", std::string(300 * 1024, ' '), 413, "payload_too_large", ""},
    {"bad deadline header", "POST", "/v1/render", "{}", 400, "invalid_value", "X-Deadline-Ms", {{"X-Deadline-Ms", "soon"}}},
    {"empty deadline header", "POST", "/v1/render", "{}", 400, "invalid_value", "X-Deadline-Ms", {{"X-Deadline-Ms", ""}}},
    {"zero deadline header", "POST", "/v1/render", "{}", 400, "invalid_value", "X-Deadline-Ms", {{"X-Deadline-Ms", "0"}}},
};

class HttpErrors : public ::testing::TestWithParam<BadRequest> {};

TEST_P(HttpErrors, AnswerTheDocumentedStatusAndKeepServing) {
  const BadRequest& bad = GetParam();
  auto http = shared_server().client();
  const httplib::Result r = [&] {
    if (bad.method == "POST") return http->Post(bad.path, bad.headers, bad.body, "application/json");
    if (bad.method == "PUT") return http->Put(bad.path, bad.headers, bad.body, "application/json");
    if (bad.method == "DELETE") return http->Delete(bad.path, bad.headers);
    return http->Get(bad.path, bad.headers);
  }();
  EXPECT_TRUE(is_json_error(r, bad.status, bad.code, bad.field));
  if (bad.status == 405) {
    EXPECT_FALSE(r->get_header_value("Allow").empty());
  }
  const auto health = shared_server().client()->Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
}

INSTANTIATE_TEST_SUITE_P(Table, HttpErrors, ::testing::ValuesIn(kBadRequests),
                         [](const auto& info) {
                           std::string name;
                           for (char c : info.param.name) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

TEST(HttpErrorsStreamed, ChunkedBodyOverTheLimitIsCutOffWith413) {
  auto http = shared_server().client();
  const std::string chunk(64 * 1024, ' ');
  const auto r = http->Post(
      "/v1/render",
      [&](std::size_t offset, httplib::DataSink& sink) {
        if (offset < 1024 * 1024) sink.write(chunk.data(), chunk.size());
        else sink.done();
        return true;
      },
      "application/json");
  // The server may close the connection while the client still sends; either way no
  // render and no crash, and when an answer arrives it is the documented 413.
  if (r) {
    EXPECT_TRUE(is_json_error(r, 413, "payload_too_large", ""));
  }
  const auto health = shared_server().client()->Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
}

TEST(HttpErrorsAfterwards, ARenderStillSucceeds) {
  auto http = shared_server().client();
  for (const auto& bad : kBadRequests)
    if (bad.method == "POST") http->Post(bad.path, bad.headers, bad.body, "application/json");
  const auto r = http->Post("/v1/render", R"({"output": {"width": 24, "height": 24}})", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_TRUE(png_size(r->body));
}

}  // namespace
}  // namespace server_test
