// POST /v1/bench over real HTTP: a tiny suite's results, valid against
// bench/results.schema.json; round trips skipped with their reason; bad suites named by
// field (400), suites over the server's limits (422), unknown scenes (404).
#include "http_checks.hpp"
#include "json_schema_subset.hpp"
#include "server_process.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

namespace server_test {
namespace {

const nlohmann::json kTinySuite = {
    {"suite", "tiny"},
    {"version", 2},
    {"repetitions", 3},
    {"warmup", 0},
    {"cases",
     {{{"name", "direct"}, {"request", {{"output", {{"width", 32}, {"height", 24}}}, {"lpv", {{"enabled", false}}}}}},
      {{"name", "lpv"},
       {"request",
        {{"output", {{"width", 32}, {"height", 24}}}, {"lpv", {{"transfer", "sharpened"}, {"grid", 8}, {"iterations", 2}}}}}},
      {{"name", "round trip"}, {"kind", "server_round_trip"}, {"request", nlohmann::json::object()}}}}};

nlohmann::json results_schema() {
  const char* path = std::getenv("LPV_BENCH_RESULTS_SCHEMA");
  std::ifstream in(path ? path : "");
  return nlohmann::json::parse(in);
}

httplib::Result post_suite(const nlohmann::json& suite) {
  return shared_server().client()->Post("/v1/bench", suite.dump(), "application/json");
}

TEST(HttpBench, RunsASuiteAndAnswersItsResults) {
  const auto r = post_suite(kTinySuite);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const auto results = nlohmann::json::parse(r->body);
  for (const std::string& problem : schema_test::validate(results_schema(), results)) ADD_FAILURE() << problem;
  EXPECT_EQ(results["mode"], "server");
  EXPECT_EQ(results["suite"]["name"], "tiny");
  EXPECT_EQ(results["suite"]["version"], 2);
  EXPECT_EQ(results["repetitions"], 3);
  EXPECT_TRUE(results["complete"].get<bool>());
  ASSERT_EQ(results["cases"].size(), 3u);
  for (int i : {0, 1}) {
    const auto& c = results["cases"][i];
    EXPECT_EQ(c["status"], "ok") << c.dump();
    EXPECT_EQ(c["image"]["width"], 32);
    EXPECT_EQ(c["image"]["height"], 24);
    EXPECT_EQ(c["metrics"][0]["name"], "gpu_ms");
    EXPECT_EQ(c["metrics"][0]["samples"].size(), 3u);
  }
  bool propagated = false;
  for (const auto& metric : results["cases"][1]["metrics"]) propagated = propagated || metric["name"] == "pass.propagate";
  EXPECT_TRUE(propagated);
  const auto& round_trip = results["cases"][2];
  EXPECT_EQ(round_trip["status"], "skipped");
  EXPECT_NE(round_trip["reason"].get<std::string>().find("lpv-bench run --url"), std::string::npos);
}

// A suite whose first case is quick and whose others each take about fifteen times longer
// (100 direct-light renders at 32x32, then 100 at 128x128 with a 32^3 grid): the quick case
// alone is timed on this machine, and a deadline of three times that falls in the second
// case, so the answer is what was done.
TEST(HttpBench, ASuitePastItsDeadlineAnswersTheCasesDone) {
  nlohmann::json long_suite = kTinySuite;
  long_suite["repetitions"] = 100;
  long_suite["cases"] = {
      {{"name", "quick"}, {"request", {{"output", {{"width", 32}, {"height", 32}}}, {"lpv", {{"enabled", false}}}}}}};
  const double quick_ms = elapsed_ms([&] {
    const auto r = shared_server().client()->Post("/v1/bench", long_suite.dump(), "application/json");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
  });
  for (const char* name : {"b", "c", "d"})
    long_suite["cases"].push_back(
        {{"name", name}, {"request", {{"output", {{"width", 128}, {"height", 128}}}, {"lpv", {{"grid", 32}}}}}});
  const std::string deadline_ms = std::to_string(static_cast<long>(3.0 * quick_ms) + 100);
  const auto r = shared_server().client()->Post("/v1/bench", {{"X-Deadline-Ms", deadline_ms}}, long_suite.dump(),
                                                "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const auto results = nlohmann::json::parse(r->body);
  EXPECT_FALSE(results["complete"].get<bool>()) << "deadline " << deadline_ms << " ms";
  ASSERT_GE(results["cases"].size(), 1u) << "deadline " << deadline_ms << " ms";
  EXPECT_EQ(results["cases"][0]["name"], "quick");
  EXPECT_LT(results["cases"].size(), 4u);
  for (const auto& c : results["cases"]) EXPECT_EQ(c["metrics"][0]["samples"].size(), 100u) << c["name"];
}

TEST(HttpBench, ABadSuiteNamesTheField) {
  nlohmann::json bad = kTinySuite;
  bad["cases"][1]["request"]["lpv"]["grid"] = 0;
  EXPECT_TRUE(is_json_error(post_suite(bad), 400, "invalid_value", "cases[1].request.lpv.grid"));
  bad = kTinySuite;
  bad.erase("version");
  EXPECT_TRUE(is_json_error(post_suite(bad), 400, "invalid_value", "version"));
  bad = kTinySuite;
  bad["cases"][0]["scene_file"] = "/etc/passwd";
  EXPECT_TRUE(is_json_error(post_suite(bad), 400, "invalid_value", "cases[0].scene_file"));
  EXPECT_TRUE(is_json_error(shared_server().client()->Post("/v1/bench", "{\"suite\": ", "application/json"), 400,
                            "malformed_json", ""));
}

TEST(HttpBench, ASuiteOverTheServersLimitsIs422) {
  nlohmann::json big = kTinySuite;
  big["cases"][0]["request"]["output"] = {{"width", 2048}, {"height", 2048}};  // the shared server allows 1048576 pixels
  EXPECT_TRUE(is_json_error(post_suite(big), 422, "limit_exceeded", "cases[0].request.output"));
  big = kTinySuite;
  big["repetitions"] = 101;  // over --max-repeat
  EXPECT_TRUE(is_json_error(post_suite(big), 422, "limit_exceeded", "repetitions"));
}

TEST(HttpBench, AnUnknownSceneIs404AndOtherMethods405) {
  nlohmann::json unknown = kTinySuite;
  unknown["cases"][1]["request"]["scene"] = "atlantis";
  EXPECT_TRUE(is_json_error(post_suite(unknown), 404, "scene_not_found", "cases[1].request.scene"));
  EXPECT_TRUE(is_json_error(shared_server().client()->Get("/v1/bench"), 405, "method_not_allowed", ""));
}

}  // namespace
}  // namespace server_test
