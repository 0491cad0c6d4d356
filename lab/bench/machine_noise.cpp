#include "core/elapsed.hpp"
#include "lab/bench/machine_noise.hpp"

#include <string>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <tuple>

namespace bench {
namespace {

// About 11 ms of integer work on one thread of the project's machine: several scheduler
// slices, so that a steady load averages out as it does over a render and what is left is a
// load that comes and goes; short enough that a probe before each of a suite's few hundred
// rounds costs a few seconds. One thread, not one per core: with a CPU hog on one of two
// cores, a thread per core put one of them beside the hog at the scheduler's whim and
// scattered the probe by 10-22% while the renders' pairs still agreed.
constexpr std::uint32_t kProbeSteps = 6'000'000;

// Where the probe's results go, so that the compiler cannot drop the work.
volatile std::uint64_t probe_sink = 0;

// A dependency chain the compiler cannot shorten.
std::uint64_t probe_work(std::uint64_t seed) {
  std::uint64_t x = seed | 1u;
  for (std::uint32_t i = 0; i < kProbeSteps; ++i) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
  }
  return x;
}

// 1-minute load average; 0 where /proc is not there.
double load_average() {
  std::ifstream file("/proc/loadavg");
  double load = 0.0;
  file >> load;
  return file ? load : 0.0;
}

// The CPU line of /proc/stat: stolen time and all time, in clock ticks; zeros without /proc.
std::pair<std::uint64_t, std::uint64_t> cpu_ticks() {
  std::ifstream file("/proc/stat");
  std::string line, label;
  if (!std::getline(file, line)) return {0, 0};
  std::istringstream fields(line);
  fields >> label;
  // user nice system idle iowait irq softirq steal (guest time is counted in user already)
  std::uint64_t value = 0, total = 0, steal = 0;
  for (int i = 0; i < 8 && fields >> value; ++i) {
    total += value;
    if (i == 7) steal = value;
  }
  return {steal, total};
}

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f%%", 100.0 * fraction);
  return text;
}

}  // namespace

NoiseMonitor::NoiseMonitor() {
  noise_.load_start = load_average();
  std::tie(steal_start_, total_start_) = cpu_ticks();
}

void NoiseMonitor::probe() {
  const auto start = std::chrono::steady_clock::now();
  probe_sink = probe_sink ^ probe_work(noise_.probe_ms.size());
  noise_.probe_ms.push_back(core::ms_since(start));
}

api::BenchNoise NoiseMonitor::noise() const {
  api::BenchNoise noise = noise_;
  noise.load_end = load_average();
  const auto [steal, total] = cpu_ticks();
  noise.steal = total > total_start_ ? double(steal - steal_start_) / double(total - total_start_) : 0.0;
  return noise;
}

std::optional<std::string> too_noisy(const api::BenchNoise& noise, double max_probe_spread) {
  const api::BenchSummary probe = api::summarize(noise.probe_ms);
  if (probe.spread <= max_probe_spread) return std::nullopt;
  return "the CPU probe's times scatter by " + percent(probe.spread) + " (MAD / median of " + std::to_string(probe.n) +
         "; at most " + percent(max_probe_spread) + " for a verdict)";
}

}  // namespace bench
