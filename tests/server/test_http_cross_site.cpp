// What a web page on another site must not make a browser do to a token-less server on
// loopback (docs/server.md, "Cross-site requests"): post a body a browser sends without asking
// first (text/plain, forms: 415), be answered under a DNS-rebound name (421), or change state
// from another origin (403). Clients that are no browser (curl, the tests, lpv-bench) send
// their media types and a loopback Host, and pass.
#include "http_checks.hpp"
#include "server_process.hpp"

#include <gtest/gtest.h>

#include <signal.h>

#include <string>

namespace server_test {
namespace {

constexpr const char* kSmallRender = R"({"output": {"width": 16, "height": 16}})";

TEST(CrossSite, RoutesReadOnlyTheirMediaTypes) {
  auto http = shared_server().client();
  // The types a page elsewhere may post without a CORS preflight.
  for (const char* type : {"text/plain", "application/x-www-form-urlencoded", "multipart/form-data; boundary=x"}) {
    SCOPED_TRACE(type);
    for (const char* path : {"/v1/render", "/v1/compare", "/v1/sweep", "/v1/bench"}) {
      const auto r = http->Post(path, kSmallRender, type);
      EXPECT_TRUE(is_json_error(r, 415, "unsupported_media_type", "")) << path;
      if (r) {
        EXPECT_EQ(r->get_header_value("Accept-Post"), "application/json");
      }
    }
    const auto upload = http->Post("/v1/scenes", "glTF", type);
    EXPECT_TRUE(is_json_error(upload, 415, "unsupported_media_type", ""));
    if (upload) {
      EXPECT_NE(upload->get_header_value("Accept-Post").find("model/gltf-binary"), std::string::npos);
    }
  }
  // JSON in any case and with parameters; an empty body with no type is the empty request.
  const auto json = http->Post("/v1/render", kSmallRender, "Application/JSON; charset=utf-8");
  ASSERT_TRUE(json);
  EXPECT_EQ(json->status, 200);
  const std::string no_type = send_raw(shared_server().port(),
                                       "POST /v1/render?x HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\n"
                                       "Connection: close\r\n\r\n",
                                       60);
  EXPECT_EQ(no_type.rfind("HTTP/1.1 200", 0), 0u) << no_type;
  const std::string body_without_type = send_raw(shared_server().port(),
                                                 "POST /v1/render HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 2\r\n"
                                                 "Connection: close\r\n\r\n{}",
                                                 60);
  EXPECT_EQ(body_without_type.rfind("HTTP/1.1 415", 0), 0u) << body_without_type;
  // An upload as the web page sends it: application/octet-stream (the bytes are not glTF).
  EXPECT_TRUE(is_json_error(http->Post("/v1/scenes", "not a scene", "application/octet-stream"), 422, "invalid_scene",
                            ""));
}

TEST(CrossSite, WithoutATokenOnlyLoopbackAndAllowedNamesAreAnswered) {
  auto http = shared_server().client();
  // A page of evil.example that rebinds its name to 127.0.0.1: the browser sends its own name.
  EXPECT_TRUE(is_json_error(http->Get("/v1/scenes", {{"Host", "evil.example:8080"}}), 421, "misdirected_request", ""));
  EXPECT_TRUE(is_json_error(http->Post("/v1/render", {{"Host", "evil.example"}}, kSmallRender, "application/json"), 421,
                            "misdirected_request", ""));
  EXPECT_TRUE(is_json_error(http->Get("/", {{"Host", "evil.example"}}), 421, "misdirected_request", ""));
  // Probes answer whatever the Host (an orchestrator probes by the pod's address).
  EXPECT_EQ(http->Get("/healthz", {{"Host", "10.1.2.3:8080"}})->status, 200);
  EXPECT_EQ(http->Get("/readyz", {{"Host", "10.1.2.3:8080"}})->status, 200);
  for (const char* host : {"127.0.0.1", "localhost:8080", "[::1]:8080", "LOCALHOST"})
    EXPECT_EQ(http->Get("/v1/scenes", {{"Host", host}})->status, 200) << host;

  ServerProcess allowing({"--allowed-host", "render.example.com,10.0.0.7"});
  auto allowed = allowing.client();
  EXPECT_EQ(allowed->Get("/v1/scenes", {{"Host", "render.example.com:8080"}})->status, 200);
  EXPECT_EQ(allowed->Get("/v1/scenes", {{"Host", "10.0.0.7"}})->status, 200);
  EXPECT_TRUE(is_json_error(allowed->Get("/v1/scenes", {{"Host", "evil.example"}}), 421, "misdirected_request", ""));
  EXPECT_EQ(allowing.stop(SIGTERM), 0);

  // With a token the name is not checked: a page cannot know the token.
  ServerProcess guarded({"--token", "s3cret"});
  EXPECT_EQ(guarded.client()->Get("/v1/scenes", {{"Host", "render.example.com"}, {"Authorization", "Bearer s3cret"}})->status,
            200);
  EXPECT_EQ(guarded.stop(SIGTERM), 0);
}

TEST(CrossSite, StateChangesFromAnotherOriginAreRefused) {
  auto http = shared_server().client();
  const std::string own = "http://127.0.0.1:" + std::to_string(shared_server().port());
  EXPECT_TRUE(is_json_error(http->Post("/v1/render", {{"Origin", "https://evil.example"}}, kSmallRender, "application/json"),
                            403, "forbidden_origin", ""));
  EXPECT_TRUE(is_json_error(http->Post("/v1/render", {{"Origin", "null"}}, kSmallRender, "application/json"), 403,
                            "forbidden_origin", ""));
  EXPECT_TRUE(is_json_error(http->Delete("/v1/scenes/0000", {{"Origin", "https://evil.example"}}), 403,
                            "forbidden_origin", ""));
  // The server's own page, and any loopback origin, may.
  const auto same = http->Post("/v1/render", {{"Origin", own}}, kSmallRender, "application/json");
  ASSERT_TRUE(same);
  EXPECT_EQ(same->status, 200);
  EXPECT_EQ(http->Post("/v1/render", {{"Origin", "http://localhost:3000"}}, kSmallRender, "application/json")->status, 200);
  // Reading is not a state change: a GET with a foreign Origin is answered (the browser keeps
  // the answer from the page, as there is no CORS header).
  EXPECT_EQ(http->Get("/v1/scenes", {{"Origin", "https://evil.example"}})->status, 200);
}

}  // namespace
}  // namespace server_test
