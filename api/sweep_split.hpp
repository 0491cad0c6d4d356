// One sweep as several whose rows, one part after another, are the sweep's rows in its order
// (lpv-bench sweep --url URL --jobs N sends each part to the service at once: behind a load
// balancer, each to a replica), and the parts' tables joined again.
#pragma once

#include "api/sweep_table.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <vector>

namespace api {

// The sweep request (JSON, already valid) cut along its slowest-varying parameter with more
// than one value (sweep_parameter_keys) into at most `parts` requests, the values shared out
// in order and as evenly as they go; the LPV-off row, if any, stays in the first. A sweep
// with no such parameter is one part. Every part has the whole reference settings, so each
// server traces the same reference (same seed: the same image).
std::vector<nlohmann::json> split_sweep(const nlohmann::json& request, std::size_t parts);

// The parts' rows in order, with the Pareto front marked afresh over all of them.
SweepTable join_sweep_tables(const std::vector<SweepTable>& parts);

}  // namespace api
