#include "server/bench_route.hpp"

#include "api/bench_results.hpp"
#include "api/bench_suite.hpp"
#include "server/bench_job.hpp"
#include "server/http_errors.hpp"

#include <nlohmann/json.hpp>

#include <memory>

namespace server {
namespace {

std::string case_path(std::size_t index, const std::string& field) {
  return "cases[" + std::to_string(index) + "]." + field;
}

// What a suite may ask of this server beyond the schema: scenes it has, no files.
std::optional<HttpError> unservable(const api::BenchSuite& suite, const Service& service) {
  for (std::size_t i = 0; i < suite.cases.size(); ++i) {
    const api::BenchCase& c = suite.cases[i];
    if (c.scene_file)
      return HttpError{400, "invalid_value",
                       "not available in POST /v1/bench: upload the scene (POST /v1/scenes) and name its id in "
                       "request.scene",
                       case_path(i, "scene_file")};
    if (std::optional<HttpError> error = missing_scene(c.request.scene, case_path(i, "request.scene"), service))
      return error;
  }
  return std::nullopt;
}

}  // namespace

void handle_bench(const httplib::Request& request, httplib::Response& response, const httplib::ContentReader& content,
                  Service& service) {
  auto accepted = accept_request<api::BenchSuite>(
      request, response, content, service, api::parse_bench_suite, service.options.accuracy_deadline,
      [&](const api::BenchSuite& suite) { return unservable(suite, service); });
  if (!accepted) return;
  const std::optional<nlohmann::json> device = service.queue.device_report();
  if (!device) return send_unavailable(response, "not_ready", "the render device is still starting");
  auto job = std::make_shared<BenchJob>(std::move(accepted->request),
                                        api::BenchDevice{device->value("name", ""), device->value("driver", "")},
                                        request_arrival() + accepted->deadline);
  if (!run_job(job, accepted->deadline, request, response, service)) return;
  send_json(response, api::to_json(*job->result));
}

}  // namespace server
