#include "http_sweep.hpp"

#include "api/sweep_split.hpp"
#include "server_connection.hpp"

#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace bench {
namespace {

struct Part {
  api::SweepTable table;
  api::ReferenceReport reference;
  bool complete = false;
};

Part sweep_part(const std::string& url, const nlohmann::json& request) {
  ServerConnection server(url);
  const auto result = server.http().Post("/v1/sweep?format=json", request.dump(), "application/json");
  if (!result || result->status != 200) throw server.failure("POST /v1/sweep", result);
  const nlohmann::json answer = parse_answer(result->body, "the sweep's answer");
  if (!answer.is_object()) throw std::runtime_error("the sweep's answer is not a JSON object");
  return {api::sweep_table_from_json(answer.value("table", nlohmann::json())),
          api::reference_report_from_json(answer.value("reference", nlohmann::json())), answer.value("complete", false)};
}

}  // namespace

accuracy::SweepResult sweep_through(const std::string& url, const nlohmann::json& request, std::uint32_t jobs,
                                    const std::function<void(std::size_t done, std::size_t parts)>& parts_done) {
  ServerConnection checked(url);  // a bad URL is refused before any part starts
  const std::vector<nlohmann::json> requests = api::split_sweep(request, jobs);
  std::vector<std::optional<Part>> parts(requests.size());
  std::mutex mutex;
  std::size_t done = 0;
  std::exception_ptr error;
  std::vector<std::thread> senders;
  for (std::size_t k = 0; k < requests.size(); ++k)
    senders.emplace_back([&, k] {
      try {
        Part part = sweep_part(url, requests[k]);
        std::lock_guard lock(mutex);
        parts[k] = std::move(part);
        if (parts_done) parts_done(++done, requests.size());
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
      }
    });
  for (std::thread& s : senders) s.join();
  if (error) std::rethrow_exception(error);

  accuracy::SweepResult result;
  std::vector<api::SweepTable> tables;
  for (const auto& part : parts) {
    tables.push_back(part->table);
    result.complete = result.complete && part->complete;
  }
  result.table = api::join_sweep_tables(tables);
  result.reference = parts.front()->reference;
  return result;
}

}  // namespace bench
