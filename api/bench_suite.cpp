// Strict JSON -> BenchSuite. Each case's request is read by the render request's own reader,
// so a field is checked by the same rule (and named the same way) as in POST /v1/render.
#include "api/bench_suite.hpp"

#include "api/json_reader.hpp"
#include "api/request_error.hpp"
#include "api/request_reader.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>

namespace api {
namespace {

using namespace reader;

constexpr std::array<std::string_view, 6> suite_keys{"suite", "version", "description", "repetitions", "warmup",
                                                     "cases"};
constexpr std::array<std::string_view, 4> case_keys{"name", "kind", "request", "scene_file"};
constexpr std::uint32_t max_suite_version = 1000000;

// Suite names are shown in report titles and tables: the scene-name alphabet.
std::string read_suite_name(const Field& f) { return as_name(f, limits::max_bench_name_bytes); }

// Case names are shown in tables and reports: printable ASCII, no '|' (a Markdown cell).
std::string read_case_name(const Field& f) {
  const std::string expectation = "a string of 1 to " + std::to_string(limits::max_bench_name_bytes) +
                                  " printable ASCII characters other than '|'";
  if (!f.value->is_string()) f.reject(expectation);
  const std::string& name = f.value->get_ref<const std::string&>();
  const bool valid = std::ranges::all_of(name, [](char c) { return c >= 0x20 && c < 0x7f && c != '|'; });
  if (name.empty() || name.size() > limits::max_bench_name_bytes || !valid) f.reject(expectation);
  return name;
}

BenchCase read_case(const Field& f) {
  const Object obj(f, case_keys);
  BenchCase c;
  c.name = read_case_name(obj.require("name", "the case's name, unique in the suite"));
  if (auto v = obj.get("kind")) c.kind = as_enum(*v, kBenchCaseKinds);
  const Field request = obj.require("request", "the render request to time; {} for the defaults");
  c.request = read_render_request(request);
  if (c.request.dry_run)
    throw RequestError(member_path(request.path, "dry_run"), "must be false: a benchmark renders what it times");
  if (auto v = obj.get("scene_file")) {
    c.scene_file = as_string(*v, limits::max_scene_file_bytes);
    if (c.scene_file->empty()) v->reject("a path to a .gltf or .glb file");
    if (request.value->is_object() && request.value->contains("scene"))
      throw RequestError(obj.path_of("scene_file"), "give one of scene_file and request.scene");
    if (c.request.budget_ms)  // a budget's calibration sweeps find the scene by name
      throw RequestError(obj.path_of("scene_file"), "give one of scene_file and request.budget_ms");
  }
  return c;
}

}  // namespace

std::string to_string(BenchCaseKind kind) {
  switch (kind) {
    case BenchCaseKind::render: return "render";
    case BenchCaseKind::server_round_trip: return "server_round_trip";
  }
  return "?";
}

BenchSuite parse_bench_suite(std::string_view json_text) {
  const nlohmann::json document = parse_document(json_text);
  const Object obj(Field{&document, ""}, suite_keys);
  BenchSuite suite;
  suite.name = read_suite_name(obj.require("suite", "the suite's name"));
  suite.version =
      as_uint<std::uint32_t>(obj.require("version", "the suite's version, an integer"), 1, max_suite_version);
  if (auto v = obj.get("description")) suite.description = as_string(*v, limits::max_bench_description_bytes);
  if (auto v = obj.get("repetitions"))
    suite.repetitions = as_uint<std::uint32_t>(*v, 1, limits::max_bench_repetitions);
  if (auto v = obj.get("warmup")) suite.warmup = as_uint<std::uint32_t>(*v, 0, limits::max_bench_warmup);
  const Field cases = obj.require("cases", "an array of cases");
  const std::vector<Field> elements = as_array(cases, limits::max_bench_cases);
  if (elements.empty()) cases.reject("a non-empty array of at most " + std::to_string(limits::max_bench_cases) + " cases");
  for (const Field& element : elements) {
    BenchCase c = read_case(element);
    const auto same = std::ranges::find(suite.cases, c.name, &BenchCase::name);
    if (same != suite.cases.end())
      throw RequestError(member_path(element.path, "name"),
                         "must be unique in the suite, got " + quote(c.name) + " again (cases[" +
                             std::to_string(same - suite.cases.begin()) + "])");
    suite.cases.push_back(std::move(c));
  }
  return suite;
}

}  // namespace api
