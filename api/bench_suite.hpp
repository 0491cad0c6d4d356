// A benchmark suite (docs/perf-regression.md): a named, versioned list of cases, each a render
// request, that `lpv-bench run` and POST /v1/bench time with warm-up and repetitions.
// Plain data with defaults; parsing and validation live in bench_suite.cpp.
#pragma once

#include "api/render_request.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace api {

// render: the renderer's own times (per pass, the frame's GPU and wall time);
// server_round_trip: a client's POST /v1/render to a server, image in the body, timed from
// sending the request to the last byte of the answer.
enum class BenchCaseKind { render, server_round_trip };
inline constexpr std::array kBenchCaseKinds{BenchCaseKind::render, BenchCaseKind::server_round_trip};

struct BenchCase {
  std::string name;  // unique within the suite; how results and comparisons name the case
  BenchCaseKind kind = BenchCaseKind::render;
  RenderRequest request;
  // A glTF file to render instead of request.scene (lpv-bench only: a server renders only
  // what was uploaded to it). Relative paths are relative to the suite file.
  std::optional<std::string> scene_file;
};

struct BenchSuite {
  std::string name;
  std::uint32_t version = 1;  // changes whenever the cases change: results of different versions do not compare
  std::string description;
  std::uint32_t repetitions = 5;  // timed renders per case
  std::uint32_t warmup = 1;       // untimed renders per case before them
  std::vector<BenchCase> cases;
};

namespace limits {
inline constexpr std::size_t max_bench_cases = 256;
inline constexpr std::uint32_t max_bench_repetitions = 1000;
inline constexpr std::uint32_t max_bench_warmup = 100;
inline constexpr std::size_t max_bench_name_bytes = 100;
inline constexpr std::size_t max_bench_description_bytes = 2000;
inline constexpr std::size_t max_scene_file_bytes = 4096;
}  // namespace limits

std::string to_string(BenchCaseKind kind);

// Throws RequestError naming the field ("cases[2].request.lpv.grid").
BenchSuite parse_bench_suite(std::string_view json_text);

}  // namespace api
