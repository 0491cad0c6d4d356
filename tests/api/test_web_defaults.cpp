// The web page leaves a value out of its request when it equals its copy of the API's
// defaults (DEFAULTS in web/request_state.js). A copy that drifted from the parser's
// defaults would silently drop a user's choice; this test reads the copy and checks that
// the parser accepts it (no renamed or removed field) and reads it as the request with no
// fields, that is, every value in it is the parser's default.
#include "api/request_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

// The object literal after `const DEFAULTS = `, as JSON: keys quoted, 'strings' in double
// quotes, trailing commas dropped. The page writes it as plain data, which this covers.
nlohmann::json web_defaults() {
  std::ifstream in(LPV_WEB_DIR "/request_state.js");
  std::stringstream text;
  text << in.rdbuf();
  const std::string source = text.str();
  const std::size_t start = source.find("const DEFAULTS = {");
  const std::size_t end = source.find("\n};", start);
  if (start == std::string::npos || end == std::string::npos)
    throw std::runtime_error("no `const DEFAULTS = {...};` in web/request_state.js");
  const std::size_t open = source.find('{', start);
  std::string literal = source.substr(open, end + 2 - open);
  literal = std::regex_replace(literal, std::regex(R"(([{,]\s*)([A-Za-z_][A-Za-z0-9_]*)\s*:)"), "$1\"$2\":");
  literal = std::regex_replace(literal, std::regex("'([^']*)'"), "\"$1\"");
  literal = std::regex_replace(literal, std::regex(R"(,(\s*[}\]]))"), "$1");
  return nlohmann::json::parse(literal);
}

TEST(WebDefaults, AreTheParsersDefaults) {
  const nlohmann::json web = web_defaults();
  ASSERT_TRUE(web.contains("lpv")) << web;
  api::RenderRequest from_web;
  ASSERT_NO_THROW(from_web = api::parse_render_request(web)) << "the page's defaults are not a valid request";
  const nlohmann::json got = api::to_json(from_web);
  const nlohmann::json expected = api::to_json(api::parse_render_request("{}"));
  EXPECT_EQ(got, expected) << "where web/request_state.js differs from the API's defaults: "
                           << nlohmann::json::diff(expected, got).dump();
}

}  // namespace
