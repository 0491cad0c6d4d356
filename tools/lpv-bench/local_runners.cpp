#include "local_runners.hpp"

#include "input_files.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>

namespace bench {

RoundTrips::RoundTrips(const Options& options, const api::BenchSuite& suite) {
  const bool needed = std::ranges::any_of(suite.cases, [](const api::BenchCase& c) {
    return c.kind == api::BenchCaseKind::server_round_trip;
  });
  if (!needed) return;
  if (options.no_server) {
    unavailable = "--no-server: no server for round trips";
    return;
  }
  const std::filesystem::path binary =
      options.server_binary ? std::filesystem::path(*options.server_binary) : server_beside_this_program();
  if (options.server_binary && ::access(binary.c_str(), X_OK) != 0)
    throw BadInput("--server-binary: '" + binary.string() + "' is not an executable file");
  if (binary.empty()) {
    unavailable = "no lpv-server beside lpv-bench: give --server-binary PATH or --url URL";
    return;
  }
  if (options.device) ::setenv("LPV_DEVICE", options.device->c_str(), 1);  // the server renders on the same device
  server = std::make_unique<LaunchedServer>(binary);
  runner = std::make_unique<HttpCaseRunner>(server->url());
}

namespace {

api::BenchDevice device_of(const renderer::DeviceReport& report) { return {report.name, report.driver}; }

}  // namespace

LocalRunners::LocalRunners(const Options& options, const api::BenchSuite& suite)
    : round_trips_(options, suite),
      lab_(options),
      renders_(lab_.bench, device_of(lab_.device.report()), true) {}

}  // namespace bench
