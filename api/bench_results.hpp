// The results of a benchmark suite run: what `lpv-bench run` writes, POST /v1/bench answers
// and `lpv-bench compare` reads. One JSON schema, bench/results.schema.json, described in
// docs/perf-regression.md. Plain data; JSON in both directions in bench_results.cpp.
#pragma once

#include "api/bench_suite.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace api {

inline constexpr std::uint32_t bench_results_schema_version = 1;

// Median, min and max of the samples, and their spread: the median absolute deviation (MAD)
// and, relative to the median, mad / median (0 when the median is 0). The MAD, unlike the
// standard deviation, is not blown up by the one slow repetition a shared machine produces.
struct BenchSummary {
  double median = 0.0;
  double min = 0.0;
  double max = 0.0;
  double mad = 0.0;
  double spread = 0.0;
  std::size_t n = 0;
};
BenchSummary summarize(std::span<const double> samples);

// One measured quantity of a case over its repetitions, in milliseconds: "gpu_ms" (the
// frame's passes), "wall_ms" (the whole frame), "round_trip_ms" (a client's request to the
// last byte of the answer), "pass.<name>" (one pass's device time).
struct BenchMetric {
  std::string name;
  std::vector<double> samples;  // in the order they were measured
};

// The case's image, so that a comparison can tell "faster" from "faster but different":
// the SHA-256 of its linear radiance as PFM (what output.format "pfm" answers), and a
// thumbnail small enough to keep in the results (the image box-filtered to at most
// bench_thumbnail_side pixels a side, PFM) for error metrics when the hashes differ.
struct BenchImage {
  std::string sha256;  // 64 lowercase hex digits
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t thumbnail_width = 0;
  std::uint32_t thumbnail_height = 0;
  std::string thumbnail_pfm_base64;
};
inline constexpr std::uint32_t bench_thumbnail_side = 64;

enum class BenchCaseStatus { ok, skipped, failed };

struct BenchCaseResult {
  std::string name;
  BenchCaseKind kind = BenchCaseKind::render;
  BenchCaseStatus status = BenchCaseStatus::ok;
  std::string reason;        // why it was skipped or failed
  nlohmann::json request;    // the request as rendered, every field (api::to_json)
  std::vector<BenchMetric> metrics;
  std::optional<BenchImage> image;

  const BenchMetric* metric(std::string_view name) const;
};

struct BenchMachine {
  std::string hostname;
  std::string cpu_model;
  std::uint32_t cores = 0;
  std::string os;      // /etc/os-release's PRETTY_NAME
  std::string kernel;  // uname: sysname release machine
};

struct BenchDevice {
  std::string name;
  std::string driver;
};

struct BenchBuild {
  std::string version;     // the project's
  std::string compiler;    // "GNU 12.2.0"
  std::string build_type;  // "Release"
  std::string commit;      // git commit of the source tree, or "unknown"
  bool dirty = false;      // the tree had uncommitted changes when it was built
  bool sanitizers = false; // an LPV_SANITIZE build: its times say nothing about a release
};

// How steady the machine was while the run measured (lab/bench/machine_noise.hpp): a
// fixed piece of CPU work timed before every round of renders, the load average at the start
// and the end, and the share of CPU time the hypervisor took (steal). A comparison says
// "inconclusive: noisy machine" rather than judge times a noisy run measured.
struct BenchNoise {
  std::vector<double> probe_ms;  // the probe's times, in the order measured
  double load_start = 0.0;  // 1-minute load average
  double load_end = 0.0;
  double steal = 0.0;       // stolen / all CPU time over the run, 0 .. 1
};

struct BenchResults {
  std::string suite;
  std::uint32_t suite_version = 0;
  std::string label;  // the run's name in reports ("A", "nightly", a commit)
  std::string mode;   // "in_process" (lpv-bench), "http" (lpv-bench --url), "server" (POST /v1/bench)
  std::string url;    // the server's, in "http" mode
  std::string started_at;  // UTC, ISO 8601
  double duration_s = 0.0;
  std::uint32_t repetitions = 0;
  std::uint32_t warmup = 0;
  bool complete = true;  // false: stopped early (deadline, client gone); the cases not run are absent
  BenchMachine machine;
  BenchDevice device;
  BenchBuild build;
  std::optional<BenchNoise> noise;  // absent in results of lpv-bench before it measured noise
  std::vector<BenchCaseResult> cases;

  const BenchCaseResult* find(std::string_view case_name) const;
};

std::string to_string(BenchCaseStatus status);

nlohmann::json to_json(const BenchResults& results);
nlohmann::json to_json(const BenchImage& image);
// Reads a results document. Keys this version does not know are ignored (a newer lpv-bench
// may add some), but every key it reads must be there with its documented type: errors are
// RequestError naming the field ("cases[3].metrics[0].samples[2]").
BenchResults parse_bench_results(std::string_view json_text);
// One image as to_json writes it (lpv-bench's A/B workers send them); errors as above.
BenchImage parse_bench_image(const nlohmann::json& json);

}  // namespace api
