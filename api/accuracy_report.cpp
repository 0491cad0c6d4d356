#include "api/accuracy_report.hpp"

#include <nlohmann/json.hpp>

namespace api {

nlohmann::json to_json(const ReferenceReport& report) {
  return {{"samples", report.settings.samples},
          {"bounces", report.settings.bounces},
          {"seed", report.settings.seed},
          {"paths", report.paths},
          {"rays", report.rays},
          {"build_ms", report.build_ms},
          {"trace_ms", report.trace_ms},
          {"noise_rmse", report.noise_rmse},
          {"relative_noise", report.relative_noise},
          {"cached", report.cached}};
}

}  // namespace api
