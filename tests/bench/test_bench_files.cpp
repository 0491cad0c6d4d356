// Suites and results files as lpv-bench and POST /v1/bench read them: errors name the field.
#include "api/bench_results.hpp"
#include "api/bench_suite.hpp"
#include "api/request_error.hpp"

#include <gtest/gtest.h>

namespace {

// The field a RequestError names, or "(no error)".
template <class Parse>
std::string error_field(Parse parse, const std::string& text) {
  try {
    parse(text);
  } catch (const api::RequestError& e) {
    return e.field();
  }
  return "(no error)";
}

std::string suite_error(const std::string& text) { return error_field(api::parse_bench_suite, text); }
std::string results_error(const std::string& text) { return error_field(api::parse_bench_results, text); }

TEST(BenchSuiteFile, ReadsASuite) {
  const api::BenchSuite suite = api::parse_bench_suite(R"({
    "suite": "nightly", "version": 3, "repetitions": 7, "warmup": 0,
    "cases": [{"name": "a", "request": {"lpv": {"grid": 16}}},
              {"name": "b", "kind": "server_round_trip", "request": {}},
              {"name": "c", "scene_file": "models/box.glb", "request": {"output": {"width": 64, "height": 64}}}]})");
  EXPECT_EQ(suite.name, "nightly");
  EXPECT_EQ(suite.version, 3u);
  EXPECT_EQ(suite.repetitions, 7u);
  EXPECT_EQ(suite.warmup, 0u);
  ASSERT_EQ(suite.cases.size(), 3u);
  EXPECT_EQ(suite.cases[0].request.lpv.grid.x, 16u);
  EXPECT_EQ(suite.cases[1].kind, api::BenchCaseKind::server_round_trip);
  EXPECT_EQ(suite.cases[2].scene_file, "models/box.glb");
}

TEST(BenchSuiteFile, ErrorsNameTheField) {
  EXPECT_EQ(suite_error("{"), "");
  EXPECT_EQ(suite_error(R"({"version": 1, "cases": [{"name": "a", "request": {}}]})"), "suite");
  EXPECT_EQ(suite_error(R"({"suite": "s", "cases": [{"name": "a", "request": {}}]})"), "version");
  EXPECT_EQ(suite_error(R"({"suite": "a b", "version": 1, "cases": [{"name": "a", "request": {}}]})"), "suite");
  EXPECT_EQ(suite_error(R"({"suite": "..", "version": 1, "cases": [{"name": "a", "request": {}}]})"), "suite");
  EXPECT_EQ(suite_error(R"({"suite": "s", "version": 1, "cases": []})"), "cases");
  EXPECT_EQ(suite_error(R"({"suite": "s", "version": 1, "repetitions": 0, "cases": [{"name": "a", "request": {}}]})"),
            "repetitions");
  EXPECT_EQ(suite_error(R"({"suite": "s", "version": 1, "cases": [{"name": "a", "request": {}},
                         {"name": "b", "request": {"output": {"width": 0}}}]})"),
            "cases[1].request.output.width");
  EXPECT_EQ(suite_error(R"({"suite": "s", "version": 1, "cases": [{"name": "a", "request": {}}, {"name": "a", "request": {}}]})"),
            "cases[1].name");
  EXPECT_EQ(suite_error(R"({"suite": "s", "version": 1, "cases": [{"name": "a", "request": {"dry_run": true}}]})"),
            "cases[0].request.dry_run");
  EXPECT_EQ(suite_error(R"({"suite": "s", "version": 1, "cases": [{"name": "a", "kind": "x", "request": {}}]})"),
            "cases[0].kind");
  EXPECT_EQ(suite_error(R"({"suite": "s", "version": 1, "cases": [{"name": "a"}]})"), "cases[0].request");
  EXPECT_EQ(suite_error(R"({"suite": "s", "version": 1, "cases": [{"name": "a|b", "request": {}}]})"), "cases[0].name");
  EXPECT_EQ(suite_error(R"({"suite": "s", "version": 1, "cases": [{"name": "a", "repeat": 3, "request": {}}]})"),
            "cases[0].repeat");
  EXPECT_EQ(suite_error(R"({"suite": "s", "version": 1,
                         "cases": [{"name": "a", "scene_file": "x.glb", "request": {"scene": "cornell-box"}}]})"),
            "cases[0].scene_file");
}

api::BenchResults sample_results() {
  api::BenchResults r;
  r.suite = "s";
  r.suite_version = 2;
  r.label = "nightly";
  r.mode = "http";
  r.url = "http://127.0.0.1:8080";
  r.started_at = "2024-05-01T12:00:00.000Z";
  r.duration_s = 12.5;
  r.repetitions = 3;
  r.warmup = 1;
  r.machine = {"host", "CPU", 8, "Debian", "Linux"};
  r.device = {"llvmpipe", "Mesa"};
  r.build = {"0.1.0", "GNU 12", "Release", "abc123", true, false};
  api::BenchCaseResult ok{"a", api::BenchCaseKind::render, api::BenchCaseStatus::ok, "", {{"scene", "cornell-box"}},
                          {{"gpu_ms", {1.5, 1.25, 2.0}}, {"pass.rsm", {0.5, 0.5, 0.75}}},
                          api::BenchImage{std::string(64, 'a'), 64, 32, 32, 16, "UEY="}};
  api::BenchCaseResult skipped{"b", api::BenchCaseKind::server_round_trip, api::BenchCaseStatus::skipped, "no server",
                               nlohmann::json::object(), {}, std::nullopt};
  r.cases = {ok, skipped};
  return r;
}

TEST(BenchResultsFile, RoundTripsThroughJson) {
  const api::BenchResults r = sample_results();
  const nlohmann::json j = api::to_json(r);
  EXPECT_EQ(j["cases"][0]["metrics"][0]["median"], 1.5);
  EXPECT_EQ(j["cases"][0]["metrics"][0]["n"], 3);
  const api::BenchResults back = api::parse_bench_results(j.dump());
  EXPECT_EQ(api::to_json(back), j);
}

TEST(BenchResultsFile, ErrorsNameTheFieldAndUnknownKeysAreIgnored) {
  nlohmann::json j = api::to_json(sample_results());
  j["added_by_a_newer_version"] = true;
  EXPECT_EQ(results_error(j.dump()), "(no error)");
  EXPECT_EQ(results_error(R"({"suite": "s"})"), "format");
  EXPECT_EQ(results_error("[1, 2]"), "format");
  nlohmann::json bad = j;
  bad["schema_version"] = 2;
  EXPECT_EQ(results_error(bad.dump()), "schema_version");
  bad = j;
  bad["cases"][0]["metrics"][0]["samples"][1] = -1.0;
  EXPECT_EQ(results_error(bad.dump()), "cases[0].metrics[0].samples[1]");
  bad = j;
  bad["cases"][0]["status"] = "great";
  EXPECT_EQ(results_error(bad.dump()), "cases[0].status");
  bad = j;
  bad["machine"].erase("cores");
  EXPECT_EQ(results_error(bad.dump()), "machine.cores");
  bad = j;
  bad["cases"][0]["image"]["thumbnail"]["width"] = 65;
  EXPECT_EQ(results_error(bad.dump()), "cases[0].image.thumbnail.width");
}

TEST(BenchResultsFile, SummaryIsMedianRangeAndMad) {
  const api::BenchSummary s = api::summarize(std::vector{10.0, 12.0, 11.0, 30.0, 9.0});
  EXPECT_DOUBLE_EQ(s.median, 11.0);
  EXPECT_DOUBLE_EQ(s.min, 9.0);
  EXPECT_DOUBLE_EQ(s.max, 30.0);
  EXPECT_DOUBLE_EQ(s.mad, 1.0);  // deviations 1 1 0 19 2: the outlier barely counts
  EXPECT_DOUBLE_EQ(s.spread, 1.0 / 11.0);
  EXPECT_EQ(s.n, 5u);
  EXPECT_EQ(api::summarize({}).n, 0u);
}

}  // namespace
