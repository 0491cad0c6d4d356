#include "lab/bench/build_info.hpp"

#include "bench_commit.hpp"  // generated: bench::generated::kCommit, kDirty

#include <sys/utsname.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

namespace bench {
namespace {

constexpr const char* kUnknown = "unknown";

// The value of the first line "key<separator>value" of a text file, trimmed and unquoted.
std::string file_value(const char* path, const std::string& key, char separator) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    const auto at = line.find(separator);
    if (at == std::string::npos) continue;
    std::string name = line.substr(0, at);
    while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.pop_back();
    if (name != key) continue;
    std::string value = line.substr(at + 1);
    value.erase(0, value.find_first_not_of(" \t\""));
    while (!value.empty() && (value.back() == '"' || value.back() == ' ')) value.pop_back();
    return value.empty() ? kUnknown : value;
  }
  return kUnknown;
}

}  // namespace

api::BenchMachine this_machine() {
  api::BenchMachine machine;
  char host[256] = {};
  machine.hostname = gethostname(host, sizeof(host) - 1) == 0 ? host : kUnknown;
  machine.cpu_model = file_value("/proc/cpuinfo", "model name", ':');
  machine.cores = std::thread::hardware_concurrency();
  machine.os = file_value("/etc/os-release", "PRETTY_NAME", '=');
  utsname name{};
  machine.kernel = uname(&name) == 0 ? std::string(name.sysname) + " " + name.release + " " + name.machine : kUnknown;
  return machine;
}

api::BenchBuild this_build() {
  api::BenchBuild build;
  build.version = LPV_BENCH_VERSION;
  build.compiler = LPV_BENCH_COMPILER;
  build.build_type = LPV_BENCH_BUILD_TYPE;
  build.sanitizers = LPV_BENCH_SANITIZERS;
  const char* commit = std::getenv("LPV_BENCH_COMMIT");
  build.commit = commit && *commit ? commit : generated::kCommit;
  build.dirty = commit && *commit ? false : generated::kDirty;
  return build;
}

std::string default_label(const api::BenchBuild& build) { return build.commit.substr(0, 12); }

}  // namespace bench
