#include "worker_protocol.hpp"

#include "api/request_error.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace bench {
namespace {

using nlohmann::json;

json parse_reply(const std::string& line) {
  const json reply = json::parse(line, nullptr, false);
  if (!reply.is_object()) throw std::runtime_error("the worker said something else than JSON: " + line.substr(0, 200));
  if (reply.contains("error")) throw std::runtime_error(reply["error"].is_string() ? reply["error"].get<std::string>()
                                                                                   : reply["error"].dump());
  return reply;
}

std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

}  // namespace

std::string hello_line(const WorkerHello& hello) {
  return dump({{"lpv_bench_worker", kWorkerProtocol},
               {"results", api::to_json(hello.header)},
               {"no_round_trips", hello.no_round_trips}});
}

std::string image_reply(const api::BenchImage& image) { return dump({{"image", api::to_json(image)}}); }

std::string metrics_reply(const Measurement& measurement) {
  json metrics = json::array();
  for (const auto& [name, ms] : measurement) metrics.push_back({name, ms});
  return dump({{"metrics", std::move(metrics)}});
}

std::string error_reply(const std::string& message) { return dump({{"error", message}}); }

WorkerHello read_hello(const std::string& line) {
  const json hello = parse_reply(line);
  if (hello.value("lpv_bench_worker", 0) != kWorkerProtocol)
    throw std::runtime_error("the worker speaks another protocol: " + line.substr(0, 200));
  try {
    return {api::parse_bench_results(dump(hello.at("results"))), hello.at("no_round_trips").get<std::string>()};
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("the worker's greeting: ") + e.what());
  }
}

api::BenchImage read_image_reply(const std::string& line) {
  const json reply = parse_reply(line);
  if (!reply.contains("image")) throw std::runtime_error("the worker answered no image: " + line.substr(0, 200));
  try {
    return api::parse_bench_image(reply["image"]);
  } catch (const api::RequestError& e) {
    throw std::runtime_error(std::string("the worker's image: ") + e.what());
  }
}

Measurement read_metrics_reply(const std::string& line) {
  const json reply = parse_reply(line);
  Measurement m;
  for (const json& metric : reply.value("metrics", json::array())) {
    if (!metric.is_array() || metric.size() != 2 || !metric[0].is_string() || !metric[1].is_number())
      throw std::runtime_error("the worker answered no metrics: " + line.substr(0, 200));
    m.emplace_back(metric[0].get<std::string>(), metric[1].get<double>());
  }
  if (m.empty()) throw std::runtime_error("the worker answered no metrics: " + line.substr(0, 200));
  return m;
}

}  // namespace bench
