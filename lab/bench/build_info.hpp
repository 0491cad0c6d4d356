// Where results come from: this machine and this build (docs/perf-regression.md).
#pragma once

#include "api/bench_results.hpp"

#include <string>

namespace bench {

// Host name, CPU model (/proc/cpuinfo), logical cores, OS (/etc/os-release) and kernel
// (uname); "unknown" for what cannot be read.
api::BenchMachine this_machine();

// The project's version, compiler, build type, sanitizers, and the git commit the build was
// made from (written at build time; $LPV_BENCH_COMMIT overrides it, e.g. for a build from a
// source archive).
api::BenchBuild this_build();

// The label results carry when their run names none: the commit's first 12 characters.
std::string default_label(const api::BenchBuild& build);

}  // namespace bench
