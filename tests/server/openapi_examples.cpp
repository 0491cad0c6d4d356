#include "openapi_examples.hpp"

#include <fstream>
#include <map>
#include <stdexcept>

namespace server_test {
namespace {

std::size_t indent_of(const std::string& line) {
  const auto first = line.find_first_not_of(' ');
  return first == std::string::npos ? line.size() : first;
}

// "  /v1/render:" -> "/v1/render"; "'200':" -> "200"; empty when the line is not a bare key.
std::string key_of(const std::string& line) {
  std::string text = line.substr(indent_of(line));
  if (text.empty() || text.back() != ':' || text.front() == '#' || text.front() == '-') return "";
  text.pop_back();
  if (text.size() >= 2 && (text.front() == '\'' || text.front() == '"')) text = text.substr(1, text.size() - 2);
  return text;
}

}  // namespace

std::vector<OpenApiExample> read_openapi_examples(const std::string& yaml_file) {
  std::ifstream in(yaml_file);
  if (!in) throw std::runtime_error("cannot read " + yaml_file);
  std::vector<OpenApiExample> examples;
  std::map<std::size_t, std::string> keys;  // the last bare key seen at each indentation
  bool in_paths = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.find_first_not_of(' ') == std::string::npos) continue;
    const std::size_t indent = indent_of(line);
    if (indent == 0) in_paths = line == "paths:";
    if (!in_paths) continue;
    for (auto it = keys.lower_bound(indent); it != keys.end();) it = keys.erase(it);  // leave deeper scopes
    if (const std::string key = key_of(line); !key.empty()) {
      keys[indent] = key;
      continue;
    }
    const std::string text = line.substr(indent);
    if (!text.starts_with("value: ") || indent < 2 || !keys.count(indent - 2) || !keys.count(2) || !keys.count(4) ||
        !keys.count(6))
      continue;
    OpenApiExample example;
    example.path = keys[2];
    example.method = keys[4];
    example.location = keys[6] == "responses" && keys.count(8) ? keys[8] : keys[6];
    example.name = keys[indent - 2];
    try {
      example.value = nlohmann::json::parse(text.substr(7));
    } catch (const nlohmann::json::exception& e) {
      throw std::runtime_error(yaml_file + ":" + std::to_string(number) + ": example value is not one line of JSON: " +
                               e.what());
    }
    examples.push_back(std::move(example));
  }
  return examples;
}

}  // namespace server_test
