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
    if (!scene_exists(c.request.scene, service)) {
      HttpError error = unknown_scene(c.request.scene);
      error.field = case_path(i, "request.scene");
      return error;
    }
  }
  return std::nullopt;
}

}  // namespace

void handle_bench(const httplib::Request& request, httplib::Response& response, const httplib::ContentReader& content,
                  Service& service) {
  const std::optional<std::string> body =
      read_body(request, response, content, service.options, service.options.max_body_bytes, "--max-body-bytes");
  if (!body) return;
  api::BenchSuite suite;
  std::chrono::milliseconds deadline{};
  try {
    suite = api::parse_bench_suite(*body);
    deadline = deadline_for(request, service.options.accuracy_deadline);
  } catch (const api::RequestError& e) {
    return send_error(response, parse_error(e));
  }
  if (const std::optional<HttpError> error = unservable(suite, service)) return send_error(response, *error);
  try {
    check_limits(suite, service.options.limits);
  } catch (const LimitExceeded& e) {
    return send_error(response, limit_error(e));
  }
  const std::optional<nlohmann::json> device = service.queue.device_report();
  if (!device) return send_unavailable(response, "not_ready", "the render device is still starting");
  auto job = std::make_shared<BenchJob>(std::move(suite),
                                        api::BenchDevice{device->value("name", ""), device->value("driver", "")},
                                        request_arrival() + deadline);
  if (!run_job(job, deadline, request, response, service)) return;
  send_json(response, api::to_json(*job->result));
}

}  // namespace server
