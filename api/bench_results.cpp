// BenchResults <-> JSON (bench/results.schema.json). Reading is strict about the keys it
// reads and lenient about others, so a file from a newer lpv-bench still compares.
#include "api/bench_results.hpp"

#include "api/json_reader.hpp"
#include "api/render_stats.hpp"
#include "api/request_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace api {
namespace {

using nlohmann::json;
using namespace reader;

constexpr std::string_view kFormat = "lpv-bench-results";
constexpr std::size_t kMaxText = 4096;
constexpr std::size_t kMaxThumbnailBase64 = 4 * (bench_thumbnail_side * bench_thumbnail_side * 12 + 64) / 3 + 8;
constexpr std::size_t kMaxSamples = 1u << 20;
constexpr std::size_t kMaxMetrics = 256;
constexpr double kMaxMs = 1.0e9;
constexpr std::array statuses{BenchCaseStatus::ok, BenchCaseStatus::skipped, BenchCaseStatus::failed};

// ---- reading: members of objects, unknown members ignored (Field::member) -----------------

std::string text(const Field& object, std::string_view key) { return as_string(object.member(key), kMaxText); }

BenchMetric read_metric(const Field& f) {
  BenchMetric metric;
  metric.name = as_string(f.member("name"), limits::max_bench_name_bytes);
  for (const Field& sample : as_array(f.member("samples"), kMaxSamples))
    metric.samples.push_back(as_double(sample, 0.0, kMaxMs));
  return metric;
}

BenchImage read_image(const Field& f) {
  BenchImage image;
  image.sha256 = text(f, "sha256");
  image.width = as_uint<std::uint32_t>(f.member("width"), 1, limits::max_image_side);
  image.height = as_uint<std::uint32_t>(f.member("height"), 1, limits::max_image_side);
  const Field thumbnail = f.member("thumbnail");
  if (as_string(thumbnail.member("format"), 16) != "pfm") thumbnail.member("format").reject("\"pfm\"");
  image.thumbnail_width = as_uint<std::uint32_t>(thumbnail.member("width"), 1, bench_thumbnail_side);
  image.thumbnail_height = as_uint<std::uint32_t>(thumbnail.member("height"), 1, bench_thumbnail_side);
  image.thumbnail_pfm_base64 = as_string(thumbnail.member("base64"), kMaxThumbnailBase64);
  return image;
}

BenchCaseResult read_case_result(const Field& f) {
  BenchCaseResult c;
  c.name = as_string(f.member("name"), limits::max_bench_name_bytes);
  c.kind = as_enum(f.member("kind"), kBenchCaseKinds);
  c.status = as_enum(f.member("status"), statuses);
  if (auto v = f.optional_member("reason")) c.reason = as_string(*v, kMaxText);
  const Field request = f.member("request");
  if (!request.value->is_object()) request.reject("an object");
  c.request = *request.value;
  for (const Field& metric : as_array(f.member("metrics"), kMaxMetrics)) c.metrics.push_back(read_metric(metric));
  if (auto v = f.optional_member("image"); v && !v->value->is_null()) c.image = read_image(*v);
  return c;
}

// ---- writing ---------------------------------------------------------------------------

json metric_json(const BenchMetric& metric) {
  const BenchSummary s = summarize(metric.samples);
  return {{"name", metric.name}, {"unit", "ms"},     {"median", s.median}, {"min", s.min},
          {"max", s.max},        {"mad", s.mad},     {"spread", s.spread}, {"n", s.n},
          {"samples", metric.samples}};
}

}  // namespace

nlohmann::json to_json(const BenchImage& image) {
  return {{"sha256", image.sha256},
          {"width", image.width},
          {"height", image.height},
          {"thumbnail",
           {{"format", "pfm"},
            {"width", image.thumbnail_width},
            {"height", image.thumbnail_height},
            {"base64", image.thumbnail_pfm_base64}}}};
}

namespace {

json case_json(const BenchCaseResult& c) {
  json metrics = json::array();
  for (const BenchMetric& metric : c.metrics) metrics.push_back(metric_json(metric));
  json j = {{"name", c.name},       {"kind", to_string(c.kind)},   {"status", to_string(c.status)},
            {"reason", c.reason},   {"request", c.request},        {"metrics", std::move(metrics)},
            {"image", nullptr}};
  if (c.image) j["image"] = to_json(*c.image);
  return j;
}

}  // namespace

BenchSummary summarize(std::span<const double> samples) {
  const TimeSummary t = TimeSummary::of({samples.begin(), samples.end()});
  std::vector<double> deviations;
  for (const double x : samples)
    if (!std::isnan(x)) deviations.push_back(std::abs(x - t.median));
  const double mad = TimeSummary::of(deviations).median;
  return {t.median, t.min, t.max, mad, t.median > 0.0 ? mad / t.median : 0.0, deviations.size()};
}

const BenchMetric* BenchCaseResult::metric(std::string_view metric_name) const {
  const auto it = std::ranges::find(metrics, metric_name, &BenchMetric::name);
  return it == metrics.end() ? nullptr : &*it;
}

const BenchCaseResult* BenchResults::find(std::string_view case_name) const {
  const auto it = std::ranges::find(cases, case_name, &BenchCaseResult::name);
  return it == cases.end() ? nullptr : &*it;
}

std::string to_string(BenchCaseStatus status) {
  switch (status) {
    case BenchCaseStatus::ok: return "ok";
    case BenchCaseStatus::skipped: return "skipped";
    case BenchCaseStatus::failed: return "failed";
  }
  return "?";
}

nlohmann::json to_json(const BenchResults& r) {
  json cases = json::array();
  for (const BenchCaseResult& c : r.cases) cases.push_back(case_json(c));
  json noise = nullptr;
  if (r.noise)
    noise = {{"probe", metric_json({"probe_ms", r.noise->probe_ms})},
             {"load_average", {r.noise->load_start, r.noise->load_end}},
             {"steal", r.noise->steal}};
  return {{"format", kFormat},
          {"schema_version", bench_results_schema_version},
          {"suite", {{"name", r.suite}, {"version", r.suite_version}}},
          {"label", r.label},
          {"mode", r.mode},
          {"url", r.url},
          {"started_at", r.started_at},
          {"duration_s", r.duration_s},
          {"repetitions", r.repetitions},
          {"warmup", r.warmup},
          {"complete", r.complete},
          {"machine",
           {{"hostname", r.machine.hostname},
            {"cpu_model", r.machine.cpu_model},
            {"cores", r.machine.cores},
            {"os", r.machine.os},
            {"kernel", r.machine.kernel}}},
          {"device", {{"name", r.device.name}, {"driver", r.device.driver}}},
          {"build",
           {{"version", r.build.version},
            {"compiler", r.build.compiler},
            {"build_type", r.build.build_type},
            {"commit", r.build.commit},
            {"dirty", r.build.dirty},
            {"sanitizers", r.build.sanitizers}}},
          {"noise", std::move(noise)},
          {"cases", std::move(cases)}};
}

BenchImage parse_bench_image(const nlohmann::json& json) { return read_image(Field{&json, "image"}); }

BenchResults parse_bench_results(std::string_view json_text) {
  const json document = parse_document(json_text);
  const Field root{&document, ""};
  if (!root.value->is_object() || root.value->value("format", "") != kFormat)
    throw RequestError("format", "must be \"lpv-bench-results\": this is not a results file of lpv-bench");
  const Field version = root.member("schema_version");
  if (as_uint<std::uint32_t>(version, 0, std::numeric_limits<std::uint32_t>::max()) != bench_results_schema_version)
    version.fail("must be " + std::to_string(bench_results_schema_version) + " (the version this lpv-bench reads), got " +
                 describe(*version.value));
  BenchResults r;
  const Field suite = root.member("suite");
  r.suite = text(suite, "name");
  r.suite_version = as_uint<std::uint32_t>(suite.member("version"), 0, std::numeric_limits<std::uint32_t>::max());
  r.label = text(root, "label");
  r.mode = text(root, "mode");
  r.url = text(root, "url");
  r.started_at = text(root, "started_at");
  r.duration_s = as_double(root.member("duration_s"), 0.0, kMaxMs);
  r.repetitions = as_uint<std::uint32_t>(root.member("repetitions"), 0, limits::max_bench_repetitions);
  r.warmup = as_uint<std::uint32_t>(root.member("warmup"), 0, limits::max_bench_warmup);
  r.complete = as_bool(root.member("complete"));
  const Field machine = root.member("machine");
  r.machine = {text(machine, "hostname"), text(machine, "cpu_model"),
               as_uint<std::uint32_t>(machine.member("cores"), 0, 1u << 20), text(machine, "os"),
               text(machine, "kernel")};
  const Field device = root.member("device");
  r.device = {text(device, "name"), text(device, "driver")};
  const Field build = root.member("build");
  r.build = {text(build, "version"),       text(build, "compiler"), text(build, "build_type"),
             text(build, "commit"),        as_bool(build.member("dirty")),
             as_bool(build.member("sanitizers"))};
  if (auto noise = root.optional_member("noise"); noise && !noise->value->is_null()) {
    const Field load = noise->member("load_average");
    if (!load.value->is_array() || load.value->size() != 2) load.reject("an array of 2 numbers");
    r.noise = BenchNoise{read_metric(noise->member("probe")).samples, as_double(load.element(0), 0.0, 1e6),
                         as_double(load.element(1), 0.0, 1e6), as_double(noise->member("steal"), 0.0, 1.0)};
  }
  for (const Field& c : as_array(root.member("cases"), limits::max_bench_cases)) r.cases.push_back(read_case_result(c));
  return r;
}

}  // namespace api
