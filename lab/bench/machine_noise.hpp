// How steady the machine is while a run measures: what the A/B pairs cannot cancel. Pairing
// takes out a load that stays put for the seconds a pair takes; a load that comes and goes
// faster than that (a build starting jobs, a hypervisor lending the cores out) moves each
// render on its own, and no statistics over a dozen pairs tell that from a change. So a run
// times a fixed piece of CPU work (the probe, on one thread) before every round of renders,
// and reads the load average and the CPU time stolen by a hypervisor; a comparison refuses a
// verdict when the probe's own times scatter (docs/perf-regression.md, "A noisy machine").
#pragma once

#include "api/bench_results.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace bench {

// Beyond this the probe's MAD / median rules out a verdict on a run's times (lpv-bench
// --max-probe-spread sets another). Measured on the project's 2-core VM: 0.007 quiet,
// 0.009 with a CPU hog on one core, 0.020 with a hog on each, 0.018-0.024 idle while the
// hypervisor stole 12-23% of the time, 0.048 with loads on both cores that come and go every
// few tenths of a second. Stolen time is reported, not judged: on that VM it was high on an
// idle machine whose probe stayed steady, and the probe measures what the renders feel.
inline constexpr double kMaxProbeSpread = 0.05;

class NoiseMonitor {
 public:
  NoiseMonitor();  // reads the load average and the CPU counters at the start

  // Times the probe once.
  void probe();

  // The probe's times, and the load and the stolen time from the start until now.
  api::BenchNoise noise() const;

 private:
  api::BenchNoise noise_;
  std::uint64_t steal_start_ = 0, total_start_ = 0;
};

// Why a run's noise rules out a verdict ("the CPU probe's times scatter by 23% (MAD / median
// of 65; at most 5% for a verdict)"), or nothing when it is steady enough.
std::optional<std::string> too_noisy(const api::BenchNoise& noise, double max_probe_spread = kMaxProbeSpread);

}  // namespace bench
