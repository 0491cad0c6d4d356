// The web page (docs/web.md) over real HTTP: / and every file of web/ are served from the
// binary byte for byte, with their content type, an ETag that turns a repeat into a 304,
// and a Content-Security-Policy that keeps the page to this server. The browser test
// (tests/web) checks what the page does.
#include "http_checks.hpp"
#include "server_process.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace server_test {
namespace {

// LPV_WEB_ASSETS: the embedded file names, comma-separated; LPV_WEB_DIR: where they are.
std::vector<std::string> web_assets() {
  const char* list = std::getenv("LPV_WEB_ASSETS");
  std::vector<std::string> names;
  std::stringstream stream(list ? list : "");
  for (std::string name; std::getline(stream, name, ',');) names.push_back(name);
  return names;
}

std::string source_of(const std::string& name) {
  const char* dir = std::getenv("LPV_WEB_DIR");
  std::ifstream file(std::string(dir ? dir : "") + "/" + name, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

std::string content_type_of(const std::string& name) {
  const std::string extension = name.substr(name.rfind('.'));
  if (extension == ".html") return "text/html; charset=utf-8";
  if (extension == ".css") return "text/css; charset=utf-8";
  if (extension == ".js") return "text/javascript; charset=utf-8";
  if (extension == ".svg") return "image/svg+xml";
  return "unknown extension " + extension;
}

TEST(HttpWeb, ThePageIsServedAtTheRootWithAPolicyThatKeepsItToThisServer) {
  auto http = shared_server().client();
  const auto r = http->Get("/");
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  ASSERT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type"), "text/html; charset=utf-8");
  EXPECT_EQ(r->body, source_of("index.html"));
  const std::string policy = r->get_header_value("Content-Security-Policy");
  EXPECT_NE(policy.find("default-src 'none'"), std::string::npos) << policy;
  EXPECT_NE(policy.find("script-src 'self'"), std::string::npos) << policy;
  EXPECT_NE(policy.find("connect-src 'self'"), std::string::npos) << policy;
  EXPECT_NE(policy.find("img-src 'self';"), std::string::npos) << "the canvas needs no blob: or data: images: " << policy;
  EXPECT_EQ(r->get_header_value("X-Content-Type-Options"), "nosniff");
}

TEST(HttpWeb, EveryAssetIsServedAsItIsInWebWithItsContentType) {
  const std::vector<std::string> names = web_assets();
  ASSERT_GE(names.size(), 3u) << "LPV_WEB_ASSETS lists the embedded files";
  auto http = shared_server().client();
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    const auto r = http->Get("/" + name);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200);
    EXPECT_EQ(r->get_header_value("Content-Type"), content_type_of(name));
    EXPECT_EQ(r->get_header_value("Cache-Control"), "no-cache");
    EXPECT_EQ(r->body, source_of(name)) << "the embedded file differs from web/" << name;
    const std::string etag = r->get_header_value("ETag");
    ASSERT_FALSE(etag.empty());
    const auto again = http->Get("/" + name, {{"If-None-Match", etag}});
    ASSERT_TRUE(again);
    EXPECT_EQ(again->status, 304);
    EXPECT_TRUE(again->body.empty());
  }
}

TEST(HttpWeb, EveryFileThePageNamesIsServed) {
  // Scripts import each other as "./name.js"; the page names its stylesheet, icon and entry.
  auto http = shared_server().client();
  for (const std::string& name : web_assets()) {
    const std::string text = source_of(name);
    for (std::size_t at = text.find("./"); at != std::string::npos; at = text.find("./", at + 2)) {
      const std::size_t end = text.find_first_of("'\"", at);
      const std::string referenced = text.substr(at + 1, end - at - 1);
      if (!referenced.ends_with(".js")) continue;
      const auto r = http->Get(referenced);
      ASSERT_TRUE(r);
      EXPECT_EQ(r->status, 200) << name << " imports " << referenced;
    }
  }
  for (const char* path : {"/style.css", "/app.js", "/favicon.svg"}) {
    const auto r = http->Get(path);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << path;
    EXPECT_NE(source_of("index.html").find(std::string("\"") + path + "\""), std::string::npos) << path;
  }
}

TEST(HttpWeb, UnknownFilesAre404AndOtherMethods405AsJson) {
  auto http = shared_server().client();
  EXPECT_TRUE(is_json_error(http->Get("/missing.js"), 404, "not_found", ""));
  EXPECT_TRUE(is_json_error(http->Get("/../CMakeLists.txt"), 404, "not_found", ""));
  EXPECT_TRUE(is_json_error(http->Post("/", "{}", "application/json"), 405, "method_not_allowed", ""));
  EXPECT_TRUE(is_json_error(http->Delete("/app.js"), 405, "method_not_allowed", ""));
}

TEST(HttpWeb, ThePageNeedsNoTokenButTheApiStillDoes) {
  ServerProcess server({"--token", "web-secret"});
  auto http = server.client();
  const auto page = http->Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  const auto script = http->Get("/app.js");
  ASSERT_TRUE(script);
  EXPECT_EQ(script->status, 200);
  EXPECT_TRUE(is_json_error(http->Get("/v1/scenes"), 401, "unauthorized", ""));
}

}  // namespace
}  // namespace server_test
