#include "api/sweep_split.hpp"

#include "api/accuracy_request.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <stdexcept>

namespace api {

std::vector<nlohmann::json> split_sweep(const nlohmann::json& request, std::size_t parts) {
  if (parts == 0) throw std::invalid_argument("split_sweep: parts must be at least 1");
  const nlohmann::json* parameters = request.contains("parameters") ? &request["parameters"] : nullptr;
  const auto split_key = std::ranges::find_if(sweep_parameter_keys, [&](std::string_view key) {
    return parameters && parameters->contains(key) && (*parameters)[std::string(key)].size() > 1;
  });
  if (split_key == sweep_parameter_keys.end() || parts == 1) return {request};

  const std::string key(*split_key);
  const nlohmann::json& values = (*parameters)[key];
  const std::size_t n = std::min(parts, values.size());
  std::vector<nlohmann::json> split;
  for (std::size_t k = 0, begin = 0; k < n; ++k) {
    const std::size_t end = begin + values.size() / n + (k < values.size() % n ? 1 : 0);
    nlohmann::json part = request;
    part["parameters"][key] = nlohmann::json(values.begin() + std::ptrdiff_t(begin), values.begin() + std::ptrdiff_t(end));
    if (k > 0) {  // the rows that vary nothing go with the first part only
      part["lpv_off_row"] = false;
      part.erase("path_traced");
    }
    split.push_back(std::move(part));
    begin = end;
  }
  return split;
}

SweepTable join_sweep_tables(const std::vector<SweepTable>& parts) {
  SweepTable joined;
  if (parts.empty()) return joined;
  joined.axis = parts.front().axis;
  for (const SweepTable& part : parts) joined.rows.insert(joined.rows.end(), part.rows.begin(), part.rows.end());
  mark_pareto(joined);
  return joined;
}

}  // namespace api
