// The server's policy on how much work one request may ask for, on top of the hard
// limits the api/ parser enforces (api::limits). A request within the schema but over
// these limits is answered 422 with the field named.
#pragma once

#include "api/accuracy_request.hpp"
#include "api/bench_suite.hpp"
#include "api/render_request.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace server {

struct RenderLimits {
  std::uint64_t max_pixels = 4096ull * 4096ull;                  // output.width * output.height
  std::uint64_t max_grid_cells = 128ull * 128ull * 128ull;       // lpv.grid x * y * z * lpv.cascades
  std::uint32_t max_iterations = 64;                             // lpv.iterations
  std::uint32_t max_repeat = 100;                                // repeat
  std::uint64_t max_reference_paths = 1ull << 26;                // reference samples x pixels (compare, sweep)
};

class LimitExceeded : public std::runtime_error {
 public:
  LimitExceeded(std::string field, const std::string& message)
      : std::runtime_error(message), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

// Throws LimitExceeded naming the first field over its limit.
void check_limits(const api::RenderRequest& request, const RenderLimits& limits);
// The same for every render they make (errors name the field under "base", "against" or
// "parameters"), and for the reference's cost.
void check_limits(const api::CompareRequest& request, const RenderLimits& limits);
void check_limits(const api::SweepRequest& request, const RenderLimits& limits);
// Every case's request (errors name the field under "cases[i].request"); repetitions and
// warm-up renders per case within max_repeat, as a request's frames are.
void check_limits(const api::BenchSuite& suite, const RenderLimits& limits);

}  // namespace server
