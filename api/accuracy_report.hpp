// What the accuracy requests answer besides images and tables: how exact the ground truth
// is and what it cost.
#pragma once

#include "api/accuracy_request.hpp"
#include "api/error_metrics.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>

namespace api {

struct ReferenceReport {
  ReferenceSettings settings;
  std::uint64_t paths = 0;  // camera paths traced (pixels x samples)
  std::uint64_t rays = 0;   // of every kind: camera, bounce and shadow
  double build_ms = 0.0;    // the ray-tracing acceleration structure
  double trace_ms = 0.0;
  // Its own noise: the RMSE it adds to any comparison (sqrt of the mean squared standard error
  // over the surface pixels), and that relative to its mean indirect light.
  double noise_rmse = 0.0;
  double relative_noise = 0.0;
  bool cached = false;  // computed by an earlier request: nothing was spent on it now
};

nlohmann::json to_json(const ReferenceReport& report);
// The inverse of to_json, as sweep_table_from_json reads a table (sweep_table_read.cpp).
ReferenceReport reference_report_from_json(const nlohmann::json& json, const std::string& path = "reference");

}  // namespace api
