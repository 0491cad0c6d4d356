#include "input_files.hpp"

#include "api/request_error.hpp"
#include "image/file_io.hpp"

#include <algorithm>
#include <fstream>
#include <span>
#include <sstream>

namespace bench {

std::string read_text_file(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw BadInput("cannot read '" + path.string() + "': no such file");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw BadInput("cannot read '" + path.string() + "'");
  return text.str();
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  image::write_file_atomically(path, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

SuiteFile load_suite(const std::string& name_or_path) {
  std::filesystem::path path = name_or_path;
  std::error_code error;
  const bool is_name = name_or_path.find('/') == std::string::npos && path.extension() != ".json";
  if (!std::filesystem::exists(path, error) && is_name)
    path = std::filesystem::path(LPV_BENCH_SUITE_DIR) / (name_or_path + ".json");
  if (!std::filesystem::exists(path, error))
    throw BadInput("no suite '" + name_or_path + "'" +
                   (is_name ? " (nor " + path.string() + ")" : std::string()));
  SuiteFile file{std::filesystem::absolute(path), {}};
  try {
    file.suite = api::parse_bench_suite(read_text_file(file.path));
  } catch (const api::RequestError& e) {
    throw BadInput("bad suite " + file.path.string() + ": " + e.what());
  }
  for (api::BenchCase& c : file.suite.cases)
    if (c.scene_file) c.scene_file = (file.path.parent_path() / *c.scene_file).lexically_normal().string();
  return file;
}

std::vector<std::string> suite_names() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(LPV_BENCH_SUITE_DIR, error))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

api::BenchResults load_results(const std::filesystem::path& path) {
  try {
    return api::parse_bench_results(read_text_file(path));
  } catch (const api::RequestError& e) {
    throw BadInput("bad results file " + path.string() + ": " + e.what());
  }
}

}  // namespace bench
